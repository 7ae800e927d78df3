#!/usr/bin/python3
"""One case of the extremes suite (docs/accuracy.md, "Where each method stops working").

Runs `catena run SCENE --set ...` at a setting at or past some method's limit and passes
if Catena's answer is one of the two a user may get there:

  * the run completes (exit 0) with an output that is all finite and bounded: no node of
    the structure further than --max-displacement from its mesh position, the plucked
    string's energy (--string-energy) never above its start by more than the tolerance;
  * the run stops with exit code 3 and a message that names the cause (the step fell
    below its minimum, a state that is not finite, energy growth), and whatever it wrote
    before is finite.

--expect says which of the two the case must give (or `either`), --warn/--no-warn what
the run must (not) say, --loss-of-contact whether contact must be lost (past the wire's
wave speed it must be counted). A crash, a hang (the CTest timeout), another exit code or
NaN in a file fails the case. Prints one line with what happened, for the table.
"""
import argparse
import math
import os
import re
import subprocess
import sys

import h5py
import numpy as np

# The named causes of an exit 3 (solvers/time/state_guard.hpp, transient_solver.cpp): the
# step cut below dt_min, a state not finite, growth past the reach bound, or fixed steps
# that fail at every step (50 cut steps in a row covering less than one dt).
CAUSES = (r"step size fell below its minimum|state is not finite|grew without bound|"
          r"failed in each of [0-9]+ steps in a row")


def finite_file(path):
    """(True, "") if every sample and step dataset of `path` is finite, else (False, which)."""
    with h5py.File(path, "r") as f:
        for group in ("samples", "steps"):
            for name in f.get(group, {}):
                data = f[group][name]
                if data.dtype.kind == "f" and not np.all(np.isfinite(data[:])):
                    return False, f"{group}/{name}"
    return True, ""


def structure_displacement(path):
    """Largest distance of a structure node from its mesh position, the pantographs' stage
    nodes left out (the output draws them under their contact point, travelling along x):
    the nodes of the elements in the sets named "pantograph NAME"."""
    with h5py.File(path, "r") as f:
        positions = f["samples/positions"][:]
        mesh = f["mesh/node_positions"][:]
        keep = np.ones(mesh.shape[0], bool)
        names = [n.decode() if isinstance(n, bytes) else str(n)
                 for n in f["mesh/element_set"].attrs.get("set_names", [])]
        stage_sets = [i for i, n in enumerate(names) if n.startswith("pantograph ")]
        if stage_sets:
            in_stage = np.isin(f["mesh/element_set"][:], stage_sets)
            keep[np.unique(f["mesh/element_nodes"][:][in_stage])] = False
        d = np.linalg.norm(positions[:, keep, :] - mesh[None, keep, :], axis=2)
        return float(d.max())


def string_energy(path, tension, mass_per_length):
    """Per sample, ½μ∫|v|² dx + ½T∫|w'|² dx of a straight string along x (trapezoid over
    the nodes; w' from the slopes): the plucked string's energy to small-amplitude order."""
    with h5py.File(path, "r") as f:
        x = f["mesh/node_positions"][:, 0]
        v = f["samples/velocities"][:]
        s = f["samples/slopes"][:]
    order = np.argsort(x)
    x = x[order]
    kinetic = 0.5 * mass_per_length * np.trapz(np.sum(v[:, order, :] ** 2, axis=2), x, axis=1)
    slope = s[:, order, 1:] / np.linalg.norm(s[:, order, :], axis=2, keepdims=True)
    potential = 0.5 * tension * np.trapz(np.sum(slope**2, axis=2), x, axis=1)
    return kinetic + potential


def contact_force(path):
    """The pantographs' sampled contact forces (samples × pantographs), or None without."""
    with h5py.File(path, "r") as f:
        if "samples/contact_force" not in f or f["samples/contact_force"].shape[1] == 0:
            return None
        return f["samples/contact_force"][:]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--catena", required=True)
    p.add_argument("--scene", required=True)
    p.add_argument("--output", required=True, help="the case's output file (OUT.h5)")
    p.add_argument("--set", action="append", default=[], dest="sets")
    p.add_argument("--petsc", action="append", default=[], help="a PETSc option (repeat)")
    p.add_argument("--expect", choices=("bounded", "stops", "either"), required=True)
    p.add_argument("--warn", help="a regex the run's output must match")
    p.add_argument("--no-warn", help="a regex the run's output must not match")
    p.add_argument("--max-displacement", type=float, help="m, structure nodes, if completed")
    p.add_argument("--loss-of-contact", choices=("some", "none"))
    p.add_argument("--string-energy", nargs=3, type=float,
                   metavar=("TENSION", "MASS_PER_LENGTH", "GROWTH"),
                   help="the energy never above its start by more than GROWTH (relative)")
    a = p.parse_args()

    for stale in (a.output, a.output.replace(".h5", ".part.h5")):
        if os.path.exists(stale):
            os.remove(stale)
    cmd = [a.catena, "run", a.scene, "-o", a.output, "--quiet"]
    for s in a.sets:
        cmd += ["--set", s]
    for o in a.petsc:
        cmd += o.split(" ", 1)
    run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    out = run.stdout
    problems = []
    verdict = ""
    if run.returncode == 0:
        verdict = "completed"
        if a.expect == "stops":
            problems.append("completed, but the case must stop with exit 3")
        ok, which = finite_file(a.output)
        if not ok:
            problems.append(f"{which} holds values that are not finite")
        else:
            d = structure_displacement(a.output)
            verdict += f", largest displacement {d:.3g} m"
            if a.max_displacement is not None and d > a.max_displacement:
                problems.append(f"a node moved {d:.3g} m > {a.max_displacement} m")
            force = contact_force(a.output)
            if force is not None:
                # per pantograph; the largest loss of contact is the one that must be counted
                loss = float(max(np.mean(force <= 0.0, axis=0)) * 100.0)
                stds = ", ".join(f"{s:.2f}" for s in force.std(axis=0))
                verdict += f", contact force std {stds} N, loss of contact {loss:.2f} %"
            if a.loss_of_contact:
                if force is None:
                    problems.append("no contact force in the output")
                    loss = 0.0
                elif (loss > 0) != (a.loss_of_contact == "some"):
                    problems.append(f"loss of contact {loss:.2f} %, expected {a.loss_of_contact}")
            if a.string_energy:
                tension, mu, growth = a.string_energy
                e = string_energy(a.output, tension, mu)
                drift = e.max() / e[0] - 1.0
                verdict += f", energy max/start - 1 = {drift:.2e}, end/start = {e[-1] / e[0]:.4f}"
                if not math.isfinite(drift) or drift > growth:
                    problems.append(f"the energy grew by {drift:.3g} > {growth}")
    elif run.returncode == 3:
        cause = re.search(CAUSES, out)
        verdict = "stopped (exit 3): " + (cause.group(0) if cause else "no cause named")
        if a.expect == "bounded":
            problems.append("stopped, but the case must complete")
        if not cause:
            problems.append("exit 3 without a named cause")
        partial = a.output.replace(".h5", ".part.h5")
        if os.path.exists(partial):
            ok, which = finite_file(partial)
            if not ok:
                problems.append(f"{partial}: {which} holds values that are not finite")
    else:
        verdict = f"exit {run.returncode}"
        problems.append(f"exit code {run.returncode}: neither a result nor a named failure")
    if a.warn and not re.search(a.warn, out):
        problems.append(f"the output does not say /{a.warn}/")
    if a.no_warn and re.search(a.no_warn, out):
        problems.append(f"the output says /{a.no_warn}/")
    roughness = re.search(r"roughness ([0-9.]+)", out)
    if roughness:
        verdict += f", contact force roughness {roughness.group(1)}"
    # A multistep method's step against the contact spring's own mode, said before the run.
    under_stepped = re.search(r"steps a period \(dt\*omega = ([0-9.e+-]+)", out)
    if under_stepped and run.returncode == 0:  # a stop's verdict ends with its cause
        verdict += f", contact mode under-stepped (dt*omega {under_stepped.group(1)})"
    # Repeated strikes after losses of contact: the loss of contact is then the step's too.
    strikes = re.search(r"struck the wire again ([0-9]+) times", out)
    if strikes and run.returncode == 0:
        verdict += f", struck the wire again {strikes.group(1)} times"
    print(out)
    print(f"extremes: {os.path.basename(a.output)}: {verdict}")
    for problem in problems:
        print("extremes: FAIL: " + problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
