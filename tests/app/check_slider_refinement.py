#!/usr/bin/python3
"""Checks that a slider's travel converges as the wire it runs on is refined: runs of
meshes/trolley.yaml with 80, 320 and 1280 elements (each four times the last; the longest
beyond what a slider took before its constraint acted on one element at a time) give arc
lengths s(t) whose differences shrink at second order or better: |s_320 - s_1280| at most
1/8 of |s_80 - s_320| over the samples they share (measured: 9.8 mm, then 0.52 mm).
Usage: check_slider_refinement.py RUN_80.h5 RUN_320.h5 RUN_1280.h5
"""
import sys

import h5py
import numpy as np


def travel(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["status"] == "complete", f.attrs["status"]
        row = int(f["sliders/trolley"].attrs["index"])
        return f["time"][:], f["samples/slider_position"][:, row]


runs = [travel(p) for p in sys.argv[1:4]]
n = min(len(t) for t, _ in runs)
for t, _ in runs:
    assert np.allclose(t[:n], runs[0][0][:n]), "the runs' samples differ in time"
coarse = np.abs(runs[0][1][:n] - runs[1][1][:n]).max()
fine = np.abs(runs[1][1][:n] - runs[2][1][:n]).max()
print(f"s differences: 80 -> 320 elements {coarse:.3e} m, 320 -> 1280 {fine:.3e} m, "
      f"ratio {coarse / fine:.1f}")
if not (fine > 0 and coarse / fine >= 8):
    print("FAIL: the slider's travel does not converge at second order under refinement")
    sys.exit(1)
