#!/usr/bin/python3
"""`catena stats --series steps` against the samples.

Usage: check_stats_series.py CATENA FINE.h5 COARSE.h5 X0 X1

FINE.h5 and COARSE.h5 are the same fixed-step run with output.interval = dt and with a
coarse output.interval. The steps of a fixed-step run do not depend on the output interval,
so the statistics of COARSE.h5's steps (--series steps) are those of FINE.h5's samples, and
of FINE.h5's steps, to round-off in the filter (1e-9 relative), while COARSE.h5's own samples
cannot be evaluated at the 20 Hz cut-off (too coarse: `--series samples` is refused, and
without --series the steps are taken, with a note). On a
catenary the uplift at the supports is among the numbers: from every step's registration
heights, it must not depend on the output interval either.
"""
import json
import subprocess
import sys

catena, fine, coarse, x0, x1 = sys.argv[1:6]


def stats(path, *extra):
    out = subprocess.run([catena, "stats", path, "--json", "--section", x0, x1, *extra],
                         capture_output=True, text=True)
    return out.returncode, out.stdout, out.stderr


def numbers(text):
    pantograph = json.loads(text)["pantographs"][0]
    return {k: v for k, v in pantograph.items() if isinstance(v, (int, float))}


ok = True
code, reference, err = stats(fine)
assert code == 0, err
reference = numbers(reference)
# Without --series the coarse file's samples are too coarse for the cut-off: its steps are
# evaluated instead, with a note (the table's), giving the same numbers.
for label, path, extra in (("fine, steps", fine, ("--series", "steps")),
                           ("coarse, steps", coarse, ("--series", "steps")),
                           ("coarse, chosen", coarse, ())):
    code, text, err = stats(path, *extra)
    if code != 0:
        print(f"{label}: exit {code}: {err}")
        ok = False
        continue
    got = numbers(text)
    for key, value in reference.items():
        if abs(got[key] - value) > 1e-9 * max(1.0, abs(value)):
            print(f"{label}: {key} {got[key]} against the samples' {value}")
            ok = False
    print(f"{label}: {len(reference)} numbers compared, " + ("equal" if ok else "differ"))
code, _, err = stats(coarse, "--series", "samples")
print(f"coarse, samples: exit {code} ({err.strip()[:120]})")
ok = ok and code != 0
table = subprocess.run([catena, "stats", coarse, "--section", x0, x1], capture_output=True,
                       text=True).stdout
print(table.splitlines()[1] if len(table.splitlines()) > 1 else table)
ok = ok and "too coarse for the 20 Hz cutoff" in table
sys.exit(0 if ok else 1)
