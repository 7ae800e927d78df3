#!/usr/bin/python3
"""Checks a run of meshes/slider_crank.yaml: the slider's position against the crank angle,
x = r cos(theta) + sqrt(L^2 - r^2 sin^2(theta)) (exact kinematics), and the kinetic energy
of the three bodies (no gravity, no damping: constant), and the joints' links drawn in
the XDMF (/samples/joint_links): each starts at its body's node, the points the two sides
carry coincide where the joint holds them together (the main bearing, the crank pin and the
gudgeon pin) and part along the guide by the slider's travel.
Usage: check_slider_crank.py OUT.h5 [OTHER.h5]  (OTHER: the same run on another rank count)
"""
import sys

import h5py
import numpy as np

R, L = 0.1, 0.3
MASS = {"crank": 0.5, "rod": 0.3, "slider": 0.4}
INERTIA = {"crank": [1e-4, 5e-4, 5e-4], "rod": [5e-5, 8e-4, 8e-4], "slider": [2e-4] * 3}


def rotation(q):
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        rows = {name: int(f["bodies/" + name].attrs["index"]) for name in MASS}
        nodes = f["mesh/body_nodes"][:]
        return (f["time"][:], f["samples/positions"][:], f["samples/velocities"][:],
                f["samples/body_orientation"][:], f["samples/body_angular_velocity"][:], rows,
                nodes, f["samples/joint_links"][:])


# The scene's joints in order: (body A, body B or None for the ground, whether the joint
# holds the two sides' points together).
JOINTS = [("crank", None, True), ("rod", "crank", True), ("rod", "slider", True),
          ("slider", None, False)]
GUIDE_POINT = np.array([0.4, 0.0, 0.0])

t, x, v, q, w, rows, nodes, links = read(sys.argv[1])
crank, slider = rows["crank"], rows["slider"]
# The crank turns about z: its angle from its quaternion (a rotation about z).
theta = 2.0 * np.arctan2(q[:, crank, 3], q[:, crank, 0])
turns = np.ptp(np.unwrap(theta)) / (2 * np.pi)
expected = R * np.cos(theta) + np.sqrt(L * L - (R * np.sin(theta)) ** 2)
slider_x = x[:, nodes[slider], 0]
kinematics = np.abs(slider_x - expected).max()
energy = np.zeros(len(t))
for name, row in rows.items():
    node = nodes[row]
    energy += 0.5 * MASS[name] * np.einsum("ij,ij->i", v[:, node], v[:, node])
    for k in range(len(t)):
        Rk = rotation(q[k, row])
        energy[k] += 0.5 * w[k, row] @ (Rk @ np.diag(INERTIA[name]) @ Rk.T) @ w[k, row]
drift = np.ptp(energy) / energy[0]
print("%.2f crank turns; slider position error %.3g m; kinetic energy %.6g J, drift %.3g" %
      (turns, kinematics, energy[0], drift))
assert turns > 1.0, "the crank should turn at least once: %g" % turns
assert kinematics < 1e-10, kinematics
assert drift < 1e-6, drift
assert np.abs(x[:, nodes[slider], 1:]).max() < 1e-12, "the slider leaves its guide"
assert links.shape == (len(t), len(JOINTS), 4, 3), links.shape
worst_start = worst_gap = 0.0
for j, (a, b, together) in enumerate(JOINTS):
    worst_start = max(worst_start, np.abs(links[:, j, 0] - x[:, nodes[rows[a]]]).max())
    if b is not None:
        worst_start = max(worst_start, np.abs(links[:, j, 3] - x[:, nodes[rows[b]]]).max())
    else:
        assert np.abs(links[:, j, 2:] - links[0, j, 2]).max() == 0.0, "the ground moves"
    if together:
        worst_gap = max(worst_gap, np.abs(links[:, j, 1] - links[:, j, 2]).max())
slide = links[:, 3, 1] - links[:, 3, 2]
print("joint links: from the bodies' nodes within %.3g m, held points together within %.3g m, "
      "the guide's slide %.4g..%.4g m" % (worst_start, worst_gap, slide[:, 0].min(),
                                           slide[:, 0].max()))
assert worst_start < 1e-12 and worst_gap < 1e-10
assert np.abs(links[:, 3, 2] - GUIDE_POINT).max() == 0.0
assert np.abs(slide[:, 0] - (slider_x - GUIDE_POINT[0])).max() < 1e-12
assert np.abs(slide[:, 1:]).max() < 1e-12 and np.ptp(slide[:, 0]) > 0.1
if len(sys.argv) > 2:
    t2, x2, _, q2, _, _, _, links2 = read(sys.argv[2])
    n = min(len(t), len(t2))
    dx, dq = np.abs(x[:n] - x2[:n]).max(), np.abs(q[:n] - q2[:n]).max()
    dl = np.abs(links[:n] - links2[:n]).max()
    print("against %s: positions %.3g m, quaternions %.3g, joint links %.3g m" %
          (sys.argv[2], dx, dq, dl))
    assert dx < 1e-10 and dq < 1e-10 and dl < 1e-10
print("slider crank: OK")
