#!/usr/bin/python3
"""`catena run --realtime`'s figures in the output file's statistics (docs/output.md).

Usage: check_realtime.py RUN.h5 N_INTERVALS

The run's root attributes hold realtime_intervals (N_INTERVALS), realtime_intervals_behind
(0 for this run, which keeps up), and step wall times with 0 < mean <= 99th percentile <=
worst, all below a second; the same of the stepping alone (after the first step), each
step's stepping no longer than the step with its output, so its worst no longer than the
worst step, as the first step's stepping, which (its set-up included) is no shorter than
the mean.
"""
import sys

import h5py

path, n_intervals = sys.argv[1], int(sys.argv[2])
with h5py.File(path, "r") as f:
    a = f.attrs
    intervals, behind = int(a["realtime_intervals"]), int(a["realtime_intervals_behind"])
    mean, p99, worst = (float(a["realtime_mean_step_seconds"]),
                        float(a["realtime_step_seconds_p99"]),
                        float(a["realtime_worst_step_seconds"]))
    lag = float(a["realtime_largest_lag_seconds"])
    first, s_mean, s_p99, s_worst = (float(a["realtime_first_stepping_seconds"]),
                                     float(a["realtime_mean_stepping_seconds"]),
                                     float(a["realtime_stepping_seconds_p99"]),
                                     float(a["realtime_worst_stepping_seconds"]))
print(f"check_realtime: {intervals} intervals, {behind} behind, step mean {mean:.3g} s, "
      f"p99 {p99:.3g} s, worst {worst:.3g} s, largest lag {lag:.3g} s")
assert intervals == n_intervals, intervals
assert behind == 0 and lag == 0.0, (behind, lag)
assert 0.0 < mean <= p99 <= worst < 1.0, (mean, p99, worst)
print(f"check_realtime: stepping alone: first {first:.3g} s, then mean {s_mean:.3g} s, "
      f"p99 {s_p99:.3g} s, worst {s_worst:.3g} s")
assert 0.0 < s_mean <= s_p99 <= s_worst <= worst, (s_mean, s_p99, s_worst, worst)
assert 0.0 < first <= worst, (first, worst)
# The first step sets up and factors the method's matrices: longer than the steps' mean.
assert first >= s_mean, (first, s_mean)
