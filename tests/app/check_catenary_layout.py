#!/usr/bin/python3
"""The /catenary group of a result file against the file's own mesh and solution
(docs/output.md, "Catenary").

Usage: check_catenary_layout.py RUN.h5 DROPPER_STIFFNESS N_STITCH_WIRES [MU_C MU_M]

Checks, for a scene built by the catenary builder with bar droppers of the given
stiffness EA/l0 (N/m):
* the droppers are numbered span by span from 1, in x order; each one's contact-wire and
  upper nodes lie at its x, the upper one above; its element is a dropper joining the two;
  it hangs from the messenger (0) or from one of the N_STITCH_WIRES stitch wires;
* each support's contact-wire and messenger nodes lie at its x;
* the reactions' rows (/mesh/support_nodes) are nodes at the supports, the four anchors
  among them: a 2D line's out-of-plane hold of every node adds none;
* in a static result, the contact wire rests at each dropper's design height (within the
  1 mm the shape-finding tests allow) and each dropper's unstretched length is its static
  length less its stretch N/k, N its axial force in /static/axial_force (to 1e-9 m);
* in a static result with the wires' masses per length MU_C and MU_M (kg/m; a scene
  without clamp or dropper masses), each wire's section resultants balance every dropper:
  between the mid-points of the two wire elements at a dropper, the section forces
  N t + Q (/static/axial_force along the mid-point tangent, /static/shear_force), the
  dropper's pull and the wire's weight sum to zero within 0.05 N. Without the shear the
  sum is off by several newtons (the tangent wire's bending at the dropper's kink).
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
        slopes = f["static/slopes"][:]
        axial_force = f["static/axial_force"][:]
        shear_force = f["static/shear_force"][:]
        element_set = f["mesh/element_set"][:]
        set_names = list(f["mesh/element_set"].attrs["set_names"])

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

# The reactions' rows on the catenary (the nodes its elements connect to the anchors; a
# pantograph's stages are held apart) are the nodes held in the x-z plane (anchors, elastic
# supports), never the nodes a 2D line holds only in y (all of them): each lies at a
# support's x, and the four anchors are among them.
with h5py.File(path, "r") as f:
    support_rows = f["mesh/support_nodes" if "mesh/support_nodes" in f else "static/support_nodes"][:]
anchors = {int(s[key][j]) for key in ("contact_node_id", "messenger_node_id") for j in (0, -1)}
neighbours = {}
for a, b in element_nodes:
    neighbours.setdefault(int(a), []).append(int(b))
    neighbours.setdefault(int(b), []).append(int(a))
line = {row_of_node[i] for i in anchors}
todo = list(line)
while todo:
    for other in neighbours.get(todo.pop(), []):
        if other not in line:
            line.add(other)
            todo.append(other)
support_ids = {int(node_ids[r]) for r in support_rows if int(r) in line}
at_supports = set(s["contact_node_id"].tolist()) | set(s["messenger_node_id"].tolist())
assert support_ids <= at_supports, sorted(support_ids - at_supports)[:5]
assert anchors <= support_ids, sorted(anchors - support_ids)
print(f"reaction rows on the line: {len(support_ids)} of its {len(line)} nodes, all at supports")
if static:
    print(f"largest |z - design height| {1e3 * worst_height:.4f} mm, "
          f"largest |l0 - (L - N/k)| {worst_length:.2e} m")
    assert worst_height < 1e-3, worst_height
    assert worst_length < 1e-9, worst_length

if static and len(sys.argv) > 5:
    g = 9.81
    for wire, mu, key, other in (("contact_wire", float(sys.argv[4]), "contact_node_id",
                                  "upper_node_id"),
                                 ("messenger", float(sys.argv[5]), "upper_node_id",
                                  "contact_node_id")):
        in_set = element_set == set_names.index(wire)
        left = {int(b): e for e, (a, b) in enumerate(element_nodes) if in_set[e]}
        right = {int(a): e for e, (a, b) in enumerate(element_nodes) if in_set[e]}

        def section(e):
            """The section force at element e's mid-point (axial along the cubic's tangent)
            without and with the shear, and the element's reference length."""
            a, b = element_nodes[e]
            length = np.linalg.norm(x0[b] - x0[a])
            tangent = 1.5 * (positions[b] - positions[a]) / length - 0.25 * (slopes[a] + slopes[b])
            axial = axial_force[e] * tangent / np.linalg.norm(tangent)
            return axial, axial + shear_force[e], length

        worst = worst_without_shear = 0.0
        for k in range(n):
            node = row_of_node[int(d[key][k])]
            pull = positions[row_of_node[int(d[other][k])]] - positions[node]
            pull *= axial_force[row_of_element[int(d["element_id"][k])]] / np.linalg.norm(pull)
            n_l, s_l, h_l = section(left[node])
            n_r, s_r, h_r = section(right[node])
            weight = np.array([0.0, 0.0, -mu * g * (h_l + h_r) / 2])
            worst = max(worst, np.abs(s_r - s_l + pull + weight).max())
            worst_without_shear = max(worst_without_shear, np.abs(n_r - n_l + pull + weight).max())
        print(f"{wire}: section forces balance every dropper to {worst:.2e} N "
              f"({worst_without_shear:.2f} N without the shear)")
        assert worst < 0.05, worst
