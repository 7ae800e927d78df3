#!/usr/bin/python3
"""The EN 50318 statistics of a `catena sweep` against its first varied key (docs/study.md,
"Sweeps"): mean, F_m + 3 sigma, F_m - 3 sigma, maximum and minimum of the filtered contact
force, one panel per pantograph.

    /usr/bin/python3 apps/plot_sweep.py SWEEP_DIR/sweep.csv SWEEP_DIR/sweep.png

With more than one varied key, each combination of the others is its own set of lines.
A first key whose values are not numbers is plotted in the order the sweep ran them.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STATISTICS = [("mean_N", "mean", "-"), ("stat_max_N", "F_m + 3 sigma", "--"),
              ("stat_min_N", "F_m - 3 sigma", "--"), ("max_N", "max", ":"), ("min_N", "min", ":")]


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    with open(sys.argv[1], newline="") as f:
        reader = csv.DictReader(f)
        header = reader.fieldnames
        rows = [r for r in reader if r["status"] == "completed"]
    keys = header[1:header.index("pantograph")]
    if not rows or not keys:
        raise SystemExit(f"plot_sweep: no completed case in {sys.argv[1]}")
    first, others = keys[0], keys[1:]
    numeric = all(number(r[first]) is not None for r in rows)
    order = {}
    for r in rows:
        order.setdefault(r[first], len(order))
    pantographs = sorted({r["pantograph"] for r in rows})
    fig, axes = plt.subplots(len(pantographs), 1, figsize=(7, 4.5 * len(pantographs)),
                             squeeze=False)
    for ax, name in zip(axes[:, 0], pantographs):
        groups = {}
        for r in rows:
            if r["pantograph"] == name:
                groups.setdefault(" ".join(f"{k}={r[k]}" for k in others), []).append(r)
        for label, group in sorted(groups.items()):
            group.sort(key=lambda r: number(r[first]) if numeric else order[r[first]])
            x = [number(r[first]) if numeric else order[r[first]] for r in group]
            for column, what, style in STATISTICS:
                ax.plot(x, [float(r[column]) for r in group], style, marker="o",
                        label=f"{what} {label}".strip())
        if not numeric:
            ax.set_xticks(list(order.values()), list(order.keys()), rotation=20, fontsize=7)
        ax.set_xlabel(first)
        ax.set_ylabel("contact force, filtered [N]")
        ax.set_title(f"pantograph {name}")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
