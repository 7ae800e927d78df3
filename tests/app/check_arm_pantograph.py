#!/usr/bin/python3
"""Checks a run of meshes/pantograph_wire.yaml with `model: arm_en50318` (the single-arm
mechanism of two rigid bodies) from its output alone:
  - the static start is the mechanism's equilibrium in closed form: with θ the arm's angle
    (from its axis e1, written as the arm node's slope) and d the head's horizontal distance
    from the base pivot, moments about the pivot give
        (F_c + m_h g) d = (F0 + m_h g) L cos θ − k_θ (θ − α₀)
    (the air spring carries the weights and F0 at every height; only the torsion spring
    k_θ resists the arm's turn from its design angle α₀);
  - the head stays level with the arm's tip: the arm's tip L e1 from the pivot is below the
    head on its slide axis;
  - against the lumped EN 50318 model on the same wire (its equivalent at α₀) the contact
    force's mean and spread agree to a few per cent: they differ by the arm's height
    dependence, the wire's 0.3 m sag turning the arm by about 10 degrees;
  - runs on other rank counts give the same contact force (Newton tolerance).
Usage: check_arm_pantograph.py ARM.h5 LUMPED.h5 [ARM_OTHER_RANKS.h5 ...]
"""
import math
import sys

import h5py
import numpy as np

L, ALPHA0, K_THETA = 1.8, math.radians(30.0), 50.0 * (1.8 * math.cos(math.radians(30.0))) ** 2
M_HEAD, G, F0, START = 7.2, 9.81, 120.0, 5.0


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        head, arm = (int(f["bodies/leading " + part].attrs["index"]) for part in ("head", "arm"))
        nodes = f["mesh/body_nodes"][:]
        return (f["samples/contact_force"][:, 0], f["samples/positions"][0],
                f["samples/slopes"][0], nodes[head], nodes[arm])


force, x, slopes, head, arm = read(sys.argv[1])
pivot = np.array([START - L * math.cos(ALPHA0), 0.0, -L * math.sin(ALPHA0)])
e1 = slopes[arm]
theta = math.atan2(e1[2], e1[0])
d = x[head][0] - pivot[0]
closed = ((F0 + M_HEAD * G) * L * math.cos(theta) - K_THETA * (theta - ALPHA0)) / d - M_HEAD * G
tip = pivot + L * e1
print("static start: arm at %.4f degrees, contact force %.6f N, closed form %.6f N; "
      "head %.3g m off the arm's tip horizontally" %
      (math.degrees(theta), force[0], closed, abs(x[head][0] - tip[0])))
assert abs(force[0] - closed) < 1e-6 * F0, (force[0], closed)
# The slide axis turns with the arm by θ − α₀: the head sits on it above (or below) the tip.
slide = x[head] - tip
turn = theta - ALPHA0
assert abs(slide[0] * math.cos(turn) + slide[2] * math.sin(turn)) < 1e-8, slide

with h5py.File(sys.argv[2], "r") as f:
    lumped = f["samples/contact_force"][:, 0]
n = min(len(force), len(lumped))
print("against the lumped model: mean %.3f N (lumped %.3f N), std %.3f N (lumped %.3f N)" %
      (force[:n].mean(), lumped[:n].mean(), force[:n].std(), lumped[:n].std()))
assert abs(force[:n].mean() - lumped[:n].mean()) < 0.02 * lumped[:n].mean()
assert abs(force[:n].std() - lumped[:n].std()) < 0.06 * lumped[:n].std()
for other in sys.argv[3:]:
    f2 = read(other)[0]
    m = min(len(force), len(f2))
    diff = np.abs(force[:m] - f2[:m]).max()
    print("against %s: contact force %.3g N" % (other, diff))
    assert diff < 1e-5, diff
