#!/usr/bin/python3
"""Checks a run of meshes/heavy_top.yaml against the closed form of steady precession.

The Lagrange top (mass m, centre of mass at l along its axis e3 from the fixed point,
moments I1, I3 about the centre of mass) started with nutation theta, spin w3 about its
axis and the precession rate Omega, the slow root of
    m g l = Omega (I3 w3 - I1' Omega cos(theta)),   I1' = I1 + m l^2,
keeps theta and precesses at Omega (Goldstein, Classical Mechanics, Sect. 5.7); the pin
holds it with m (a_c - g): m g up and m Omega^2 l sin(theta) towards the vertical.
The energy (kinetic about the fixed point plus m g z_c) and the angular momentum about the
vertical L_z are conserved; both are computed from the orientation and angular velocity.
Usage: check_heavy_top.py OUT.h5 [OTHER.h5] [--nutation RAD] [--precession-rtol R]
                          [--energy R] [--momentum R] [--omega-z R]
(OTHER: the same run on another rank count, whose poses and pin force must agree; the
tolerances default to those of the Radau IIA run of the scene).
"""
import argparse
import math

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


parser = argparse.ArgumentParser()
parser.add_argument("output")
parser.add_argument("other", nargs="?")
parser.add_argument("--nutation", type=float, default=1e-7, help="largest nutation error, rad")
parser.add_argument("--precession-rtol", type=float, default=1e-6)
parser.add_argument("--energy", type=float, default=1e-7, help="largest |E - E0| / E0")
parser.add_argument("--momentum", type=float, default=1e-7, help="largest |L_z - L_z0| / L_z0")
parser.add_argument("--omega-z", type=float, default=1e-6,
                    help="largest spread of the angular velocity's vertical component, relative")
args = parser.parse_args()

t, quaternion, omega, pin = read(args.output)
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
assert nutation_error < args.nutation, "the nutation angle moves: %g rad" % nutation_error
assert abs(rate - omega_expected) < args.precession_rtol * omega_expected, "precession %g" % rate

# Energy and L_z about the fixed point: R from the quaternion, the centre of mass at l e3.
R = np.empty((len(t), 3, 3))
R[:, :, 0] = np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)], axis=1)
R[:, :, 1] = np.stack([2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)], axis=1)
R[:, :, 2] = e3
centre = L * e3
v_centre = np.cross(omega, centre)
spin_momentum = np.einsum("nij,j,nkj,nk->ni", R, np.array([I1, I1, I3]), R, omega)
energy = (0.5 * M * (v_centre ** 2).sum(axis=1) + 0.5 * (omega * spin_momentum).sum(axis=1)
          + M * G * centre[:, 2])
momentum = spin_momentum[:, 2] + M * np.cross(centre, v_centre)[:, 2]
energy_error = np.abs(energy - energy[0]).max() / energy[0]
momentum_error = np.abs(momentum - momentum[0]).max() / abs(momentum[0])
print("energy %.3g relative (E = %.9f J), L_z %.3g relative" % (energy_error, energy[0],
                                                                 momentum_error))
assert energy_error < args.energy, "energy changes: %g" % energy_error
assert momentum_error < args.momentum, "L_z changes: %g" % momentum_error
# The angular velocity's vertical component Omega + psi' cos(theta) is constant.
assert np.ptp(omega[:, 2]) < args.omega_z * abs(omega[0, 2]), "omega_z varies: %g" % np.ptp(
    omega[:, 2])

# The pin force: vertical m g, horizontal m Omega^2 l sin(theta) towards the axis (Radau
# IIA's multipliers are of order s - 1: 1e-3 relative).
horizontal = pin[:, :2]
centripetal = M * omega_expected ** 2 * L * math.sin(THETA)
toward_axis = -np.einsum("ij,ij->i", horizontal, e3[:, :2] / np.linalg.norm(e3[:, :2], axis=1)[:, None])
print("pin force: vertical %.6f..%.6f N (m g = %.6f), towards the axis %.6f..%.6f N (%.6f)" %
      (pin[:, 2].min(), pin[:, 2].max(), M * G, toward_axis.min(), toward_axis.max(), centripetal))
assert np.abs(pin[:, 2] - M * G).max() < 1e-3 * M * G
assert np.abs(toward_axis - centripetal).max() < 1e-2 * centripetal

if args.other:
    t2, q2, _, pin2 = read(args.other)
    n = min(len(t), len(t2))
    assert np.allclose(t[:n], t2[:n], rtol=0, atol=1e-12)
    dq = np.abs(quaternion[:n] - q2[:n]).max()
    dpin = np.abs(pin[:n] - pin2[:n]).max()
    print("against %s: quaternions %.3g, pin force %.3g N" % (args.other, dq, dpin))
    assert dq < 1e-10 and dpin < 1e-6 * M * G
print("heavy top: OK")
