#!/usr/bin/python3
"""`catena plot` draws what docs/output.md ("Plots") promises, and `catena export` writes
what a short run has, even where its pantograph never reached the evaluation section:

- a catenary run with a pantograph (RUN.h5): contact_force, spectrum, uplift and
  static_shape, as PNG and PDF, each a valid file of its kind and not empty; the files the
  command prints are exactly those; no temporary file is left beside them;
- the pantograph's stage nodes written under its contact point (they travel with it);
- a dynamic run without pantographs and a static result, run here (cable_pendulum,
  hanging_cable, briefly): static_shape and displacement, static_shape alone.
Usage: check_plot.py CATENA RUN.h5 OUTDIR
"""
import os
import shutil
import subprocess
import sys

PNG = b"\x89PNG\r\n\x1a\n"
PDF = b"%PDF-"


def plot(catena, args, expected, outdir):
    run = subprocess.run([catena, "plot", *args], capture_output=True, text=True)
    print(run.stdout, run.stderr)
    assert run.returncode == 0, run.returncode
    printed = sorted(line for line in run.stdout.splitlines() if not line.startswith("plot:"))
    assert printed == sorted(expected), (printed, expected)
    for path in expected:
        with open(path, "rb") as f:
            head = f.read(8)
        signature = PNG if path.endswith(".png") else PDF
        assert head.startswith(signature), (path, head)
        assert os.path.getsize(path) > 10_000, (path, os.path.getsize(path))
    leftovers = [n for n in os.listdir(outdir) if ".tmp-" in n]
    assert not leftovers, leftovers


def check_pantograph_travel(run_file):
    """The time series draws each pantograph under its contact point: its stage nodes (the
    elements of the set 'pantograph NAME') move along x by the contact point's travel along
    the path (a straight line in x here, so arc length and x agree to the wire's slope)."""
    import h5py
    import numpy as np
    with h5py.File(run_file, "r") as f:
        sets = list(f["mesh/element_set"].attrs["set_names"])
        element_set = f["mesh/element_set"][:]
        nodes = f["mesh/element_nodes"][:]
        positions = f["samples/positions"]
        travel = f["samples/contact_position"][:, 0] - f["samples/contact_position"][0, 0]
        name = next(s for s in sets if s.startswith("pantograph "))
        stage_nodes = np.unique(nodes[element_set == sets.index(name)])
        for node in stage_nodes:
            x = positions[:, int(node), 0]
            worst = np.abs((x - x[0]) - travel).max()
            assert worst < 1e-3, (name, node, worst)
    print(f"{name}: {len(stage_nodes)} stage nodes travel with the contact point "
          f"({travel[-1]:.2f} m): ok")


def main():
    catena, run_file, outdir = sys.argv[1], sys.argv[2], sys.argv[3]
    shutil.rmtree(outdir, ignore_errors=True)
    os.makedirs(outdir)
    prefix = os.path.join(outdir, "cp")
    figures = ["contact_force", "spectrum", "uplift", "static_shape"]
    plot(catena, [run_file, "-o", prefix, "--format", "png,pdf"],
         [f"{prefix}_{n}.{e}" for n in figures for e in ("png", "pdf")], outdir)

    # The same run against a section its pantograph never reaches: the series are still
    # exported, the statistics' cells empty.
    export = subprocess.run([catena, "export", run_file, "--section", "5000", "6000", "-o",
                             prefix + "_far"], capture_output=True, text=True)
    print(export.stdout, export.stderr)
    assert export.returncode == 0, export.returncode
    with open(prefix + "_far_statistics.csv") as f:
        lines = f.read().splitlines()
    assert lines[1].split(",")[5:8] == ["0", "", ""], lines[1]

    check_pantograph_travel(run_file)

    env = dict(os.environ)
    pendulum, cable = os.path.join(outdir, "pendulum.h5"), os.path.join(outdir, "cable.h5")
    for scene, out, extra in [("meshes/cable_pendulum.yaml", pendulum,
                               ["--set", "analysis.duration=0.2"]),
                              ("meshes/hanging_cable.yaml", cable, [])]:
        run = subprocess.run([catena, "run", scene, "-o", out, "--quiet", *extra],
                             capture_output=True, text=True, env=env)
        assert run.returncode == 0, (run.stdout, run.stderr)
    plot(catena, [pendulum], [os.path.join(outdir, f"pendulum_{n}.png")
                              for n in ("static_shape", "displacement")], outdir)
    plot(catena, [cable, "--format", "pdf"], [os.path.join(outdir, "cable_static_shape.pdf")],
         outdir)
    print("plots: ok")


if __name__ == "__main__":
    main()
