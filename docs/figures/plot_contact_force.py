#!/usr/bin/python3
"""Contact force against position for EN 50318 runs (docs/validation.md).

    /usr/bin/python3 docs/figures/plot_contact_force.py OUT_250.h5 OUT_300.h5 -o FIG.png

Plots, per file, the raw sampled contact force and the same signal low-pass filtered at
20 Hz the way `catena stats` does (2nd-order Butterworth, forward and backward), against
the pantograph's position, with the evaluation section shaded and the registration
(support) positions marked.
"""
import argparse

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def butterworth_zero_phase(x, dt, cutoff):
    """2nd-order Butterworth low pass (bilinear transform), run forward then backward."""
    wc = np.tan(np.pi * cutoff * dt)
    k = 1.0 + np.sqrt(2.0) * wc + wc * wc
    b = np.array([wc * wc, 2 * wc * wc, wc * wc]) / k
    a = np.array([1.0, 2 * (wc * wc - 1) / k, (1 - np.sqrt(2.0) * wc + wc * wc) / k])

    def run(s):
        y = np.empty_like(s)
        y[0], y[1] = s[0], s[1]
        for n in range(2, len(s)):
            y[n] = b[0] * s[n] + b[1] * s[n - 1] + b[2] * s[n - 2] - a[1] * y[n - 1] - a[2] * y[n - 2]
        return y

    return run(run(x)[::-1])[::-1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    fig, axes = plt.subplots(len(args.files), 1, figsize=(9, 3.2 * len(args.files)), squeeze=False)
    for ax, name in zip(axes[:, 0], args.files):
        with h5py.File(name, "r") as f:
            t = f["time"][:]
            force = f["samples/contact_force"][:, 0]
            x = f["samples/contact_position"][:, 0]
            section = (f.attrs["evaluation_start"], f.attrs["evaluation_end"])
            supports = f["mesh/node_positions"][:, 0][f["mesh/registration_nodes"][:]]
            speed = 3.6 * list(f["pantographs"].values())[0].attrs["speed"]
        filtered = butterworth_zero_phase(force, t[1] - t[0], 20.0)
        ax.axvspan(*section, color="0.92", label="evaluation section")
        for s in supports:
            ax.axvline(s, color="0.6", lw=0.6, ls=":")
        ax.plot(x, force, lw=0.5, color="tab:blue", alpha=0.5, label="contact force")
        ax.plot(x, filtered, lw=1.2, color="tab:red", label="filtered at 20 Hz")
        ax.set_xlim(x[0], x[-1])
        ax.set_ylabel("force (N)")
        ax.set_title(f"{speed:.0f} km/h ({name.split('/')[-1]})", fontsize=10)
        ax.legend(loc="upper right", fontsize=8)
    axes[-1, 0].set_xlabel("pantograph position along the contact wire (m)")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


if __name__ == "__main__":
    main()
