"""Patterns, generators and files: the same facts and files as the CLI's."""
import json
import math

import numpy as np
import pytest

import foldkit

GENERATED = {
    "miura": (lambda: foldkit.generators.miura(3, 5), ["miura", "--rows", 3, "--cols", 5]),
    "waterbomb": (lambda: foldkit.generators.waterbomb(2, 2), ["waterbomb", "--units", 2, "--rows", 2]),
    "boat": (lambda: foldkit.generators.boat(), ["boat"]),
    "circular": (lambda: foldkit.generators.circular_lattice(2, 7), ["circular", "--rings", 2, "--spokes", 7]),
    "cube-sheet": (lambda: foldkit.generators.cube_sheet(3), ["cube-sheet", "--cubes", 3]),
    "square-twist": (lambda: foldkit.generators.square_twist(twist=math.radians(30)), ["square-twist", "--twist", 30]),
}


@pytest.mark.parametrize("kind", sorted(GENERATED))
def test_generators_match_cli_generate(kind, cli, tmp_path):
    make, args = GENERATED[kind]
    path = tmp_path / "cli.pmml"
    rc, _, err = cli("generate", *args, "-o", path, json_out=False)
    assert rc == 0, err
    ours, theirs = make(), foldkit.read_pmml(str(path))
    np.testing.assert_allclose(ours.vertices, theirs.vertices, atol=1e-9)
    assert ours.joint_ids == theirs.joint_ids
    assert ours.assignments == theirs.assignments
    np.testing.assert_array_equal(ours.joint_actors, theirs.joint_actors)


@pytest.mark.parametrize("kind", sorted(GENERATED))
def test_info_matches_cli_info(kind, cli, tmp_path):
    pattern = GENERATED[kind][0]()
    path = tmp_path / "p.pmml"
    foldkit.write_pmml(str(path), pattern)
    rc, expected, err = cli("info", path)
    assert rc == 0, err
    ours = pattern.info()
    np.testing.assert_allclose(ours.pop("bounds"), expected.pop("bounds"), atol=1e-12)
    assert ours == expected


def test_pattern_facts_are_consistent():
    p = foldkit.generators.miura(4, 4)
    n = len(p.joint_ids)
    assert p.vertices.shape == (len(p.boundary_vertices), 2)
    assert p.joint_vertices.shape == (n, 2) and p.joint_actors.shape == (n, 2)
    assert len(p.assignments) == len(p.springs) == len(p.dampings) == n
    # Crease directions are unit vectors along each joint's segment.
    d = p.crease_directions
    np.testing.assert_allclose(np.linalg.norm(d, axis=1), 1.0)
    seg = p.vertices[p.joint_vertices[:, 1]] - p.vertices[p.joint_vertices[:, 0]]
    np.testing.assert_allclose(d, seg / np.linalg.norm(seg, axis=1)[:, None])
    for star in p.interior_vertices:
        assert sum(star.sectors) == pytest.approx(2 * math.pi)
        assert not p.boundary_vertices[star.vertex]
    assert p.joint_index(p.joint_ids[7]) == 7 and p.joint_index(-12345) is None
    assert p.actor_index(p.actor_ids[3]) == 3
    assert np.all(p.flat() == 0) and p.flat().shape == (n,)
    assert p.diagonal == pytest.approx(np.linalg.norm(p.vertices.max(0) - p.vertices.min(0)))


def test_single_vertex_sectors():
    sectors = foldkit.generators.random_sectors(9, seed=4)
    assert sectors == foldkit.generators.random_sectors(9, seed=4)
    assert sum(sectors) == pytest.approx(2 * math.pi) and min(sectors) >= 0.05
    p = foldkit.generators.single_vertex(sectors)
    (star,) = p.interior_vertices
    np.testing.assert_allclose(sorted(star.sectors), sorted(sectors), atol=1e-9)


@pytest.mark.parametrize("call", [
    lambda: foldkit.generators.miura(0, 3),
    lambda: foldkit.generators.miura(3, 3, angle=2.0),
    lambda: foldkit.generators.grid(3, 3, cell=-1),
    lambda: foldkit.generators.single_vertex([1.0, 1.0, 1.0]),
    lambda: foldkit.generators.waterbomb(3000, 3000),
    lambda: foldkit.generators.strip(3, spring=float("nan")),
])
def test_generators_refuse_bad_arguments(call):
    with pytest.raises(ValueError):
        call()


def test_pmml_round_trip(tmp_path):
    p = foldkit.generators.waterbomb(2, 2)
    q = foldkit.parse_pmml(foldkit.pmml_text(p), "x.pmml")
    np.testing.assert_allclose(p.vertices, q.vertices)
    assert p.joint_ids == q.joint_ids and p.assignments == q.assignments
    path = tmp_path / "w.pmml"
    foldkit.write_pmml(str(path), p)
    assert foldkit.load_pattern(str(path)).joint_ids == p.joint_ids
    assert [f.name for f in tmp_path.iterdir()] == ["w.pmml"]  # no temporary left behind


def joint_order(p, q):
    """For each joint of q, the index of the joint of p with the same two ends (FOLD numbers its
    edges anew)."""
    def key(pattern, j):
        a, b = pattern.joint_vertices[j]
        return frozenset(tuple(np.round(pattern.vertices[k], 9)) for k in (a, b))
    index = {key(p, j): j for j in range(len(p.joint_ids))}
    return np.array([index[key(q, j)] for j in range(len(q.joint_ids))])


def test_fold_file_sign_is_opposite(tmp_path):
    p = foldkit.generators.miura(3, 3)
    state = foldkit.fold(p, fraction=0.3, collisions=False, replay=False).states[-1]
    path = tmp_path / "m.fold"
    foldkit.write_fold(str(path), p, state=state)
    # FOLD's edges_foldAngle is in degrees with positive = valley, read here without foldkit.
    doc = json.loads(path.read_text())
    fold_angles = sorted(a for a in doc["edges_foldAngle"] if a != 0)
    ours = sorted(-math.degrees(a) for a in state if a != 0)
    np.testing.assert_allclose(fold_angles, ours, atol=1e-9)
    back = foldkit.read_fold(str(path))
    np.testing.assert_allclose(back.state, state[joint_order(p, back.pattern)], atol=1e-12)


def test_fold_frames_round_trip(tmp_path):
    p = foldkit.generators.miura(2, 2)
    states = foldkit.fold(p, fraction=0.2, collisions=False, replay=False).states
    text = foldkit.fold_text(p, state=states[-1], frames=states[::5])
    back = foldkit.parse_fold(text, "f.fold")
    np.testing.assert_allclose(back.frames, states[::5][:, joint_order(p, back.pattern)], atol=1e-12)


def test_cmml_round_trip(tmp_path):
    p = foldkit.generators.miura(3, 3)
    state = foldkit.fold(p, fraction=0.4, collisions=False, replay=False).states[-1]
    seq = foldkit.sequence_to(p, state, speed=0.5, title="to 0.4")
    path = tmp_path / "s.cmml"
    foldkit.write_cmml(str(path), seq)
    back = foldkit.read_cmml(str(path))
    assert back.source == str(path) and back.title == "to 0.4" and len(back) == 1
    np.testing.assert_allclose(back.end_state(p), state, atol=1e-9)  # degrees in the file, shortest round trip
    np.testing.assert_allclose(foldkit.read_state(p, str(path)), state, atol=1e-9)
    assert back.check(p) == []


def test_sequences_built_in_python():
    p = foldkit.generators.strip(3)
    a, b = p.joint_ids
    seq = foldkit.FoldSequence([
        foldkit.FoldEvent(1, [foldkit.FoldCommand(a, 0.5, 1.0)]),
        foldkit.FoldEvent(2, [foldkit.FoldCommand(b, -0.25, 2.0)]),
    ], title="two")
    np.testing.assert_allclose(seq.event_states(p), [[0, 0], [0.5, 0], [0.5, -0.25]])
    with pytest.raises(ValueError):
        foldkit.FoldSequence([foldkit.FoldEvent(2, []), foldkit.FoldEvent(1, [])])
    with pytest.raises(ValueError):
        foldkit.FoldCommand(a, 0.5, speed=0.0)
    bad = foldkit.FoldSequence([foldkit.FoldEvent(1, [foldkit.FoldCommand(99, 0.5)])])
    assert len(bad.check(p)) == 1 and "99" in bad.check(p)[0]


def test_path_sequence_passes_every_waypoint():
    p = foldkit.generators.miura(2, 3)
    states = foldkit.fold(p, fraction=0.3, collisions=False, replay=False).states[::10]
    seq = foldkit.path_sequence(p, states, max_speed=0.7)
    np.testing.assert_allclose(seq.event_states(p)[1:], states[1:], atol=1e-12)


def test_speed_keywords_renamed_by_issue_37_still_work_with_a_warning():
    """speed (the CMML's <Velocity>, rad/s) replaced velocity; the old names work for one release."""
    p = foldkit.generators.miura(2, 3)
    states = foldkit.fold(p, fraction=0.3, collisions=False, replay=False).states[::10]
    new = foldkit.path_sequence(p, states, max_speed=0.7)
    with pytest.warns(DeprecationWarning, match="max_speed"):
        old = foldkit.path_sequence(p, states, max_velocity=0.7)
    assert [f.speed for e in old.events for f in e.folds] == [f.speed for e in new.events for f in e.folds]
    with pytest.warns(DeprecationWarning, match="speed"):
        assert foldkit.sequence_to(p, states[-1], velocity=0.25).events[0].folds[0].speed == 0.25
    with pytest.warns(DeprecationWarning, match="speed"):
        command = foldkit.FoldCommand(1, 0.5, velocity=2.0)
    assert command.speed == 2.0 and "speed=2.0" in repr(command)
    with pytest.warns(DeprecationWarning, match="speed"):
        assert command.velocity == 2.0
    with pytest.raises(TypeError, match="not both"):
        foldkit.FoldCommand(1, 0.5, speed=3.0, velocity=2.0)
    result = foldkit.fold(p, fraction=0.3, collisions=False, replay=False)
    with pytest.warns(DeprecationWarning, match="seconds"):
        assert result.time == result.seconds > 0


def test_svg_is_written(tmp_path):
    p = foldkit.generators.boat()
    path = tmp_path / "b.svg"
    foldkit.write_svg(str(path), p, joint_ids=True)
    assert path.read_text().lstrip().startswith("<") and "<svg" in path.read_text()


def test_shapes_and_chains(tmp_path):
    grid = tmp_path / "l.txt"
    grid.write_text("##.\n###\n")
    np.testing.assert_array_equal(foldkit.read_shape(str(grid)), [[1, 1, 0], [1, 1, 1]])
    chain = tmp_path / "c.txt"
    chain.write_text("0 0\n1 0\n1 1\n")
    np.testing.assert_allclose(foldkit.read_chain(str(chain)), [[0, 0], [1, 0], [1, 1]])


def test_read_pattern_takes_an_svg_with_its_targets_as_the_cli_does(tmp_path, cli):
    """An SVG in Origami Simulator's convention: the pattern the CLI's convert writes as PMML, and
    the targets as the state (mountain positive)."""
    svg = tmp_path / "sq.svg"
    svg.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg">\n'
        '<rect stroke="#000" fill="none" x="0" y="0" width="10" height="10"/>\n'
        '<line stroke="#f00" stroke-opacity="0.5" x1="0" y1="0" x2="10" y2="10"/>\n'
        '<line stroke="#00f" x1="10" y1="0" x2="0" y2="10"/>\n</svg>\n')
    f = foldkit.read_pattern(str(svg))
    assert len(f.pattern.joint_ids) == 4 and f.warnings == []
    state = dict(zip(f.pattern.assignments, f.state))
    assert state["M"] == pytest.approx(np.pi / 2) and state["V"] == pytest.approx(-np.pi)
    rc, _, err = cli("convert", str(svg), str(tmp_path / "sq.pmml"), json_out=False)
    assert rc == 0, err
    q = foldkit.read_pmml(str(tmp_path / "sq.pmml"))
    np.testing.assert_allclose(sorted(map(tuple, q.vertices)), sorted(map(tuple, f.pattern.vertices)))
    assert foldkit.load_pattern(str(svg)).joint_ids == f.pattern.joint_ids
    with pytest.raises(ValueError, match=r"\.pmml, \.fold, \.svg, \.cp or \.opx"):
        foldkit.read_pattern(str(tmp_path / "notes.txt"))
