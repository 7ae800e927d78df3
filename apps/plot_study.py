#!/usr/bin/python3
"""Work-precision plot of a `catena study`: wall time of the time stepping against the
error, log-log, one line per method (docs/study.md).

    /usr/bin/python3 apps/plot_study.py STUDY_DIR/study.csv STUDY_DIR/study.png [MEASURE]

MEASURE is a study.csv error column's measure (std, force_rms_filtered, probe_rms, ...;
default std); the absolute value is plotted. Settings without a measured error are left out.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# study.csv's error columns by measure (docs/study.md), with their units.
COLUMNS = {
    "force_rms": ("force_rms_N", "N"),
    "force_max": ("force_max_N", "N"),
    "force_rms_filtered": ("force_rms_filtered_N", "N"),
    "force_max_filtered": ("force_max_filtered_N", "N"),
    "mean": ("mean_error_percent", "%"),
    "std": ("std_error_percent", "%"),
    "stat_max": ("stat_max_error_percent", "%"),
    "stat_min": ("stat_min_error_percent", "%"),
    "max": ("max_error_percent", "%"),
    "min": ("min_error_percent", "%"),
    "uplift": ("uplift_error_percent", "%"),
    "loss": ("loss_difference_points", "points"),
    "probe_rms": ("probe_rms_m", "m"),
    "probe_max": ("probe_max_m", "m"),
}


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    source, target = sys.argv[1], sys.argv[2]
    measure = sys.argv[3] if len(sys.argv) > 3 else "std"
    with open(source, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"plot_study: {source} has no rows")
    if measure not in COLUMNS:
        raise SystemExit(f"plot_study: unknown measure '{measure}'; accepted: {', '.join(COLUMNS)}")
    column, unit = COLUMNS[measure]
    lines = {}
    for row in rows:
        if not row["role"].startswith("setting") or not row[column] or not row["wall_seconds"]:
            continue
        error = abs(float(row[column]))
        if error <= 0.0:
            continue
        lines.setdefault(row["method"], []).append((error, float(row["wall_seconds"]), row["setting"]))
    fig, ax = plt.subplots(figsize=(7, 5))
    for method, points in sorted(lines.items()):
        points.sort()
        ax.loglog([p[0] for p in points], [p[1] for p in points], "o-", label=method)
        for error, wall, setting in points:
            ax.annotate(setting.split("=")[-1] if setting else "", (error, wall), fontsize=7,
                        textcoords="offset points", xytext=(4, 4))
    ax.set_xlabel(f"|{column}| [{unit}] against the reference")
    ax.set_ylabel("wall time of the time stepping [s]")
    ax.set_title("catena study: cost against error")
    ax.grid(True, which="both", alpha=0.3)
    if lines:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(target, dpi=120)


if __name__ == "__main__":
    main()
