#!/usr/bin/python3
"""Strong and weak scaling of Catena's dynamic step and of a whole run.

Runs scaling/moving_load_benchmark (a pre-tensioned contact wire on elastic supports every
62.5 m, 0.25 m ANCF cable elements, 24 DOFs per metre, loads of 120 N moving at 80 m/s;
HHT with the scenes' defaults; docs/performance.md) at each rank count:

  strong  the same line (--strong-length, default 10 km: 240 000 DOFs) on every rank count;
          efficiency E(P) = P0 T(P0) / (P T(P)), P0 the smallest rank count run
  weak    a line of --weak-length-per-rank metres per rank (default 10 km), so that every
          rank holds as much line; efficiency E(P) = T(P0) / T(P)

with a moving load (a "train") every --load-spacing metres (default 5 km) in both, so that
in the weak study the trains grow with the line. T is the wall time of a dynamic step
(steps after the first, averaged) and of the whole run (scene, statics and --steps steps).

Writes OUT_DIR/scaling.csv (one row per study and rank count; columns in
docs/performance.md, "Scaling study"), OUT_DIR/scaling_efficiency.png (efficiency against
ranks) and keeps each run's report in OUT_DIR/runs/ (a study that is stopped and started
again reuses the runs already finished: delete the directory to measure anew).

  /usr/bin/python3 scaling/scaling_study.py OUT_DIR [--ranks 1,2] [--study strong,weak]
      [--strong-length M] [--weak-length-per-rank M] [--load-spacing M] [--steps N]
      [--benchmark PATH] [--launcher "mpirun --oversubscribe -n {ranks}"] [--baseline]
      [--single-launcher "mpirun --bind-to none -n 1"] [-- BENCH_OPTS]

On a Slurm cluster: scaling/slurm/scaling_study.sbatch (srun as the launcher). Rank counts
beyond the cores of the machine measure correctness and communication counts, not time.

With --baseline the weak study also runs, for each rank count P > 1, P independent
one-rank copies of its one-rank case at once (--single-launcher, default "mpirun
--bind-to none -n 1"): they share the machine as the P ranks do but never communicate, so
T(1) / T(P copies) (machine_step_efficiency) is what the machine's shared memory bandwidth
and caches allow, and T(P copies) / T(P ranks) (step_efficiency_on_machine) is the part of
the loss that is Catena's own (communication, imbalance).
"""
import argparse
import csv
import json
import os
import shlex
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# The benchmark's SCALING line carries these (see moving_load_benchmark.cpp); the CSV adds
# the study, the efficiencies and the memory ratio.
MEASURED = ["method", "ranks", "length_m", "loads", "dofs", "dt", "steps", "newton_per_step",
            "step_s", "first_step_s", "whole_run_s", "static_s", "residual_s",
            "solve_pair_s", "factorisation_s", "factorisations_per_step",
            "residual_in_run_s", "solve_in_run_s", "interface_rows", "messages_per_step",
            "bytes_per_step", "reductions_per_step", "flops_per_step",
            "peak_memory_largest_bytes", "peak_memory_total_bytes", "final_motion", "local_newton_s"]
DERIVED = ["study", "step_efficiency", "whole_run_efficiency", "step_speedup",
           "memory_per_rank_ratio", "baseline_step_s", "machine_step_efficiency",
           "step_efficiency_on_machine"]
COLUMNS = DERIVED[:1] + MEASURED + DERIVED[1:]


def rank_list(text):
    try:
        ranks = sorted({int(r) for r in text.split(",") if r.strip()})
    except ValueError:
        ranks = []
    if not ranks or ranks[0] < 1:
        raise argparse.ArgumentTypeError(
            f"--ranks {text!r}: expected rank counts >= 1 separated by commas, e.g. 1,2,4")
    return ranks


def study_list(text):
    studies = [s.strip() for s in text.split(",") if s.strip()]
    bad = [s for s in studies if s not in ("strong", "weak")]
    if not studies or bad:
        raise argparse.ArgumentTypeError(
            f"--study {text!r}: expected strong, weak or strong,weak")
    return studies


def positive(text):
    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not value > 0.0:
        raise argparse.ArgumentTypeError(f"{text!r}: expected a number > 0")
    return value


def parse(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out_dir")
    p.add_argument("--ranks", type=rank_list, default=[1, 2])
    p.add_argument("--study", type=study_list, default=["strong", "weak"])
    p.add_argument("--strong-length", type=positive, default=10000.0)
    p.add_argument("--weak-length-per-rank", type=positive, default=10000.0)
    p.add_argument("--load-spacing", type=positive, default=5000.0)
    p.add_argument("--steps", type=int, default=100)
    p.add_argument("--benchmark",
                   default=os.path.join(ROOT, "build", "scaling", "moving_load_benchmark"))
    p.add_argument("--launcher", default="mpirun --oversubscribe -n {ranks}",
                   help="the command that starts N ranks; {ranks} is replaced")
    p.add_argument("--baseline", action="store_true",
                   help="weak study: also run P independent one-rank copies at once")
    p.add_argument("--single-launcher", default="mpirun --bind-to none -n 1",
                   help="starts one of the baseline's independent one-rank copies")
    # After "--": options of the benchmark, passed on as they are.
    bench_options = argv[argv.index("--") + 1:] if "--" in argv else []
    args = p.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    args.bench_options = bench_options
    if args.steps < 2:
        p.error(f"--steps {args.steps}: expected at least 2 (the first step is timed apart)")
    if args.baseline and 1 not in args.ranks:
        p.error("--baseline compares with one rank alone: --ranks must include 1")
    if "{ranks}" not in args.launcher:
        p.error(f"--launcher {args.launcher!r}: expected {{ranks}} where the rank count goes")
    if not os.access(args.benchmark, os.X_OK):
        p.error(f"--benchmark {args.benchmark}: not an executable file (build it with "
                "./build.sh moving_load_benchmark, or give its path)")
    return args


def length_of(args, study, ranks):
    return args.strong_length if study == "strong" else args.weak_length_per_rank * ranks


def run_case(args, study, ranks, runs_dir):
    """The benchmark's SCALING record for one case: from runs_dir if a run finished it."""
    length = length_of(args, study, ranks)
    name = f"{study}_np{ranks}_{length:g}m"
    record_path = os.path.join(runs_dir, name + ".json")
    command = shlex.split(args.launcher.format(ranks=ranks)) + bench_command(args, length)
    if (record := saved_record(record_path, command)) is not None:
        print(f"scaling_study: {name}: measured before ({record_path}), reused", flush=True)
        return record
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    print(f"scaling_study: {name}: {' '.join(command)}", flush=True)
    started = time.monotonic()
    result = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    log_path = os.path.join(runs_dir, name + ".log")
    with open(log_path, "w") as f:
        f.write(result.stdout)
    record = scaling_record(result.stdout)
    if result.returncode != 0 or record is None:
        sys.exit(f"scaling_study: {name} failed (exit {result.returncode}); its output is in "
                 f"{log_path}")
    print(f"scaling_study: {name}: {record['dofs']} DOFs, step {1e3 * record['step_s']:.2f} ms, "
          f"whole run {record['whole_run_s']:.2f} s ({time.monotonic() - started:.0f} s)",
          flush=True)
    save_record(record, record_path, command)
    return record


def saved_record(path, command):
    """A finished run's record, or None; a record of another command is refused."""
    if not os.path.exists(path):
        return None
    with open(path) as f:
        record = json.load(f)
    if record.get("command") != command:
        sys.exit(f"scaling_study: {path} was measured with other settings\n  "
                 f"{' '.join(record.get('command', ['(unknown)']))}\n  instead of\n  "
                 f"{' '.join(command)}\nuse another output directory, or delete that one")
    return record


def save_record(record, path, command):
    """Written last and whole (renamed into place): a record on disk is a finished run."""
    with open(path + ".tmp", "w") as f:
        json.dump(dict(record, command=command), f)
    os.replace(path + ".tmp", path)


def bench_command(args, length):
    return [args.benchmark, "-length", f"{length:g}", "-load_spacing", f"{args.load_spacing:g}",
            "-steps", str(args.steps)] + args.bench_options


def scaling_record(output):
    lines = [l for l in output.splitlines() if l.startswith("SCALING ")]
    return json.loads(lines[0][len("SCALING "):]) if len(lines) == 1 else None


def run_baseline(args, ranks, runs_dir):
    """The machine's own limit for the weak study: `ranks` independent one-rank copies of its
    one-rank case at once (no communication between them). Their slowest step against the
    one-rank step alone is what shared memory bandwidth and caches leave of the ideal."""
    length = args.weak_length_per_rank
    name = f"baseline_{ranks}x_{length:g}m"
    record_path = os.path.join(runs_dir, name + ".json")
    command = shlex.split(args.single_launcher) + bench_command(args, length)
    if (saved := saved_record(record_path, command)) is not None:
        return saved
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    print(f"scaling_study: {name}: {ranks} at once of {' '.join(command)}", flush=True)
    copies = [subprocess.Popen(command, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True) for _ in range(ranks)]
    records = []
    for k, copy in enumerate(copies):
        output = copy.communicate()[0]
        with open(os.path.join(runs_dir, f"{name}_copy{k + 1}.log"), "w") as f:
            f.write(output)
        record = scaling_record(output)
        if copy.returncode != 0 or record is None:
            sys.exit(f"scaling_study: {name}, copy {k + 1} failed (exit {copy.returncode}); "
                     f"its output is in {runs_dir}")
        records.append(record)
    slowest = max(records, key=lambda r: r["step_s"])
    print(f"scaling_study: {name}: slowest copy's step {1e3 * slowest['step_s']:.2f} ms",
          flush=True)
    save_record(slowest, record_path, command)
    return slowest


def with_efficiencies(study, records):
    """The derived columns, against the smallest rank count of the study."""
    base = records[0]
    p0 = base["ranks"]
    rows = []
    for r in records:
        p = r["ranks"]
        row = dict(r, study=study)
        if study == "strong":
            row["step_efficiency"] = p0 * base["step_s"] / (p * r["step_s"])
            row["whole_run_efficiency"] = p0 * base["whole_run_s"] / (p * r["whole_run_s"])
        else:
            row["step_efficiency"] = base["step_s"] / r["step_s"]
            row["whole_run_efficiency"] = base["whole_run_s"] / r["whole_run_s"]
        row["step_speedup"] = base["step_s"] / r["step_s"]
        row["memory_per_rank_ratio"] = (r["peak_memory_largest_bytes"] /
                                        base["peak_memory_largest_bytes"])
        rows.append(row)
    return rows


def plot(rows, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("scaling_study: no matplotlib (Debian: python3-matplotlib, for /usr/bin/python3):"
              " no plot", file=sys.stderr)
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    for study in ("strong", "weak"):
        mine = [r for r in rows if r["study"] == study]
        if not mine:
            continue
        ranks = [r["ranks"] for r in mine]
        ax.plot(ranks, [r["step_efficiency"] for r in mine], "o-", label=f"{study}: step")
        ax.plot(ranks, [r["whole_run_efficiency"] for r in mine], "s--",
                label=f"{study}: whole run")
    ax.set_xscale("log", base=2)
    ax.set_xlabel("ranks")
    ax.set_ylabel("parallel efficiency")
    ax.set_ylim(0.0, 1.2)
    ax.axhline(1.0, color="grey", linewidth=0.5)
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend()
    ax.set_title("Catena, moving-load line, HHT")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(argv):
    args = parse(argv)
    runs_dir = os.path.join(args.out_dir, "runs")
    os.makedirs(runs_dir, exist_ok=True)
    rows = []
    for study in args.study:
        records = [run_case(args, study, ranks, runs_dir) for ranks in args.ranks]
        study_rows = with_efficiencies(study, records)
        if study == "weak" and args.baseline:
            for row in study_rows:
                if row["ranks"] == 1:
                    continue
                base = run_baseline(args, row["ranks"], runs_dir)
                row["baseline_step_s"] = base["step_s"]
                row["machine_step_efficiency"] = study_rows[0]["step_s"] / base["step_s"]
                row["step_efficiency_on_machine"] = base["step_s"] / row["step_s"]
        rows += study_rows
    csv_path = os.path.join(args.out_dir, "scaling.csv")
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    png_path = os.path.join(args.out_dir, "scaling_efficiency.png")
    plot(rows, png_path)
    print(f"{'study':6} {'ranks':>5} {'DOFs':>9} {'step ms':>8} {'eff':>5} {'whole s':>8} "
          f"{'eff':>5} {'iface':>5} {'MiB/rank':>8} {'machine':>7} {'own':>5}")
    for r in rows:
        machine = (f" {r['machine_step_efficiency']:7.2f} {r['step_efficiency_on_machine']:5.2f}"
                   if "machine_step_efficiency" in r else "")
        print(f"{r['study']:6} {r['ranks']:5d} {r['dofs']:9d} {1e3 * r['step_s']:8.2f} "
              f"{r['step_efficiency']:5.2f} {r['whole_run_s']:8.2f} "
              f"{r['whole_run_efficiency']:5.2f} {r['interface_rows']:5d} "
              f"{r['peak_memory_largest_bytes'] / 2**20:8.0f}{machine}")
    print("(eff: parallel efficiency of the step and of the whole run; with --baseline, machine:"
          " what P independent copies keep of one alone, own: the weak step's efficiency"
          " against them)")
    print(f"scaling_study: {csv_path}, {png_path}")


if __name__ == "__main__":
    main(sys.argv[1:])
