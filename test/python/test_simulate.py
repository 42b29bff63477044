"""The simulator from Python: the CLI's verdicts and numbers, frames and poses."""
import math

import numpy as np
import pytest

import foldkit


def files(tmp_path, pattern, sequence):
    pmml, cmml = tmp_path / "p.pmml", tmp_path / "s.cmml"
    foldkit.write_pmml(str(pmml), pattern)
    foldkit.write_cmml(str(cmml), sequence)
    return pmml, cmml


def test_valid_fold_matches_cli(cli, tmp_path):
    p = foldkit.generators.miura(5, 5)
    seq = foldkit.fold(p, fraction=0.7, replay=False).sequence
    pmml, cmml = files(tmp_path, p, seq)
    rc, expected, err = cli("simulate", pmml, cmml)
    assert rc == 0, err
    r = foldkit.simulate(p, foldkit.read_cmml(str(cmml)))
    assert r.valid and r.status.code == expected["status"] == "success"
    assert r.steps == expected["steps"] and r.checks == expected["checks"]
    assert r.duration == pytest.approx(expected["duration"])
    assert r.max_closure_error == pytest.approx(expected["max_closure_error"], rel=1e-9, abs=1e-15)
    assert r.collision_count == 0 and r.problems == []


def test_collision_matches_cli(cli, tmp_path):
    # Three panels, both creases folded 170° the same way: the outer panels cross over the middle.
    p = foldkit.generators.strip(3)
    seq = foldkit.sequence_to(p, np.full(2, math.radians(170)), speed=1.0)
    pmml, cmml = files(tmp_path, p, seq)
    rc, expected, err = cli("simulate", pmml, cmml)
    assert rc == 3, err
    r = foldkit.simulate(p, seq)
    assert not r.valid and r.status.code == expected["status"] == "collision"
    assert r.collision_count == expected["collision_count"] >= 1
    assert tuple(r.collisions[0].actors) in {(p.actor_ids[0], p.actor_ids[2]), (p.actor_ids[2], p.actor_ids[0])}
    assert foldkit.simulate(p, seq, collisions=False).valid


def test_frames_and_poses():
    p = foldkit.generators.miura(3, 3)
    seq = foldkit.fold(p, fraction=0.5, collisions=False, replay=False).sequence
    r = foldkit.simulate(p, seq, poses=True)
    t, f = r.frame_times, r.frames
    assert f.shape == (len(t), len(p.joint_ids)) and len(t) > 10
    assert np.all(np.diff(t) > 0) and t[0] == 0 and r.frame_events[0] == -1
    np.testing.assert_allclose(f[0], 0)
    np.testing.assert_allclose(f[-1], r.final_state)
    np.testing.assert_allclose(r.final_state, seq.end_state(p), atol=1e-9)
    assert r.poses.shape == (len(t), len(p.actor_ids), 4, 4)
    np.testing.assert_allclose(r.poses[-1], foldkit.facet_poses(p, f[-1]))
    quiet = foldkit.simulate(p, seq, record_frames=False)
    # Without recording, only the flat start and each event's end are kept.
    assert quiet.frames.shape[0] == len(seq) + 1 and quiet.poses is None and quiet.steps == r.steps


def test_models():
    p = foldkit.generators.strip(2)
    seq = foldkit.sequence_to(p, np.array([0.5]), speed=0.5)
    for model in ["motor", "spring", "sync"]:
        r = foldkit.simulate(p, seq, model=model)
        assert r.valid and r.model in {"motor", "spring", "sync", "synchronised"}
        assert r.final_state[0] == pytest.approx(0.5, abs=1e-4)
