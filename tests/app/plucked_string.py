"""The plucked taut string of meshes/taut_string.yaml, for the check scripts beside it.

T = 20 kN, mu = 1.35 kg/m per unstretched length, EI = 195 N m^2, EA = 1.8e7 N, L = 60 m,
started in its first mode with amplitude a = 0.05 m. Linearised about its straight
equilibrium it vibrates at the tensioned beam's f_1 (mu over 1 + T/EA per current length,
EI times 1 + T/EA: the bending law per unstretched length).
"""
import math

import h5py
import numpy as np

T, mu0, EI, EA, L, a = 20000.0, 1.35, 195.0, 1.8e7, 60.0, 0.05
strain = T / EA
f1 = 1 / (2 * L) * math.sqrt(T * (1 + strain) / mu0) * math.sqrt(
    1 + math.pi ** 2 * EI * (1 + strain) / (T * L * L))


def midpoint(path):
    """Sample times, the mid-point's height, and every step's Newton iterations."""
    with h5py.File(path, "r") as f:
        t = f["time"][:]
        x = f["mesh/node_positions"][:, 0]
        mid = int(np.argmin(abs(x - L / 2)))
        z = f["samples/positions"][:, mid, 2]
        iterations = f["steps/newton_iterations"][:]
    return t, z, iterations


def closed_form_miss(t, z):
    """Largest distance of z(t) from a cos(2 pi f_1 t), over the amplitude."""
    return np.abs(z - a * np.cos(2 * math.pi * f1 * t)).max() / a


def reference_miss(t, z, t_ref, z_ref):
    """Largest distance of z from z_ref at their common sample times, over the amplitude,
    and how many times they share."""
    common = [(i, int(np.argmin(abs(t_ref - tc)))) for i, tc in enumerate(t)]
    common = [(i, j) for i, j in common if abs(t_ref[j] - t[i]) < 1e-9]
    if not common:
        return float("inf"), 0
    return max(abs(z[i] - z_ref[j]) for i, j in common) / a, len(common)
