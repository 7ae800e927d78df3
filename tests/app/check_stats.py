#!/usr/bin/python3
"""Runs `catena stats --json` and `catena export` on make_stats_fixture.py's outputs (a
complete run, one still running, one declaring the EN 50318 ranges, one interrupted inside
the section) and compares every number with an independent NumPy evaluation of the same definitions (docs/output.md,
"Contact-force statistics"): the prewarped bilinear 2nd-order Butterworth run forward and
backward over the whole record from its steady state, population statistics of the
section samples, raw-force contact loss, uplift of the registration nodes inside the
section while the pantograph is between each one's neighbouring registration nodes.
An unfinished run is evaluated over the part of the section each pantograph covered; the
acceptance checks against the ranges restated below. Tolerance 1e-9 relative (1e-12 m for
the uplift).
Usage: check_stats.py CATENA OUTDIR
"""
import csv
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


# EN 50318:2002's acceptance ranges (as reproduced by Wang et al., IEEE Trans. Power
# Delivery 2016, Table III), restated here independently of the code: (low, high) at
# 250 km/h and at 300 km/h; the uplift in mm.
RANGES = {
    "mean": ((110, 120), (110, 120)),
    "std": ((26, 31), (32, 40)),
    "stat_max": ((190, 210), (210, 230)),
    "stat_min": ((20, 40), (-5, 20)),
    "max": ((175, 210), (190, 225)),
    "min": ((50, 75), (30, 55)),
    "max_uplift_at_support": ((48, 55), (55, 65)),
    "contact_loss_percent": ((0, 0), (0, 0)),
}


def run_json(catena, path):
    run = subprocess.run([catena, "stats", path, "--json"], capture_output=True, text=True)
    print(run.stdout, run.stderr)
    assert run.returncode == 0, run.returncode
    return json.loads(run.stdout)


def expected_statistics(path):
    """Per pantograph: the statistics over the section the record covers (all of it for a
    complete run), by the definitions of docs/output.md."""
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
    out = []
    for j, name in enumerate(names):
        filtered = filtfilt(force[:, j], dt, 20.0)
        # Only what the record covers, less the filter's end transient (2 / cutoff seconds
        # of travel) where the record ends inside the section (docs/output.md).
        lo, hi = position[:, j].min(), position[:, j].max()
        edge = abs(speeds[j]) * 2.0 / 20.0
        if position[-1, j] >= position[0, j] and hi < x1:
            hi -= edge
        if position[-1, j] < position[0, j] and lo > x0:
            lo += edge
        a, b = max(x0, lo), min(x1, hi)
        # docs/output.md: a position that differs from a section end by round-off is at
        # that end (the trailing head stands at 99.99999999999999 m at t = 1.2 s here).
        tol = max(1e-6 * abs(speeds[j]) * dt, 1e-9 * max(abs(a), abs(b)))
        rows = (position[:, j] >= a - tol) & (position[:, j] <= b + tol)
        sec = filtered[rows]
        mean, std = sec.mean(), sec.std()
        # Each support inside the section, while the head is between its neighbours.
        xs = np.sort(ref_x)
        uplift = -np.inf
        for i in np.flatnonzero((ref_x >= a - tol) & (ref_x <= b + tol)):
            lower, upper = xs[xs < ref_x[i]], xs[xs > ref_x[i]]
            lo = lower[-1] if lower.size else -np.inf
            hi = upper[0] if upper.size else np.inf
            passing = (position[:, j] >= lo) & (position[:, j] <= hi)
            uplift = max(uplift, (z[passing, i] - z[0, i]).max())
        out.append({"name": name, "section": [a, b], "filtered": filtered,
                    "values": {"speed_kmh": speeds[j] * 3.6, "mean": mean, "std": std,
                               "stat_max": mean + 3 * std, "stat_min": mean - 3 * std,
                               "max": sec.max(), "min": sec.min(),
                               "contact_loss_percent": 100 * np.mean(force[rows, j] <= 0)},
                    "uplift": uplift})
    return out


def check_values(got, expected):
    worst = 0.0
    assert [p["name"] for p in got] == [e["name"] for e in expected], got
    for p, e in zip(got, expected):
        assert np.allclose(p["section"], e["section"], rtol=0, atol=1e-9), (p["section"], e)
        for key, value in e["values"].items():
            error = abs(p[key] - value) / max(abs(value), 1.0)
            worst = max(worst, error)
            assert error < 1e-9, (p["name"], key, p[key], value)
        assert abs(p["max_uplift_at_support"] - e["uplift"]) < 1e-12, (p, e["uplift"])
        v = e["values"]
        print(f"{p['name']}: section {e['section']}, mean {v['mean']:.3f} N, std "
              f"{v['std']:.3f} N, loss {v['contact_loss_percent']:.3f} %, uplift "
              f"{e['uplift'] * 1e3:.3f} mm: ok")
    return worst


def check_acceptance(got):
    """Every pantograph at 250 or 300 km/h carries the eight checks of RANGES."""
    for p in got:
        column = {250: 0, 300: 1}[round(p["speed_kmh"])]
        checks = {c["statistic"]: c for c in p["acceptance"]["checks"]}
        assert set(checks) == set(RANGES), checks
        passed = 0
        for key, ranges in RANGES.items():
            low, high = ranges[column]
            value = p[key] * (1e3 if key == "max_uplift_at_support" else 1)
            c = checks[key]
            assert (c["low"], c["high"]) == (low, high), c
            assert abs(c["value"] - value) <= 1e-9 * max(1, abs(value)), (c, value)
            assert c["pass"] == (low <= value <= high), (c, value)
            passed += c["pass"]
        assert p["acceptance"]["passed"] == passed and p["acceptance"]["total"] == 8, p
        print(f"{p['name']}: {passed} of 8 in range, each as the table says: ok")


def check_export(catena, path, got, expected, prefix):
    """catena export's CSV files hold the same statistics and the filtered series."""
    run = subprocess.run([catena, "export", path, "--csv", "-o", prefix], capture_output=True,
                         text=True)
    print(run.stdout, run.stderr)
    assert run.returncode == 0, run.returncode
    with open(prefix + "_statistics.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    columns = {"mean_N": "mean", "std_N": "std", "stat_max_N": "stat_max",
               "stat_min_N": "stat_min", "max_N": "max", "min_N": "min",
               "contact_loss_percent": "contact_loss_percent"}
    for row, p in zip(rows, got):
        assert row["pantograph"] == p["name"], row
        for column, key in columns.items():
            assert abs(float(row[column]) - p[key]) <= 1e-8 * max(1, abs(p[key])), (row, p)
        assert abs(float(row["max_uplift_at_support_mm"]) -
                   1e3 * p["max_uplift_at_support"]) < 1e-6, row
        if p.get("acceptance"):
            assert int(row["in_range"]) == p["acceptance"]["passed"], row
    with open(prefix + "_contact.csv", newline="") as f:
        series = list(csv.DictReader(f))
    for e in expected:
        filtered = np.array([float(r[e["name"] + "_force_filtered_N"]) for r in series])
        assert len(filtered) == len(e["filtered"]), (len(filtered), len(e["filtered"]))
        assert np.abs(filtered - e["filtered"]).max() < 1e-6, e["name"]
    print(f"export {prefix}: {len(rows)} statistics rows, {len(series)} samples: ok")


def main():
    catena, out = sys.argv[1], sys.argv[2]
    worst = 0.0
    for name in ["stats_run", "stats_running", "stats_acceptance", "stats_interrupted",
                 "stats_short"]:
        path = f"{out}/{name}.h5"
        report = run_json(catena, path)
        expected = expected_statistics(path)
        worst = max(worst, check_values(report["pantographs"], expected))
        assert report["complete"] == (name in ("stats_run", "stats_acceptance", "stats_short")), \
            report
        if name in ("stats_acceptance", "stats_interrupted"):
            check_acceptance(report["pantographs"])
        else:
            assert all(p["acceptance"] is None for p in report["pantographs"]), report
        check_export(catena, path, report["pantographs"], expected, f"{out}/export_{name}")
    got = run_json(catena, f"{out}/stats_run.h5")["pantographs"]
    assert got[0]["contact_loss_percent"] == 0 and got[1]["contact_loss_percent"] > 0
    print(f"worst relative difference {worst:.2e}")


if __name__ == "__main__":
    main()
