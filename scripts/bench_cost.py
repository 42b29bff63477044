"""Best cost against time from OMPL benchmark logs (`foldkit bench optimal`): the log reader, each
run's best cost as a step function of time, medians and interquartile bands over the runs, and
the figures of scripts/plot_bench.py. Exits with "FILE:LINE: what is wrong" on a log it cannot
read.
"""
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

INF = math.inf
GRID = 600  # time points per figure (only those where a value changes are drawn)


def fail(path, line, what):
    sys.exit(f"{path}:{line}: {what}")


def count_line(path, lines, i, pattern):
    """The number N of a line "N <pattern>" at index i."""
    m = re.fullmatch(r"(\d+) " + pattern, lines[i]) if i < len(lines) else None
    if not m:
        fail(path, i + 1, f"expected 'N {pattern}', found {lines[i]!r}" if i < len(lines) else f"the log ends before 'N {pattern}'")
    return int(m.group(1))


def values(line):
    """A run's line "v; v; …; " as its values (an empty value stays '')."""
    return [v.strip() for v in line.split(";")[:-1]]


def read_planner(path, lines, i):
    """One planner's block from index i: (planner, index after its closing '.')."""
    if i >= len(lines):
        fail(path, i, "the log ends before all of its planners")
    p = {"name": lines[i].removeprefix("geometric_"), "properties": [], "runs": [], "progress_properties": [], "progress": []}
    i += 1
    i += count_line(path, lines, i, "common properties") + 1
    n = count_line(path, lines, i, "properties for each run")
    p["properties"] = lines[i + 1:i + 1 + n]
    i += n + 1
    runs = count_line(path, lines, i, "runs")
    p["runs"] = [values(line) for line in lines[i + 1:i + 1 + runs]]
    i += runs + 1
    if i < len(lines) and lines[i].endswith("progress properties for each run"):
        n = count_line(path, lines, i, "progress properties for each run")
        p["progress_properties"] = lines[i + 1:i + 1 + n]
        i += n + 1
        runs = count_line(path, lines, i, "runs")
        p["progress"] = lines[i + 1:i + 1 + runs]
        i += runs + 1
    if i >= len(lines) or lines[i] != ".":
        fail(path, i + 1, f"expected '.' after planner {p['name']}")
    return p, i + 1


def read_log(path):
    """{experiment, objective, max_time, planners} of an OMPL benchmark log."""
    with open(path) as f:
        lines = f.read().splitlines()
    log = {"experiment": os.path.splitext(os.path.basename(path))[0], "objective": "length", "max_time": None, "planners": []}
    i = 0
    while i < len(lines):
        line = lines[i]
        if line == "<<<|":  # the setup and CPU blocks: free text
            while i < len(lines) and lines[i] != "|>>>":
                i += 1
        elif line.startswith("Experiment "):
            log["experiment"] = line[len("Experiment "):]
        elif line.startswith("objective STRING = "):
            log["objective"] = line[len("objective STRING = "):]
        elif line.endswith(" seconds per run"):
            log["max_time"] = float(line.split()[0])
        elif re.fullmatch(r"\d+ planners", line):
            i += 1
            for _ in range(int(line.split()[0])):
                planner, i = read_planner(path, lines, i)
                log["planners"].append(planner)
            return log
        i += 1
    fail(path, len(lines), "no 'N planners' line (not an OMPL benchmark log?)")


def number(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def run_curve(planner, r):
    """Run r's best cost over time: [(seconds, cost)], non-increasing, from its progress samples
    and its final solution cost."""
    props = planner["properties"]
    run = dict(zip(props, planner["runs"][r]))
    points = []
    pp = planner["progress_properties"]
    cost_at = next((k for k, name in enumerate(pp) if name.startswith("best cost ")), None)
    if cost_at is not None and "time REAL" in pp and r < len(planner["progress"]):
        time_at = pp.index("time REAL")
        for sample in planner["progress"][r].split(";"):
            v = sample.split(",")
            if len(v) <= max(cost_at, time_at):
                continue
            t, c = number(v[time_at]), number(v[cost_at])
            if t is not None and c is not None and (not points or c < points[-1][1]):
                points.append((t, c))
    t, c = number(run.get("time REAL")), number(run.get("solution cost REAL"))
    if t is not None and c is not None and (not points or c < points[-1][1]):
        points.append((max(t, points[-1][0]) if points else t, c))
    return points


def best_at(points, t):
    best = INF
    for pt, c in points:
        if pt > t:
            break
        best = c
    return best


def quantile(sorted_values, q):
    """Linear-interpolated quantile of sorted values that may end in +inf (then +inf where it
    touches one)."""
    pos = q * (len(sorted_values) - 1)
    lo, hi = math.floor(pos), math.ceil(pos)
    a, b = sorted_values[lo], sorted_values[hi]
    if lo == hi or a == b:
        return a
    return INF if b == INF else a + (pos - lo) * (b - a)


def planner_series(planner, times):
    """Per time: (share of runs with a path %, 25th, 50th, 75th percentile of the best cost)."""
    curves = [run_curve(planner, r) for r in range(len(planner["runs"]))]
    out = []
    for t in times:
        best = sorted(best_at(c, t) for c in curves)
        share = 100.0 * sum(b < INF for b in best) / len(best) if best else 0.0
        out.append((share,) + tuple(quantile(best, q) if best else INF for q in (0.25, 0.5, 0.75)))
    return curves, out


def finite_or_nan(v):
    return v if v < INF else math.nan


def plot_log(log, out_dir, fmt):
    max_time = log["max_time"] or max((p[0] for pl in log["planners"] for r in range(len(pl["runs"]))
                                       for p in run_curve(pl, r)), default=1.0)
    times = [max_time * k / (GRID - 1) for k in range(GRID)]
    fig, (cost_ax, share_ax) = plt.subplots(1, 2, figsize=(13, 4.6), constrained_layout=True, gridspec_kw={"width_ratios": [2, 1]})
    markers = "osD^v<>px*h"
    finite = [c for pl in log["planners"] for r in range(len(pl["runs"])) for _, c in run_curve(pl, r)]
    lo, hi = (min(finite), max(finite)) if finite else (0.0, 1.0)
    pad = 0.05 * (hi - lo) if hi > lo else 0.05 * abs(hi) + 1e-9
    runs = 0
    for k, planner in enumerate(log["planners"]):
        runs = max(runs, len(planner["runs"]))
        _, series = planner_series(planner, times)
        # Steps: only the points where something changes, each value held until the next (small
        # files; exact for step functions).
        keep = [i for i in range(len(times)) if i in (0, len(times) - 1) or series[i] != series[i - 1]]
        xs, series = [times[i] for i in keep], [series[i] for i in keep]
        share = [s[0] for s in series]
        q25, q50, q75 = ([finite_or_nan(s[j]) for s in series] for j in (1, 2, 3))
        style = dict(marker=markers[k % len(markers)], markevery=[0], label=planner["name"], drawstyle="steps-post")
        (line,) = cost_ax.plot(xs, q50, **style)
        # The band where the lower quartile exists; where the upper one is infinite (a quarter of
        # the runs or more have no path yet) it reaches the top of the axes.
        top = [b if not math.isnan(b) else (hi + pad if not math.isnan(a) else math.nan) for a, b in zip(q25, q75)]
        cost_ax.fill_between(xs, q25, top, color=line.get_color(), alpha=0.15, linewidth=0, step="post")
        share_ax.plot(xs, share, color=line.get_color(), **style)
    cost_ax.set_ylim(lo - pad, hi + pad)
    cost_ax.set_ylabel(f"best cost so far ({log['objective']})")
    share_ax.set_ylabel("runs with a path (%)")
    share_ax.set_ylim(-5, 105)
    for ax in (cost_ax, share_ax):
        ax.set_xlabel("time (s)")
        ax.set_xlim(0, max_time)
        ax.grid(True, alpha=0.3)
    cost_ax.legend(title="planner", fontsize=8, loc="upper right", ncol=2)
    fig.suptitle(f"{log['experiment']}: best {log['objective']} cost against time "
                 f"(median of {runs} run(s), band = interquartile range)")
    path = os.path.join(out_dir, f"{log['experiment']}.cost.{fmt}")
    fig.savefig(path, metadata={"Date": None} if fmt == "svg" else None)
    plt.close(fig)
    return path


def median(v):
    v = sorted(v)
    return quantile(v, 0.5) if v else math.nan


def summary_rows(log):
    """(scene, planner, runs, solved, median time to first path, median final cost)."""
    rows = []
    for planner in log["planners"]:
        curves = [run_curve(planner, r) for r in range(len(planner["runs"]))]
        solved = [c for c in curves if c]
        rows.append((log["experiment"], planner["name"], len(curves), len(solved),
                     median([c[0][0] for c in solved]), median([c[-1][1] for c in solved])))
    return rows


def plot_costs(paths, out_dir, fmt, summary):
    rows = []
    for path in paths:
        log = read_log(path)
        if not log["planners"]:
            fail(path, 1, "no planners")
        print(plot_log(log, out_dir, fmt), file=sys.stderr)
        rows += summary_rows(log)
    if summary:
        print("| scene | planner | solved | median time to first path (s) | median final cost |")
        print("|---|---|---|---|---|")
        for scene, planner, runs, solved, first, final in rows:
            print(f"| {scene} | {planner} | {solved}/{runs} | {first:.3g} | {final:.4g} |")
