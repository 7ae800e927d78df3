#!/usr/bin/python3
"""check_error_bar.py RUN.h5 REFERENCE.h5 [SAME_AS.h5] — the error bar `catena run
--error-bar` stored in RUN.h5 (/error_bar) against the true error: the RMS distance between
RUN's and REFERENCE's track of the node that moves most (the plucked string's middle),
REFERENCE a run of the same scene at a step small enough to count as converged. Passes if
the estimate is within a factor of 3 of it and rests on an observed order (not the bound),
and, with SAME_AS (the same run's error bar made another way: the comparison runs beside the
run, --error-bar-ranks), if both files hold the same estimate and order to 1e-9."""
import math
import sys

import h5py
import numpy as np


def positions(path):
    with h5py.File(path, "r") as f:
        return f["samples/positions"][:], f["mesh/node_positions"][:]


def main():
    run_path, reference_path = sys.argv[1], sys.argv[2]
    run, mesh = positions(run_path)
    reference, _ = positions(reference_path)
    if run.shape != reference.shape:
        sys.exit(f"samples differ: {run.shape} against {reference.shape}")
    node = int(np.argmax(np.linalg.norm(reference - mesh[None], axis=2).max(axis=0)))
    true = float(np.sqrt(np.mean(np.sum((run[:, node] - reference[:, node]) ** 2, axis=1))))
    with h5py.File(run_path, "r") as f:
        if "error_bar" not in f:
            sys.exit(f"{run_path} has no /error_bar")
        parts = list(f["error_bar"])
        if len(parts) != 1 or not parts[0].startswith("node "):
            sys.exit(f"/error_bar holds {parts}, expected one probe node")
        bar = dict(f["error_bar"][parts[0]].attrs)
    estimate, order = float(bar["probe_rms"]), float(bar["probe_rms_order"])
    print(f"node index {node}: true RMS error {true:.4g} m, estimate {estimate:.4g} m "
          f"(ratio {estimate / true:.3f}), observed order {order:.3f}")
    if math.isnan(order):
        sys.exit("the estimate is the bound, not a Richardson estimate")
    if not (true / 3 <= estimate <= 3 * true):
        sys.exit("the estimate is not within a factor of 3 of the true error")
    if len(sys.argv) > 3:
        with h5py.File(sys.argv[3], "r") as f:
            other = dict(f["error_bar"][parts[0]].attrs)
        for key in ("probe_rms", "probe_rms_order"):
            a, b = float(bar[key]), float(other[key])
            print(f"{key}: {a:.12g} here, {b:.12g} in {sys.argv[3]}")
            if abs(a - b) > 1e-9 * abs(b):
                sys.exit(f"{key} differs from {sys.argv[3]}'s")


if __name__ == "__main__":
    main()
