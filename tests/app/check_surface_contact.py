#!/usr/bin/python3
"""Checks runs of tests/data/app/surface_bounce.yaml and surface_friction.yaml against closed
forms (a 2 kg point mass, g = 9.81 m/s^2, a floor of penalty stiffness k = 2e5 N/m):

  bounce:   dropped from h = 50 mm, it meets the floor at t1 = sqrt(2h/g) with v1 = sqrt(2gh);
            in contact it swings about the static penetration d = mg/k with amplitude
            A = sqrt(d^2 + m v1^2/k) for (pi + 2 asin(d/A)) sqrt(m/k) s, reaching -(d + A) and
            pushing k (d + A); without damping it rebounds to h.
  friction: resting on the floor (its reaction mg), launched along x at 2 m/s with Coulomb
            friction 0.3, it decelerates at 0.3 g: v = 2 - 0.3 g t, the reaction's
            horizontal part 0.3 m g against the motion, until it stops at 2/(0.3 g) =
            0.6796 s after 0.6796 m; then friction holds it (creep below the stick speed).
Usage: check_surface_contact.py BOUNCE.h5 FRICTION.h5
"""
import sys

import h5py
import numpy as np

G, M, K, H, MU = 9.81, 2.0, 2.0e5, 0.05, 0.3


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        return (f["time"][:], f["samples/positions"][:, 0], f["samples/velocities"][:, 0],
                f["samples/reaction_force"][:, 0])


t, x, v, reaction = read(sys.argv[1])
t1, v1 = np.sqrt(2 * H / G), np.sqrt(2 * G * H)
d = M * G / K
A = np.sqrt(d * d + M * v1 * v1 / K)
contact = (np.pi + 2 * np.arcsin(d / A)) * np.sqrt(M / K)
touching = t[x[:, 2] < 0.0]
after = t > t1 + contact
apex = x[after, 2].max()
print("bounce: contact %.5f..%.5f s (closed form %.5f..%.5f), deepest %.6g m (%.6g), "
      "largest reaction %.2f N (%.2f), rebound to %.7f m (%.7f)" %
      (touching.min(), touching.max(), t1, t1 + contact, x[:, 2].min(), -(d + A),
       reaction[:, 2].max(), K * (d + A), apex, H))
assert abs(touching.min() - t1) < 2e-4 and abs(touching.max() - (t1 + contact)) < 2e-4
assert abs(x[:, 2].min() + (d + A)) < 1e-3 * (d + A)  # sampled every 0.1 ms
assert abs(reaction[:, 2].max() - K * (d + A)) < 1e-3 * K * (d + A)
assert abs(apex - H) < 2e-4 * H, apex
assert np.abs(reaction[t < t1 - 1e-3]).max() == 0.0, "a force before the contact"

t, x, v, reaction = read(sys.argv[2])
stop = 2.0 / (MU * G)
sliding, held = t < stop - 0.01, t > stop + 0.02
assert held.sum() > 50, "the run ends before the mass stops"
speed_error = np.abs(v[sliding, 0] - (2.0 - MU * G * t[sliding])).max()
travel_error = np.abs(x[sliding, 0] - (2.0 * t[sliding] - 0.5 * MU * G * t[sliding] ** 2)).max()
# The regularisation's share of the friction, (stick speed / v)^2 / 2, stays below 2e-7
# of it down to v = 0.15 m/s, 0.05 s before the stop.
fast = t < stop - 0.05
friction_error = np.abs(reaction[1:, 0][fast[1:]] + MU * M * G).max()
creep = np.abs(v[held, 0]).max()
rest_error = np.abs(x[held, 0] - 0.5 * 2.0 * stop).max()
normal_error = np.abs(reaction[:, 2] - M * G).max()
print("friction: speed within %.3g m/s, travel %.3g m, friction force %.3g N, normal force "
      "%.3g N of the closed form" % (speed_error, travel_error, friction_error, normal_error))
print("friction: at rest from %.4f s, creeping at most %.3g m/s, %.3g m from the stop" %
      (stop, creep, rest_error))
assert creep < 1e-4 and rest_error < 1e-4, (creep, rest_error)
assert speed_error < 1e-6 and travel_error < 1e-6
assert friction_error < 1e-5 and normal_error < 1e-5
print("surface contact: OK")
