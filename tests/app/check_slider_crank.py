#!/usr/bin/python3
"""Checks a run of meshes/slider_crank.yaml: the slider's position against the crank angle,
x = r cos(theta) + sqrt(L^2 - r^2 sin^2(theta)) (exact kinematics), and the kinetic energy
of the three bodies (no gravity, no damping: constant).
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
                nodes)


t, x, v, q, w, rows, nodes = read(sys.argv[1])
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
if len(sys.argv) > 2:
    t2, x2, _, q2, _, _, _ = read(sys.argv[2])
    n = min(len(t), len(t2))
    dx, dq = np.abs(x[:n] - x2[:n]).max(), np.abs(q[:n] - q2[:n]).max()
    print("against %s: positions %.3g m, quaternions %.3g" % (sys.argv[2], dx, dq))
    assert dx < 1e-10 and dq < 1e-10
print("slider crank: OK")
