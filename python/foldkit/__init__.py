"""foldkit: plan, simulate and analyse the folding of rigid crease patterns.

The compiled core (foldkit._foldkit) does the work; this package adds what is easier in Python.
Conventions are the CLI's (docs/CLI.md): a fold state is a float array with one angle per joint,
in radians (0 flat, positive mountain, negative valley); files hold degrees. Bad input raises
foldkit.ParseError, a ValueError whose text is 'FILE:LINE: message'. Algorithms that end without an
answer do not raise: their result's `status` says why (docs/ARCHITECTURE.md, "How an algorithm ends").

    import foldkit
    p = foldkit.generators.miura(10, 10)
    r = foldkit.fold(p, fraction=0.5)
    foldkit.dof(p, r.states[-1]).dof   # 1
"""

import numpy as _np

from . import _foldkit
from ._foldkit import *  # noqa: F401,F403  (the bound classes and functions)
from ._foldkit import ClosureSystem, CreasePattern, ParseError, generators  # noqa: F401

__all__ = [name for name in dir(_foldkit) if not name.startswith("_")] + [
    "closure_residual", "closure_jacobian", "closure_error", "info",
]


def _sparse(coo):
    """A scipy.sparse CSR matrix of (rows, cols, values, shape) when SciPy is there, else the tuple."""
    try:
        from scipy import sparse
    except ImportError:
        return coo
    rows, cols, values, shape = coo
    return sparse.csr_matrix((values, (rows, cols)), shape=shape)


def _jacobian(self, state):
    """The closure Jacobian at `state`: a scipy.sparse CSR matrix (rows × joints), or, without
    SciPy, the COO arrays (rows, cols, values, shape)."""
    return _sparse(self.jacobian_coo(state))


ClosureSystem.jacobian = _jacobian


def _tangent(self, x, load_factor=1.0, geometric=True):
    """The tangent of the residual at `x` (with respect to a left perturbation of each module): a
    scipy.sparse CSR matrix (size × size), or, without SciPy, the COO arrays (rows, cols, values,
    shape). `geometric` False: the small-displacement stiffness at x = 0, whatever x is."""
    return _sparse(self.tangent_coo(x, load_factor, geometric))


EquilibriumSystem.tangent = _tangent


def closure_residual(pattern, state):
    """The closure residual of `pattern` at `state` (zero on closed states)."""
    return ClosureSystem(pattern).residual(state)


def closure_jacobian(pattern, state):
    """The closure Jacobian of `pattern` at `state` (see ClosureSystem.jacobian)."""
    return ClosureSystem(pattern).jacobian(state)


def closure_error(pattern, state):
    """The largest loop error of `pattern` at `state`, radians."""
    return ClosureSystem(pattern).max_error(state)


def info(pattern):
    """The facts `foldkit info --json` reports, as a dict with the same keys."""
    degrees = {}
    for star in pattern.interior_vertices:
        d = len(star.joints)
        degrees[str(d)] = degrees.get(str(d), 0) + 1
    vertices = pattern.vertices
    boundary = int(_np.count_nonzero(pattern.boundary_vertices))
    triangles = sum(len(pattern.actor_triangles(i)) for i in range(len(pattern.actor_ids)))
    return {
        "title": pattern.title,
        "actors": len(pattern.actor_ids),
        "joints": len(pattern.joint_ids),
        "triangles": triangles,
        "vertices": len(vertices),
        "interior_vertices": len(vertices) - boundary,
        "boundary_vertices": boundary,
        "boundary_edges": len(pattern.boundary_edges),
        "interior_vertex_degrees": dict(sorted(degrees.items(), key=lambda kv: int(kv[0]))),
        "bounds": [vertices.min(axis=0).tolist(), vertices.max(axis=0).tolist()],
    }


CreasePattern.info = info
