#!/usr/bin/python3
"""Runs `catena elasticity meshes/simple_catenary.yaml --json --step 5` (1 m elements) at
np 1 and np 2 and checks that
  * every number agrees between the rank counts to 1e-6 relative;
  * the JSON is what docs/catenary.md ("Elasticity") says: span 5 (the first evaluation
    span) by default, force 100 N, points every 5 m from support to support, elasticity =
    uplift / force, and max, min, mean and uniformity (EN 50119) recomputed from the points,
    for the elasticity under the force and for the linear one;
  * the linear elasticity is the small-force limit: within 1 % of the elasticity under
    100 N where no dropper goes slack, below it where one does (the droppers at x = 5 and
    55 m, next to the supports), and the run warns about those points;
  * the values are plausible for an EN 50318 catenary: positive, below 2 mm/N, larger at
    mid-span than at the steady arm;
  * a pantograph standing in the span and a dynamic analysis in the scene change nothing
    (both are ignored, and the output header says so).
Usage: check_elasticity.py CATENA MPIEXEC
"""
import json
import subprocess
import sys

SCENE = "meshes/simple_catenary.yaml"
COMMON = ["elasticity", SCENE, "--json", "--step", "5", "--set", "catenary.element_length=1.0"]
PANTOGRAPH = ("pantographs=[{name: p, path: contact_wire, speed: 0, start: 270, "
              "static_force: 120, model: en50318}]")


def run(command):
    print("$", " ".join(command), flush=True)
    done = subprocess.run(command, capture_output=True, text=True)
    print(done.stderr)
    assert done.returncode == 0, f"exit code {done.returncode}"
    return json.loads(done.stdout), done.stderr


def close(a, b, rtol):
    return abs(a - b) <= rtol * max(abs(a), abs(b)) + 1e-12


def compare(a, b, rtol, label):
    assert a["span"] == b["span"] and a["force"] == b["force"], label
    assert len(a["points"]) == len(b["points"]), label
    worst = 0.0
    for p, q in zip(a["points"], b["points"]):
        for key in ("x", "uplift", "elasticity", "linear_elasticity", "slack_droppers"):
            assert close(p[key], q[key], rtol), f"{label}: {key} {p[key]} vs {q[key]}"
            worst = max(worst, abs(p[key] - q[key]) / max(abs(p[key]), 1e-300))
    for key in ("max", "min", "mean", "uniformity"):
        assert close(a[key], b[key], rtol), f"{label}: {key} {a[key]} vs {b[key]}"
        assert close(a["linear"][key], b["linear"][key], rtol), f"{label}: linear {key}"
    print(f"{label}: largest relative difference {worst:.2e}")


def summary_matches(summary, values, label):
    assert close(summary["max"], max(values), 1e-12), label
    assert close(summary["min"], min(values), 1e-12), label
    assert close(summary["mean"], sum(values) / len(values), 1e-12), label
    u = (max(values) - min(values)) / (max(values) + min(values))
    assert close(summary["uniformity"], u, 1e-12), (label, summary["uniformity"], u)


def main():
    catena, mpiexec = sys.argv[1], sys.argv[2]
    np1, warnings = run([mpiexec, "-n", "1", "--oversubscribe", catena] + COMMON)
    np2, _ = run([mpiexec, "-n", "2", "--oversubscribe", catena] + COMMON)
    compare(np1, np2, 1e-6, "np 1 vs np 2")

    assert np1["span"] == 5 and np1["force"] == 100, np1
    points = np1["points"]
    xs = [p["x"] for p in points]
    assert xs == [5.0 * k for k in range(13)], xs
    e = [p["elasticity"] for p in points]
    for p in points:
        assert close(p["elasticity"], p["uplift"] / 100.0, 1e-12), p
        assert 0.0 < p["elasticity"] < 2.0, p
    u = (max(e) - min(e)) / (max(e) + min(e))
    summary_matches(np1, e, "under 100 N")
    linear = [p["linear_elasticity"] for p in points]
    summary_matches(np1["linear"], linear, "linear")
    slack = [p["slack_droppers"] for p in points]
    assert [k for k, n in enumerate(slack) if n > 0] == [1, 11], slack
    for p in points:
        if p["slack_droppers"] == 0:
            assert close(p["elasticity"], p["linear_elasticity"], 0.01), p
        else:
            assert p["elasticity"] > 1.05 * p["linear_elasticity"], p
    assert "droppers go slack at 2 of 13 points (x = 5.000 to 55.000 m" in warnings, warnings
    mid, support = e[6], e[0]
    assert mid > support, (mid, support)
    print(f"span 5: support {support:.4f} mm/N, mid-span {mid:.4f} mm/N, "
          f"max {max(e):.4f}, min {min(e):.4f}, uniformity {u:.4f}")

    ignored, header = run([catena] + COMMON + ["--set", PANTOGRAPH, "--set",
                                               "analysis={type: dynamic, duration: 0.1}"])
    assert "pantographs (1)" in header and "dynamic analysis" in header, header
    compare(np1, ignored, 1e-9, "without vs with a pantograph and dynamics")


if __name__ == "__main__":
    main()
