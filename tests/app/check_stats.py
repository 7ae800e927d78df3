#!/usr/bin/python3
"""Runs `catena stats --json` on make_stats_fixture.py's stats_run.h5 and compares every
number with an independent NumPy evaluation of the same definitions (docs/output.md,
"Contact-force statistics"): the prewarped bilinear 2nd-order Butterworth run forward and
backward over the whole record from its steady state, population statistics of the
section samples, raw-force contact loss, uplift of the registration nodes inside the
section while the pantograph is between each one's neighbouring registration nodes.
Tolerance 1e-9 relative (1e-12 m for the uplift).
Usage: check_stats.py CATENA OUTDIR
"""
import json
import subprocess
import sys

import h5py
import numpy as np


def biquad(dt, fc):
    k = np.tan(np.pi * fc * dt)
    a0 = 1 + np.sqrt(2) * k + k * k
    b = np.array([k * k, 2 * k * k, k * k]) / a0
    a = np.array([2 * (k * k - 1), 1 - np.sqrt(2) * k + k * k]) / a0
    return b, a


def one_pass(b, a, x):
    y = np.empty_like(x)
    z1, z2 = (1 - b[0]) * x[0], (b[2] - a[1]) * x[0]
    for n, xn in enumerate(x):
        y[n] = b[0] * xn + z1
        z1 = b[1] * xn - a[0] * y[n] + z2
        z2 = b[2] * xn - a[1] * y[n]
    return y


def filtfilt(x, dt, fc):
    b, a = biquad(dt, fc)
    return one_pass(b, a, one_pass(b, a, x)[::-1])[::-1]


def main():
    catena, out = sys.argv[1], sys.argv[2]
    path = out + "/stats_run.h5"
    run = subprocess.run([catena, "stats", path, "--json"], capture_output=True, text=True)
    print(run.stdout, run.stderr)
    assert run.returncode == 0, run.returncode
    got = json.loads(run.stdout)["pantographs"]
    with h5py.File(path, "r") as f:
        t = f["time"][:]
        force = f["samples/contact_force"][:]
        position = f["samples/contact_position"][:]
        x0, x1 = f.attrs["evaluation_start"], f.attrs["evaluation_end"]
        reg = f["mesh/registration_nodes"][:]
        ref_x = f["mesh/node_positions"][:, 0][reg]
        z = f["samples/positions"][:, :, 2][:, reg]
        names = sorted(f["pantographs"], key=lambda n: f["pantographs"][n].attrs["index"])
        speeds = [f["pantographs"][n].attrs["speed"] for n in names]
    dt = t[1] - t[0]
    assert [p["name"] for p in got] == names, got
    worst = 0.0
    for j, p in enumerate(got):
        filtered = filtfilt(force[:, j], dt, 20.0)
        # docs/output.md: a position that differs from a section end by round-off is at
        # that end (the trailing head stands at 99.99999999999999 m at t = 1.2 s here).
        tol = max(1e-6 * abs(speeds[j]) * dt, 1e-9 * max(abs(x0), abs(x1)))
        rows = (position[:, j] >= x0 - tol) & (position[:, j] <= x1 + tol)
        sec = filtered[rows]
        mean, std = sec.mean(), sec.std()
        # Each support inside the section, while the head is between its neighbours.
        xs = np.sort(ref_x)
        uplift = -np.inf
        for i in np.flatnonzero((ref_x >= x0 - tol) & (ref_x <= x1 + tol)):
            lower, upper = xs[xs < ref_x[i]], xs[xs > ref_x[i]]
            lo = lower[-1] if lower.size else -np.inf
            hi = upper[0] if upper.size else np.inf
            passing = (position[:, j] >= lo) & (position[:, j] <= hi)
            uplift = max(uplift, (z[passing, i] - z[0, i]).max())
        expected = {"speed_kmh": speeds[j] * 3.6, "mean": mean, "std": std,
                    "stat_max": mean + 3 * std, "stat_min": mean - 3 * std,
                    "max": sec.max(), "min": sec.min(),
                    "contact_loss_percent": 100 * np.mean(force[rows, j] <= 0)}
        assert p["section"] == [x0, x1], p["section"]
        for key, value in expected.items():
            error = abs(p[key] - value) / max(abs(value), 1.0)
            worst = max(worst, error)
            assert error < 1e-9, (p["name"], key, p[key], value)
        assert abs(p["max_uplift_at_support"] - uplift) < 1e-12, (p, uplift)
        print(f"{p['name']}: mean {mean:.3f} N, std {std:.3f} N, loss "
              f"{expected['contact_loss_percent']:.3f} %, uplift {uplift * 1e3:.3f} mm: ok")
    assert got[0]["contact_loss_percent"] == 0 and got[1]["contact_loss_percent"] > 0
    print(f"worst relative difference {worst:.2e}")


if __name__ == "__main__":
    main()
