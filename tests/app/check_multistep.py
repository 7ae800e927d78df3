#!/usr/bin/python3
"""The multistep integrators (integrator.type bdf, park, abm) on the plucked taut string.

Usage: check_multistep.py PARK_COARSE.h5 PARK_FINE.h5 BDF_ADAPTIVE.h5 ABM.h5 RADAU.h5

meshes/taut_string.yaml (T = 20 kN, L = 60 m, first mode at 0.05 m) for 1 s: Park's method
at dt = 0.01 s on 2 ranks and at 0.005 s on one; variable-step BDF-2 with adaptive steps
(rtol 1e-5); Adams-Bashforth-Moulton of order 2 (PECE, explicit) at dt = 2.5e-5 s on
2 ranks for 0.5 s, below its stability limit 1.28/omega_max = 3.42e-5 s; RADAU.h5 the
scene as it is (Radau IIA s = 3 at dt = 0.02 s, fifth order: its own error is far below
the others'). The mid-point against Radau's at the common samples:
- Park's error falls by 4 when dt halves (order 2, between 1.8 and 2.2) and is at most
  1e-2 of the amplitude at dt = 0.01 s (4.7e-3 measured);
- adaptive BDF-2 stays within 2e-3 of the amplitude (6.5e-4 measured, in 552 steps): the
  tolerance is per step (rtol 1e-5 of the 0.05 m displacement), and the steps sum it;
- ABM-2 agrees with Radau's run to 1e-6 of the amplitude (5.6e-7 measured, most of it
  Radau's own error at its 0.02 s step: against Radau at 0.0025 s ABM-2 is within 6e-8):
  two methods of unrelated construction on the same nonlinear model.
"""
import math
import sys

from plucked_string import midpoint, reference_miss

t_ref, z_ref, _ = midpoint(sys.argv[5])
misses = []
for path in sys.argv[1:5]:
    t, z, _ = midpoint(path)
    miss, common = reference_miss(t, z, t_ref, z_ref)
    assert common >= 100, (path, common)
    misses.append(miss)
coarse, fine, adaptive, adams = misses
order = math.log2(coarse / fine)
print(f"park: {coarse:.3e} (dt 0.01 s, 2 ranks), {fine:.3e} (dt 0.005 s) of the amplitude, "
      f"observed order {order:.2f}; adaptive bdf(order=2) at rtol 1e-5: {adaptive:.3e}; "
      f"abm(order=2) at dt 2.5e-5 s: {adams:.3e}")
assert 1.8 < order < 2.2, order
assert coarse < 1e-2, coarse
assert adaptive < 2e-3, adaptive
assert adams < 1e-6, adams
