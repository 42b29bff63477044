"""plan, fold, stiffness, Carpenter's rule, Hamiltonian paths: the CLI's numbers on the same
files, and invariants checked here with numpy."""
import math
import os
import subprocess

import numpy as np
import pytest

import foldkit


def test_fold_matches_cli(cli, tmp_path):
    p = foldkit.generators.miura(6, 6)
    pmml = tmp_path / "m.pmml"
    foldkit.write_pmml(str(pmml), p)
    rc, expected, err = cli("fold", pmml, "--fraction", 0.5, "-o", tmp_path / "f.cmml")
    assert rc == 0, err
    r = foldkit.fold(p, fraction=0.5)
    assert r.reached and r.status.code == expected["status"]
    assert r.steps == expected["steps"] and r.newton_iterations == expected["newton_iterations"]
    assert r.dof == expected["dof"] == 1 and r.rank == expected["rank"]
    assert r.rank_decisions == expected["rank_decisions"] and r.rank_method == expected["rank_method"]
    assert r.min_pivot_ratio == pytest.approx(expected["min_pivot_ratio"], rel=1e-9)
    assert (r.min_rank_gap is None) == (expected["min_rank_gap"] is None)
    assert r.fraction == pytest.approx(expected["fraction"], rel=1e-12)
    assert r.max_closure_error == pytest.approx(expected["max_closure_error"], rel=1e-6, abs=1e-16)
    assert r.replay is not None and r.replay.valid
    assert r.states.shape == (r.steps + 1, len(p.joint_ids))
    system = foldkit.ClosureSystem(p)
    assert max(system.max_error(s) for s in r.states) <= 1e-10
    np.testing.assert_allclose(r.states[-1], foldkit.read_state(p, str(tmp_path / "f.cmml")), atol=1e-9)



def test_fold_toward_a_files_targets_matches_cli(cli, tmp_path):
    """toward: the targets an SVG carries (stroke opacity x 180 degrees) as the direction, and the
    fraction of their largest angle, as `foldkit fold --toward`."""
    svg = tmp_path / "m.svg"
    rc, _, err = cli("generate", "miura", "--rows", 3, "--cols", 3, "-o", svg)
    assert rc == 0, err
    rc, expected, err = cli("fold", svg, "--toward", svg, "--fraction", 0.8, "-o", tmp_path / "f.cmml")
    assert rc == 0, err
    f = foldkit.read_pattern(str(svg))
    r = foldkit.fold(f.pattern, fraction=0.8, toward=f.state)
    assert r.reached and r.steps == expected["steps"]
    assert r.target_distance == pytest.approx(expected["target_distance"], rel=1e-9)
    assert r.fraction == pytest.approx(0.8 * np.abs(f.state).max() / np.pi, rel=1e-9)
    assert foldkit.fold(f.pattern, fraction=0.8).target_distance is None
    with pytest.raises(ValueError, match="velocity or toward"):
        foldkit.fold(f.pattern, velocity=f.state, toward=f.state)
    with pytest.raises(ValueError, match="nothing to fold toward"):
        foldkit.fold(f.pattern, toward=np.zeros(len(f.state)))

def single_vertex_goal():
    p = foldkit.generators.single_vertex([math.radians(a) for a in (50, 70, 60, 55, 65, 60)])
    # No assignment on a generated vertex: fold along alternating mountain/valley velocities.
    velocity = np.array([1.0, -1.0, 1.0, -1.0, 1.0, -1.0])
    goal = foldkit.fold(p, fraction=0.6, velocity=velocity, collisions=False, replay=False).states[-1]
    return p, goal


def test_spaces_are_the_clis(cli):
    """foldkit.spaces() is the C++ table the CLI's --space choices come from, and plan() names each."""
    help_text = subprocess.run([os.environ["FOLDKIT_CLI"], "plan", "--help"], capture_output=True, text=True).stdout
    names = foldkit.spaces()
    assert names[0] == "auto" and len(names) == len(set(names)) >= 6
    assert "{" + ",".join(names) + "}" in help_text
    for name in names:
        assert "'" + name + "'" in foldkit.plan.__doc__


def test_plan_single_vertex_matches_cli(cli, tmp_path):
    p, goal = single_vertex_goal()
    pmml, goal_cmml = tmp_path / "v.pmml", tmp_path / "goal.cmml"
    foldkit.write_pmml(str(pmml), p)
    foldkit.write_cmml(str(goal_cmml), foldkit.sequence_to(p, goal))
    goal = foldkit.read_state(p, str(goal_cmml))
    rc, expected, err = cli("plan", pmml, "--goal", goal_cmml, "--planner", "RRTConnect", "--time", 5, "--seed", 3,
                            "-o", tmp_path / "plan.cmml")
    assert rc == 0, err
    r = foldkit.plan(p, goal, planner="RRTConnect", time=5, seed=3)
    assert r.solved and r.space == expected["space"] == "single-vertex"
    assert len(r.waypoints) == expected["waypoints"]
    assert r.path_length == pytest.approx(expected["path_length"], rel=1e-9)
    w = r.waypoints
    np.testing.assert_allclose(w[0], 0, atol=1e-12)
    np.testing.assert_allclose(w[-1], goal, atol=1e-6)
    assert np.max(np.abs(np.diff(w, axis=0))) <= 0.02 + 1e-12
    assert max(foldkit.closure_error(p, s) for s in w) <= 1e-6
    assert r.replay.valid and not r.fallback and expected["fallback"] is False
    assert not r.via_flat and expected["via_flat"] is False
    # RRT held to steps of 1e-7 rad finds nothing: the Carpenter fallback plans, as the CLI's.
    rc, expected, err = cli("plan", pmml, "--goal", goal_cmml, "--planner", "RRT", "--param", "range=1e-7", "--time", 0.4,
                            "-o", tmp_path / "fallback.cmml")
    assert rc == 0, err
    r = foldkit.plan(p, goal, planner="RRT", params={"range": "1e-7"}, time=0.4)
    assert r.solved and r.fallback and expected["fallback"] is True and r.replay.valid
    assert not r.via_flat and expected["via_flat"] is False  # Carpenter's path, not two plans from flat
    assert not foldkit.plan(p, goal, planner="RRT", params={"range": "1e-7"}, time=0.4, fallback=False).solved


def test_plan_miura_in_the_driving_space_matches_cli(cli, tmp_path):
    p = foldkit.generators.miura(6, 6)
    goal = foldkit.fold(p, fraction=0.5).states[-1]
    pmml, goal_cmml = tmp_path / "m.pmml", tmp_path / "goal.cmml"
    foldkit.write_pmml(str(pmml), p)
    foldkit.write_cmml(str(goal_cmml), foldkit.sequence_to(p, goal))
    goal = foldkit.read_state(p, str(goal_cmml))
    rc, expected, err = cli("plan", pmml, "--goal", goal_cmml, "--param", "range=0.3", "--time", 10, "--seed", 3,
                            "-o", tmp_path / "plan.cmml")
    assert rc == 0, err
    r = foldkit.plan(p, goal, time=10, seed=3, params={"range": "0.3"})
    assert r.solved and r.space == expected["space"] == "driving"
    assert len(r.waypoints) == expected["waypoints"]
    system = foldkit.ClosureSystem(p)
    assert max(system.max_error(s) for s in r.waypoints) <= 1e-10
    assert r.replay.valid
    with pytest.raises(ValueError, match="range"):
        foldkit.plan(p, goal, params={"nonsense": "1"})
    # The goal as the CLI takes it, a sequence (its end state): the same plan.
    s = foldkit.plan(p, foldkit.read_cmml(str(goal_cmml)), time=10, seed=3, params={"range": "0.3"})
    assert s.solved and np.array_equal(s.waypoints, r.waypoints)


def test_plan_is_seeded_and_starts_anywhere():
    p, goal = single_vertex_goal()
    a = foldkit.plan(p, goal, seed=7, time=5)
    b = foldkit.plan(p, goal, seed=7, time=5)
    assert a.solved and np.array_equal(a.waypoints, b.waypoints)
    assert 0 < a.seconds < 5
    # The old names of speed and seconds still work for one release, with a DeprecationWarning.
    with pytest.warns(DeprecationWarning, match="speed"):
        old = foldkit.plan(p, goal, seed=7, time=5, velocity=0.5)
    assert np.array_equal(old.waypoints, a.waypoints)
    assert old.sequence.events[-1].folds[0].speed != a.sequence.events[-1].folds[0].speed
    with pytest.warns(DeprecationWarning, match="seconds"):
        assert old.time == old.seconds
    with pytest.raises(TypeError, match="goal must be"):
        foldkit.plan(p, "not a state")
    # From a state part-way, reached from flat along the first plan's own closed waypoints.
    half = a.waypoints[: len(a.waypoints) // 2 + 1]
    c = foldkit.plan(p, goal, start=foldkit.path_sequence(p, half), seed=7, time=5)
    assert c.solved, c.status
    np.testing.assert_allclose(c.waypoints[0], half[-1], atol=1e-9)
    assert c.replay.valid


def test_stiffness_matches_cli(cli, data, tmp_path):
    sheet = foldkit.generators.cube_sheet(1, tile=0.01)
    pmml = tmp_path / "cube.pmml"
    foldkit.write_pmml(str(pmml), sheet)
    cmml, loadcase = data / "good" / "cube-fold.cmml", data / "good" / "cube-top-load.loadcase"
    rc, expected, err = cli("stiffness", pmml, loadcase, "--state", cmml)
    assert rc == 0, err
    state = foldkit.read_state(sheet, str(cmml))
    r = foldkit.stiffness(sheet, str(loadcase), state=state)
    assert r.status.ok and r.status.code == expected["status"]
    assert r.iterations == expected["iterations"]
    assert r.max_displacement == pytest.approx(expected["max_displacement"], rel=1e-9)
    lc = foldkit.read_load_case(str(loadcase))
    assert foldkit.stiffness(sheet, lc, state=state).max_displacement == pytest.approx(r.max_displacement)
    fixed = np.array(r.fixed)
    assert np.all(r.displacements[fixed] == 0) and np.all(r.rotations[fixed] == 0)
    assert np.max(np.linalg.norm(r.displacements, axis=1)) == pytest.approx(r.max_displacement)
    assert r.module_ids == sheet.actor_ids


def random_walk(n, seed):
    """A self-avoiding lattice walk of n links, jittered, as a (n + 1, 2) array."""
    rng = np.random.default_rng(seed)
    while True:
        pts, seen = [(0, 0)], {(0, 0)}
        for _ in range(n):
            x, y = pts[-1]
            free = [q for q in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)) if q not in seen]
            if not free:
                break
            q = free[rng.integers(len(free))]
            pts.append(q)
            seen.add(q)
        if len(pts) == n + 1:
            return np.array(pts, float) + 0.1 * rng.uniform(-1, 1, (n + 1, 2))


@pytest.mark.parametrize("method", ["carried", "lp", "pseudo"])
def test_carpenter_is_expansive_and_matches_cli(cli, tmp_path, method):
    pts = random_walk(30, seed=2)
    chain = tmp_path / "c.txt"
    chain.write_text("".join(f"{x!r} {y!r}\n" for x, y in pts))
    rc, expected, err = cli("carpenter", chain, "--method", method, "-o", tmp_path / "out.json")
    assert rc == 0, err
    r = foldkit.carpenter(foldkit.read_chain(str(chain)), method=method)
    assert r.status.ok and r.steps == expected["steps"] and expected["method"] == method
    assert (r.carried_steps > 0) == (method == "carried") and r.window_lp_solves <= r.lp_solves
    assert r.flips == expected["flips"] and (r.flips + r.straightenings > 0) == (method == "pseudo")
    f = r.frames
    np.testing.assert_allclose(f[0], pts, atol=1e-12)
    bars = np.linalg.norm(np.diff(f, axis=1), axis=2)
    np.testing.assert_allclose(bars, np.broadcast_to(bars[0], bars.shape), rtol=1e-6)
    d = np.linalg.norm(f[:, :, None, :] - f[:, None, :, :], axis=3)
    assert np.all(np.diff(d, axis=0) >= -1e-9)  # no distance decreases between frames
    end = f[-1] - f[-1][0]
    direction = end[-1] / np.linalg.norm(end[-1])
    assert np.max(np.abs(end[:, 0] * direction[1] - end[:, 1] * direction[0])) < 1e-6  # straight


# Every metric of CarpenterPlanarResult (docs/CARPENTER.md, Metrics), as the C++ result names it.
CARPENTER_METRICS = {"closed", "steps", "lp_solves", "window_lp_solves", "carried_steps", "held_steps", "max_struts",
                     "flips", "straightenings", "pseudo_lp_steps", "certificate_seconds", "seconds",
                     "max_length_error", "min_distance_growth"}
CARPENTER_TIMES = {"seconds", "certificate_seconds"}  # wall-clock seconds: the two runs' own


@pytest.mark.parametrize("method", ["carried", "lp", "pseudo"])
def test_carpenter_metrics_have_one_name_in_python_and_json(cli, tmp_path, method):
    pts = random_walk(30, seed=2)
    chain = tmp_path / "c.txt"
    chain.write_text("".join(f"{x!r} {y!r}\n" for x, y in pts))
    rc, j, err = cli("carpenter", chain, "--method", method)
    assert rc == 0, err
    r = foldkit.carpenter(foldkit.read_chain(str(chain)), method=method)
    # Python's result has exactly the metrics besides its frames and status, and the JSON has each.
    attributes = {a for a in dir(foldkit.CarpenterResult) if not a.startswith("_")}
    assert attributes - {"frames", "status"} == CARPENTER_METRICS
    assert CARPENTER_METRICS <= j.keys(), CARPENTER_METRICS - j.keys()
    # The same run in both: every count and length error equal, the frames counted, the times spent.
    for name in CARPENTER_METRICS - CARPENTER_TIMES:
        assert getattr(r, name) == j[name], name
    assert j["frames"] == len(r.frames) and j["status"] == r.status.code
    for seconds, certificate in ((r.seconds, r.certificate_seconds), (j["seconds"], j["certificate_seconds"])):
        assert 0 <= certificate <= seconds
        assert (certificate > 0) == (method == "pseudo")  # only the pseudo-triangulation checks its steps so


def test_carpenter_refuses_an_unknown_method():
    with pytest.raises(ValueError, match="unknown Carpenter method 'fast'"):
        foldkit.carpenter(random_walk(5, seed=1), method="fast")


def test_carpenter_convexifies_a_polygon():
    arrow = np.array([[0, 0], [4, 0], [4, 4], [2, 1], [0, 4]], float)
    r = foldkit.carpenter(arrow, closed=True)
    assert r.status.ok and r.closed
    last = r.frames[-1]
    edges = np.roll(last, -1, axis=0) - last
    cross = edges[:, 0] * np.roll(edges, -1, axis=0)[:, 1] - edges[:, 1] * np.roll(edges, -1, axis=0)[:, 0]
    assert np.all(cross >= -1e-9) or np.all(cross <= 1e-9)


def test_carpenter_vertex_flattens():
    p, goal = single_vertex_goal()
    r = foldkit.carpenter_vertex(p, goal)
    assert r.status.ok
    np.testing.assert_allclose(r.frames[0], goal, atol=1e-9)
    assert np.max(np.abs(r.frames[-1])) < 1e-4
    assert r.min_distance_growth >= -1e-9
    assert foldkit.simulate(p, r.folding).valid


def hamiltonian_path_ok(shape, path):
    cells = {tuple(c) for c in np.argwhere(shape)[:, ::-1]}  # (x, y[, z])
    steps = np.abs(np.diff(path, axis=0)).sum(axis=1)
    return len(path) == len(cells) and {tuple(c) for c in path} == cells and np.all(steps == 1)


def test_hamiltonian_paths(cli, tmp_path):
    shape = np.array([[1, 1, 1, 0], [1, 1, 1, 1], [0, 1, 1, 1]], bool)
    r = foldkit.hamiltonian(shape)
    assert r.status.ok and hamiltonian_path_ok(shape, r.path)
    grid = tmp_path / "s.txt"
    grid.write_text("\n".join("".join("#" if c else "." for c in row) for row in shape) + "\n")
    rc, expected, err = cli("hamiltonian", grid)
    assert rc == 0 and expected["status"] == r.status.code, err
    # A 3×3 block minus an edge cell leaves 5 cells of one colour and 3 of the other: no path.
    no = np.ones((3, 3), bool)
    no[0, 1] = False
    assert foldkit.hamiltonian(no).status.code == "no-solution"
    cycle = foldkit.hamiltonian(no, refine=True)
    assert cycle.status.ok and cycle.cycle and len(cycle.path) == 4 * no.sum()
    voxels = np.ones((2, 2, 3), bool)
    v = foldkit.hamiltonian(voxels)
    assert v.status.ok and v.path.shape == (12, 3) and hamiltonian_path_ok(voxels, v.path)


def test_cube_chain_folds_validly():
    sheet = foldkit.generators.cube_sheet(2)
    seq = foldkit.fold_cube_chain(sheet, 2)
    assert len(seq) > 0 and foldkit.simulate(sheet, seq).valid


def test_plan_experience_database_is_shared_with_the_cli(cli, cli_experience, tmp_path):
    # A database the CLI made is recalled from in Python, and Python's is read by the CLI.
    p, pmml, g8, db = cli_experience
    r = foldkit.plan(p, foldkit.fold(p, fraction=0.7).states[-1], experience=str(db))
    assert r.solved and r.replay.valid
    assert r.experience["recalled"] and r.experience["loaded"] == 1 and r.experience["paths"] == 2
    assert r.experience["bytes"] == db.stat().st_size
    rc, out, err = cli("plan", pmml, "--goal", g8, "--experience", db, "-o", tmp_path / "again.cmml")
    assert rc == 0, err
    assert out["experience"]["loaded"] == 2 and out["experience"]["recalled"]
    assert foldkit.plan(p, foldkit.fold(p, fraction=0.7).states[-1]).experience is None
    db.write_bytes(b"not a database")
    with pytest.raises(foldkit.ParseError, match="m.db: not a foldkit experience database"):
        foldkit.plan(p, foldkit.fold(p, fraction=0.7).states[-1], experience=str(db))
    assert db.read_bytes() == b"not a database"


def test_carpenter_holds_a_spirals_slow_end_as_the_cli_does(cli, data, tmp_path):
    # The 90-point spiral: no LP over the whole chain solves in doubles, so part of it is
    # held rigid for some steps (held_steps, the CLI's JSON key of the same name).
    chain = data / "carpenter_spiral90.txt"
    rc, expected, err = cli("carpenter", chain, "--method", "lp", "-o", tmp_path / "out.json")
    assert rc == 0, err
    r = foldkit.carpenter(foldkit.read_chain(str(chain)), method="lp")
    assert r.status.ok and r.held_steps == expected["held_steps"] > 0 and r.steps == expected["steps"]
