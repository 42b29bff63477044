#!/usr/bin/env python3
"""Repeated queries on one pattern with and without experience (issue 38, item 4).

Draws goals on the Resch tessellation the bench uses (bench/data/robbykraft_resch-tess.fold) as
the `resch` scene does: the assignment's signs, each crease scaled by its own draw from
[0.2, 0.6] rad, projected onto the closure manifold keeping signs. Then, for each goal in turn,
plans from flat twice through the CLI: cold (`foldkit plan`, RRTConnect) and with
`--experience DB`, the database growing over the queries. Prints one line per query and the
medians of the first and the second half (docs/PLANNING.md, "Planning from experience").

Usage: PYTHONPATH=build/python python3 scripts/experience-queries.py build/apps/foldkit OUTDIR [--goals 40] [--time 10]
"""
import argparse
import json
import os
import random
import statistics
import subprocess

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
    r = subprocess.run([cli, "plan", pmml, "--goal", goal, "-o", out, "--seed", str(seed), "--time", str(seconds), "--json"] + extra,
                       capture_output=True, text=True, check=False)
    return r.returncode, json.loads(r.stdout) if r.stdout.strip() else {}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cli")
    ap.add_argument("out")
    ap.add_argument("--goals", type=int, default=40)
    ap.add_argument("--time", type=float, default=10.0)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    pmml, db = os.path.join(a.out, "resch.pmml"), os.path.join(a.out, "resch.db")
    foldkit.write_pmml(pmml, foldkit.load_pattern(os.path.join(REPO, "bench/data/robbykraft_resch-tess.fold")))
    pattern = foldkit.read_pmml(pmml)
    if os.path.exists(db):
        os.remove(db)
    rows = []
    for i, g in enumerate(goals_for(pattern, a.goals, a.seed)):
        goal = os.path.join(a.out, f"goal{i}.cmml")
        foldkit.write_cmml(goal, foldkit.sequence_to(pattern, g, 1.0))
        plan_out = os.path.join(a.out, "plan.cmml")
        rc_cold, cold = plan(a.cli, pmml, goal, plan_out, i + 1, a.time, [])
        rc_exp, exp = plan(a.cli, pmml, goal, plan_out, i + 1, a.time, ["--experience", db])
        e = exp.get("experience", {})
        rows.append((rc_cold, cold.get("seconds"), rc_exp, exp.get("seconds"), bool(e.get("recalled"))))
        print(f"query {i}: cold exit {rc_cold} {cold.get('seconds')} s; experience exit {rc_exp} {exp.get('seconds')} s, "
              f"recalled {e.get('recalled')}, recall {e.get('recall_seconds')} s, {e.get('paths')} paths, {e.get('bytes')} bytes",
              flush=True)
    half = len(rows) // 2
    for name, part in (("first half", rows[:half]), ("second half", rows[half:])):
        cold = [r[1] for r in part if r[0] == 0]
        exp = [r[3] for r in part if r[2] == 0]
        print(f"{name}: cold solved {len(cold)}/{len(part)}, median {statistics.median(cold) if cold else float('nan'):.4f} s; "
              f"experience solved {len(exp)}/{len(part)}, median {statistics.median(exp) if exp else float('nan'):.4f} s, "
              f"recalled {sum(r[4] for r in part)}")
    print(f"database: {os.path.getsize(db)} bytes")


if __name__ == "__main__":
    main()
