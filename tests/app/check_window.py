#!/usr/bin/python3
"""Checks runs of a moving window (catenary.window): six spans of a 14-span line (60 m spans,
EN 50318's wires, 1 m elements) follow a pantograph at 300 km/h from 174.96 m for 1.2 s;
the window moves one span back at the steps ending after 0.06048 s and 0.78048 s.

  WINDOW:    the window on 1 rank.
  LINE:      the whole 14-span line with absorbing ends (catenary.ends: absorbing): the
             contact force agrees with the window's to 3 % of its standard deviation (RMS)
             and 10 % (largest difference); the moves are recorded at those times; the
             contact point and the drawn nodes are the line's (x grows with the moves).
  NP2:       the window on 2 ranks: the same run (1e-5 N: Newton's tolerance, grown by
             the contact over 1200 steps).
  RESTARTED: the window stopped at 0.5 s (after its first move) and continued with
             --restart: the same run and moves (1e-5 N: the first run's last step, cut to
             land on 0.5 s, differs from dt by round-off).
  STATS:     `catena stats` of the window and of the line over the evaluation span (180 m to
             240 m): sigma and the uplift at the supports (each registration point of
             the line followed through the window) within 3 %.
Usage: check_window.py WINDOW.h5 LINE.h5 NP2.h5 RESTARTED.h5 CATENA
"""
import json
import subprocess
import sys

import h5py
import numpy as np

SPEED = 300 / 3.6  # m/s
START = 174.96     # m


def read(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        out = {"t": f["steps/time"][:], "force": f["steps/contact_force"][:, 0],
               "sample_t": f["time"][:], "position": f["samples/contact_position"][:, 0],
               "x": f["samples/positions"][:, :, 0]}
        if "steps/window_moves" in f:
            out["moves"] = f["steps/window_moves"][:]
            out["sample_moves"] = f["samples/window_moves"][:]
            out["shift"] = f.attrs["window_shift_x"]
        return out


failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


window, line, np2, restarted = (read(p) for p in sys.argv[1:5])

d = window["force"] - line["force"]
rms, largest, spread = np.sqrt(np.mean(d ** 2)), np.abs(d).max(), line["force"].std()
check(rms < 0.03 * spread and largest < 0.10 * spread,
      f"window against the whole line: RMS difference {rms:.3f} N, largest {largest:.3f} N "
      f"(the line's contact force: sigma {spread:.2f} N)")

# The first step of each new window starts where the move was made: at the first step
# boundary after the pantograph passed 180 m (t = 0.06048 s) and 240 m (0.78048 s).
moves_at = window["t"][np.nonzero(np.diff(window["moves"]))[0] + 1] - 0.001
check(window["moves"][-1] == 2 and np.allclose(moves_at, [0.061, 0.781], atol=1e-9),
      f"the window moved at t = {moves_at} s (the first step boundaries after the pantograph "
      f"passed 180 m and 240 m)")
check(window["shift"] == 60.0, f"each move is one span: window_shift_x = {window['shift']} m")

expected = START + SPEED * window["sample_t"]
check(np.abs(window["position"] - expected).max() < 1e-9,
      "the contact point is recorded on the line: start + speed * t throughout")
# The drawn nodes are the line's: the rear end (the smallest x) is 0 m before the first
# move, 60 m after it, 120 m after the second.
rear = window["x"].min(axis=1)
moves = window["sample_moves"]
check(np.abs(rear - 60.0 * moves).max() < 0.05,
      f"the window's rear end is drawn at 60 m per move (largest miss "
      f"{np.abs(rear - 60.0 * moves).max():.3g} m)")

check(np.abs(np2["force"] - window["force"]).max() < 1e-5,
      f"2 ranks: largest difference {np.abs(np2['force'] - window['force']).max():.3g} N")
check(len(restarted["force"]) == len(window["force"]) and
      np.abs(restarted["force"] - window["force"]).max() < 1e-5 and
      np.array_equal(restarted["moves"], window["moves"]),
      "stopped at 0.5 s and restarted: the same steps and moves")

def statistics(path):
    out = subprocess.run([sys.argv[5], "stats", path, "--json"], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)["pantographs"][0]


ws, ls = statistics(sys.argv[1]), statistics(sys.argv[2])
for key in ("std", "max_uplift_at_support"):
    check(abs(ws[key] - ls[key]) < 0.03 * abs(ls[key]),
          f"catena stats {key}: window {ws[key]:.5g}, line {ls[key]:.5g}")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
