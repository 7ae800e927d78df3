#!/usr/bin/python3
"""Crash-safety campaign: kill -9, SIGTERM and restarts of a 2-rank dynamic run at random
moments, and what survives.

Each trial starts `mpirun -n 2 catena run SCENE`, waits a random time, then does one of
  kill9      kill -9 of mpirun (the ranks must notice and stop by themselves),
  term       SIGTERM to mpirun (mpirun forwards it; see docs/output.md for its grace period),
  term_rank  SIGTERM to one rank only,
then restarts the run with --restart (until it completes) and compares the final output with
an uninterrupted reference run, dataset by dataset, for exact (bitwise) equality.

Counted per trial: the files left readable by h5py, whether a restart was possible (a
checkpoint existed) and completed, whether the result is bit-identical to the reference,
whether anything hung (a timeout) and whether any rank outlived mpirun.

  /usr/bin/python3 scaling/crash_campaign.py build/apps/catena --trials 30 [--seed 1]

Exit status 0 when no trial hung, no rank was orphaned, every file was readable and every
completed restart was bit-identical to the reference.
"""
import argparse
import glob
import os
import random
import signal
import subprocess
import sys
import time

import h5py
import numpy as np

SERIES = ("time", "samples", "steps")


def environment():
    env = dict(os.environ)
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return env


def command(args, out, restart=False):
    cmd = ["mpirun", "-n", "2", "--oversubscribe"]
    if args.sigkill_timeout:
        cmd += ["--mca", "odls_base_sigkill_timeout", str(args.sigkill_timeout)]
    cmd += [args.catena, "run", args.scene, "-o", out] + args.set
    if restart:
        cmd.append("--restart")
    return cmd


def catena_pids():
    found = subprocess.run(["pgrep", "-f", "apps/catena run"], capture_output=True, text=True)
    return [int(p) for p in found.stdout.split()]


def rank_pids(mpirun_pid):
    found = subprocess.run(["pgrep", "-P", str(mpirun_pid)], capture_output=True, text=True)
    return [int(p) for p in found.stdout.split()]


def readable(path):
    try:
        with h5py.File(path, "r") as f:
            for name in SERIES:
                if name in f:
                    f.visititems(lambda _, obj: obj[...] if isinstance(obj, h5py.Dataset) else None)
        return True
    except Exception:  # noqa: BLE001 - any failure to read counts
        return False


def status(path):
    try:
        with h5py.File(path, "r") as f:
            return f.attrs["status"]
    except Exception:  # noqa: BLE001 - missing or unreadable
        return None


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        def take(name, obj):
            if isinstance(obj, h5py.Dataset) and name.split("/")[0] in SERIES:
                out[name] = obj[...]
        f.visititems(take)
    return out


def identical(reference, path):
    a, b = datasets(reference), datasets(path)
    if a.keys() != b.keys():
        return False, f"datasets differ: {sorted(a.keys() ^ b.keys())}"
    for name in a:
        if a[name].shape != b[name].shape:
            return False, f"{name}: shape {a[name].shape} vs {b[name].shape}"
        if not np.array_equal(a[name], b[name]):
            d = np.max(np.abs(a[name].astype(float) - b[name].astype(float)))
            return False, f"{name}: max difference {d:.3g}"
    return True, ""


def remove_run_files(out):
    stem = out[:-3] if out.endswith(".h5") else out
    for p in glob.glob(out + "*") + glob.glob(stem + ".part.*") + glob.glob(stem + ".xmf"):
        os.remove(p)


def run_to_end(args, out, log):
    """Restarts until the run completes (a restart may itself be the last one)."""
    for _ in range(3):
        try:
            r = subprocess.run(command(args, out, restart=True), env=environment(),
                               stdout=log, stderr=log, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            return "hung"
        if r.returncode == 0:
            return "complete"
        return f"exit {r.returncode}"
    return "incomplete"


def wait_for_dynamics(log_path, p):
    """Waits until the run prints its `dynamics:` line (the time stepping has begun)."""
    while p.poll() is None:
        with open(log_path) as f:
            if any(line.startswith("dynamics:") for line in f):
                return time.time()
        time.sleep(0.05)
    return time.time()


def trial(args, k, mode, delay, reference, counts):
    out = os.path.join(args.dir, f"campaign_{k}.h5")
    remove_run_files(out)
    log_path = os.path.join(args.dir, f"campaign_{k}.log")
    log = open(log_path, "w")
    p = subprocess.Popen(command(args, out), env=environment(), stdout=log, stderr=log,
                         start_new_session=True)
    wait_for_dynamics(log_path, p)
    time.sleep(delay)
    note = ""
    if p.poll() is None:
        ranks = rank_pids(p.pid)
        if mode == "kill9":
            p.send_signal(signal.SIGKILL)
        elif mode == "term":
            p.send_signal(signal.SIGTERM)
        elif ranks:
            os.kill(random.choice(ranks), signal.SIGTERM)
        try:
            p.wait(timeout=args.timeout)
        except subprocess.TimeoutExpired:
            counts["hung"] += 1
            note = "hung after the signal"
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
        # Ranks must not outlive mpirun: allow them the documented grace to stop cleanly.
        deadline = time.time() + args.orphan_grace
        while time.time() < deadline and any(os.path.exists(f"/proc/{r}") for r in ranks):
            time.sleep(0.2)
        alive = [r for r in ranks if os.path.exists(f"/proc/{r}")]
        if alive:
            counts["orphaned"] += 1
            note += f" orphans {alive}"
            for r in alive:
                os.kill(r, signal.SIGKILL)
    else:
        note = "finished before the signal"
        counts["not_interrupted"] += 1
    code = p.wait()
    files = [f for f in glob.glob(out + "*") + glob.glob(out[:-3] + ".part.h5")
             if f.endswith((".h5", ".chk"))]
    n_readable = sum(readable(f) for f in files)
    counts["files"] += len(files)
    counts["readable"] += n_readable
    # mpirun exits 1 when it was signalled even if the ranks completed the run.
    result = "complete" if code == 0 or status(out) == "complete" else None
    if result is None:
        if os.path.exists(out + ".chk"):
            counts["restartable"] += 1
            result = run_to_end(args, out, log)
            if result == "hung":
                counts["hung"] += 1
            elif result == "complete":
                counts["restarted"] += 1
        else:
            result = "no checkpoint yet"
            counts["no_checkpoint"] += 1
    same = None
    if result == "complete":
        same, why = identical(reference, out)
        counts["bit_identical" if same else "differs"] += 1
        if not same:
            note += " " + why
    print(f"trial {k:3d}: {mode:9s} {delay:5.2f} s into the dynamics: exit {code:4d}, "
          f"{n_readable}/{len(files)} files readable, {result}"
          f"{', bit-identical' if same else ''}{'; ' + note.strip() if note.strip() else ''}",
          flush=True)
    log.close()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("catena")
    ap.add_argument("--scene", default="meshes/pantograph_wire.yaml")
    ap.add_argument("--set", nargs="*", default=[
        "--set", "analysis.duration=0.15", "--set", "output.checkpoint_wall_seconds=1",
        "--set", "output.flush_wall_seconds=0.5"])
    ap.add_argument("--trials", type=int, default=30)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--dir", default="campaign")
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--orphan-grace", type=float, default=70)
    ap.add_argument("--sigkill-timeout", type=int, default=5,
                    help="mpirun's grace between SIGTERM and SIGKILL (0: Open MPI's 1 s)")
    args = ap.parse_args()
    random.seed(args.seed)
    os.makedirs(args.dir, exist_ok=True)
    reference = os.path.join(args.dir, "campaign_reference.h5")
    remove_run_files(reference)
    log_path = os.path.join(args.dir, "campaign_reference.log")
    with open(log_path, "w") as log:
        p = subprocess.Popen(command(args, reference), env=environment(), stdout=log,
                             stderr=log)
        start = wait_for_dynamics(log_path, p)
        if p.wait() != 0:
            sys.exit(f"crash_campaign: the reference run failed; see {log_path}")
    duration = time.time() - start
    print(f"reference run: {duration:.1f} s wall in the dynamics", flush=True)
    counts = dict.fromkeys(["not_interrupted", "files", "readable", "restartable", "restarted",
                            "bit_identical", "differs", "hung", "orphaned", "no_checkpoint"], 0)
    modes = ["kill9", "term", "term_rank"]
    for k in range(args.trials):
        # The reference's dynamics time bounds the moment of the signal; a trial that ends
        # before it (a quieter machine) is counted apart, as not interrupted.
        trial(args, k, modes[k % 3], random.uniform(0.05, 0.7) * duration, reference, counts)
    print("campaign: " + ", ".join(f"{key} {value}" for key, value in counts.items()))
    ok = (counts["hung"] == 0 and counts["orphaned"] == 0 and counts["differs"] == 0 and
          counts["readable"] == counts["files"])
    print(f"campaign: {'passed' if ok else 'FAILED'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
