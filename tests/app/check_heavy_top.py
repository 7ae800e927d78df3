#!/usr/bin/python3
"""Checks a run of meshes/heavy_top.yaml against the closed form of steady precession.

The Lagrange top (mass m, centre of mass at l along its axis e3 from the fixed point,
moments I1, I3 about the centre of mass) started with nutation theta, spin w3 about its
axis and the precession rate Omega, the slow root of
    m g l = Omega (I3 w3 - I1' Omega cos(theta)),   I1' = I1 + m l^2,
keeps theta and precesses at Omega (Goldstein, Classical Mechanics, Sect. 5.7); the pin
holds it with m (a_c - g): m g up and m Omega^2 l sin(theta) towards the vertical.
Usage: check_heavy_top.py OUT.h5 [OTHER.h5]  (OTHER: the same run on another rank count,
whose poses and pin force must agree).
"""
import math
import sys

import h5py
import numpy as np

M, L, I1, I3, W3, THETA, G = 1.0, 0.1, 0.003, 0.005, 60.0, math.radians(30.0), 9.81


def closed_form_precession():
    a = (I1 + M * L * L) * math.cos(THETA)
    b = I3 * W3
    return (b - math.sqrt(b * b - 4.0 * a * M * G * L)) / (2.0 * a)


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        row = int(f["bodies/top"].attrs["index"])
        return (f["time"][:], f["samples/body_orientation"][:, row],
                f["samples/body_angular_velocity"][:, row], f["samples/constraint_forces"][:, 0])


t, quaternion, omega, pin = read(sys.argv[1])
w, x, y, z = quaternion.T
norm_error = np.abs(np.linalg.norm(quaternion, axis=1) - 1.0).max()
assert norm_error < 1e-12, "quaternions not of unit norm: %g" % norm_error
e3 = np.stack([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)], axis=1)
nutation = np.arccos(np.clip(e3[:, 2], -1.0, 1.0))
nutation_error = np.abs(nutation - THETA).max()
rate = np.polyfit(t, np.unwrap(np.arctan2(e3[:, 1], e3[:, 0])), 1)[0]
omega_expected = closed_form_precession()
print("nutation error %.3g rad; precession %.9f rad/s, closed form %.9f" %
      (nutation_error, rate, omega_expected))
assert nutation_error < 1e-7, "the nutation angle moves: %g rad" % nutation_error
assert abs(rate - omega_expected) < 1e-6 * omega_expected, "precession rate %g" % rate
# The angular velocity's vertical component Omega + psi' cos(theta) is constant.
assert np.ptp(omega[:, 2]) < 1e-6 * abs(omega[0, 2]), "omega_z varies: %g" % np.ptp(omega[:, 2])

# The pin force: vertical m g, horizontal m Omega^2 l sin(theta) towards the axis (Radau
# IIA's multipliers are of order s - 1: 1e-3 relative).
horizontal = pin[:, :2]
centripetal = M * omega_expected ** 2 * L * math.sin(THETA)
toward_axis = -np.einsum("ij,ij->i", horizontal, e3[:, :2] / np.linalg.norm(e3[:, :2], axis=1)[:, None])
print("pin force: vertical %.6f..%.6f N (m g = %.6f), towards the axis %.6f..%.6f N (%.6f)" %
      (pin[:, 2].min(), pin[:, 2].max(), M * G, toward_axis.min(), toward_axis.max(), centripetal))
assert np.abs(pin[:, 2] - M * G).max() < 1e-3 * M * G
assert np.abs(toward_axis - centripetal).max() < 1e-2 * centripetal

if len(sys.argv) > 2:
    t2, q2, _, pin2 = read(sys.argv[2])
    n = min(len(t), len(t2))
    assert np.allclose(t[:n], t2[:n], rtol=0, atol=1e-12)
    dq = np.abs(quaternion[:n] - q2[:n]).max()
    dpin = np.abs(pin[:n] - pin2[:n]).max()
    print("against %s: quaternions %.3g, pin force %.3g N" % (sys.argv[2], dq, dpin))
    assert dq < 1e-10 and dpin < 1e-6 * M * G
print("heavy top: OK")
