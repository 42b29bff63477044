#!/usr/bin/env python3
"""Error reached against the time allowed, one SVG per scene, from the CSV of
`foldkit bench SUITE --error-vs-time T1,T2,... -o DIR` (DIR/error_vs_time.csv).

usage: python3 scripts/plot_bench.py DIR/error_vs_time.csv [-o PLOTDIR] [--format svg|png]

Each figure has three panels over the time limit (log scale): the share of runs that reached the
goal exactly, the distance to the goal of the best solution (largest joint-angle difference,
radians; a run without any solution counts the start's distance) and the largest closure error
along that solution (radians). Lines are medians over the runs, shaded bands span min to max.
Zero cannot be drawn on a log scale: values below FLOOR are drawn at FLOOR (dotted line).
"""
import argparse
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

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
    fig.savefig(path)
    plt.close(fig)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv", help="error_vs_time.csv written by foldkit bench --error-vs-time")
    parser.add_argument("-o", "--output", help="folder for the SVGs (default: beside the CSV)")
    parser.add_argument("--format", choices=["svg", "png"], default="svg", help="image format (default svg)")
    args = parser.parse_args()
    if not os.path.isfile(args.csv):
        parser.error(f"{args.csv}: no such file")
    rows = read(args.csv)
    if not rows:
        sys.exit(f"{args.csv}: no runs")
    out_dir = args.output or os.path.dirname(os.path.abspath(args.csv))
    os.makedirs(out_dir, exist_ok=True)
    for scene in sorted(rows):
        print(plot_scene(scene, rows[scene], out_dir, args.format), file=sys.stderr)


if __name__ == "__main__":
    main()
