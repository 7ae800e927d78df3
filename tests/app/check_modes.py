#!/usr/bin/python3
"""`catena modes` on the taut string of meshes/taut_string.yaml (docs/output.md, "Modes").

Usage: check_modes.py MODES.h5 N_MODES

The string (T = 20 kN, mu = 1.35 kg/m, EI = 195 N m^2, EA = 1.8e7 N, L = 60 m, pinned)
vibrates in y and in z alike, so its modes come in pairs: mode 2n-1 and 2n at the
tensioned beam's f_n = n/(2L) sqrt(T/mu) sqrt(1 + n^2 pi^2 EI'/(T L^2)), EI' = EI(1 + T/EA)
(the bending law's curvature per unstretched length), mu the mass per current length
(the scene's mass per unstretched length over 1 + T/EA). Checks the frequencies to 1e-5,
that each shape is the sine with n half waves across the span (correlation > 0.99999),
mass-normalised (its amplitude sqrt(2/(mu0 L0)) to 1e-5, mu0 the mass per unstretched
length and L0 = L/(1 + T/EA) the unstretched length), and that the XDMF names one grid per
mode.
"""
import math
import pathlib
import sys

import h5py
import numpy as np

path, n_modes = sys.argv[1], int(sys.argv[2])
T, mu0, EI, EA, L = 20000.0, 1.35, 195.0, 1.8e7, 60.0
strain = T / EA
mu = mu0 / (1 + strain)
with h5py.File(path, "r") as f:
    assert f.attrs["format"] == "catena-modes-1", f.attrs["format"]
    frequency = f["modes/frequency"][:]
    x = f["modes/equilibrium_positions"][:, 0]
    shapes = [f[f"modes/shape_{k + 1}"][:] for k in range(n_modes)]
assert len(frequency) == n_modes, frequency
worst_f = worst_shape = worst_amplitude = 0.0
for k in range(n_modes):
    n = k // 2 + 1
    exact = n / (2 * L) * math.sqrt(T / mu) * math.sqrt(
        1 + n * n * math.pi ** 2 * EI * (1 + strain) / (T * L * L))
    worst_f = max(worst_f, abs(frequency[k] / exact - 1))
    lateral = shapes[k][:, 1] + shapes[k][:, 2]  # one of the two is zero for a pure mode
    if abs(shapes[k][:, 1]).max() > 1e-9 and abs(shapes[k][:, 2]).max() > 1e-9:
        # a pair's modes may come out as any orthonormal mix of y and z: take the larger
        lateral = np.hypot(shapes[k][:, 1], shapes[k][:, 2]) * np.sign(
            shapes[k][:, 1] + shapes[k][:, 2])
    sine = np.sin(n * math.pi * x / L)
    correlation = abs(lateral @ sine) / (np.linalg.norm(lateral) * np.linalg.norm(sine))
    worst_shape = max(worst_shape, 1 - correlation)
    amplitude = abs(lateral @ sine) / (sine @ sine)
    L0 = L / (1 + strain)
    worst_amplitude = max(worst_amplitude, abs(amplitude / math.sqrt(2 / (mu0 * L0)) - 1))
print(f"{n_modes} modes: largest frequency error {worst_f:.2e}, shape 1 - correlation "
      f"{worst_shape:.2e}, amplitude error {worst_amplitude:.2e}")
assert worst_f < 1e-5, worst_f
assert worst_shape < 1e-5, worst_shape
assert worst_amplitude < 1e-5, worst_amplitude
xdmf = pathlib.Path(path).with_suffix(".xmf").read_text()
assert xdmf.count("<Grid Name=\"mode ") == n_modes, "XDMF grids"
assert f"/modes/shape_{n_modes}</DataItem>" in xdmf
