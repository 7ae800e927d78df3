#!/usr/bin/python3
"""analysis.structure: linear on the plucked taut string (meshes/taut_string.yaml).

Usage: check_linear_structure.py LINEAR.h5 NONLINEAR.h5

The string (T = 20 kN, mu = 1.35 kg/m per unstretched length, EI = 195 N m^2, EA = 1.8e7 N,
L = 60 m) starts in its first mode with 0.05 m amplitude. Linearised about its straight
equilibrium it vibrates at the tensioned beam's f_1 (mu over 1 + T/EA per current length,
EI times 1 + T/EA: the bending law per unstretched length): its mid-point follows
0.05 cos(2 pi f_1 t) to 1e-4 of the amplitude over 5 s (measured 2e-7; Radau IIA, 50 steps
per period), every step taking one Newton iteration. The nonlinear run of the same scene
drifts from that by more than 1e-3 of the amplitude (measured 1.7e-2): the stretch of a
0.05 m arch raises the tension (amplitude-dependent frequency), which a linear model
leaves out.
"""
import sys

from plucked_string import closed_form_miss, f1, midpoint


def miss(path):
    t, z, iterations = midpoint(path)
    return closed_form_miss(t, z), iterations


linear, linear_iterations = miss(sys.argv[1])
nonlinear, _ = miss(sys.argv[2])
print(f"mid-point against 0.05 cos(2 pi {f1:.6f} Hz t): linear {linear:.2e}, nonlinear "
      f"{nonlinear:.2e} of the amplitude; linear Newton iterations per step "
      f"{linear_iterations.min()}..{linear_iterations.max()}")
assert linear < 1e-4, linear
assert nonlinear > 1e-3, nonlinear
assert (linear_iterations == 1).all(), linear_iterations
