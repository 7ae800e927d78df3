#!/usr/bin/python3
"""Checks the support reactions of tests/data/app/trolley_mid_support.yaml's static start: an
80 kg trolley on a wire of two 20 m spans (1.07 kg/m per unstretched length, prestrain
16 kN / 1.2e7 N), held 0.25 m before the middle support. The vertical reactions balance the
weights, and their moment about the left mast balances the weights' moment (the wire's at
its middle, the trolley's at its written position) to 0.2 % (measured 0.02-0.03 %: the
release's first inertia). A reaction booked against the wrong node - the trolley's load on
the middle support given to the right mast - is off by 2 x 10^4 N m.
Usage: check_slider_reactions.py OUT.h5
"""
import sys

import h5py
import numpy as np

G, TROLLEY, SPAN = 9.81, 80.0, 40.0
WIRE = SPAN * 1.07 / (1 + 16000 / 1.2e7)  # kg: mass per unstretched length
with h5py.File(sys.argv[1], "r") as f:
    assert f.attrs["status"] == "complete", f.attrs["status"]
    ids = list(f["mesh/node_ids"][:])
    supports = f["mesh/support_nodes"][:]
    force = f["samples/reaction_force"][0]
    x = f["samples/positions"][0]
trolley_x = x[ids.index(3), 0]
weight = (TROLLEY + WIRE) * G
moment = TROLLEY * G * trolley_x + WIRE * G * SPAN / 2
measured_force = force[:, 2].sum()
measured_moment = (force[:, 2] * x[supports, 0]).sum()
middle = force[list(ids[i] for i in supports).index(4), 2]
print(f"vertical reactions {measured_force:.2f} N (weights {weight:.2f} N), moment about the "
      f"left mast {measured_moment:.1f} N m (weights' {moment:.1f} N m); middle support "
      f"{middle:.1f} N")
failures = []
if abs(measured_force / weight - 1) > 2e-3:
    failures.append("the vertical reactions do not balance the weights")
if abs(measured_moment / moment - 1) > 2e-3:
    failures.append("the reactions' moment does not balance the weights' (a reaction on the "
                    "wrong node?)")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
