#!/usr/bin/env python3
"""SciPy's least_squares (trust-region reflective, LSMR, finite differences grouped by a Jacobian
sparsity pattern: what a Python user would pick) against foldkit.stiffness on the cube beam of
issue 20, the same equations (foldkit.equilibrium_system) and the same structure.

SciPy solves residual(x) = 0 in the unknowns as they are (x ↦ x + dx), with its own Jacobian by
differences; ours is Newton on the analytic tangent with the screw retraction. Ours is timed with
building the structure from the folded pattern (foldkit.stiffness does both), SciPy from the built
system; SciPy stops at its tolerances (1e-15) or max_nfev, and the table shows the scaled ∞-norm
residual each reached. Needs the built module on PYTHONPATH (build/python) and SciPy. At 300
modules SciPy runs out its 2,000 evaluations (minutes), so larger beams are not in the default.

    PYTHONPATH=build/python python3 microbench/stiffness_scipy.py [--modules 48 300] [--max-nfev 2000]
"""
import argparse
import time

import numpy as np
from scipy.optimize import least_squares

import foldkit


def load_case(ids, fixed, tip, force):
    return foldkit.parse_load_case(
        "<LoadCase><Title>cube beam</Title><Fixed>%s</Fixed><Load><ActorID>%d</ActorID><Force>%r %r %r</Force></Load></LoadCase>"
        % (" ".join(str(i) for i in fixed), tip, *force), "<cube beam>")


def beam(modules, rotation=0.1):
    """The cube beam of microbench/stiffness_problems.hpp: the first cube clamped, a load across the
    beam on its last tile that turns some module by `rotation` (linear solution)."""
    cubes = max(2, modules // 6)
    sheet = foldkit.generators.cube_sheet(cubes, tile=0.01)
    state = foldkit.fold_cube_chain(sheet, cubes).end_state(sheet)
    ids = sheet.actor_ids
    fixed, tip = ids[:6], ids[-1]
    # Across the beam: of the three axes, a unit load along the beam barely moves its tip.
    best = None
    for axis in np.eye(3):
        r = foldkit.stiffness(sheet, load_case(ids, fixed, tip, axis), state=state, linear=True)
        turned = np.linalg.norm(r.rotations, axis=1).max()
        if best is None or turned > best[0]:
            best = (turned, axis)
    case = load_case(ids, fixed, tip, best[1] * rotation / best[0])
    return sheet, state, case


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--modules", type=int, nargs="+", default=[48, 300])
    parser.add_argument("--max-nfev", type=int, default=2000)
    args = parser.parse_args()
    print("| modules | unknowns | ours | ours residual | SciPy least_squares | SciPy residual | evaluations | ratio |")
    print("|---|---|---|---|---|---|---|---|")
    for modules in args.modules:
        sheet, state, case = beam(modules)
        eq = foldkit.equilibrium_system(sheet, case, state=state)
        start = time.perf_counter()
        ours = foldkit.stiffness(sheet, case, state=state)
        ours_s = time.perf_counter() - start
        pattern = eq.tangent(np.zeros(eq.size))
        pattern.data[:] = 1.0
        start = time.perf_counter()
        fit = least_squares(eq.residual, np.zeros(eq.size), jac_sparsity=pattern, method="trf", tr_solver="lsmr",
                            x_scale="jac", ftol=1e-15, xtol=1e-15, gtol=1e-15, max_nfev=args.max_nfev)
        scipy_s = time.perf_counter() - start
        reached = np.abs(eq.residual(fit.x)).max()
        ratio = ("%.0f×" % (scipy_s / ours_s)) if reached <= ours.residual_norm else "not reached (> %.0f×)" % (scipy_s / ours_s)
        print("| %d | %d | %.3g s | %.2g | %.3g s | %.2g | %d | %s |" % (
            len(sheet.actor_ids), eq.size, ours_s, ours.residual_norm, scipy_s, reached, fit.nfev, ratio), flush=True)


if __name__ == "__main__":
    main()
