"""Closure, Jacobian, mobility, projection and poses: against the CLI, finite differences and
rigid-body invariants."""
import math
import sys

import numpy as np
import pytest

import foldkit


@pytest.fixture(scope="module")
def miura():
    p = foldkit.generators.miura(8, 8)
    r = foldkit.fold(p, fraction=0.6, collisions=False, replay=False)
    assert r.status.ok, r.status
    return p, r.states[-1]


def test_dof_matches_cli(miura, cli, tmp_path):
    p, state = miura
    pmml, cmml = tmp_path / "m.pmml", tmp_path / "m.cmml"
    foldkit.write_pmml(str(pmml), p)
    foldkit.write_cmml(str(cmml), foldkit.sequence_to(p, state))
    for python_state, cli_args in [(None, []), (foldkit.read_state(p, str(cmml)), ["--state", cmml])]:
        rc, expected, err = cli("dof", pmml, *cli_args)
        assert rc == 0, err
        d = foldkit.dof(p, python_state)
        for key in ["dof", "rank", "creases", "method", "vertex_loops", "hole_cycles"]:
            assert getattr(d, key) == expected[key], key
        for key in ["tolerance", "closure_error", "largest_zero_singular_value", "smallest_kept_singular_value", "rank_gap"]:
            assert getattr(d, key) == pytest.approx(expected[key], rel=1e-6, abs=1e-15), key
    assert foldkit.dof(p, state).dof == 1


def test_jacobian_matches_finite_differences(miura):
    p, state = miura
    rng = np.random.default_rng(5)
    x = state + 0.05 * rng.standard_normal(state.shape)  # off the manifold too
    system = foldkit.ClosureSystem(p)
    jac = system.jacobian(x)
    assert jac.shape == (system.rows, system.cols) == (system.rows, len(p.joint_ids))
    h = 1e-6
    for j in rng.choice(len(x), size=12, replace=False):
        e = np.zeros_like(x)
        e[j] = h
        column = (system.residual(x + e) - system.residual(x - e)) / (2 * h)
        np.testing.assert_allclose(jac[:, j].toarray().ravel(), column, atol=1e-7)


def test_closure_on_and_off_the_manifold(miura):
    p, state = miura
    assert foldkit.closure_error(p, state) < 1e-10
    assert np.max(np.abs(foldkit.closure_residual(p, state))) < 1e-9
    bent = state.copy()
    bent[0] += 0.1
    assert foldkit.closure_error(p, bent) > 1e-3
    errors = foldkit.ClosureSystem(p).loop_errors(bent)
    assert max(errors) == pytest.approx(foldkit.closure_error(p, bent))


def test_jacobian_without_scipy_is_coo(miura, monkeypatch):
    p, state = miura
    monkeypatch.setitem(sys.modules, "scipy", None)
    rows, cols, values, shape = foldkit.closure_jacobian(p, state)
    monkeypatch.undo()
    dense = np.zeros(shape)
    np.add.at(dense, (rows, cols), values)
    np.testing.assert_allclose(dense, foldkit.closure_jacobian(p, state).toarray())


def test_project_matches_cli(miura, cli, tmp_path):
    p, state = miura
    rough = state + 0.02 * np.sin(np.arange(len(state)))
    pmml, cmml, out = tmp_path / "m.pmml", tmp_path / "rough.cmml", tmp_path / "closed.cmml"
    foldkit.write_pmml(str(pmml), p)
    foldkit.write_cmml(str(cmml), foldkit.sequence_to(p, rough))
    rough = foldkit.read_state(p, str(cmml))  # as the CLI sees it (degrees in the file)
    rc, expected, err = cli("project", pmml, "--state", cmml, "-o", out)
    assert rc == 0, err
    r = foldkit.project(p, rough)
    assert r.status.ok and r.error <= 1e-10
    assert r.iterations == expected["iterations"]
    np.testing.assert_allclose(r.state, foldkit.read_state(p, str(out)), atol=1e-9)
    assert np.all(np.sign(r.state[np.abs(rough) > 1e-3]) == np.sign(rough[np.abs(rough) > 1e-3]))


def test_goal_from_angles_holds_the_named_crease():
    p = foldkit.generators.single_vertex([math.radians(a) for a in (80, 100, 80, 100)])
    jid = p.joint_ids[0]
    goal = foldkit.goal_from_angles(p, {jid: 1.0})
    assert goal[p.joint_index(jid)] == pytest.approx(1.0)
    assert foldkit.closure_error(p, goal) < 1e-9
    with pytest.raises(ValueError):
        foldkit.goal_from_angles(p, {12345: 1.0})


def test_facet_poses_are_rigid_and_agree_on_creases(miura):
    p, state = miura
    poses = foldkit.facet_poses(p, state)
    assert poses.shape == (len(p.actor_ids), 4, 4)
    rot = poses[:, :3, :3]
    np.testing.assert_allclose(rot @ rot.transpose(0, 2, 1), np.broadcast_to(np.eye(3), rot.shape), atol=1e-12)
    np.testing.assert_allclose(np.linalg.det(rot), 1.0)
    # Both facets of every crease put its two ends at the same place (the sheet stays connected).
    v = np.c_[p.vertices, np.zeros(len(p.vertices)), np.ones(len(p.vertices))]
    for (a, b), (v0, v1) in zip(p.joint_actors, p.joint_vertices):
        for k in (v0, v1):
            np.testing.assert_allclose(poses[a] @ v[k], poses[b] @ v[k], atol=1e-9)
    flat = foldkit.facet_poses(p, None)
    np.testing.assert_allclose(flat, np.broadcast_to(np.eye(4), flat.shape), atol=1e-15)
    both = foldkit.facet_poses(p, np.vstack([p.flat(), state]))
    assert both.shape == (2, *poses.shape)
    np.testing.assert_allclose(both[1], poses)
