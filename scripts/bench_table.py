#!/usr/bin/env python3
"""One Markdown table from the OMPL benchmark logs of `foldkit bench`: per scene and planner entry,
the runs, the exact solutions, the median and slowest planner time of the exact ones, the replays
that the simulator accepted, the largest closure error along a returned path, and the ratio of the
median time to that of a reference entry of the same scene.

    bench_table.py DIR_OR_LOG... [--reference ENTRY] [--csv FILE]
    bench_table.py DIR/error_vs_time.csv


Several folders (one per seed, say) are pooled: a scene's runs are summed over them. An exact
solution is a run whose `status ENUM` is OMPL's EXACT_SOLUTION; a run stopped by the time limit,
or with only an approximate path, is not. The ratio column (ENTRY's median / this median; > 1:
this entry is faster) needs --reference, e.g. RRTConnect@driving; it is empty where either has no
exact run. Given the CSV of `foldkit bench … --error-vs-time`, it prints per scene, entry and
time limit the exact solutions, the median distance to the goal reached (radians) and the largest
closure error along an exact path. Standard library only.
"""
import argparse
import csv
import statistics
import sys
from collections import defaultdict

from result_files import result_files

EXACT = "6"  # ompl::base::PlannerStatus::EXACT_SOLUTION in a log's "status ENUM" column


def log_files(paths):
    return result_files(paths, ".log", "bench_table.py")


def parse(path):
    """(scene, {entry: [run dict]}) of one OMPL log."""
    with open(path) as f:
        lines = [line.rstrip("\n") for line in f]
    scene = next((line.split(" ", 1)[1] for line in lines if line.startswith("Experiment ")), path)
    planners = {}
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("geometric_"):
            name = line[len("geometric_"):]
            i += 1
            common = int(lines[i].split()[0])
            i += 1 + common
            count = int(lines[i].split()[0])
            props = [" ".join(p.split()[:-1]) for p in lines[i + 1:i + 1 + count]]
            i += 1 + count
            runs = int(lines[i].split()[0])
            rows = []
            for raw in lines[i + 1:i + 1 + runs]:
                values = [v.strip() for v in raw.split(";")]
                rows.append(dict(zip(props, values)))
            planners[name] = rows
            i += 1 + runs
        else:
            i += 1
    return scene, planners


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def summarise(files):
    pooled = defaultdict(lambda: defaultdict(list))
    for f in files:
        scene, planners = parse(f)
        for name, rows in planners.items():
            pooled[scene][name] += rows
    table = []
    for scene, planners in pooled.items():
        for name, rows in planners.items():
            exact = [r for r in rows if r.get("status") == EXACT]
            times = sorted(t for t in (number(r.get("time")) for r in exact) if t is not None)
            errors = [e for e in (number(r.get("max closure error")) for r in exact) if e is not None]
            table.append({
                "scene": scene,
                "entry": name,
                "runs": len(rows),
                "exact": len(exact),
                "median_s": statistics.median(times) if times else None,
                "slowest_s": times[-1] if times else None,
                "replay_valid": sum(r.get("replay valid") == "1" for r in exact),
                "max_closure_error": max(errors) if errors else None,
            })
    return table


def add_ratios(table, reference):
    medians = {(r["scene"], r["entry"]): r["median_s"] for r in table}
    for r in table:
        ref = medians.get((r["scene"], reference))
        r["ratio"] = ref / r["median_s"] if ref and r["median_s"] else None


def fmt(v, spec):
    return "–" if v is None else format(v, spec)


def error_vs_time(path):
    """Rows (scene, entry, limit, exact, runs, median goal distance, largest path closure error)
    of an error_vs_time.csv (`foldkit bench … --error-vs-time`)."""
    groups = defaultdict(list)
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            groups[(row["scene"], row["planner"], float(row["time_limit_s"]))].append(row)
    out = []
    for (scene, entry, limit), rows in groups.items():
        errors = [number(r["max_closure_error_rad"]) for r in rows if r["solution"] == "exact"]
        errors = [e for e in errors if e is not None and e == e]
        out.append([scene, entry, limit, sum(r["solution"] == "exact" for r in rows), len(rows),
                    statistics.median(number(r["goal_distance_rad"]) for r in rows), max(errors) if errors else None])
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("paths", nargs="+")
    ap.add_argument("--reference", help="the entry the ratio column compares with (e.g. RRTConnect@driving)")
    ap.add_argument("--csv", help="also write the table as CSV")
    a = ap.parse_args()
    if len(a.paths) == 1 and a.paths[0].endswith(".csv"):
        print("| scene | entry | time limit (s) | exact | median goal distance (rad) | max closure error (rad) |")
        print("|---|---|---|---|---|---|")
        for scene, entry, limit, exact, runs, distance, error in error_vs_time(a.paths[0]):
            print(f"| {scene} | {entry} | {limit:g} | {exact}/{runs} | {distance:.3g} | {fmt(error, '.2g')} |")
        return
    table = summarise(log_files(a.paths))
    add_ratios(table, a.reference)
    header = ["scene", "entry", "runs", "exact", "median (s)", "slowest (s)", "replay valid", "max closure error (rad)"]
    if a.reference:
        header.append("ratio " + a.reference + " / entry")
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for r in table:
        cells = [r["scene"], r["entry"], str(r["runs"]), str(r["exact"]), fmt(r["median_s"], ".4g"), fmt(r["slowest_s"], ".4g"),
                 str(r["replay_valid"]), fmt(r["max_closure_error"], ".2g")]
        if a.reference:
            cells.append(fmt(r["ratio"], ".3g"))
        print("| " + " | ".join(cells) + " |")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(table[0].keys()) if table else ["scene"])
            w.writeheader()
            w.writerows(table)


if __name__ == "__main__":
    main()
