#!/usr/bin/env python3
"""Plots columns of a CSV file as lines (one per y column, or per group) into an SVG or PNG.

  plot_csv.py DATA.csv --x COL --y COL[,COL...] [--group COL] [--logx] [--logy]
              [--title T] [--xlabel L] [--ylabel L] [--labels L1,L2...] -o OUT.svg

An x column of names (not numbers) gives grouped bars, one per y column, in file order.
Empty cells are left out of the line they belong to; on a log axis so are values <= 0.
Exit 1 for a file or column that is not there, 2 for usage. The SVG is reproducible: the same
data gives the same bytes (no date, fixed hash salt).
"""
import argparse
import csv
import os
import sys


def fail(message):
    print(f"plot_csv.py: {message}", file=sys.stderr)
    sys.exit(1)


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def main():
    ap = argparse.ArgumentParser(description="Plot CSV columns (matplotlib).")
    ap.add_argument("csv")
    ap.add_argument("--x", required=True, help="column for the x axis")
    ap.add_argument("--y", required=True, help="column(s) for the y axis, comma-separated")
    ap.add_argument("--group", help="one line per value of this column")
    ap.add_argument("--logx", action="store_true")
    ap.add_argument("--logy", action="store_true")
    ap.add_argument("--title", default="")
    ap.add_argument("--xlabel")
    ap.add_argument("--ylabel")
    ap.add_argument("--labels", help="legend labels for the y columns, comma-separated")
    ap.add_argument("-o", "--output", required=True, help="OUT.svg or OUT.png")
    args = ap.parse_args()

    try:
        import matplotlib
    except ImportError:
        fail("matplotlib is missing (Debian: apt-get install python3-matplotlib)")
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "foldkit"
    matplotlib.rcParams["svg.fonttype"] = "none"  # text stays text: small files
    import matplotlib.pyplot as plt

    try:
        with open(args.csv, newline="") as f:
            rows = list(csv.DictReader(f))
            header = rows[0].keys() if rows else []
    except OSError as e:
        fail(f"{args.csv}: cannot read: {e.strerror}")
    if not rows:
        fail(f"{args.csv}: no data rows")
    ys = [c for c in args.y.split(",") if c]
    for col in [args.x] + ys + ([args.group] if args.group else []):
        if col not in header:
            fail(f"{args.csv}: no column '{col}' (columns: {', '.join(header)})")
    labels = args.labels.split(",") if args.labels else ys
    if len(labels) != len(ys):
        fail(f"--labels names {len(labels)} lines, --y {len(ys)}")

    groups = {}
    for r in rows:
        key = r[args.group] if args.group else ""
        groups.setdefault(key, []).append(r)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    lines = 0
    # A column of names for x (a table of cases): grouped bars, one per y column, in file order.
    categories = [r[args.x] for r in rows]
    if not args.group and any(number(c) is None for c in categories):
        width = 0.8 / len(ys)
        for i, (col, label) in enumerate(zip(ys, labels)):
            vals = [number(r[col]) for r in rows]
            xs = [k + (i - (len(ys) - 1) / 2) * width for k, v in enumerate(vals) if v is not None]
            ax.bar(xs, [v for v in vals if v is not None], width=width, label=label)
            lines += 1
        ax.set_xticks(range(len(categories)))
        ax.set_xticklabels(categories, rotation=20, ha="right", fontsize=8)
        groups = {}
    for key, members in groups.items():
        for col, label in zip(ys, labels):
            pts = []
            for r in members:
                x, y = number(r[args.x]), number(r[col])
                if x is None or y is None:
                    continue
                if (args.logx and x <= 0) or (args.logy and y <= 0):
                    continue
                pts.append((x, y))
            if not pts:
                continue
            pts.sort()
            name = f"{key}: {label}" if args.group and len(ys) > 1 else (key if args.group else label)
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o" if len(pts) <= 60 else None,
                    markersize=3, linewidth=1.3, label=name)
            lines += 1
    if lines == 0:
        fail(f"{args.csv}: nothing to plot (every value empty, or not positive on a log axis)")
    if args.logx:
        ax.set_xscale("log")
    if args.logy:
        ax.set_yscale("log")
    ax.set_xlabel(args.xlabel or args.x)
    ax.set_ylabel(args.ylabel or (ys[0] if len(ys) == 1 else ""))
    if args.title:
        ax.set_title(args.title)
    ax.grid(True, which="both", alpha=0.3)
    if lines > 1:
        ax.legend(fontsize=8, ncol=2 if lines > 6 else 1)
    fig.tight_layout()
    # Written beside the target and renamed, so a failure never leaves a partial file.
    fmt = os.path.splitext(args.output)[1].lstrip(".").lower() or "svg"
    tmp = f"{args.output}.tmp{os.getpid()}"
    try:
        fig.savefig(tmp, format=fmt, metadata={"Date": None} if fmt == "svg" else None)
        os.replace(tmp, args.output)
    except (OSError, ValueError) as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        fail(f"{args.output}: cannot write: {getattr(e, 'strerror', None) or e}")


if __name__ == "__main__":
    main()
