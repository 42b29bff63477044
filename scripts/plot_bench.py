#!/usr/bin/env python3
"""Plots of `foldkit bench` results, one figure per scene.

usage: python3 scripts/plot_bench.py DIR/error_vs_time.csv [-o PLOTDIR] [--format svg|png]
       python3 scripts/plot_bench.py DIR [DIR/SCENE.log ...] [-o PLOTDIR] [--format svg|png] [--summary]

Error against the time allowed, from the CSV of `foldkit bench SUITE --error-vs-time T1,T2,... -o DIR`:
three panels over the time limit (log scale): the share of runs that reached the goal exactly, the
distance to the goal of the best solution (largest joint-angle difference, radians; a run without
any solution counts the start's distance) and the largest closure error along that solution
(radians). Lines are medians over the runs, shaded bands span min to max. Zero cannot be drawn on
a log scale: values below FLOOR are drawn at FLOOR (dotted line).

Cost against time, from OMPL benchmark logs (`foldkit bench optimal -o DIR`; a folder stands for
its *.log files): SCENE.cost.svg with two panels over the run time: the best cost so far (the
log's objective, as the planner counts it), median over the runs with the interquartile band,
and the share of runs that have a path. A run's best cost over time is its "best cost" progress
samples (every 0.05 s) closed by its "solution cost" at its "time"; a planner that reports no
best cost while it runs (FMT) has that one point. A run without a path by time t counts as an
infinite cost there, so the median is drawn only where at least half of the runs have a path.
--summary prints, per scene and planner, the runs solved, the median time to the first path and
the median final cost.
"""
import argparse
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "foldkit"  # the same figure, byte for byte, from the same logs
matplotlib.rcParams["svg.fonttype"] = "none"  # text stays text: small files
import matplotlib.pyplot as plt  # noqa: E402

from bench_cost import plot_costs  # noqa: E402  (the cost-against-time figures, beside this script)

FLOOR = 1e-16


def read(path):
    rows = defaultdict(lambda: defaultdict(lambda: defaultdict(list)))
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        need = {"scene", "planner", "time_limit_s", "solution", "goal_distance_rad", "max_closure_error_rad"}
        missing = need - set(reader.fieldnames or [])
        if missing:
            sys.exit(f"{path}:1: missing columns {', '.join(sorted(missing))} (not a foldkit error-vs-time CSV?)")
        for line, r in enumerate(reader, start=2):
            try:
                limit = float(r["time_limit_s"])
            except ValueError:
                sys.exit(f"{path}:{line}: time_limit_s '{r['time_limit_s']}' is not a number")
            rows[r["scene"]][r["planner"]][limit].append(r)
    return rows


def number(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return None if math.isnan(v) else v


def median(values):
    v = sorted(values)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def series(by_limit, column):
    xs, mid, lo, hi = [], [], [], []
    for limit in sorted(by_limit):
        values = [number(r[column]) for r in by_limit[limit]]
        values = [max(v, FLOOR) for v in values if v is not None]
        if not values:
            continue
        xs.append(limit)
        mid.append(median(values))
        lo.append(min(values))
        hi.append(max(values))
    return xs, mid, lo, hi


def plot_scene(scene, planners, out_dir, fmt="svg"):
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6), constrained_layout=True)
    success, distance, closure = axes
    markers = "osD^v<>px*h"
    for i, planner in enumerate(sorted(planners)):
        by_limit = planners[planner]
        style = dict(marker=markers[i % len(markers)], label=planner)
        limits = sorted(by_limit)
        share = [100.0 * sum(r["solution"] == "exact" for r in by_limit[t]) / len(by_limit[t]) for t in limits]
        (line,) = success.plot(limits, share, **style)
        for ax, column in ((distance, "goal_distance_rad"), (closure, "max_closure_error_rad")):
            xs, mid, lo, hi = series(by_limit, column)
            if xs:
                ax.plot(xs, mid, color=line.get_color(), **style)
                ax.fill_between(xs, lo, hi, color=line.get_color(), alpha=0.15, linewidth=0)
    success.set_ylabel("runs that reached the goal (%)")
    success.set_ylim(-5, 105)
    distance.set_ylabel("distance to goal of best solution (rad, max over creases)")
    closure.set_ylabel("largest closure error along the solution (rad)")
    for ax in axes:
        ax.set_xscale("log")
        ax.set_xlabel("time allowed per run (s)")
        ax.grid(True, which="both", alpha=0.3)
    for ax in (distance, closure):
        ax.set_yscale("log")
        ax.axhline(FLOOR, color="grey", linestyle=":", linewidth=1)
        ax.annotate(f"0 is drawn at {FLOOR:g}", xy=(0.02, 0.02), xycoords="axes fraction", fontsize=8, color="grey")
    success.legend(title="planner", fontsize=9, loc="best")
    runs = max(len(v) for p in planners.values() for v in p.values())
    fig.suptitle(f"{scene}: error reached against the time allowed (median of {runs} run(s), band = min to max)")
    path = os.path.join(out_dir, f"{scene}.{fmt}")
    fig.savefig(path, metadata={"Date": None} if fmt == "svg" else None)
    plt.close(fig)
    return path


def plot_error_vs_time(csv_path, out_dir, fmt):
    rows = read(csv_path)
    if not rows:
        sys.exit(f"{csv_path}: no runs")
    out_dir = out_dir or os.path.dirname(os.path.abspath(csv_path))
    os.makedirs(out_dir, exist_ok=True)
    for scene in sorted(rows):
        print(plot_scene(scene, rows[scene], out_dir, fmt), file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("inputs", nargs="+",
                        help="error_vs_time.csv of foldkit bench --error-vs-time, or OMPL logs of foldkit bench (or folders of them)")
    parser.add_argument("-o", "--output", help="folder for the figures (default: beside the first input)")
    parser.add_argument("--format", choices=["svg", "png"], default="svg", help="image format (default svg)")
    parser.add_argument("--summary", action="store_true", help="logs: print runs solved, time to first path and final cost")
    args = parser.parse_args()
    for path in args.inputs:
        if not os.path.exists(path):
            parser.error(f"{path}: no such file or folder")
    if len(args.inputs) == 1 and args.inputs[0].endswith(".csv"):
        plot_error_vs_time(args.inputs[0], args.output, args.format)
        return
    if any(p.endswith(".csv") for p in args.inputs):
        parser.error("give either one error_vs_time.csv or benchmark logs, not both")
    logs = []
    for path in args.inputs:
        logs += sorted(os.path.join(path, f) for f in os.listdir(path) if f.endswith(".log")) if os.path.isdir(path) else [path]
    if not logs:
        parser.error(f"no .log files in {', '.join(args.inputs)}")
    first = args.inputs[0]
    out_dir = args.output or (first if os.path.isdir(first) else os.path.dirname(os.path.abspath(first)))
    os.makedirs(out_dir, exist_ok=True)
    plot_costs(logs, out_dir, args.format, args.summary)


if __name__ == "__main__":
    main()
