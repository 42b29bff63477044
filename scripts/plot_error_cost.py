#!/usr/bin/env python3
"""Draws the error-versus-cost measurements of microbench/measure_error_cost as SVG.

    plot_error_cost.py [CSV_DIR] [--out DIR]

Reads CSV_DIR/error_cost_projection.csv and CSV_DIR/error_cost_stiffness.csv (default: .) and
writes DIR/error_cost_projection.svg and DIR/error_cost_stiffness.svg (default DIR: CSV_DIR).
Needs matplotlib (Debian: python3-matplotlib).
"""
import argparse
import csv
import math
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plot_error_cost.py: matplotlib is missing (Debian: apt-get install python3-matplotlib; "
             "run it with /usr/bin/python3 if another python3 comes first on PATH)")

ZERO = 1e-17  # an error of exactly 0 is drawn here on the log scale

PROJECTION_STYLE = {
    "ours_iteration_limit": dict(label="ours (LM), stopped after k iterations", color="C0", marker="o", ms=3, lw=1.5),
    "ours_tolerance": dict(label="ours, tolerance 1e-2 … 1e-14", color="C0", marker="s", ms=6, lw=0, mfc="none"),
    "ours_tolerance_free_signs": dict(label="ours, keep_signs off, tolerance 1e-2 … 1e-14", color="C2", marker="^", ms=6, lw=0, mfc="none"),
    "gn_svd_step_1": dict(label="generic Gauss–Newton, J⁺ by JacobiSVD, step 1", color="C3", marker=".", lw=1.2),
    "gn_svd_step_0.5": dict(label="generic Gauss–Newton, step ½", color="C1", marker=".", lw=1.2, ls="--"),
    "gn_svd_step_0.25": dict(label="generic Gauss–Newton, step ¼", color="C4", marker=".", lw=1.2, ls=":"),
}

PROBLEM_TITLES = {
    "disturbed": "Miura-ori {n}, closed state + ±0.02 rad",
    "near_flat": "Miura-ori {n}, ±1e-3 rad from flat (singular)",
    "vertex_degree64": "single vertex, degree 64, ±0.5 rad",
    "vertex_degree256": "single vertex, degree 256, ±0.5 rad",
    "vertex_sliver_sectors": "degree 8 with two 1e-3 rad sliver sectors",
}


def read(path):
    try:
        with open(path, newline="") as fh:
            rows = list(csv.DictReader(fh))
    except OSError as e:
        sys.exit("plot_error_cost.py: %s (run measure_error_cost first)" % e)
    for r in rows:
        for k in ("value", "error", "residual", "time_s"):
            r[k] = float(r[k]) if r[k] != "" else math.nan
        for k in ("iterations", "load_steps", "converged"):
            r[k] = int(r[k])
    return rows


def positive(v):
    return v if v > 0 else ZERO


def title_of(problem):
    for key, t in PROBLEM_TITLES.items():
        if problem.endswith(key) or problem == key:
            n = problem.split("_")[0].replace("miura", "")
            return t.format(n=n)
    return problem


def plot_projection(rows, out):
    problems = list(dict.fromkeys(r["problem"] for r in rows))
    cols = 3
    nrows = math.ceil(len(problems) / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(16, 5 * nrows), squeeze=False)
    for ax, problem in zip(axes.flat, problems):
        mine = [r for r in rows if r["problem"] == problem]
        start = next((r["error"] for r in mine if r["method"] == "start"), None)
        for method, style in PROJECTION_STYLE.items():
            # In the order measured: k = 1, 2, … (lines); tolerances are markers only.
            pts = [(r["time_s"], positive(r["error"])) for r in mine if r["method"] == method and r["time_s"] > 0]
            if pts:
                ax.plot(*zip(*pts), **style)
        if start:
            ax.axhline(start, color="grey", ls="--", lw=0.8)
            ax.annotate("start error", (0.02, start), xycoords=("axes fraction", "data"), va="bottom", color="grey", fontsize=8)
        ax.axhline(1e-10, color="k", ls=":", lw=0.8)
        ax.annotate("default tolerance 1e-10", (0.02, 1e-10), xycoords=("axes fraction", "data"), va="bottom", fontsize=8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(ZERO / 2, max(10.0, (start or 1) * 3))
        ax.set_xlabel("CPU time per projection (s)")
        ax.set_ylabel("largest loop error (rad)")
        ax.set_title(title_of(problem), fontsize=10)
        ax.grid(True, which="major", alpha=0.3)
    for ax in list(axes.flat)[len(problems):]:
        ax.axis("off")
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=9, frameon=False)
    fig.suptitle("Closure projection: error reached versus cost (errors of 0 drawn at 1e-17)", fontsize=12)
    fig.tight_layout(rect=(0, 0.07, 1, 0.96))
    path = os.path.join(out, "error_cost_projection.svg")
    fig.savefig(path)
    plt.close(fig)
    return path


def series(rows, problem, method, x, y="error"):
    pts = [(r[x], r) for r in rows if r["problem"] == problem and r["method"] == method]
    return [(px, positive(r[y]) if not math.isnan(r[y]) else math.nan, r) for px, r in pts]


def label_extremes(ax, pts):
    """Names the loosest and the tightest tolerance of a sweep beside their points."""
    if pts:
        for (x, e, r), dy in ((pts[0], 6), (pts[-1], -12)):
            ax.annotate("tol %.0e" % r["value"], (x, e), fontsize=7, textcoords="offset points", xytext=(4, dy))


def plot_stiffness(rows, out):
    fig, axes = plt.subplots(2, 3, figsize=(16, 10))
    newton = dict(color="C0", marker="o", lw=1.5, label="Newton (nonlinear)")
    linear = dict(color="C3", marker="s", lw=1.5, ls="--", label="linear (one solve)")

    def failures(ax, pts, style):
        bad = [(x, 1.0) for x, _, r in pts if not r["converged"] or r["error"] == 1.0]
        if bad:
            ax.plot(*zip(*bad), lw=0, marker="x", ms=10, color=style["color"], label=style["label"].split(" ")[0] + ": failed or zero answer")

    # (a) load sweep: error against α
    ax = axes[0, 0]
    for method, st in (("newton", newton), ("linear", linear)):
        pts = series(rows, "elastica_load_sweep", method, "value")
        ax.plot([p[0] for p in pts], [p[1] for p in pts], **st)
        failures(ax, pts, st)
    ax.set(xscale="log", yscale="log", xlabel="load α = PL²/EI", ylabel="relative error of the tip deflection",
           title="Elastica, 10 links (k_t/k = 1e6): error as the load grows")
    ax.legend(fontsize=8)

    # (b) load sweep: cost against α, with Newton's iterations and load steps
    ax = axes[0, 1]
    for method, st in (("newton", newton), ("linear", linear)):
        pts = series(rows, "elastica_load_sweep", method, "value", "time_s")
        ax.plot([p[0] for p in pts], [p[1] for p in pts], **st)
        if method == "newton":
            for x, t, r in pts:
                ax.annotate("%d it, %d steps" % (r["iterations"], r["load_steps"]), (x, t), fontsize=7,
                            textcoords="offset points", xytext=(3, 4))
    ax.set(xscale="log", yscale="log", xlabel="load α = PL²/EI", ylabel="CPU time per solve (s)",
           title="Elastica: cost as the load grows (Newton iterations, load steps)")
    ax.legend(fontsize=8)

    # (c) tolerance and iteration limit at α = 1: error against cost
    ax = axes[0, 2]
    pts = series(rows, "elastica_alpha1", "newton_tolerance", "time_s")
    ax.plot([p[0] for p in pts], [p[1] for p in pts], lw=0, marker="o", color="C0", label="Newton, tolerance 1e-2 … 1e-14")
    label_extremes(ax, pts)
    pts = series(rows, "elastica_alpha1", "newton_iteration_limit", "time_s")
    ok = [p for p in pts if p[2]["converged"]]
    ax.plot([p[0] for p in ok], [p[1] for p in ok], lw=0, marker="^", color="C2", mfc="none", ms=8,
            label="Newton, max_iterations 1 … 8 per load step")
    for x, e, r in ok[:2]:
        ax.annotate("max %d" % r["value"], (x, e), fontsize=7, textcoords="offset points", xytext=(4, 4))
    bad = [(p[0], 1.0) for p in pts if not p[2]["converged"]]
    if bad:
        ax.plot(*zip(*bad), lw=0, marker="x", ms=10, color="C2", label="max_iterations ≤ 3: no convergence")
    lin = series(rows, "elastica_alpha1", "linear", "time_s")
    if lin and lin[0][2]["converged"]:
        ax.plot([lin[0][0]], [lin[0][1]], marker="s", color="C3", lw=0, label="linear")
    ax.set(xscale="log", yscale="log", xlabel="CPU time per solve (s)", ylabel="relative error of the tip deflection",
           title="Elastica α = 1: tolerance and iteration limit")
    ax.legend(fontsize=8)

    # Error of both methods against a swept parameter of one problem.
    def error_by_value(ax, problem, xlabel, title):
        for method, st in (("newton", newton), ("linear", linear)):
            pts = series(rows, problem, method, "value")
            good = [p for p in pts if p[2]["converged"] and p[2]["error"] != 1.0]
            ax.plot([p[0] for p in good], [p[1] for p in good], **st)
            failures(ax, pts, st)
        ax.set(xscale="log", yscale="log", xlabel=xlabel, ylabel="relative error of the tip deflection", title=title)
        ax.legend(fontsize=8)

    # (d) stiffness ratio
    error_by_value(axes[1, 0], "elastica_stiffness_ratio", "stiffness ratio k_translation / k_hinge",
                   "Stiffness ratio (Newton at α = 1, linear at α = 0.01)")

    # (e) small loads on stiff springs
    error_by_value(axes[1, 1], "elastica_small_load", "tip load P (k = 1, k_t = 1e9)",
                   "Small loads on stiff springs (k_t·L/P up to 1e18)")

    # (f) plate: tolerance against cost
    ax = axes[1, 2]
    plate = next((r["problem"] for r in rows if r["problem"].startswith("plate")), None)
    if plate:
        pts = series(rows, plate, "newton_tolerance", "time_s")
        ax.plot([p[0] for p in pts], [p[1] for p in pts], lw=0, marker="o", color="C0", label="Newton, tolerance 1e-2 … 1e-14")
        label_extremes(ax, pts)
        lin = series(rows, plate, "linear", "time_s")
        if lin:
            ax.plot([lin[0][0]], [lin[0][1]], marker="s", color="C3", lw=0, label="linear")
        n = "".join(ch for ch in plate.split("_")[0] if ch.isdigit())
        ax.set(xscale="log", yscale="log", xlabel="CPU time per solve (s)",
               ylabel="relative difference to the solution at tol 1e-14",
               title="Plate of %s tiles (bench_stiffness's grid): tolerance" % n)
        ax.legend(fontsize=8)
    for ax in axes.flat:
        ax.grid(True, which="major", alpha=0.3)
    fig.suptitle("Stiffness solver: error versus cost (errors of 0 drawn at 1e-17; × = no answer or a zero answer)", fontsize=12)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    path = os.path.join(out, "error_cost_stiffness.svg")
    fig.savefig(path)
    plt.close(fig)
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv_dir", nargs="?", default=".")
    ap.add_argument("--out", help="folder for the SVG files (default: the CSV folder)")
    a = ap.parse_args()
    out = a.out or a.csv_dir
    os.makedirs(out, exist_ok=True)
    plt.rcParams.update({"svg.fonttype": "none", "font.size": 9})
    p1 = plot_projection(read(os.path.join(a.csv_dir, "error_cost_projection.csv")), out)
    p2 = plot_stiffness(read(os.path.join(a.csv_dir, "error_cost_stiffness.csv")), out)
    print("wrote %s and %s" % (p1, p2), file=sys.stderr)


if __name__ == "__main__":
    main()
