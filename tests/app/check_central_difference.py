#!/usr/bin/python3
"""Central differences (integrator.type central_difference) on the plucked taut string.

Usage: check_central_difference.py LINEAR.h5 NONLINEAR.h5 RADAU.h5

LINEAR.h5 and NONLINEAR.h5: meshes/taut_string.yaml (T = 20 kN, L = 60 m, 60 cables, first
mode at 0.05 m) run by central differences at dt = 5e-5 s (just below the stability limit
2/omega_max = 5.34e-5 s of its 1 m cables), with the linear and the nonlinear structure;
RADAU.h5 the scene as it is (Radau IIA s = 3 at dt = 0.02 s, 2500 times longer steps).
- linear: the mid-point follows the closed form 0.05 cos(2 pi f_1 t) (the tensioned beam's
  f_1, as in check_linear_structure.py) to 1e-4 of the amplitude, with one Newton
  iteration per step at most (the implicit part is the damping: none here);
- nonlinear: the mid-point agrees with Radau IIA's at the common sample times to 1e-4 of
  the amplitude: two methods of unrelated construction on the same nonlinear model.
"""
import math
import sys

import h5py
import numpy as np

T, mu0, EI, EA, L, a = 20000.0, 1.35, 195.0, 1.8e7, 60.0, 0.05
strain = T / EA
f1 = 1 / (2 * L) * math.sqrt(T * (1 + strain) / mu0) * math.sqrt(
    1 + math.pi ** 2 * EI * (1 + strain) / (T * L * L))


def midpoint(path):
    with h5py.File(path, "r") as f:
        t = f["time"][:]
        x = f["mesh/node_positions"][:, 0]
        mid = int(np.argmin(abs(x - L / 2)))
        z = f["samples/positions"][:, mid, 2]
        iterations = f["steps/newton_iterations"][:]
    return t, z, iterations


t, z, iterations = midpoint(sys.argv[1])
linear = np.abs(z - a * np.cos(2 * math.pi * f1 * t)).max() / a
t_cd, z_cd, _ = midpoint(sys.argv[2])
t_ref, z_ref, _ = midpoint(sys.argv[3])
common = [(i, int(np.argmin(abs(t_ref - tc)))) for i, tc in enumerate(t_cd)]
common = [(i, j) for i, j in common if abs(t_ref[j] - t_cd[i]) < 1e-9]
nonlinear = max(abs(z_cd[i] - z_ref[j]) for i, j in common) / a
print(f"linear: mid-point against 0.05 cos(2 pi {f1:.6f} Hz t) {linear:.2e} of the amplitude, "
      f"Newton iterations per step {iterations.min()}..{iterations.max()}; nonlinear: against "
      f"Radau IIA at {len(common)} common samples {nonlinear:.2e}")
assert linear < 1e-4, linear
assert iterations.max() <= 1, iterations.max()
assert len(common) >= 100, len(common)
assert nonlinear < 1e-4, nonlinear
