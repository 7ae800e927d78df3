#!/usr/bin/python3
"""The /catenary group of a result file against the file's own mesh and solution
(docs/output.md, "Catenary").

Usage: check_catenary_layout.py RUN.h5 DROPPER_STIFFNESS N_STITCH_WIRES

Checks, for a scene built by the catenary builder with bar droppers of the given
stiffness EA/l0 (N/m):
* the droppers are numbered span by span from 1, in x order; each one's contact-wire and
  upper nodes lie at its x, the upper one above; its element is a dropper joining the two;
  it hangs from the messenger (0) or from one of the N_STITCH_WIRES stitch wires;
* each support's contact-wire and messenger nodes lie at its x;
* in a static result, the contact wire rests at each dropper's design height (within the
  1 mm the shape-finding tests allow) and each dropper's unstretched length is its static
  length less its stretch N/k, N its axial force in /static/axial_force (to 1e-9 m).
"""
import sys

import h5py
import numpy as np

path, stiffness, n_stitch = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
with h5py.File(path, "r") as f:
    node_ids = f["mesh/node_ids"][:]
    x0 = f["mesh/node_positions"][:]
    element_ids = f["mesh/element_ids"][:]
    element_nodes = f["mesh/element_nodes"][:]
    d = {k: f["catenary/droppers"][k][:] for k in f["catenary/droppers"]}
    s = {k: f["catenary/supports"][k][:] for k in f["catenary/supports"]}
    static = "static" in f
    if static:
        positions = f["static/positions"][:]
        axial_force = f["static/axial_force"][:]

row_of_node = {int(i): r for r, i in enumerate(node_ids)}
row_of_element = {int(i): r for r, i in enumerate(element_ids)}
n = len(d["span"])
assert n > 0 and all(len(v) == n for v in d.values()), {k: len(v) for k, v in d.items()}

# Numbering: spans from 1, nondecreasing; numbers restart at 1 in each span; x increases.
assert d["span"][0] == 1 and np.all(np.diff(d["span"]) >= 0), d["span"]
for k in range(n):
    first_in_span = k == 0 or d["span"][k] != d["span"][k - 1]
    assert d["number"][k] == (1 if first_in_span else d["number"][k - 1] + 1), k
assert np.all(np.diff(d["x"]) > 0), "dropper x not increasing"

worst_height = worst_length = 0.0
for k in range(n):
    lower = row_of_node[int(d["contact_node_id"][k])]
    upper = row_of_node[int(d["upper_node_id"][k])]
    assert abs(x0[lower, 0] - d["x"][k]) < 1e-9 and abs(x0[upper, 0] - d["x"][k]) < 1e-9, k
    assert x0[upper, 2] > x0[lower, 2], k
    element = row_of_element[int(d["element_id"][k])]
    assert sorted(element_nodes[element]) == sorted([lower, upper]), (k, element_nodes[element])
    assert 0 <= d["upper_wire"][k] <= n_stitch, d["upper_wire"][k]
    if static:
        worst_height = max(worst_height, abs(positions[lower, 2] - d["design_height"][k]))
        length = np.linalg.norm(positions[upper] - positions[lower])
        l0 = length - axial_force[element] / stiffness
        worst_length = max(worst_length, abs(l0 - d["unstretched_length"][k]))
assert (d["upper_wire"] > 0).any() == (n_stitch > 0), "stitch droppers missing or unexpected"

for j in range(len(s["x"])):
    for key in ("contact_node_id", "messenger_node_id"):
        row = row_of_node[int(s[key][j])]
        assert abs(x0[row, 0] - s["x"][j]) < 1e-9, (key, j, x0[row], s["x"][j])

print(f"{n} droppers, {len(s['x'])} supports: numbering, nodes and elements consistent")
if static:
    print(f"largest |z - design height| {1e3 * worst_height:.4f} mm, "
          f"largest |l0 - (L - N/k)| {worst_length:.2e} m")
    assert worst_height < 1e-3, worst_height
    assert worst_length < 1e-9, worst_length
