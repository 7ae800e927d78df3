#!/usr/bin/python3
"""Checks the sweep.csv of the app test sweep_pantograph (docs/study.md, "Sweeps"): every
combination of the two varied keys ran and was measured, each under its own values — the
mean contact force rises with the static force it was given — and the plot was drawn.

    check_sweep.py SWEEP_DIR
"""
import csv
import os
import sys


def main():
    directory = sys.argv[1]
    with open(os.path.join(directory, "sweep.csv"), newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        header = reader.fieldnames
    speed, force = "pantographs[0].speed_kmh", "pantographs[0].static_force"
    for column in (speed, force, "pantograph", "mean_N", "std_N", "stat_max_N", "min_N",
                   "contact_loss_percent", "wall_per_simulated_second"):
        if column not in header:
            sys.exit(f"check_sweep: no column {column} in {header}")
    combinations = {(r[speed], r[force]) for r in rows}
    if combinations != {(s, f) for s in ("80", "100") for f in ("100", "120")}:
        sys.exit(f"check_sweep: combinations {sorted(combinations)}")
    for r in rows:
        if r["status"] != "completed":
            sys.exit(f"check_sweep: {r['case']} {r['status']} {r['message']}")
    # Each run got its own static force: at each speed, 20 N more static force lifts the
    # mean contact force by about 20 N (measured 17.8 and 17.5 N over this short run, whose
    # start-up transient the mean includes).
    mean = {(r[speed], r[force]): float(r["mean_N"]) for r in rows}
    for s in ("80", "100"):
        lift = mean[(s, "120")] - mean[(s, "100")]
        if not 15.0 < lift < 22.0:
            sys.exit(f"check_sweep: at {s} km/h the mean rises by {lift} N for 20 N more static force")
    if os.path.getsize(os.path.join(directory, "sweep.png")) < 1000:
        sys.exit("check_sweep: no plot")
    print("check_sweep: passed:", [(r[speed], r[force], r["mean_N"]) for r in rows])


if __name__ == "__main__":
    main()
