#!/usr/bin/python3
"""analysis.structure: modal against analysis.structure: linear on the same scene.

Usage: check_modal_structure.py LINEAR.h5 MODAL.h5 RMS SIGMA [MODAL_OTHER_RANKS.h5]

The contact force of the modal run (the catenary's modes below the cut-off plus the static
correction, contact and slack droppers as forces) against the linear run's (the full
linearised structure, HHT): the RMS of their difference within RMS of the linear run's
mean force, their standard deviations within SIGMA (relative), and as many dropper samples
slack (zero axial force) within 10 %: the droppers still go slack and tighten in the modal
model. With a third file (the same modal run on another number of ranks) the two modal
runs agree to 1e-6 of the mean force: the modes differ by round-off and within
degenerate pairs, the model does not.
"""
import sys

import h5py
import numpy as np


def read(path):
    with h5py.File(path, "r") as f:
        force = f["samples/contact_force"][:, 0]
        axial = f["samples/axial_force"][:]
    return force, int((axial == 0.0).sum())


linear, linear_slack = read(sys.argv[1])
modal, modal_slack = read(sys.argv[2])
rms_tolerance, sigma_tolerance = float(sys.argv[3]), float(sys.argv[4])
rms = np.sqrt(np.mean((modal - linear) ** 2)) / linear.mean()
sigma = modal.std() / linear.std() - 1.0
print(f"contact force: mean {linear.mean():.3f} / {modal.mean():.3f} N, sigma {linear.std():.3f} / "
      f"{modal.std():.3f} N ({sigma:+.2e}), RMS difference {rms:.2e} of the mean; "
      f"slack dropper samples {linear_slack} / {modal_slack}")
ok = rms <= rms_tolerance and abs(sigma) <= sigma_tolerance
if linear_slack > 0 and abs(modal_slack / linear_slack - 1.0) > 0.1:
    print("slack dropper samples differ by more than 10 %")
    ok = False
if len(sys.argv) > 5:
    other, _ = read(sys.argv[5])
    spread = np.abs(other - modal).max() / linear.mean()
    print(f"modal run on another rank count: largest difference {spread:.2e} of the mean")
    ok = ok and spread <= 1e-6
sys.exit(0 if ok else 1)
