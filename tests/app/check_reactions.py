#!/usr/bin/python3
"""Supports' reactions over time in a dynamic output (docs/output.md).

Usage: check_reactions.py RUN.h5 TENSION TOLERANCE

For a wire pinned at its two ends under TENSION (N) along x (meshes/taut_string.yaml,
written on two ranks): the output names the two end nodes as its supported nodes, and at
every sample each end's support pulls its node outwards with the tension, -T at the
first end and +T at the last, to within TOLERANCE relative (the plucked wire's extra
stretch), and the two balance along x to within TOLERANCE (the wire's horizontal
inertia is small). Prints the largest deviations.
"""
import sys

import h5py
import numpy as np

path, tension, tol = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
with h5py.File(path, "r") as f:
    nodes = f["mesh/support_nodes"][:]
    x = f["mesh/node_positions"][:, 0]
    force = f["samples/reaction_force"][:]
    moment = f["samples/reaction_moment"][:]
    n_samples = f["time"].shape[0]
assert force.shape == (n_samples, 2, 3), force.shape
assert moment.shape == force.shape, moment.shape
first, last = (0, 1) if x[nodes[0]] < x[nodes[1]] else (1, 0)
assert x[nodes[first]] == x.min() and x[nodes[last]] == x.max(), (nodes, x.min(), x.max())
pull_first = np.abs(force[:, first, 0] / -tension - 1).max()
pull_last = np.abs(force[:, last, 0] / tension - 1).max()
balance = np.abs(force[:, first, 0] + force[:, last, 0]).max() / tension
print(f"check_reactions: {n_samples} samples, end pulls within {max(pull_first, pull_last):.2e} "
      f"of the tension, x balance {balance:.2e}, |moment| max {np.abs(moment).max():.2e} N m")
assert pull_first < tol and pull_last < tol, (pull_first, pull_last)
assert balance < tol, balance
assert np.abs(moment).max() == 0.0  # pinned: no slope held, no couple
