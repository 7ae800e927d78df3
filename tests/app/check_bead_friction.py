#!/usr/bin/python3
"""Checks a run of tests/data/app/bead_on_incline.yaml (a 2 kg bead on a rigid wire inclined
at 30 degrees, Coulomb friction mu, stick speed v) against the block on an incline:
  - the wheel force (/samples/constraint_forces, the force the wire puts on the bead) has
    the normal component m g cos 30 and, up the slope, mu times it while sliding;
  - sliding (mu < tan 30): after the start, ds/dt grows at g (sin 30 - mu cos 30);
  - sticking (mu > tan 30): the bead creeps at the regularised law's speed
    v phi / sqrt(1 - phi^2), phi = tan 30 / mu.
The first sample is skipped: at rest the regularised friction is zero, and the law's stick
to slip transition (about v / (g sin 30) long) falls inside the first step.
Usage: check_bead_friction.py OUT.h5 MU STICK_SPEED slide|stick
"""
import sys

import h5py
import numpy as np

MASS, G, THETA = 2.0, 9.81, np.pi / 6
path, mu, stick_speed, mode = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
with h5py.File(path, "r") as f:
    assert f.attrs["status"] == "complete", f.attrs["status"]
    row = int(f["sliders/bead"].attrs["index"])
    constraint = int(f["sliders/bead"].attrs["constraint"])
    t = f["time"][:]
    rate = f["samples/slider_speed"][:, row]
    force = f["samples/constraint_forces"][:, constraint, :3]

normal_dir = np.array([np.sin(THETA), 0.0, np.cos(THETA)])
up_slope = np.array([-np.cos(THETA), 0.0, np.sin(THETA)])
normal, along = force[1:] @ normal_dir, force[1:] @ up_slope
weight_share = MASS * G * np.cos(THETA)
failures = []
if np.abs(normal / weight_share - 1).max() > 1e-7:
    failures.append(f"normal force {normal.min()}..{normal.max()} N, expected {weight_share} N")

if mode == "slide":
    # Coulomb's closed form once the regularisation's share, mu (v/(ds/dt))^2/2, is below
    # 1e-7 of mu (t >= 0.1 s, ds/dt >= 0.23 m/s); the law itself at every sample.
    acceleration = G * (np.sin(THETA) - mu * np.cos(THETA))
    late = t[1:] >= 0.1
    measured = np.diff(rate[1:][late]) / np.diff(t[1:][late])
    if np.abs(measured / acceleration - 1).max() > 1e-6:
        failures.append(f"acceleration {measured.min()}..{measured.max()} m/s^2, expected "
                        f"{acceleration} (g (sin 30 - mu cos 30))")
    law = mu * rate[1:] / np.sqrt(rate[1:] ** 2 + stick_speed**2)
    if np.abs(along / normal - law).max() > 1e-7 * mu:
        failures.append(f"friction / normal force {(along / normal).min()}.."
                        f"{(along / normal).max()}, expected mu phi(ds/dt), mu = {mu}")
    print(f"sliding: acceleration {measured[-1]:.9f} m/s^2 (closed form {acceleration:.9f}), "
          f"friction/normal {along[-1] / normal[-1]:.8f}")
else:
    phi = np.tan(THETA) / mu
    creep = stick_speed * phi / np.sqrt(1 - phi * phi)
    late = t > 0.1
    if np.abs(rate[late] / creep - 1).max() > 1e-6:
        failures.append(f"creep speed {rate[late].min()}..{rate[late].max()} m/s, expected "
                        f"{creep}")
    # Holding: the friction carries the weight's share along the slope.
    if np.abs(along[late[1:]] / (MASS * G * np.sin(THETA)) - 1).max() > 1e-6:
        failures.append("the friction does not hold the weight along the slope")
    print(f"sticking: creep {rate[-1]:.10e} m/s (regularised law {creep:.10e})")

for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
