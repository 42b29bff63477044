#!/usr/bin/env python3
"""Pairs the Google Benchmark results of our code with their baselines and prints the ratios.

    bench_ratios.py DIR_OR_JSON... [--csv FILE] [--markdown] [--real-time]

Every entry named BM_<Family>_<Variant>/<args> (in the JSON files that `--benchmark_format=json`
or `--benchmark_out` wrote) is matched with BM_<Family>_Ours/<args>: one row per family, size and
other variant (Baseline first), with ratio = variant time / our time (> 1: ours is faster). CPU
time is used unless --real-time: on a shared machine it is the fairer clock. Notes come from the
counters: a baseline that ran out of budget (found = -1) makes the ratio a lower bound; one that did
not converge, or stalled at a large residual, is flagged. Standard library only.
"""
import argparse
import csv
import json
import os
import re
import sys

from result_files import result_files

UNIT_SECONDS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
NAME = re.compile(r"^BM_([A-Za-z0-9]+)_([A-Za-z0-9]+)((?:/[^/]+)*)$")
SIZE_COUNTERS = ("facets", "creases", "modules", "cells", "actors")


def load(paths):
    """(program, entry) for every benchmark run in the given files or folders of *.json."""
    files = result_files(paths, ".json", "bench_ratios.py")
    runs = []
    for f in files:
        try:
            with open(f) as fh:
                data = json.load(fh)
        except (OSError, ValueError) as e:
            sys.exit("bench_ratios.py: %s: %s" % (f, e))
        program = os.path.splitext(os.path.basename(f))[0]
        entries = data.get("benchmarks", [])
        medians = {e.get("run_name") for e in entries if e.get("aggregate_name") == "median"}
        for e in entries:
            # With repetitions, the median stands for the runs it summarises.
            if e.get("run_type") == "aggregate" and e.get("aggregate_name") != "median":
                continue
            if e.get("run_type") != "aggregate" and e.get("run_name") in medians:
                continue
            if e.get("error_occurred"):
                print("bench_ratios.py: %s: %s skipped: %s" % (program, e["name"], e.get("error_message", "")), file=sys.stderr)
                continue
            runs.append((program, e))
    return runs


def key_of(entry):
    """(family, variant, args) from a benchmark name, without the iterations:/min_time: parts."""
    name = entry.get("run_name", entry["name"])
    parts = [p for p in name.split("/") if ":" not in p and p not in ("real_time", "manual_time")]
    m = NAME.match("/".join(parts))
    if not m:
        return None
    return m.group(1), m.group(2), m.group(3).lstrip("/")


def seconds(entry, real):
    return entry["real_time" if real else "cpu_time"] * UNIT_SECONDS[entry.get("time_unit", "ns")]


def fmt_time(s):
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("us", 1e-6), ("ns", 1e-9)):
        if s >= scale or unit == "ns":
            return "%.3g %s" % (s / scale, unit)


def note(entry):
    notes = []
    if entry.get("found") == -1:
        notes.append("budget exhausted: ratio is a lower bound")
    if entry.get("converged") == 0:
        notes.append("did not converge")
    if "residual" in entry and entry["residual"] > 1e-6:
        notes.append("stalled at residual %.2g" % entry["residual"])
    if entry.get("sign_flips", 0) > 0:
        notes.append("%d creases flipped side" % entry["sign_flips"])
    return "; ".join(notes)


def size_of(args, entry):
    for c in SIZE_COUNTERS:
        if c in entry:
            return "%s (%d %s)" % (args, round(entry[c]), c)
    return args


def pair(runs, real):
    by_key = {}
    for program, e in runs:
        k = key_of(e)
        if k:
            by_key[k] = (program, e)
    rows, unpaired = [], []
    for (family, variant, args), (program, e) in sorted(by_key.items()):
        if variant == "Ours":
            continue
        ours = by_key.get((family, "Ours", args))
        if not ours:
            unpaired.append("BM_%s_%s/%s" % (family, variant, args))
            continue
        t_ours, t_other = seconds(ours[1], real), seconds(e, real)
        rows.append({
            "program": program, "family": family, "size": size_of(args, ours[1]), "args": args,
            "variant": variant, "ours_s": t_ours, "other_s": t_other,
            "ratio": t_other / t_ours if t_ours > 0 else float("inf"), "note": note(e),
        })

    def order(r):
        try:
            a = int(r["args"].split("/")[0])
        except ValueError:
            a = 0
        return (r["family"], r["variant"] != "Baseline", r["variant"], a < 0, abs(a))

    rows.sort(key=order)
    return rows, unpaired


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("inputs", nargs="+", help="JSON files or folders holding them")
    ap.add_argument("--csv", help="also write the table here")
    ap.add_argument("--markdown", action="store_true", help="print a Markdown table")
    ap.add_argument("--real-time", action="store_true", help="use wall-clock instead of CPU time")
    a = ap.parse_args()
    rows, unpaired = pair(load(a.inputs), a.real_time)
    if not rows:
        sys.exit("bench_ratios.py: no BM_<Family>_Ours entry has a partner with the same arguments")
    head = ("family", "size", "vs", "ours", "baseline", "ratio", "note")
    table = [(r["family"], r["size"], r["variant"], fmt_time(r["ours_s"]), fmt_time(r["other_s"]),
              "%.3gx" % r["ratio"], r["note"]) for r in rows]
    if a.markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + "|".join("---" if i in (0, 1, 2, 6) else "---:" for i in range(len(head))) + "|")
        for t in table:
            print("| " + " | ".join(t) + " |")
    else:
        widths = [max(len(str(x)) for x in col) for col in zip(head, *table)]
        for t in [head] + table:
            print("  ".join(str(x).ljust(w) for x, w in zip(t, widths)).rstrip())
    print("(%s time; ratio = other / ours, > 1 means ours is faster)" % ("wall-clock" if a.real_time else "CPU"), file=sys.stderr)
    for u in unpaired:
        print("bench_ratios.py: %s has no BM_..._Ours partner" % u, file=sys.stderr)
    if a.csv:
        tmp = a.csv + ".tmp"
        with open(tmp, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["program", "family", "args", "size", "variant", "ours_s", "other_s", "ratio", "note"])
            for r in rows:
                w.writerow([r["program"], r["family"], r["args"], r["size"], r["variant"],
                            "%.6g" % r["ours_s"], "%.6g" % r["other_s"], "%.6g" % r["ratio"], r["note"]])
        os.replace(tmp, a.csv)


if __name__ == "__main__":
    main()
