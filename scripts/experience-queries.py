#!/usr/bin/env python3
"""Repeated queries on one pattern with and without experience (issue 38, item 4).

Draws goals on the Resch tessellation the bench uses (bench/data/robbykraft_resch-tess.fold) as
the `resch` scene does: the assignment's signs, each crease scaled by its own draw from
[0.2, 0.6] rad, projected onto the closure manifold keeping signs. Then, for each goal in turn,
plans from flat through the CLI: cold (`foldkit plan`, RRTConnect) and, for each framework of
--frameworks, with `--experience DB --experience-framework F` (one database per framework,
growing over the queries). Prints one line per query; then per half (the first and the second
--goals/2) the solved count and median time of each, the recalls, the median load time and wall
time of the whole `foldkit plan` process, and each database's final size, states and load time
(docs/PLANNING.md, "Planning from experience"), with the load average before and after.

--baseline CLI plans each framework's queries a second time with another foldkit build, on its own
database, in the same run (query by query, interleaved): before/after figures under the same load.

Usage: PYTHONPATH=build/python python3 scripts/experience-queries.py build/apps/foldkit OUTDIR
           [--goals 40] [--time 10] [--frameworks lightning,thunder] [--baseline OLD/foldkit]
"""
import argparse
import json
import os
import random
import statistics
import subprocess
import time

import numpy as np

import foldkit

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def goals_for(pattern, count, seed):
    sign = np.array([1.0 if a == "M" else -1.0 for a in pattern.assignments])
    rng = random.Random(seed)
    goals = []
    while len(goals) < count:
        guess = sign * np.array([rng.uniform(0.2, 0.6) for _ in sign])
        r = foldkit.project(pattern, guess)
        if r.status.ok and not np.any(r.state * sign < -1e-9):
            goals.append(r.state)
    return goals


def plan(cli, pmml, goal, out, seed, seconds, extra):
    """The exit status, the JSON, and the process's wall time (load, plan, replay, write)."""
    t0 = time.monotonic()
    r = subprocess.run([cli, "plan", pmml, "--goal", goal, "-o", out, "--seed", str(seed), "--time", str(seconds), "--json"] + extra,
                       capture_output=True, text=True, check=False)
    return r.returncode, json.loads(r.stdout) if r.stdout.strip() else {}, time.monotonic() - t0


def median(values):
    return statistics.median(values) if values else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cli")
    ap.add_argument("out")
    ap.add_argument("--goals", type=int, default=40)
    ap.add_argument("--time", type=float, default=10.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--frameworks", default="lightning", help="comma-separated: lightning, thunder")
    ap.add_argument("--baseline", help="another foldkit CLI to run each framework with too (its rows: FRAMEWORK@baseline)")
    a = ap.parse_args()
    for f in a.frameworks.split(","):
        if f not in ("lightning", "thunder"):
            ap.error(f"--frameworks: unknown framework '{f}' (known: lightning, thunder)")
    # Per column: (label, cli, framework); the baseline's columns follow each framework's own.
    columns = []
    for f in a.frameworks.split(","):
        columns.append((f, a.cli, f))
        if a.baseline:
            columns.append((f + "@baseline", a.baseline, f))
    print(f"load average before: {os.getloadavg()}", flush=True)
    os.makedirs(a.out, exist_ok=True)
    pmml = os.path.join(a.out, "resch.pmml")
    foldkit.write_pmml(pmml, foldkit.load_pattern(os.path.join(REPO, "bench/data/robbykraft_resch-tess.fold")))
    pattern = foldkit.read_pmml(pmml)
    dbs = {label: os.path.join(a.out, f"resch.{label}.db") for label, _, _ in columns}
    for db in dbs.values():
        if os.path.exists(db):
            os.remove(db)
    rows = []  # per query: {"cold": (rc, seconds), framework: (rc, seconds, experience dict)}
    for i, g in enumerate(goals_for(pattern, a.goals, a.seed)):
        goal = os.path.join(a.out, f"goal{i}.cmml")
        foldkit.write_cmml(goal, foldkit.sequence_to(pattern, g, 1.0))
        plan_out = os.path.join(a.out, "plan.cmml")
        rc, cold, wall = plan(a.cli, pmml, goal, plan_out, i + 1, a.time, [])
        row = {"cold": (rc, cold.get("seconds"), {}, wall)}
        line = f"query {i}: cold exit {rc} {cold.get('seconds')} s (wall {wall:.3f} s)"
        for label, cli, f in columns:
            rc, exp, wall = plan(cli, pmml, goal, plan_out, i + 1, a.time, ["--experience", dbs[label], "--experience-framework", f])
            e = exp.get("experience", {})
            row[label] = (rc, exp.get("seconds"), e, wall)
            line += (f"; {label} exit {rc} {exp.get('seconds')} s (wall {wall:.3f} s), recalled {e.get('recalled')}, "
                     f"recall {e.get('recall_seconds')} s, load {e.get('load_seconds')} s, {e.get('paths')} paths, "
                     f"{e.get('states')} states, {e.get('bytes')} bytes")
        rows.append(row)
        print(line, flush=True)
    half = len(rows) // 2
    for name, part in (("first half", rows[:half]), ("second half", rows[half:])):
        for key in ["cold"] + [label for label, _, _ in columns]:
            times = [r[key][1] for r in part if r[key][0] == 0]
            recalled = sum(bool(r[key][2].get("recalled")) for r in part)
            loads = [r[key][2]["load_seconds"] for r in part if "load_seconds" in r[key][2]]
            walls = [r[key][3] for r in part]
            print(f"{name}: {key} solved {len(times)}/{len(part)}, median {median(times):.4f} s, process wall median {median(walls):.3f} s"
                  + ("" if key == "cold" else f", recalled {recalled}, load median {median(loads):.5f} s (max {max(loads, default=float('nan')):.5f} s)"))
    for label, _, _ in columns:
        last = rows[-1][label][2] if rows else {}
        print(f"database {label}: {os.path.getsize(dbs[label]) if os.path.exists(dbs[label]) else 0} bytes, {last.get('paths')} paths, "
              f"{last.get('states')} states; the last query loaded it ({last.get('loaded')} paths) in {last.get('load_seconds')} s")
    print(f"load average after: {os.getloadavg()}")


if __name__ == "__main__":
    main()
