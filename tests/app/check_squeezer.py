#!/usr/bin/python3
"""Checks a run of meshes/squeezer.yaml (Andrews' squeezing mechanism) against the published
reference solution at t = 0.03 s and against its own energy balance.

Reference: F. Mazzia and C. Magherini, Test Set for Initial Value Problem Solvers, release
2.4, University of Bari (2008), problem "andrews" (computed by PSIDE in quadruple-checked
double precision); the mechanism of Hairer & Wanner, Solving Ordinary Differential
Equations II (1996), VII.7. The reference's coordinates are seven relative angles; the
scene's bodies carry absolute ones: body 1 beta, 2 beta + Theta, 3 gamma, 4 Phi + delta,
5 delta, 6 Omega + epsilon, 7 epsilon (meshes/squeezer.yaml).

Energy: the crank's torque does the work mom (beta - beta0); the kinetic energy of the
seven bodies plus the spring's c0 (l - l0)^2 / 2 minus that work stays constant.

Usage: check_squeezer.py OUT.h5 [--position-rtol R] [--velocity-rtol R] [--energy R]
                         [--other OTHER.h5]   (OTHER: the same run on another rank count)
Prints the relative errors of the seven angles and rates at the end; fails if any exceeds
its tolerance (defaults: the issue's 1e-6 for positions, 1e-4 for velocities).
"""
import argparse

import h5py
import numpy as np

NAMES = ["beta", "Theta", "gamma", "Phi", "delta", "Omega", "epsilon"]
REFERENCE_ANGLES = np.array([0.1581077119629904e+2, -0.1575637105984298e+2,
                             0.4082224013073101e-1, -0.5347301163226948e+0,
                             0.5244099658805304e+0, 0.5347301163226948e+0,
                             0.1048080741042263e+1])
REFERENCE_RATES = np.array([0.1139920302151208e+4, -0.1424379294994111e+4,
                            0.1103291221937134e+2, 0.1929337464421385e+2,
                            0.5735699284790808e+0, -0.1929337464421385e+2,
                            0.3231791658026955e+0])
MASS = [0.04325, 0.00365, 0.02373, 0.00706, 0.07050, 0.00706, 0.05498]
INERTIA = [2.194e-6, 4.410e-7, 5.255e-6, 5.667e-7, 1.169e-5, 5.667e-7, 1.912e-5]
# Centres of mass from each body's node, in body axes (meshes/squeezer.yaml).
CENTRE = [(0.00092, 0), (-0.0115, 0), (-0.00126, 0.00757), (0, -0.00579), (0.02308, 0.00916),
          (0.00579, 0), (0.01228, 0.00449)]
MOMENT, C0, L0, C = 0.033, 4530.0, 0.07785, np.array([0.014, 0.072])


def relative(absolute):
    """Seven absolute body angles (or rates) to the reference's relative coordinates."""
    a = absolute
    return np.array([a[0], a[1] - a[0], a[2], a[3] - a[4], a[4], a[5] - a[6], a[6]])


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        rows = [int(f["bodies/body%d" % (k + 1)].attrs["index"]) for k in range(7)]
        nodes = f["mesh/body_nodes"][:][rows]
        q = f["samples/body_orientation"][:][:, rows]
        return {"t": f["time"][:], "x": f["samples/positions"][:][:, nodes, :2],
                "v": f["samples/velocities"][:][:, nodes, :2],
                "angle": np.unwrap(2.0 * np.arctan2(q[:, :, 3], q[:, :, 0]), axis=0),
                "tilt": np.abs(q[:, :, 1:3]).max(),
                "omega": f["samples/body_angular_velocity"][:][:, rows]}


def energy(run):
    theta, w = run["angle"], run["omega"][:, :, 2]
    kinetic = np.zeros(len(run["t"]))
    for k in range(7):
        cx, cy = CENTRE[k]
        c, s = np.cos(theta[:, k]), np.sin(theta[:, k])
        rho = np.stack([cx * c - cy * s, cx * s + cy * c], axis=1)
        v_centre = run["v"][:, k] + w[:, k, None] * np.stack([-rho[:, 1], rho[:, 0]], axis=1)
        kinetic += 0.5 * MASS[k] * (v_centre ** 2).sum(axis=1) + 0.5 * INERTIA[k] * w[:, k] ** 2
    spring = 0.5 * C0 * (np.linalg.norm(run["x"][:, 2] - C, axis=1) - L0) ** 2
    work = MOMENT * (theta[:, 0] - theta[0, 0])
    return kinetic + spring - work, kinetic.max()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("--position-rtol", type=float, default=1e-6)
    parser.add_argument("--velocity-rtol", type=float, default=1e-4)
    parser.add_argument("--energy", type=float, default=1e-6,
                        help="largest change of the energy balance / largest kinetic energy")
    parser.add_argument("--other")
    args = parser.parse_args()

    run = read(args.output)
    assert abs(run["t"][-1] - 0.03) < 1e-12, "the run must end at t = 0.03 s: %g" % run["t"][-1]
    assert run["tilt"] < 1e-10, "a body leaves the x-y plane: %g" % run["tilt"]
    angles = relative(run["angle"][-1])
    rates = relative(run["omega"][-1, :, 2])
    e_q = np.abs(angles - REFERENCE_ANGLES) / np.abs(REFERENCE_ANGLES)
    e_v = np.abs(rates - REFERENCE_RATES) / np.abs(REFERENCE_RATES)
    print("%-8s %22s %22s %9s %9s" % ("", "angle (rad)", "reference", "rel. err", "rate err"))
    for k in range(7):
        print("%-8s %22.15g %22.15g %9.2e %9.2e" %
              (NAMES[k], angles[k], REFERENCE_ANGLES[k], e_q[k], e_v[k]))
    balance, kinetic = energy(run)
    drift = np.ptp(balance) / kinetic
    print("largest relative error: positions %.3g, velocities %.3g; energy balance %.3g of the "
          "largest kinetic energy (%.4g J)" % (e_q.max(), e_v.max(), drift, kinetic))
    assert e_q.max() <= args.position_rtol, "angles off the reference: %g" % e_q.max()
    assert e_v.max() <= args.velocity_rtol, "rates off the reference: %g" % e_v.max()
    assert drift <= args.energy, "energy balance drifts: %g" % drift
    if args.other:
        other = read(args.other)
        n = min(len(run["t"]), len(other["t"]))
        d = np.abs(run["angle"][:n] - other["angle"][:n]).max()
        print("against %s: angles %.3g rad" % (args.other, d))
        assert d < 1e-9, d
    print("squeezer: OK")


main()
