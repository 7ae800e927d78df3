#!/usr/bin/python3
"""Checks a dynamic run's constraint force against Newton's second law for the whole body.

For a body held by one constraint, the force F of the constraint satisfies
F = m (r_c'' - g), r_c the centre of mass. For ANCF cable elements of length L,
int r dx = L/2 (r_A + r_B) + L^2/12 (r_A' - r_B'), so r_c follows from the sampled
positions and slopes; r_c'' by central differences of the samples (second order).
Usage: check_pivot_force.py OUT.h5 MASS_PER_LENGTH TOLERANCE_RELATIVE
"""
import sys

import h5py
import numpy as np

path, mu, tol = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
with h5py.File(path, "r") as f:
    assert f.attrs["status"] == "complete", f.attrs["status"]
    t = f["time"][:]
    r = f["samples/positions"][:]
    d = f["samples/slopes"][:]
    ends = f["mesh/element_nodes"][:]
    ref = f["mesh/node_positions"][:]
    force = f["samples/constraint_forces"][:]
    nodes = f["mesh/constraint_nodes"][:]
assert force.shape == (len(t), 1, 3), force.shape
assert nodes.shape == (1, 2) and nodes[0, 1] == -1, nodes
first = 0
moment = np.zeros((len(t), 3))
mass = 0.0
for a, b in ends:
    L = np.linalg.norm(ref[b] - ref[a])
    moment += mu * (L / 2 * (r[:, a] + r[:, b]) + L * L / 12 * (d[:, a] - d[:, b]))
    mass += mu * L
rc = moment / mass
h = t[1] - t[0]
acc = (rc[2:] - 2 * rc[1:-1] + rc[:-2]) / (h * h)
expected = mass * (acc - np.array([0.0, 0.0, -9.81]))
got = force[1:-1, 0, :]
error = np.abs(got - expected).max()
scale = np.abs(got).max()
print(f"constraint force vs m (r_c'' - g): max difference {error:.3g} N of {scale:.3g} N "
      f"({error / scale:.2%}); mass {mass:.4g} kg, {len(t)} samples")
sys.exit(0 if error <= tol * scale else 1)
