#!/usr/bin/python3
"""Checks a run of meshes/trolley.yaml (a trolley sliding along a messenger wire) from its
output alone:
  - the trolley's point lies on the wire's ANCF curve at its arc length s: the cubic Hermite
    interpolant of the written node positions and slopes of the element holding s (0.5 m
    elements, node rows 0 (left mast), 3..81 (interior, in order), 1 (right mast));
  - the wheel force on the trolley (/samples/constraint_forces, minus the slider's
    multipliers) has, along the wire's tangent dr/ds, the rolling resistance -c ds/dt
    exactly (the slider's s equation), and across it about the trolley's weight;
  - the trolley starts at rest at 10 m and runs towards midspan (20 m).
Usage: check_trolley.py OUT.h5 [OTHER.h5 ...]  (OTHER: the same run on other rank counts)
"""
import sys

import h5py
import numpy as np

MASS, DAMPING, G, START, ELEMENT = 80.0, 5.0, 9.81, 10.0, 0.5
N_ELEMENTS = 80


def path_rows(e):
    """Node rows of element e's first and second node."""
    return (0 if e == 0 else 2 + e), (1 if e == N_ELEMENTS - 1 else 3 + e)


def hermite(xi, L):
    s = [1 - 3 * xi**2 + 2 * xi**3, L * (xi - 2 * xi**2 + xi**3), 3 * xi**2 - 2 * xi**3,
         L * (xi**3 - xi**2)]
    ds = [6 * (xi**2 - xi) / L, 1 - 4 * xi + 3 * xi**2, 6 * (xi - xi**2) / L, 3 * xi**2 - 2 * xi]
    return s, ds


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        row = int(f["sliders/trolley"].attrs["index"])
        constraint = int(f["sliders/trolley"].attrs["constraint"])
        node = int(f["mesh/slider_nodes"][row])
        return (f["time"][:], f["samples/slider_position"][:, row],
                f["samples/slider_speed"][:, row], f["samples/positions"][:],
                f["samples/slopes"][:], f["samples/constraint_forces"][:, constraint, :3], node)  # on the trolley


t, s, rate, x, slopes, force, node = read(sys.argv[1])
gap = friction = 0.0
normal = []
for k in range(len(t)):
    e = min(int(s[k] / ELEMENT), N_ELEMENTS - 1)
    a, b = path_rows(e)
    S, dS = hermite((s[k] - e * ELEMENT) / ELEMENT, ELEMENT)
    blocks = [x[k, a], slopes[k, a], x[k, b], slopes[k, b]]
    point = sum(S[i] * blocks[i] for i in range(4))
    tangent = sum(dS[i] * blocks[i] for i in range(4))
    gap = max(gap, np.linalg.norm(x[k, node] - point))
    # The s equation -t.lambda + c ds/dt = 0, with the force F = -lambda: t.F = -c ds/dt.
    friction = max(friction, abs(tangent @ force[k] + DAMPING * rate[k]))
    unit = tangent / np.linalg.norm(tangent)
    normal.append(np.linalg.norm(force[k] - (force[k] @ unit) * unit))
weight = np.abs(np.array(normal) / (MASS * G) - 1).max()
print("trolley from s = %.6g m to %.6g m (%.4g m/s at the end); off the wire %.3g m; "
      "friction law %.3g N; wheel force across the wire within %.3g of the weight" %
      (s[0], s[-1], rate[-1], gap, friction, weight))
assert abs(s[0] - START) < 1e-12 and abs(rate[0]) < 1e-12, (s[0], rate[0])
assert s[-1] > START + 1.0 and s[-1] < 2 * START, s[-1]
assert np.all(np.diff(s) > -1e-12), "the trolley turns back before midspan"
assert gap < 1e-8, gap
assert friction < 1e-5, friction
assert weight < 0.02, weight
for other in sys.argv[2:]:
    t2, s2, _, x2, _, force2, _ = read(other)
    n = min(len(t), len(t2))
    ds, dx = np.abs(s[:n] - s2[:n]).max(), np.abs(x[:n] - x2[:n]).max()
    dl = np.abs(force[:n] - force2[:n]).max() / np.abs(force).max()
    print("against %s: s %.3g m, positions %.3g m, wheel force %.3g relative" %
          (other, ds, dx, dl))
    # The multipliers agree to the Newton tolerance, not to round-off.
    assert ds < 1e-8 and dx < 1e-8 and dl < 1e-6, (ds, dx, dl)
