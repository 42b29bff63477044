#!/usr/bin/python3
"""Sweep Miura-ori sizes: fold each one, measure DOF, fold time and closure error, and plot them.

For every size n this script builds an n × n Miura-ori (foldkit.generators.miura), folds it from
flat to `--fraction` of π with projected-velocity folding (foldkit.fold, as `foldkit fold`), and
measures

  * DOF: foldkit.dof at the last folded state (a Miura-ori has 1 DOF at every size, except at the
    singular flat and fully folded states);
  * fold time: the folder's own time (FoldResult.seconds, no replay) and the wall-clock time of the
    whole foldkit.fold call (which also replays the sequence in the simulator, with collision
    checks unless --no-collision);
  * closure error: the largest loop error over the folded states. FoldResult.max_closure_error is
    checked against an independent recomputation with one ClosureSystem over FoldResult.states;
    the simulator's replay error (linear interpolation between the states) is shown beside it.

It prints a table, optionally writes it as CSV, and saves a three-panel figure. It exits with
status 1 and a message when something is wrong: a fold that did not reach the target, a replay
that is not valid, a closure error above CLOSURE_LIMIT or one that does not match its
recomputation; with status 2 on bad arguments.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/miura_sweep.py
    PYTHONPATH=build/python /usr/bin/python3 examples/python/miura_sweep.py \\
        --sizes 4,8,16,32 --fraction 0.5 --no-collision --out sweep.png --csv sweep.csv
"""

import argparse
import csv
import math
import sys
import time

import matplotlib

matplotlib.use("Agg")  # no display needed: the figure goes to a file
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import NullLocator  # noqa: E402

import foldkit  # noqa: E402

# The folder corrects every state to a loop error of 1e-10 rad (docs/PROJECTED_FOLDING.md); a
# folded state further from closure than this is a bug.
CLOSURE_LIMIT = 1e-9

COLUMNS = ["n", "creases", "steps", "fold_s", "wall_s", "dof", "rank_gap", "closure_error", "replay_error"]


def sizes_arg(text):
    """--sizes: comma-separated positive integers."""
    try:
        sizes = [int(s) for s in text.split(",") if s.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a comma-separated list of integers: {text!r}")
    if not sizes or min(sizes) < 1:
        raise argparse.ArgumentTypeError(f"sizes must be positive integers: {text!r}")
    return sizes


def fraction_arg(text):
    """--fraction: a number in (0, 1]."""
    f = float(text)
    if not 0.0 < f <= 1.0:
        raise argparse.ArgumentTypeError(f"fraction must be in (0, 1]: {text}")
    return f


def measure(n, fraction, collisions):
    """Folds an n × n Miura-ori and returns one row of COLUMNS; raises RuntimeError when wrong."""
    pattern = foldkit.generators.miura(n, n)
    start = time.perf_counter()
    result = foldkit.fold(pattern, fraction=fraction, collisions=collisions)
    wall = time.perf_counter() - start
    if not result.reached:
        raise RuntimeError(f"miura {n}x{n}: fold did not reach fraction {fraction}: {result.status}")
    if result.replay is not None and not result.replay.valid:
        raise RuntimeError(f"miura {n}x{n}: replay not valid: {result.replay.status}")

    # The closure error, recomputed independently over every state (one system, many states).
    system = foldkit.ClosureSystem(pattern)
    recomputed = max(system.max_error(state) for state in result.states)
    if not math.isclose(recomputed, result.max_closure_error, rel_tol=1e-6, abs_tol=1e-15):
        raise RuntimeError(f"miura {n}x{n}: max_closure_error {result.max_closure_error:.3g} but the states "
                           f"give {recomputed:.3g}")
    if recomputed > CLOSURE_LIMIT:
        raise RuntimeError(f"miura {n}x{n}: closure error {recomputed:.3g} rad exceeds {CLOSURE_LIMIT:g}")

    mobility = foldkit.dof(pattern, result.states[-1])
    return {
        "n": n,
        "creases": mobility.creases,
        "steps": result.steps,
        "fold_s": result.seconds,
        "wall_s": wall,
        "dof": mobility.dof,
        "rank_gap": mobility.rank_gap,
        "closure_error": recomputed,
        "replay_error": result.replay.max_closure_error if result.replay is not None else float("nan"),
    }


def print_table(rows, out=sys.stdout):
    """The rows as an aligned text table."""
    print(f"{'n':>4} {'creases':>7} {'steps':>5} {'fold s':>8} {'wall s':>8} {'DOF':>3} {'rank gap':>9} "
          f"{'closure err':>11} {'replay err':>10}", file=out)
    for r in rows:
        print(f"{r['n']:>4} {r['creases']:>7} {r['steps']:>5} {r['fold_s']:>8.3f} {r['wall_s']:>8.3f} {r['dof']:>3} "
              f"{r['rank_gap']:>9.2e} {r['closure_error']:>11.2e} {r['replay_error']:>10.2e}", file=out)


def plot(rows, fraction, collisions, path):
    """Three panels against the number of creases: fold time, closure error, DOF."""
    creases = [r["creases"] for r in rows]
    fig, (ax_time, ax_err, ax_dof) = plt.subplots(1, 3, figsize=(14, 4.2), constrained_layout=True)
    fig.suptitle(f"n × n Miura-ori folded to {fraction:g}π (projected velocity, "
                 f"collisions {'on' if collisions else 'off'})")

    ax_time.loglog(creases, [r["fold_s"] for r in rows], "o-", label="folding (FoldResult.seconds)")
    ax_time.loglog(creases, [r["wall_s"] for r in rows], "s--", label="fold() call, with replay")
    ax_time.set(ylabel="seconds", title="Fold time")

    ax_err.loglog(creases, [r["closure_error"] for r in rows], "o-", label="folded states")
    ax_err.loglog(creases, [r["replay_error"] for r in rows], "s--", label="simulator replay")
    ax_err.set(ylabel="largest loop error (rad)", title="Closure error")

    ax_dof.semilogx(creases, [r["dof"] for r in rows], "o-", color="C2", label="DOF")
    ax_dof.set(ylabel="DOF (creases − rank)", title="DOF at the folded state")
    ax_dof.set_ylim(0, max(2, max(r["dof"] for r in rows) + 1))
    ax_dof.yaxis.get_major_locator().set_params(integer=True)
    gap = ax_dof.twinx()
    gap.loglog(creases, [r["rank_gap"] for r in rows], "^:", color="C3", label="rank gap (right axis)")
    gap.set_ylabel("rank gap (smallest kept σ / largest zero σ)", color="C3", fontsize=9)
    gap.tick_params(axis="y", which="both", colors="C3")
    handles = ax_dof.get_legend_handles_labels()[0] + gap.get_legend_handles_labels()[0]
    ax_dof.legend(handles, [h.get_label() for h in handles], loc="lower left")

    for ax in (ax_time, ax_err, ax_dof):
        # One labelled tick per size: its creases, and n.
        ax.set_xticks(creases, [f"{c}\nn={r['n']}" for c, r in zip(creases, rows)], fontsize=8)
        ax.xaxis.set_minor_locator(NullLocator())
        ax.set_xlabel("creases (Miura n × n)")
        ax.grid(True, alpha=0.3)
    ax_time.legend()
    ax_err.legend()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", type=sizes_arg, default=[4, 8, 12, 16, 20],
                        help="comma-separated Miura sizes n (n × n parallelograms); default 4,8,12,16,20")
    parser.add_argument("--fraction", type=fraction_arg, default=0.9,
                        help="fold until the largest angle is this fraction of π; default 0.9")
    parser.add_argument("--out", default="miura_sweep.png", help="figure path; default miura_sweep.png")
    parser.add_argument("--csv", help="also write the table as CSV here")
    parser.add_argument("--no-collision", dest="collisions", action="store_false",
                        help="skip self-collision checks while folding and replaying")
    args = parser.parse_args(argv)

    rows = []
    try:
        for n in args.sizes:
            rows.append(measure(n, args.fraction, args.collisions))
    except (RuntimeError, ValueError) as e:  # ValueError: e.g. a size the generator refuses
        if rows:
            print_table(rows)
        print(f"miura_sweep: {e}", file=sys.stderr)
        return 1

    print_table(rows)
    try:
        if args.csv:
            with open(args.csv, "w", newline="") as f:
                writer = csv.DictWriter(f, fieldnames=COLUMNS)
                writer.writeheader()
                writer.writerows(rows)
            print(f"wrote {args.csv}")
        plot(rows, args.fraction, args.collisions, args.out)
        print(f"wrote {args.out}")
    except OSError as e:
        print(f"miura_sweep: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
