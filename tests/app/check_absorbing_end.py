#!/usr/bin/python3
"""Checks runs of tests/data/app/absorbing_end_string.yaml (60 m of wire under T = 20 kN,
m' = 1.35 kg/m, EA = 1.8e7 N, driven at its left end, an absorbing end at its right):

  transverse: driven at A = 10 mm, 5 Hz. A wave leaving through the end makes the steady
              amplitude along the wire the drive's everywhere; a reflection r adds a standing
              part, so the amplitudes range over A (1 -+ |r|): |r| = (max - min)/(max + min),
              fitted over the last second at 5 Hz. The end's dashpot pushes with the
              line's impedance times the speed: Z omega A, Z = sqrt(T m'/lambda).
  pinned:     the same wire pinned at the right: a standing wave (|r| near 1), the contrast.
  axial:      driven along the wire at 0.1 mm, 200 Hz: |r| the same way from the axial motion.
  NP2:        the transverse run on 2 ranks: the same motion.
  RESTARTED:  the transverse run stopped at 1 s and continued with --restart (which solves
              the static start again for the end's force): the same motion.
  CUT, CUT2:  a catenary with catenary.ends: absorbing on 1 and 2 ranks: the same motion.
Usage: check_absorbing_end.py TRANSVERSE.h5 PINNED.h5 AXIAL.h5 NP2.h5 RESTARTED.h5 CUT.h5 CUT2.h5
"""
import math
import sys

import h5py
import numpy as np

T, MASS, EA, AMPLITUDE = 2.0e4, 1.35, 1.8e7, 0.01


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        x0 = f["mesh/node_positions"][:, 0]
        order = np.argsort(x0)
        motion = (f["samples/positions"][:] - f["mesh/node_positions"][:][None])[:, order, :]
        return f["time"][:], motion, f["samples/reaction_force"][:, 0, :]


def amplitudes(t, series, frequency, start):
    """Amplitude of each column's `frequency` part over t >= start (least squares)."""
    window = t >= start - 1e-12
    omega = 2 * math.pi * frequency
    basis = np.stack([np.cos(omega * t[window]), np.sin(omega * t[window]),
                      np.ones(window.sum())], 1)
    coefficients, *_ = np.linalg.lstsq(basis, series[window], rcond=None)
    return np.hypot(coefficients[0], coefficients[1])


def reflection(amplitude):
    inner = amplitude[5:-5]  # away from the driven node and the end
    return (inner.max() - inner.min()) / (inner.max() + inner.min()), inner


failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


t, motion, reaction = read(sys.argv[1])
r, inner = reflection(amplitudes(t, motion[:, :, 2], 5.0, 1.0))
check(r < 2e-3, f"transverse: reflection |r| = {r:.2e} (< 2e-3)")
check(abs(inner.mean() / AMPLITUDE - 1) < 3e-3,
      f"transverse: amplitude along the wire {inner.mean() * 1e3:.4f} mm, the drive's 10 mm")
impedance = math.sqrt(T * MASS / (1 + T / EA))
push = amplitudes(t, reaction[:, 2:3], 5.0, 1.0)[0]
expected = impedance * 2 * math.pi * 5.0 * AMPLITUDE
check(abs(push / expected - 1) < 0.01,
      f"transverse: the end's force amplitude {push:.3f} N, Z omega A = {expected:.3f} N")

t_pin, motion_pin, _ = read(sys.argv[2])
r_pin, _ = reflection(amplitudes(t_pin, motion_pin[:, :, 2], 5.0, 1.0))
check(r_pin > 0.5, f"pinned: a standing wave, |r| = {r_pin:.2f} (> 0.5)")

t_ax, motion_ax, _ = read(sys.argv[3])
r_ax, _ = reflection(amplitudes(t_ax, motion_ax[:, :, 0], 200.0, 0.04))
check(r_ax < 1e-3, f"axial: reflection |r| = {r_ax:.2e} (< 1e-3)")

_, motion_np2, _ = read(sys.argv[4])
gap = np.abs(motion_np2 - motion).max()
check(gap < 1e-9, f"np 2 against np 1: largest difference {gap:.1e} m (< 1e-9)")

t_restarted, motion_restarted, _ = read(sys.argv[5])
gap = np.abs(motion_restarted - motion).max() if motion_restarted.shape == motion.shape else np.inf
check(gap < 1e-9, f"restarted at 1 s against the straight run: largest difference {gap:.1e} m")

_, cut, _ = read(sys.argv[6])
_, cut2, _ = read(sys.argv[7])
gap = np.abs(cut2 - cut).max()
check(gap < 1e-9, f"cut catenary, np 2 against np 1: largest difference {gap:.1e} m (< 1e-9)")

sys.exit(1 if failures else 0)
