"""The equilibrium equations behind `stiffness` (foldkit.equilibrium_system): the tangent against
central differences of the residual, and a Newton solve written with SciPy against the library's
own solver on the same structure."""
import numpy as np
import pytest

import foldkit

sparse = pytest.importorskip("scipy.sparse")
from scipy.sparse import linalg  # noqa: E402


@pytest.fixture()
def cube(data):
    sheet = foldkit.generators.cube_sheet(1, tile=0.01)
    state = foldkit.read_state(sheet, str(data / "good" / "cube-fold.cmml"))
    return sheet, state, str(data / "good" / "cube-top-load.loadcase")


def test_tangent_is_the_derivative_of_the_residual(cube):
    sheet, state, loadcase = cube
    eq = foldkit.equilibrium_system(sheet, loadcase, state=state)
    rng = np.random.default_rng(3)
    x = 0.05 * rng.standard_normal(eq.size)  # away from equilibrium, turned by about 0.1 rad
    h = eq.tangent(x).toarray()
    step = 1e-6
    for i in range(eq.size):
        e = np.zeros(eq.size)
        e[i] = step
        column = (eq.residual(eq.retract(x, e)) - eq.residual(eq.retract(x, -e))) / (2 * step)
        np.testing.assert_allclose(h[:, i], column, rtol=1e-5, atol=1e-5 * np.abs(h).max())


def test_newton_with_scipy_reaches_the_library_solution(cube):
    sheet, state, loadcase = cube
    eq = foldkit.equilibrium_system(sheet, loadcase, state=state)
    x = np.zeros(eq.size)
    for _ in range(20):
        r = eq.residual(x)
        if np.abs(r).max() <= max(1e-10, eq.residual_floor(x)):
            break
        x = eq.retract(x, linalg.spsolve(eq.tangent(x).tocsc(), -r))
    assert np.abs(eq.residual(x)).max() <= max(1e-10, eq.residual_floor(x))
    ours = foldkit.stiffness(sheet, loadcase, state=state)
    assert ours.status.ok
    moved = np.linalg.norm(x.reshape(-1, 6)[:, :3], axis=1) * eq.length_unit
    assert moved.max() == pytest.approx(ours.max_displacement, rel=1e-8)


def test_wrong_sizes_are_refused(cube):
    sheet, state, loadcase = cube
    eq = foldkit.equilibrium_system(sheet, loadcase, state=state)
    with pytest.raises(ValueError, match="x must be of length"):
        eq.residual(np.zeros(eq.size - 1))
    with pytest.raises(ValueError, match="dx must be of length"):
        eq.retract(np.zeros(eq.size), np.zeros(3))
