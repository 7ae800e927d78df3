#!/usr/bin/python3
"""A performance model of Catena's HHT step on a line, fitted to a scaling study, projected.

Reads one or more scaling.csv files of scaling/scaling_study.py (rows at 1 rank and at
more; of repeated studies the run of median step time per rank count is used; rank counts beyond the machine's cores are used for their counts — interface rows,
messages, bytes, reductions — not their times) and projects the step's parallel
efficiency to larger rank counts, strong (the study's fixed line) and weak (the study's
line per rank). The model, per time step on the busiest rank of P:

  T(P) = T_split / P  +  T_load · L(P)  +  T_comm(P)  +  T_interface(P)  +  T_wait(P)

  T_split       the work that divides among ranks: the one-rank step minus the loads' part
  T_load        the work per moving load that stays on the rank holding it (HHT's local
                Newton window around the load, a fixed number of unknowns per load)
  L(P)          loads on the busiest rank: ceil(loads / P) while loads >= P, else 1
  T_comm(P)     messages · α + bytes / β + reductions · α · ceil(log2 P)
                (per step and rank, as measured at P > 1; a line's partition has at most
                two neighbours per rank, so these counts do not grow with P)
  T_interface   what grows with P in the interface Schur solve, per step:
                solves · (α · ceil(log2 P) + 2 · 8 n_Γ / β + 4 n_Γ w / F)       allreduce + S solve
                + factorisations · (8 · 3 n_terms(P) / β + 2 n_Γ w² / F)          gather + S's LU
                n_Γ = g (P − 1) + h interface rows (g per cut and h hub rows, fitted),
                w = 2 g the band of S, n_terms = P · (2 g)² the gathered terms.
  T_wait(P)     what the terms above leave unexplained at P = 2, measured (ranks waiting
                for each other at the step's synchronisation points: imbalance and the
                machine's jitter), grown as the largest of P random delays, √log2 P, and in
                the strong study in proportion to the work per rank (2/P).

Times measured on more ranks than the machine has cores (--cores, default: this machine's)
are not used: those runs are oversubscribed and give their counts only.

The machine's share of memory bandwidth and caches (what P independent copies of a one-rank
run keep: the study's --baseline) multiplies the efficiency and is reported apart; it is a
property of the node, not of Catena. Network parameters are assumptions (command line):
α latency per message (default 2 µs), β bandwidth (default 10 GB/s), F the rate of the
small sparse factorisations (default 1 GFlop/s).

  /usr/bin/python3 scaling/performance_model.py STUDY_DIR/scaling.csv [MORE.csv ...]
      [--ranks 1,2,4,...,1024] [--latency 2e-6] [--bandwidth 1e10] [--flop-rate 1e9]
      [--cores N]
"""
import argparse
import csv
import math
import os
import sys


def rows_of(paths):
    rows = []
    for path in paths:
        try:
            with open(path) as f:
                rows += [dict(r, source=path) for r in csv.DictReader(f)]
        except OSError as e:
            sys.exit(f"performance_model: {path}: {e.strerror}")
    if not rows:
        sys.exit("performance_model: the studies have no rows")
    need = ("study", "ranks", "loads", "step_s", "local_newton_s", "interface_rows",
            "messages_per_step", "bytes_per_step", "reductions_per_step",
            "factorisations_per_step", "newton_per_step")
    missing = [c for c in need if c not in rows[0]]
    if missing:
        sys.exit(f"performance_model: {rows[0]['source']}: no column {', '.join(missing)} "
                 "(a scaling.csv of scaling/scaling_study.py is expected)")
    return rows


def median_rows(rows):
    """Per rank count, the row of the median step time (several studies: repeated runs)."""
    by_ranks = {}
    for r in rows:
        by_ranks.setdefault(int(r["ranks"]), []).append(r)
    out = []
    for ranks in sorted(by_ranks):
        runs = sorted(by_ranks[ranks], key=lambda r: float(r["step_s"]))
        out.append(runs[(len(runs) - 1) // 2])
    return out


def fit(rows, study, cores):
    """The model's inputs from one study's rows (the median run of each rank count)."""
    mine = median_rows([r for r in rows if r["study"] == study])
    one = [r for r in mine if int(r["ranks"]) == 1]
    more = [r for r in mine if int(r["ranks"]) > 1]
    if not one or not more:
        sys.exit(f"performance_model: the {study} study needs a row at 1 rank and one at more "
                 f"(have ranks {[int(r['ranks']) for r in mine]})")
    r1 = one[0]
    loads = int(r1["loads"])
    t_load = float(r1["local_newton_s"]) / max(loads, 1)
    # Interface rows: n_Γ = g (P − 1) + h, least squares over the rank counts run.
    xs = [int(r["ranks"]) - 1 for r in more]
    ys = [int(r["interface_rows"]) for r in more]
    if len(xs) >= 2:
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        sxx = sum((x - mx) ** 2 for x in xs)
        g = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else my / mx
        h = my - g * mx
    else:
        g, h = ys[0] / xs[0], 0.0
    # Communication counts per step and rank: the largest seen (they should not grow).
    return {
        "study": study, "loads": loads, "length": float(r1["length_m"]),
        "t_step_1": float(r1["step_s"]), "t_load": t_load,
        "t_split": float(r1["step_s"]) - loads * t_load,
        "g": g, "h": max(h, 0.0),
        "messages": max(float(r["messages_per_step"]) for r in more),
        "bytes": max(float(r["bytes_per_step"]) for r in more),
        "reductions": max(float(r["reductions_per_step"]) for r in more),
        "solves": float(r1["newton_per_step"]),
        "factorisations": float(r1["factorisations_per_step"]),
        "measured": {int(r["ranks"]): float(r["step_s"]) for r in mine
                     if int(r["ranks"]) <= cores},
        "machine": {int(r["ranks"]): float(r["machine_step_efficiency"]) for r in more
                    if r.get("machine_step_efficiency") and int(r["ranks"]) <= cores},
    }


def step_time(m, p, args):
    """Modelled step time on P ranks (weak: each rank as much line as the one-rank case)."""
    weak = m["study"] == "weak"
    loads = m["loads"] * (p if weak else 1)
    busiest = math.ceil(loads / p) if loads >= p else 1
    t_split = m["t_split"] if weak else m["t_split"] / p
    levels = math.ceil(math.log2(p)) if p > 1 else 0
    alpha, beta, flops = args.latency, args.bandwidth, args.flop_rate
    if p == 1:
        return t_split + busiest * m["t_load"], 0.0, 0.0, 0.0
    comm = m["messages"] * alpha + m["bytes"] / beta + m["reductions"] * alpha * levels
    n_g = m["g"] * (p - 1) + m["h"]
    w = 2.0 * m["g"]
    n_terms = p * w * w
    interface = (m["solves"] * (alpha * levels + 16.0 * n_g / beta + 4.0 * n_g * w / flops) +
                 m["factorisations"] * (24.0 * n_terms / beta + 2.0 * n_g * w * w / flops))
    wait = m.get("wait", 0.0) * math.sqrt(math.log2(p)) * (1.0 if weak else 2.0 / p)
    return t_split + busiest * m["t_load"] + comm + interface + wait, comm, interface, wait


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("csv", nargs="+")
    p.add_argument("--ranks", default="1,2,4,8,16,64,256,1024")
    p.add_argument("--latency", type=float, default=2e-6)
    p.add_argument("--bandwidth", type=float, default=1e10)
    p.add_argument("--flop-rate", type=float, default=1e9)
    p.add_argument("--cores", type=int, default=os.cpu_count() or 1)
    args = p.parse_args(argv)
    try:
        ranks = [int(x) for x in args.ranks.split(",")]
    except ValueError:
        p.error(f"--ranks {args.ranks!r}: expected rank counts separated by commas")
    rows = rows_of(args.csv)
    print(f"assumed: latency {args.latency * 1e6:g} us per message, bandwidth "
          f"{args.bandwidth / 1e9:g} GB/s, sparse factorisation rate {args.flop_rate / 1e9:g} "
          "GFlop/s; the node's memory-bandwidth share not included (see machine)")
    for study in ("strong", "weak"):
        if not any(r["study"] == study for r in rows):
            continue
        m = fit(rows, study, args.cores)
        m["wait"] = 0.0
        if 2 in m["measured"]:
            m["wait"] = max(0.0, m["measured"][2] - step_time(m, 2, args)[0])
        what = (f"{m['length'] / 1000:g} km line, {m['loads']} loads" if study == "strong" else
                f"{m['length'] / 1000:g} km and {m['loads']} loads per rank")
        print(f"\n{study} scaling ({what}): one-rank step {1e3 * m['t_step_1']:.2f} ms, of which "
              f"{1e3 * m['t_load']:.2f} ms per load stays with its rank; interface rows "
              f"{m['g']:.1f} per cut + {m['h']:.1f}; per step and rank {m['messages']:.1f} "
              f"messages, {m['bytes']:.0f} bytes, {m['reductions']:.1f} reductions")
        print(f"  waiting at P = 2 (measured less modelled): {1e3 * m['wait']:.2f} ms per step")
        print(f"{'ranks':>6} {'step ms':>9} {'comm ms':>8} {'iface ms':>8} {'wait ms':>8} "
              f"{'efficiency':>10} {'measured':>9} {'machine':>8}")
        t1 = step_time(m, 1, args)[0]
        for P in ranks:
            t, comm, interface, wait = step_time(m, P, args)
            eff = t1 / t if study == "weak" else t1 / (P * t)
            measured = m["measured"].get(P)
            measured_text = ""
            if measured is not None:
                e = (m["measured"][1] / measured if study == "weak"
                     else m["measured"][1] / (P * measured))
                measured_text = f"{e:9.2f}"
            machine = m["machine"].get(P)
            print(f"{P:6d} {1e3 * t:9.3f} {1e3 * comm:8.3f} {1e3 * interface:8.3f} "
                  f"{1e3 * wait:8.3f} {eff:10.2f} "
                  f"{measured_text:>9} {'' if machine is None else f'{machine:8.2f}':>8}")


if __name__ == "__main__":
    main(sys.argv[1:])
