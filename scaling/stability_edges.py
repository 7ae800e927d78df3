#!/usr/bin/python3
"""The measured stability edges of docs/accuracy.md ("Where each method stops working").

Runs every method family over steps from 1e-4 s to 0.1 s on four cases — the pantograph on
a single wire (meshes/pantograph_wire.yaml) at EN 50318's contact stiffness, at 100 times
it, at 600 km/h (past the wire's wave speed, 438 km/h), and the plucked taut string
(meshes/taut_string.yaml) — each through tests/extremes/run_case.py, and writes
OUT_DIR/stability_edges.csv (one row per run) and OUT_DIR/stability_edges.md (the table:
per case and method, what each step gave). A benchmark: about 15 minutes on one core.

  /usr/bin/python3 scaling/stability_edges.py build/apps/catena OUT_DIR [--methods M,M] [CASE ...]

With CASE names (wire, wire_contact_x100, wire_600kmh, string) only those are run: two
invocations with different OUT_DIRs share a 2-core machine. With --methods only those
method families (the names of METHODS below) are run.
"""
import csv
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
WIRE = os.path.join(ROOT, "meshes", "pantograph_wire.yaml")
STRING = os.path.join(ROOT, "meshes", "taut_string.yaml")
RUN_CASE = os.path.join(ROOT, "tests", "extremes", "run_case.py")

# Scene overrides per method family, relative to a scene that sets hht (the wire) or
# radau with 3 stages (the string): "~" removes a key the method does not take.
METHODS = {
    "hht": ["integrator.type=hht", "integrator.stages=~", "integrator.alpha=-0.1"],
    "hht_alpha0": ["integrator.type=hht", "integrator.stages=~", "integrator.alpha=0"],
    "radau3": ["integrator.type=radau", "integrator.alpha=~", "integrator.stages=3"],
    "gauss2": ["integrator.type=gauss", "integrator.alpha=~", "integrator.stages=2"],
    "lobatto_iiic3": ["integrator.type=lobatto_iiic", "integrator.alpha=~",
                      "integrator.stages=3"],
    "linearly_implicit": ["integrator.type=hht", "integrator.stages=~",
                          "integrator.newton=linearly_implicit"],
    "linear_li": ["integrator.type=hht", "integrator.stages=~", "analysis.structure=linear",
                  "integrator.newton=linearly_implicit"],
    "modal": ["integrator.type=hht", "integrator.stages=~", "analysis.structure=modal"],
    "park": ["integrator.type=park", "integrator.stages=~", "integrator.alpha=~"],
    "bdf2": ["integrator.type=bdf", "integrator.stages=~", "integrator.alpha=~",
             "integrator.order=2"],
}

CASES = {
    "wire": (WIRE, []),
    "wire_contact_x100": (WIRE, ["pantographs[0].contact.stiffness=5e6"]),
    "wire_600kmh": (WIRE, ["pantographs[0].speed_kmh=600", "analysis.duration=0.3"]),
    "string": (STRING, []),
}

STEPS = [1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1]


def outcome(line):
    """A short word for the table from run_case.py's verdict line."""
    if "completed" in line:
        warned = ("roughness" in line or "under-stepped" in line or
                  "struck the wire again" in line)
        return "warns" if warned else "ok"
    m = re.search(r"stopped \(exit 3\): (.*)", line)
    if m:
        cause = m.group(1)
        if re.match(r"failed in each of [0-9]+ steps in a row", cause):
            return "stops: step"  # fixed steps that fail at every step (transient_solver.cpp)
        return {"step size fell below its minimum": "stops: step",
                "state is not finite": "stops: not finite",
                "grew without bound": "stops: growth"}.get(cause, "stops")
    return "FAILS"


def main():
    catena, out_dir = sys.argv[1], sys.argv[2]
    rest = sys.argv[3:]
    methods = list(METHODS)
    if "--methods" in rest:
        i = rest.index("--methods")
        if i + 1 >= len(rest):
            sys.exit("stability_edges: --methods needs a comma-separated list")
        methods = rest[i + 1].split(",")
        del rest[i:i + 2]
        wrong = [m for m in methods if m not in METHODS]
        if wrong:
            sys.exit(f"stability_edges: unknown method {wrong[0]}; accepted: {', '.join(METHODS)}")
    chosen = rest or list(CASES)
    unknown = [c for c in chosen if c not in CASES]
    if unknown:
        sys.exit(f"stability_edges: unknown case {unknown[0]}; accepted: {', '.join(CASES)}")
    os.makedirs(out_dir, exist_ok=True)
    rows = []
    for case in chosen:
        scene, case_sets = CASES[case]
        for method in methods:
            method_sets = METHODS[method]
            if case == "string" and method == "modal":
                continue  # the string has no pantograph: the modal model has no loads to carry
            for dt in STEPS:
                name = f"{case}_{method}_dt{dt:g}"
                sets = method_sets + case_sets + [f"integrator.dt={dt:g}"]
                if case == "string":
                    sets.append("output.interval=0.01")
                cmd = ["/usr/bin/python3", RUN_CASE, "--catena", catena, "--scene", scene,
                       "--output", os.path.join(out_dir, name + ".h5"), "--expect", "either"]
                for s in sets:
                    cmd += ["--set", s]
                try:
                    run = subprocess.run(cmd, stdout=subprocess.PIPE,
                                         stderr=subprocess.STDOUT, text=True, timeout=600)
                    text = run.stdout
                except subprocess.TimeoutExpired:
                    text = "extremes: timeout (600 s)"
                line = next((l for l in text.splitlines() if l.startswith("extremes: ")), text)
                std = re.search(r"contact force std ([0-9.]+)", line)
                rough = re.search(r"roughness ([0-9.]+)", line)
                row = {"case": case, "method": method, "dt": dt, "outcome": outcome(line),
                       "contact_std": std.group(1) if std else "",
                       "roughness": rough.group(1) if rough else "", "verdict": line}
                rows.append(row)
                print(f"{name}: {row['outcome']} {line}", flush=True)
                for suffix in (".h5", ".part.h5", ".xmf", ".xmf2", ".h5.chk"):
                    path = os.path.join(out_dir, name + suffix)
                    if os.path.exists(path):
                        os.remove(path)
    with open(os.path.join(out_dir, "stability_edges.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(out_dir, "stability_edges.md"), "w") as f:
        for case in chosen:
            f.write(f"\n{case}\n\n| method | " + " | ".join(f"{dt:g} s" for dt in STEPS)
                    + " |\n|---|" + "---|" * len(STEPS) + "\n")
            for method in METHODS:
                cells = [r for r in rows if r["case"] == case and r["method"] == method]
                if not cells:
                    continue
                text = []
                for r in cells:
                    cell = r["outcome"]
                    if r["contact_std"]:
                        cell += f" ({r['contact_std']})"
                    text.append(cell)
                f.write(f"| {method} | " + " | ".join(text) + " |\n")


if __name__ == "__main__":
    main()
