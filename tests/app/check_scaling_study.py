#!/usr/bin/python3
"""scaling/scaling_study.py and its Slurm script on a short line (a few seconds).

  check_scaling_study.py BENCHMARK MPIEXEC WORK_DIR

Checks: the CSV has the documented columns and a row per study and rank count (with the
weak study's baseline of independent copies); the strong
study keeps the line and its answer (the final motion agrees across rank counts to the
Newton tolerance), the weak study grows the line and its loads with the ranks; the
efficiencies are the ratios of the measured times; one rank has no interface and sends no
messages, two ranks have both; a second invocation reuses the finished runs; bad options
are refused with a message; the performance model fitted to the study reproduces its
two-rank step and projects to 1024 ranks; the Slurm script runs the powers of two up to its task count
through srun (a fake one that starts mpirun).
"""
import csv
import os
import stat
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
STUDY = os.path.join(ROOT, "scaling", "scaling_study.py")
SBATCH = os.path.join(ROOT, "scaling", "slurm", "scaling_study.sbatch")
MODEL = os.path.join(ROOT, "scaling", "performance_model.py")

failures = []


def check(condition, what):
    print(("ok:   " if condition else "FAIL: ") + what)
    if not condition:
        failures.append(what)


def run(command, **kw):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    env.update(kw.pop("env", {}))
    return subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, **kw)


def rows_of(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    benchmark, mpiexec, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    out = os.path.join(work, "scaling_study")
    subprocess.run(["rm", "-rf", out], check=True)
    launcher = f"{mpiexec} --oversubscribe -n {{ranks}}"
    command = [sys.executable, STUDY, out, "--ranks", "1,2", "--strong-length", "500",
               "--weak-length-per-rank", "250", "--load-spacing", "250", "--steps", "4",
               "--benchmark", benchmark, "--launcher", launcher, "--baseline"]
    first = run(command)
    print(first.stdout)
    check(first.returncode == 0, "the study runs (exit 0)")
    csv_path = os.path.join(out, "scaling.csv")
    rows = rows_of(csv_path)
    with open(csv_path) as f:
        header = f.readline().strip().split(",")
    for column in ("study", "ranks", "dofs", "step_s", "whole_run_s", "step_efficiency",
                   "whole_run_efficiency", "interface_rows", "messages_per_step",
                   "bytes_per_step", "reductions_per_step", "peak_memory_largest_bytes",
                   "memory_per_rank_ratio", "final_motion"):
        check(column in header, f"column {column}")
    by = {(r["study"], int(r["ranks"])): r for r in rows}
    check(sorted(by) == [("strong", 1), ("strong", 2), ("weak", 1), ("weak", 2)],
          f"one row per study and rank count: {sorted(by)}")
    s1, s2, w1, w2 = by["strong", 1], by["strong", 2], by["weak", 1], by["weak", 2]
    check(s1["dofs"] == s2["dofs"] == "12000", f"strong: the same 500 m line ({s1['dofs']}, "
          f"{s2['dofs']} DOFs)")
    check(int(w2["dofs"]) == 2 * int(w1["dofs"]) == 12000,
          f"weak: 250 m per rank ({w1['dofs']}, {w2['dofs']} DOFs)")
    check((w1["loads"], w2["loads"]) == ("1", "2"), "weak: a load per 250 m")
    m1, m2 = float(s1["final_motion"]), float(s2["final_motion"])
    check(m1 > 0 and abs(m1 - m2) <= 1e-6 * m1,
          f"strong: the same motion on 1 and 2 ranks ({m1:.9g}, {m2:.9g})")
    e = float(s1["step_s"]) / (2 * float(s2["step_s"]))
    check(abs(float(s2["step_efficiency"]) - e) <= 1e-9 * e, "strong step efficiency T1/(2 T2)")
    e = float(w1["whole_run_s"]) / float(w2["whole_run_s"])
    check(abs(float(w2["whole_run_efficiency"]) - e) <= 1e-9 * e,
          "weak whole-run efficiency T1/T2")
    check(float(s1["step_efficiency"]) == 1.0, "the base row's efficiency is 1")
    check(s1["interface_rows"] == "0" and float(s1["messages_per_step"]) == 0.0,
          "one rank: no interface, no messages")
    check(int(s2["interface_rows"]) > 0 and float(s2["messages_per_step"]) > 0 and
          float(s2["reductions_per_step"]) > 0, "two ranks: an interface, messages, reductions")
    check(float(s2["peak_memory_largest_bytes"]) > 1e6, "peak memory reported")
    product = float(w2["machine_step_efficiency"]) * float(w2["step_efficiency_on_machine"])
    check(abs(product - float(w2["step_efficiency"])) <= 1e-9 * product and
          float(w2["baseline_step_s"]) > 0 and s2["baseline_step_s"] == "",
          "weak, 2 ranks: the baseline of two independent copies, and the step's efficiency "
          "as the machine's times Catena's own")
    check(os.path.getsize(os.path.join(out, "scaling_efficiency.png")) > 1000, "the plot")

    # The performance model fitted to this study: at 2 ranks it reproduces the measured
    # step (its waiting term is fitted there, unless the model already predicts more), and
    # it projects to 1024 ranks.
    model = run([sys.executable, MODEL, csv_path, "--cores", "2", "--ranks", "1,2,1024"])
    print(model.stdout)
    check(model.returncode == 0, "the performance model runs on the study (exit 0)")
    for study in ("strong", "weak"):
        block = model.stdout.split(f"{study} scaling")[1].split("scaling (")[0]
        lines = {int(l.split()[0]): l.split() for l in block.splitlines()
                 if l.strip() and l.split()[0].isdigit()}
        check(sorted(lines) == [1, 2, 1024], f"model, {study}: rows 1, 2, 1024")
        if sorted(lines) == [1, 2, 1024]:
            check(float(lines[1][5]) == 1.0 and
                  float(lines[2][5]) <= float(lines[2][6]) + 0.011,
                  f"model, {study}: efficiency 1 at one rank and at most the measured at two "
                  f"({lines[2][5]} against {lines[2][6]})")
    bad = run([sys.executable, MODEL, os.path.join(work, "no_such.csv")])
    check(bad.returncode != 0 and "no_such.csv" in bad.stdout, "model: a missing file is named")

    second = run(command)
    check(second.returncode == 0 and second.stdout.count("measured before") == 4 and
          "at once" not in second.stdout,
          "a second invocation reuses the four finished runs and the baseline")
    check(rows_of(csv_path) == rows, "... and writes the same table")

    other = run(command[:command.index("--steps") + 1] + ["5"] + command[command.index("--steps") + 2:])
    check(other.returncode != 0 and "measured with other settings" in other.stdout,
          "runs of other settings in the directory are refused, not reused")
    for bad, says in ((["--ranks", "0,2"], "--ranks"), (["--study", "both"], "--study"),
                      (["--ranks", "2,4", "--baseline"], "must include 1"),
                      (["--benchmark", "/nonexistent"], "not an executable"),
                      (["--launcher", "mpirun -n 2"], "{ranks}")):
        r = run([sys.executable, STUDY, out] + bad)
        check(r.returncode == 2 and says in r.stdout, f"{' '.join(bad)}: exit 2 naming {says!r}")

    # The Slurm script, with a fake srun that starts the ranks with mpirun.
    fake = os.path.join(work, "fake_slurm_bin")
    os.makedirs(fake, exist_ok=True)
    srun = os.path.join(fake, "srun")
    with open(srun, "w") as f:
        f.write("#!/bin/bash\n"
                "n=1\n"
                "while [ $# -gt 0 ]; do case $1 in --ntasks=*) n=${1#--ntasks=}; shift ;;\n"
                "  --*) shift ;; *) break ;; esac; done\n"
                f'exec {mpiexec} --oversubscribe -n "$n" "$@"\n')
    os.chmod(srun, os.stat(srun).st_mode | stat.S_IXUSR)
    slurm_out = os.path.join(work, "scaling_slurm")
    subprocess.run(["rm", "-rf", slurm_out], check=True)
    r = run(["bash", SBATCH, slurm_out, "--study", "strong", "--strong-length", "250",
             "--steps", "3"], cwd=ROOT,
            env={"PATH": fake + os.pathsep + os.environ["PATH"], "SLURM_NTASKS": "3",
                 "SLURM_JOB_ID": "77", "CATENA_BENCHMARK": benchmark})
    print(r.stdout)
    check(r.returncode == 0, "the Slurm script runs the study (exit 0)")
    slurm_rows = rows_of(os.path.join(slurm_out, "scaling.csv")) if r.returncode == 0 else []
    check([x["ranks"] for x in slurm_rows] == ["1", "2"],
          "3 tasks: ranks 1 and 2 (powers of two up to the task count)")

    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)


if __name__ == "__main__":
    main()
