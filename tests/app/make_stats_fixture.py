#!/usr/bin/python3
"""Writes small synthetic dynamic-run outputs for the `catena stats` app tests.

The layout is the one of docs/output.md ("Contact forces and pantographs"): /time,
/samples/contact_force and /samples/contact_position (n_samples x n_pantographs), a group
per pantograph under /pantographs (attributes index, speed), /mesh/registration_nodes,
/mesh/node_positions, /samples/positions, root attributes format, analysis, status,
evaluation_start, evaluation_end.

stats_run.h5: 5 s at 1 kHz, two pantographs on a straight line from x = 0:
  leading  250 km/h, F = 115 + 30 sin(2 pi 2 t) N (no loss of contact);
  trailing 300 km/h, F = 120 + 40 sin(2 pi 3 t) + 10 sin(2 pi 60 t) N, 0 on 50 samples
           while its contact point is in [150, 160] m (loss of contact);
  registration nodes every 60 m from 0 to 360 m (plus 3 messenger nodes), each lifted by
  0.05 exp(-((x_leading - x_node) / 10 m)^2) m as the leading pantograph passes;
  evaluation section [100, 300] m.
The variants, each changing one thing: stats_running.h5 (status "running": a run still
going or crashed, read with a warning), stats_acceptance.h5 (root attribute acceptance =
"en50318": the EN 50318 ranges checked), stats_unknown_acceptance.h5 ("en50367"),
stats_interrupted.h5 (status "interrupted", the record ending at 3 s: the leading head at
208 m, the trailing one at 250 m, inside the section; acceptance "en50318"),
stats_interrupted_early.h5 (interrupted at 1 s, before either head reaches the section),
stats_short.h5 (complete, but only 3 s: the record ends inside the section),
stats_no_section.h5 (no evaluation section), stats_coarse.h5 (100 Hz sampling),
stats_static.h5 (a static result), stats_no_pantographs.h5 (no contact datasets),
stats_old_format.h5 (no format attribute: an older Catena's), stats_other_format.h5
(format "catena-transient-0"), stats_nan_time.h5 (sample 20's time NaN: a damaged file).
Usage: make_stats_fixture.py OUTDIR
"""
import os
import sys

import h5py
import numpy as np

DT = 1e-3
DURATION = 5.0
SPEEDS = {"leading": 250 / 3.6, "trailing": 300 / 3.6}  # m/s
SECTION = (100.0, 300.0)
REGISTRATION_X = np.arange(0.0, 361.0, 60.0)
Z0 = 5.3


def signals(t):
    x = {name: v * t for name, v in SPEEDS.items()}
    lead = 115 + 30 * np.sin(2 * np.pi * 2 * t)
    trail = 120 + 40 * np.sin(2 * np.pi * 3 * t) + 10 * np.sin(2 * np.pi * 60 * t)
    lost = np.flatnonzero((x["trailing"] >= 150) & (x["trailing"] <= 160))[:50]
    trail[lost] = 0.0
    return x, np.column_stack([lead, trail])


FORMAT = "catena-transient-1"


def write(path, dt=DT, status="complete", section=SECTION, static=False, contact=True,
          file_format=FORMAT, duration=DURATION, acceptance=None):
    t = np.arange(0, round(duration / dt) + 1) * dt
    x, force = signals(t)
    reference = np.zeros((len(REGISTRATION_X) + 3, 3))
    reference[: len(REGISTRATION_X), 0] = REGISTRATION_X
    reference[: len(REGISTRATION_X), 2] = Z0
    reference[len(REGISTRATION_X):, 0] = [30.0, 90.0, 150.0]   # messenger nodes
    reference[len(REGISTRATION_X):, 2] = Z0 + 1.2
    positions = np.repeat(reference[None, :, :], len(t), axis=0)
    for j, xr in enumerate(REGISTRATION_X):
        positions[:, j, 2] += 0.05 * np.exp(-(((x["leading"] - xr) / 10.0) ** 2))
    with h5py.File(path, "w") as f:
        if static:
            f.attrs["format"] = "catena-static-1"
            f["mesh/node_positions"] = reference
            return
        if file_format is not None:
            f.attrs["format"] = file_format
        f.attrs["analysis"] = "dynamic"
        f.attrs["status"] = status
        if section is not None:
            f.attrs["evaluation_start"], f.attrs["evaluation_end"] = section
        if acceptance is not None:
            f.attrs["acceptance"] = acceptance
        f["time"] = t
        f["mesh/node_positions"] = reference
        f["mesh/registration_nodes"] = np.arange(len(REGISTRATION_X), dtype=np.int64)
        f["samples/positions"] = positions
        if contact:
            f["samples/contact_force"] = force
            f["samples/contact_position"] = np.column_stack([x["leading"], x["trailing"]])
            for index, (name, speed) in enumerate(SPEEDS.items()):
                g = f.create_group("pantographs/" + name)
                g.attrs["index"] = np.int64(index)
                g.attrs["speed"] = float(speed)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    write(os.path.join(out, "stats_run.h5"))
    write(os.path.join(out, "stats_running.h5"), status="running")
    write(os.path.join(out, "stats_no_section.h5"), section=None)
    write(os.path.join(out, "stats_coarse.h5"), dt=0.01)
    write(os.path.join(out, "stats_static.h5"), static=True)
    write(os.path.join(out, "stats_no_pantographs.h5"), contact=False)
    write(os.path.join(out, "stats_old_format.h5"), file_format=None)
    write(os.path.join(out, "stats_other_format.h5"), file_format="catena-transient-0")
    write(os.path.join(out, "stats_acceptance.h5"), acceptance="en50318")
    write(os.path.join(out, "stats_unknown_acceptance.h5"), acceptance="en50367")
    write(os.path.join(out, "stats_interrupted.h5"), status="interrupted", duration=3.0,
          acceptance="en50318")
    write(os.path.join(out, "stats_interrupted_early.h5"), status="interrupted", duration=1.0)
    write(os.path.join(out, "stats_short.h5"), duration=3.0)
    nan_time = os.path.join(out, "stats_nan_time.h5")
    write(nan_time)
    with h5py.File(nan_time, "r+") as f:
        time = f["time"][...]
        time[20] = float("nan")
        f["time"][...] = time


if __name__ == "__main__":
    main()
