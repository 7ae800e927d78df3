#!/usr/bin/python3
"""Checks the study.csv files of tests/app/study.sh (docs/study.md): the errors of the
taut-string study follow the methods' orders, and the study gives the same numbers on one
rank, on two one-rank groups and on one three-rank group.

    check_study.py NP2_DIR NP1_DIR NP3_DIR
"""
import csv
import math
import os
import sys


def rows(directory):
    with open(os.path.join(directory, "study.csv"), newline="") as f:
        return {r["case"]: r for r in csv.DictReader(f)}


def fail(message):
    print("check_study:", message, file=sys.stderr)
    sys.exit(1)


def main():
    np2, np1, np3 = (rows(d) for d in sys.argv[1:4])
    if len(np2) != 7:
        fail(f"{len(np2)} rows, expected 7 (reference + 6 settings)")
    for name, r in np2.items():
        if r["status"] != "completed":
            fail(f"{name}: {r['status']} {r['message']}")
        if r["role"] != "reference" and not r["probe_rms_m"]:
            fail(f"{name}: no probe error")
    by = {(r["method"], r["setting"]): float(r["probe_rms_m"])
          for r in np2.values() if r["role"].startswith("setting")}
    dts = ["0.04", "0.02", "0.01"]
    hht = [by[("integrator.type=hht", "integrator.dt=" + dt)] for dt in dts]
    radau = [by[("integrator.type=radau", "integrator.dt=" + dt)] for dt in dts]
    # HHT with alpha = 0 is second order: halving dt divides the error by 4.
    for coarse, fine in zip(hht, hht[1:]):
        order = math.log2(coarse / fine)
        if not 1.8 < order < 2.2:
            fail(f"HHT errors {hht}: observed order {order:.2f}, expected 2")
    for h, r in zip(hht, radau):
        if not r < h / 10:
            fail(f"Radau IIA error {r} not far below HHT's {h} at the same dt")
    print("check_study: HHT orders",
          [round(math.log2(a / b), 3) for a, b in zip(hht, hht[1:])], "Radau", radau)
    # The same numbers whatever the ranks, to Newton's tolerance (1e-10 of the force scale:
    # about 1e-10 m here, which Radau's errors of 1e-8 m come near).
    for other, label in ((np1, "one rank"), (np3, "a group of three ranks")):
        for name, r in np2.items():
            if r["role"] == "reference":
                continue
            a, b = float(r["probe_rms_m"]), float(other[name]["probe_rms_m"])
            if abs(a - b) > 1e-6 * a + 1e-9:
                fail(f"{name}: probe error {a} on two groups, {b} on {label}")
            if other[name]["steps"] != r["steps"]:
                fail(f"{name}: {r['steps']} steps on two groups, {other[name]['steps']} on {label}")
    if os.path.getsize(os.path.join(sys.argv[1], "study.png")) < 1000:
        fail("no work-precision plot")
    print("check_study: passed")


if __name__ == "__main__":
    main()
