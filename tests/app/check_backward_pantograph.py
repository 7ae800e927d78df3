#!/usr/bin/python3
"""A pantograph running backward is the mirror image of one running forward.

Usage: check_backward_pantograph.py FORWARD.h5 BACKWARD.h5 LENGTH TOLERANCE

The scene (a wire between two supports, uniform elements) is symmetric under x -> LENGTH - x.
FORWARD runs from s0 toward increasing arc length, BACKWARD from LENGTH - s0 with
`direction: backward`: their contact positions must mirror (s_b = LENGTH - s_f) and their
contact forces agree within TOLERANCE of the mean force (Newton tolerance and round-off:
the two runs' elements are traversed the other way round).
"""
import sys

import h5py
import numpy as np


def read(path):
    with h5py.File(path, "r") as f:
        return (f["samples/contact_force"][:, 0], f["samples/contact_position"][:, 0],
                f.attrs["status"])


forward, s_forward, status_f = read(sys.argv[1])
backward, s_backward, status_b = read(sys.argv[2])
length, tolerance = float(sys.argv[3]), float(sys.argv[4])
ok = True
for name, status in ((sys.argv[1], status_f), (sys.argv[2], status_b)):
    status = status.decode() if isinstance(status, bytes) else status
    if status != "complete":
        print(f"{name}: status {status!r}, expected 'complete'")
        ok = False
if forward.shape != backward.shape:
    print(f"sample counts differ: {forward.shape} and {backward.shape}")
    sys.exit(1)
mirror = np.abs(s_backward - (length - s_forward)).max()
moved = abs(s_backward[-1] - s_backward[0])
spread = np.abs(forward - backward).max() / max(abs(forward.mean()), 1e-300)
print(f"forward travels {s_forward[0]:.3f} -> {s_forward[-1]:.3f} m, backward "
      f"{s_backward[0]:.3f} -> {s_backward[-1]:.3f} m: positions mirror to {mirror:.2e} m; "
      f"contact force mean {forward.mean():.3f} / {backward.mean():.3f} N, sigma "
      f"{forward.std():.3f} / {backward.std():.3f} N, largest difference {spread:.2e} of the mean")
ok = ok and mirror <= 1e-9 * length and moved > 1.0 and s_backward[-1] < s_backward[0]
ok = ok and forward.mean() > 1.0 and spread <= tolerance and forward.std() > 0.01 * forward.mean()
sys.exit(0 if ok else 1)
