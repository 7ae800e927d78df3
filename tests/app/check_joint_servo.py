#!/usr/bin/python3
"""Checks a run of tests/data/app/joint_servo_friction.yaml against closed forms (three
bodies, I_z = 0.2 kg m^2, each on a revolute joint to the ground about z, no gravity):
  spinner:  dry friction 1 N m against 10 rad/s: omega = 10 - 5 t, angle 10 t - 2.5 t^2
            (the regularisation's share is (stick speed / omega)^2 / 2, below 1e-7 here);
  follower: a servo (gains 20 N m/rad, 4 N m s/rad) on a ramp of 1 rad/s from rest,
            critically damped: angle t - t exp(-10 t);
  limited:  a servo to 1 rad held to 2 N m by its limit: angle 5 t^2 while saturated
            (to 0.3 s);
  turner:   the follower's servo on a ramp of 12 rad/s: angle 12 t - 12 t exp(-10 t), past
            pi from 0.28 s (the joint's principal angle wraps there, its target does not).
Usage: check_joint_servo.py OUT.h5 [OTHER.h5]  (OTHER: the same run on another rank count)
"""
import sys

import h5py
import numpy as np


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        rows = {n: int(f["bodies/" + n].attrs["index"])
                for n in ("spinner", "follower", "limited", "turner")}
        return (f["time"][:], f["samples/body_orientation"][:],
                f["samples/body_angular_velocity"][:], rows)


t, q, w, rows = read(sys.argv[1])


def angle(row):
    """The rotation about z from the quaternion (w, x, y, z), unwrapped."""
    return np.unwrap(2.0 * np.arctan2(q[:, row, 3], q[:, row, 0]))


assert t[-1] >= 0.4 - 1e-12, t[-1]
spinner = rows["spinner"]
omega_error = np.abs(w[:, spinner, 2] - (10.0 - 5.0 * t)).max()
spin_error = np.abs(angle(spinner) - (10.0 * t - 2.5 * t * t)).max()
follow_error = np.abs(angle(rows["follower"]) - (t - t * np.exp(-10.0 * t))).max()
saturated = t <= 0.3 + 1e-12
limited_error = np.abs(angle(rows["limited"])[saturated] - 5.0 * t[saturated] ** 2).max()
turn = angle(rows["turner"])
turn_error = np.abs(turn - (12.0 * t - 12.0 * t * np.exp(-10.0 * t))).max()
print("joint friction: omega within %.3g rad/s, angle %.3g rad; servo on a ramp within %.3g "
      "rad; servo at its limit within %.3g rad; through pi (to %.3f rad) within %.3g rad" %
      (omega_error, spin_error, follow_error, limited_error, turn[-1], turn_error))
assert omega_error < 1e-6 and spin_error < 1e-6, (omega_error, spin_error)
assert follow_error < 1e-8, follow_error
assert limited_error < 1e-8, limited_error
assert turn[-1] > 4.0 and turn_error < 1e-8, (turn[-1], turn_error)
if len(sys.argv) > 2:
    t2, q2, w2, _ = read(sys.argv[2])
    assert t2.shape == t.shape
    dq, dw = np.abs(q - q2).max(), np.abs(w - w2).max()
    print("against %s: quaternions %.3g, angular velocities %.3g rad/s" % (sys.argv[2], dq, dw))
    assert dq < 1e-10 and dw < 1e-8
print("joint servo and friction: OK")
