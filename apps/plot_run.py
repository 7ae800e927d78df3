#!/usr/bin/python3
"""The figures of one Catena output file, drawn by `catena plot` (docs/output.md, "Plots").

    /usr/bin/python3 plot_run.py OUT.h5 PREFIX FORMATS [CONTACT_CSV STATISTICS_CSV X0 X1 CUTOFF KIND]

FORMATS is "png", "pdf" or "png,pdf". Writes PREFIX_NAME.FORMAT for each figure:

- a dynamic run with pantographs (the CSV files are `catena export`'s, X0 X1 the evaluation
  section, CUTOFF the low-pass in Hz, KIND "section", or "record" when the run sets no
  section and X0 X1 are the whole record's ends):
  contact_force  raw and filtered contact force against the position along the path, one
                 panel per pantograph, the evaluation section shaded, the supports
                 (registration points) marked, the statistics in the title;
  spectrum       the amplitude spectrum of the raw contact force over the section, with the
                 span-passing frequency v/L and its harmonics and the cutoff marked;
  uplift         the uplift of the registration points in the section against time, each
                 pantograph's passage marked;
  static_shape   the static equilibrium the run starts from (its first sample);
- a dynamic run without pantographs: static_shape and displacement (the node that moves
  most, its displacement from the first sample against time);
- a static result: static_shape.

Prints the name of every file written, one a line.
"""
import csv
import os
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

TRANSIENT = "catena-transient-1"
STATIC = "catena-static-1"


FIGURES = ["contact_force", "spectrum", "uplift", "static_shape", "displacement"]
DRAWN = set()


def save(fig, prefix, name, formats):
    """Each figure written to a temporary sibling and renamed over the old one: a reader
    sees the previous figure or the new one, never half of one."""
    for fmt in formats:
        path = f"{prefix}_{name}.{fmt}"
        temporary = f"{prefix}_{name}.tmp-{os.getpid()}.{fmt}"
        try:
            fig.savefig(temporary, format=fmt, dpi=130, bbox_inches="tight")
            os.replace(temporary, path)
        finally:
            if os.path.exists(temporary):
                os.remove(temporary)
        DRAWN.add(path)
        print(path)
    plt.close(fig)


def remove_stale(prefix, formats):
    """A figure of an earlier plot to the same prefix that this file does not have (an
    uplift without supports, a displacement of a run without pantographs) would pass for
    this file's: removed, and said."""
    for name in FIGURES:
        for fmt in formats:
            path = f"{prefix}_{name}.{fmt}"
            if path not in DRAWN and os.path.exists(path):
                os.remove(path)
                print(f"plot: removed {path} (an earlier plot's; this file has no such figure)")


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def shape_figure(nodes, element_nodes, title):
    """Elevation (x-z) and, for a staggered line, plan (x-y) of the elements' chords."""
    staggered = np.ptp(nodes[:, 1]) > 1e-6
    fig, axes = plt.subplots(2 if staggered else 1, 1, figsize=(11, 6.5 if staggered else 4),
                             squeeze=False, sharex=True)
    views = [(2, "z (m)")] + ([(1, "y (m)")] if staggered else [])
    for ax, (column, label) in zip(axes[:, 0], views):
        segments = np.stack([nodes[element_nodes[:, 0]][:, [0, column]],
                             nodes[element_nodes[:, 1]][:, [0, column]]], axis=1)
        ax.add_collection(LineCollection(segments, linewidths=0.7, colors="tab:blue"))
        ax.autoscale()
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0, 0].set_title(title)
    axes[-1, 0].set_xlabel("x (m)")
    return fig


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def pantograph_names(statistics_rows):
    return [row["pantograph"] for row in statistics_rows]


def number(text_value):
    try:
        return float(text_value)
    except (TypeError, ValueError):
        return None


def registration_x(f):
    if "mesh/registration_nodes" not in f:
        return np.array([]), np.array([], dtype=int)
    rows = f["mesh/registration_nodes"][:]
    return f["mesh/node_positions"][:, 0][rows], rows


def contact_force_figure(series, statistics, supports_x, x0, x1, cutoff, kind):
    names = pantograph_names(statistics)
    fig, axes = plt.subplots(len(names), 1, figsize=(11, 3.4 * len(names)), squeeze=False)
    for ax, name, stats in zip(axes[:, 0], names, statistics):
        position = series[f"{name}_position_m"]
        ax.plot(position, series[f"{name}_force_N"], color="0.65", linewidth=0.5,
                label="raw")
        ax.plot(position, series[f"{name}_force_filtered_N"], color="tab:blue", linewidth=1.0,
                label=f"filtered ({cutoff:g} Hz)")
        if kind == "section":
            ax.axvspan(x0, x1, color="tab:green", alpha=0.08, label="evaluation section")
        low, high = position.min(), position.max()
        for i, x in enumerate(supports_x[(supports_x >= low) & (supports_x <= high)]):
            ax.axvline(x, color="k", linestyle=":", linewidth=0.7,
                       label="support" if i == 0 else None)
        mean = number(stats["mean_N"])
        kmh = float(stats["speed_kmh"])
        title = f"{name}, {abs(kmh):g} km/h" + (" backward" if kmh < 0 else "")
        if mean is not None:
            ax.axhline(mean, color="tab:red", linewidth=0.8, linestyle="--",
                       label="mean F_m")
            title += (f": F_m {mean:.1f} N, sigma {float(stats['std_N']):.1f} N, "
                      f"max {float(stats['max_N']):.1f} N, min {float(stats['min_N']):.1f} N, "
                      f"loss {float(stats['contact_loss_percent']):.2f} %")
            if stats.get("in_range"):
                title += f"; EN 50318: {stats['in_range']} of {stats['of']} in range"
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("position along the path (m)")
        ax.set_ylabel("contact force (N)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper right", ncol=3)
    fig.tight_layout()
    return fig


def spectrum_figure(series, statistics, supports_x, x0, x1, cutoff):
    names = pantograph_names(statistics)
    fig, ax = plt.subplots(figsize=(9, 4))
    t = series["t_s"]
    dt = (t[-1] - t[0]) / (len(t) - 1)
    spans = np.diff(np.sort(supports_x))
    span = float(np.median(spans)) if len(spans) else None
    top = min(0.5 / dt, 2.0 * cutoff)
    for name, stats in zip(names, statistics):
        position = series[f"{name}_position_m"]
        inside = (position >= x0) & (position <= x1)
        force = series[f"{name}_force_N"][inside]
        if len(force) < 8:
            continue
        force = (force - force.mean()) * np.hanning(len(force))
        amplitude = 2.0 * np.abs(np.fft.rfft(force)) / (0.5 * len(force))  # Hann: gain 1/2
        frequency = np.fft.rfftfreq(len(force), dt)
        keep = frequency <= top
        line, = ax.plot(frequency[keep], amplitude[keep], linewidth=0.9, label=name)
        speed = abs(float(stats["speed_kmh"])) / 3.6  # negative: running backward
        if span and speed > 0:
            passing = speed / span
            for k in range(1, min(int(top / passing), 5) + 1):
                ax.axvline(k * passing, color=line.get_color(), linestyle=":", linewidth=0.6,
                           label=f"span passing v/L = {passing:.2f} Hz, harmonics 2-5"
                           if k == 1 else None)
    ax.axvline(cutoff, color="tab:red", linestyle="--", linewidth=0.8,
               label=f"statistics cutoff {cutoff:g} Hz")
    ax.set_xlim(0, top)
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("amplitude (N)")
    ax.set_title(f"Contact force spectrum over [{x0:g}, {x1:g}] m (Hann window)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    return fig


def uplift_figure(f, series, statistics, x0, x1):
    supports_x, rows = registration_x(f)
    chosen = [(x, r) for x, r in zip(supports_x, rows) if x0 <= x <= x1] or \
        list(zip(supports_x, rows))
    if not chosen:
        return None
    time = f["time"][:]
    fig, ax = plt.subplots(figsize=(9, 4))
    positions = f["samples/positions"]
    for x, row in sorted(chosen):
        z = positions[:, int(row), 2]
        ax.plot(time, 1e3 * (z - z[0]), linewidth=0.9, label=f"support at x = {x:g} m")
    for name in pantograph_names(statistics):
        position = series[f"{name}_position_m"]
        for x, _ in chosen:
            crossed = np.nonzero(np.diff(np.sign(position - x)))[0]
            for k in crossed[:1]:
                ax.axvline(series["t_s"][k], color="0.5", linestyle=":", linewidth=0.6)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("uplift (mm)")
    ax.set_title("Uplift of the contact wire at the supports (from the static position); "
                 "dotted: a pantograph passes", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    return fig


def displacement_figure(f):
    positions = f["samples/positions"]
    first = positions[0]
    largest, node = -1.0, 0
    for start in range(0, positions.shape[0], 256):
        block = positions[start:start + 256]
        moved = np.linalg.norm(block - first, axis=2).max(axis=0)
        k = int(moved.argmax())
        if moved[k] > largest:
            largest, node = float(moved[k]), k
    node_id = int(f["mesh/node_ids"][node])
    track = positions[:, node, :] - first[node]
    fig, ax = plt.subplots(figsize=(9, 4))
    for axis, name in enumerate("xyz"):
        ax.plot(f["time"][:], track[:, axis], linewidth=0.9, label=name)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("displacement (m)")
    ax.set_title(f"Node {node_id}, the one that moves most: displacement from the first sample",
                 fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def main():
    if len(sys.argv) not in (4, 10):
        raise SystemExit(__doc__)
    path, prefix, formats = sys.argv[1], sys.argv[2], sys.argv[3].split(",")
    with h5py.File(path, "r") as f:
        fmt = text(f.attrs.get("format", ""))
        element_nodes = f["mesh/element_nodes"][:]
        if fmt == STATIC:
            nodes = f["static/positions"][:]
            save(shape_figure(nodes, element_nodes, f"Static equilibrium: {path}"), prefix,
                 "static_shape", formats)
            return
        if fmt != TRANSIENT:
            raise SystemExit(f"plot_run: {path}: format '{fmt}', expected {TRANSIENT} or "
                             f"{STATIC}")
        nodes = f["samples/positions"][0]
        save(shape_figure(nodes, element_nodes,
                          f"Static equilibrium the run starts from: {path}"),
             prefix, "static_shape", formats)
        if len(sys.argv) == 4:
            save(displacement_figure(f), prefix, "displacement", formats)
            return
        contact_csv, statistics_csv = sys.argv[4], sys.argv[5]
        x0, x1, cutoff = float(sys.argv[6]), float(sys.argv[7]), float(sys.argv[8])
        kind = sys.argv[9]
        rows = read_rows(contact_csv)
        series = {key: np.array([float(r[key]) for r in rows]) for key in rows[0]}
        statistics = read_rows(statistics_csv)
        supports_x, _ = registration_x(f)
        save(contact_force_figure(series, statistics, supports_x, x0, x1, cutoff, kind), prefix,
             "contact_force", formats)
        save(spectrum_figure(series, statistics, supports_x, x0, x1, cutoff), prefix,
             "spectrum", formats)
        figure = uplift_figure(f, series, statistics, x0, x1)
        if figure is not None:
            save(figure, prefix, "uplift", formats)


if __name__ == "__main__":
    main()
    remove_stale(sys.argv[2], sys.argv[3].split(","))
