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
import sys

from plucked_string import closed_form_miss, f1, midpoint, reference_miss

t, z, iterations = midpoint(sys.argv[1])
linear = closed_form_miss(t, z)
t_cd, z_cd, _ = midpoint(sys.argv[2])
t_ref, z_ref, _ = midpoint(sys.argv[3])
nonlinear, common = reference_miss(t_cd, z_cd, t_ref, z_ref)
print(f"linear: mid-point against 0.05 cos(2 pi {f1:.6f} Hz t) {linear:.2e} of the amplitude, "
      f"Newton iterations per step {iterations.min()}..{iterations.max()}; nonlinear: against "
      f"Radau IIA at {common} common samples {nonlinear:.2e}")
assert linear < 1e-4, linear
assert iterations.max() <= 1, iterations.max()
assert common >= 100, common
assert nonlinear < 1e-4, nonlinear
