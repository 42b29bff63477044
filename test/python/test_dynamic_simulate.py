"""The dynamic model from Python: the CLI's verdict and numbers, and the closed form m·g·d."""
import math

import numpy as np
import pytest

import foldkit

G = 9.81
LIFT = 1.0 * G * 0.5  # m·g·d of a unit panel of 1 kg/m² hinged on its edge, N·m


def flap_files(tmp_path):
    p = foldkit.generators.strip(2)
    seq = foldkit.sequence_to(p, np.array([math.radians(-60)]), speed=math.radians(30))
    pmml, cmml = tmp_path / "p.pmml", tmp_path / "s.cmml"
    foldkit.write_pmml(str(pmml), p)
    foldkit.write_cmml(str(cmml), seq)
    return p, seq, pmml, cmml


@pytest.mark.parametrize("factor", [0.95, 1.05])
def test_flap_matches_cli(cli, tmp_path, factor):
    p, seq, pmml, cmml = flap_files(tmp_path)
    torque = factor * LIFT
    rc, expected, err = cli("simulate", pmml, cmml, "--model", "dynamic", "--gravity", "0,0,-9.81",
                            "--max-torque", repr(torque))
    r = foldkit.simulate(p, foldkit.read_cmml(str(cmml)), model="dynamic", gravity=(0, 0, -G), max_torque=torque)
    assert r.model == "dynamic" and r.status.code == expected["status"]
    assert r.steps == expected["steps"] and r.duration == pytest.approx(expected["duration"])
    if factor < 1:
        assert rc == 3 and not r.valid and r.status.code == "no-progress"
        assert [s.joint for s in r.stalls] == [1]
        assert r.stalls[0].needed_torque == pytest.approx(LIFT, rel=0.01)
        assert r.stalls[0].available_torque == pytest.approx(torque)
    else:
        assert rc == 0 and r.valid and not r.stalls
        assert r.final_state[0] == pytest.approx(math.radians(-60), abs=2e-4)
        # the torque is read off the joint's wrench, whose hinge rows lean a little with the drift
        assert LIFT * 0.99 <= r.joints[0].peak_torque <= torque * (1 + 1e-3)
        assert r.frames.shape[1] == 1 and len(r.frame_times) == r.frames.shape[0] > 10
        assert r.frame_torques.shape == r.frames.shape
        # Turning steadily between 25° and 35° lifted, the motor carries m·g·d·cos θ.
        steady = (r.frames[:, 0] < math.radians(-25)) & (r.frames[:, 0] > math.radians(-35))
        assert steady.sum() > 10
        np.testing.assert_allclose(-r.frame_torques[steady, 0], LIFT * np.cos(r.frames[steady, 0]), atol=0.01 * LIFT)


def test_dynamic_refuses_bad_physics():
    p = foldkit.generators.strip(2)
    seq = foldkit.sequence_to(p, np.array([0.5]), speed=1.0)
    for kwargs in [{"density": -1.0}, {"max_torque": float("nan")}, {"gravity": (0, 0, float("nan"))}, {"fixed": 99},
                   {"drive": "rocket"}, {"time_step": 0.0}]:
        with pytest.raises(ValueError):
            foldkit.simulate(p, seq, model="dynamic", **kwargs)


def test_kinematic_defaults_unchanged():
    p = foldkit.generators.strip(3)
    seq = foldkit.sequence_to(p, np.array([0.5, -0.5]), speed=1.0)
    r = foldkit.simulate(p, seq)
    assert r.model == "motor" and r.time_step == 0.01


def test_ground_contact_matches_cli_and_closed_form(cli, tmp_path):
    # Panel 2 (0.5 m at scale 0.5) turned down 60° toward a ground 0.25 m below the held panel: its
    # far edge lands where L sin φ + (t/2) cos φ = h (φ ≈ 30°) and the motor is blocked there.
    p = foldkit.generators.strip(2)
    seq = foldkit.sequence_to(p, np.array([math.radians(60)]), speed=math.radians(30))
    pmml, cmml = tmp_path / "p.pmml", tmp_path / "s.cmml"
    foldkit.write_pmml(str(pmml), p)
    foldkit.write_cmml(str(cmml), seq)
    L, h, t = 0.5, 0.25, 0.002
    rc, expected, err = cli("simulate", pmml, cmml, "--model", "dynamic", "--scale", "0.5", "--ground", "-0.25",
                            "--thickness", repr(t))
    r = foldkit.simulate(p, foldkit.read_cmml(str(cmml)), model="dynamic", scale=0.5, ground=-h, thickness=t)
    assert rc == 3 and r.status.code == expected["status"] == "collision"
    assert r.steps == expected["steps"]
    assert [s.blocked_by for s in r.stalls] == [[2]] == [s["blocked_by"] for s in expected["stalls"]]
    assert len(r.contacts) == 1 and r.contacts[0].ground and r.contacts[0].actors == [2]
    assert r.thickness == pytest.approx(t) and r.max_penetration == pytest.approx(expected["max_penetration"])
    phi = math.asin(h / L)
    for _ in range(50):
        phi -= (L * math.sin(phi) + t / 2 * math.cos(phi) - h) / (L * math.cos(phi) - t / 2 * math.sin(phi))
    assert r.final_state[0] == pytest.approx(phi, abs=0.1 * t / L)


def test_joint_torque_start_and_free_sheet():
    p = foldkit.generators.strip(2)
    seq = foldkit.sequence_to(p, np.array([math.radians(-60)]), speed=math.radians(30))
    # A per-joint limit below m·g·d stalls the joint the global limit would lift.
    r = foldkit.simulate(p, seq, model="dynamic", gravity=(0, 0, -G), max_torque=2 * LIFT, joint_torque={1: 0.9 * LIFT})
    assert r.status.code == "no-progress" and r.stalls[0].available_torque == pytest.approx(0.9 * LIFT)
    # Started at the target already, the motor has nothing to do.
    r = foldkit.simulate(p, seq, model="dynamic", start=np.array([math.radians(-60)]))
    assert r.valid and r.joints[0].peak_torque < 1e-6
    # A FoldSequence starts from its end state, as the CLI's --start CMML and plan(start=…) do.
    by_sequence = foldkit.simulate(p, seq, model="dynamic", start=seq)
    assert by_sequence.valid and by_sequence.steps == r.steps and by_sequence.joints[0].peak_torque < 1e-6
    # No actor held and no gravity: the free sheet still folds (the motor turns both panels).
    r = foldkit.simulate(p, seq, model="dynamic", fixed="none")
    assert r.valid and r.final_state[0] == pytest.approx(math.radians(-60), abs=2e-4)
    for kwargs in [{"fixed": "all"}, {"joint_torque": {7: 1.0}}, {"joint_torque": {1: -1.0}}, {"friction": -1.0},
                   {"ground": float("nan")}, {"thickness": 0.0}, {"start": np.array([0.1, 0.2])}]:
        with pytest.raises(ValueError):
            foldkit.simulate(p, seq, model="dynamic", **kwargs)
    # Friction and thickness act on contacts only: with nothing to touch refused, as the CLI refuses them.
    for name, value in [("friction", 0.3), ("thickness", 0.01)]:
        with pytest.raises(ValueError, match=name + " needs contacts or ground"):
            foldkit.simulate(p, seq, model="dynamic", **{name: value})
        r = foldkit.simulate(p, seq, model="dynamic", ground=-1.0, **{name: value})
        assert r.valid and r.contacts == []


def test_iterative_solver_post_stabilised_lifts_the_flap():
    p = foldkit.generators.strip(2)
    seq = foldkit.sequence_to(p, np.array([math.radians(-60)]), speed=math.radians(30))
    r = foldkit.simulate(p, seq, model="dynamic", gravity=(0, 0, -G), max_torque=1.05 * LIFT, solver="iterative",
                         iterations=20, projection_interval=1e-3)
    assert r.valid and r.final_state[0] == pytest.approx(math.radians(-60), abs=2e-4)
    assert r.max_corrected_error == 0.0  # a flap has no loop to correct
    for kwargs in [{"solver": "magic"}, {"iterations": 0}, {"projection_interval": -1.0}]:
        with pytest.raises(ValueError):
            foldkit.simulate(p, seq, model="dynamic", **kwargs)


@pytest.mark.parametrize("kwargs", [{"gravity": (0, 0, -G)}, {"contacts": True}, {"ground": 0.0}, {"fixed": 1},
                                    {"joint_torque": {1: 1.0}}, {"max_torque": 2.0}, {"solver": "iterative"},
                                    {"projection_interval": 0.01}])
def test_physics_options_are_refused_for_the_kinematic_models(kwargs):
    p = foldkit.generators.strip(2)
    seq = foldkit.sequence_to(p, np.array([0.5]), speed=1.0)
    with pytest.raises(ValueError, match="model='dynamic'"):
        foldkit.simulate(p, seq, **kwargs)


def unequal_panels(physics):
    """Actor 1 the unit square, actor 2 the rectangle [1,3]×[0,1], hinged by joint 1 on x = 1."""
    return ("<PMML>\n  <Title>unequal panels</Title>\n" + physics +
            "  <Actor><ID>1</ID><Triangle>0 0 1 0 1 1</Triangle><Triangle>0 0 1 1 0 1</Triangle></Actor>\n"
            "  <Actor><ID>2</ID><Triangle>1 0 3 0 3 1</Triangle><Triangle>1 0 3 1 1 1</Triangle></Actor>\n"
            "  <Joint><ID>1</ID><Coords>1 0 1 1</Coords><ActorIDs>1 2</ActorIDs><SpringConst>0</SpringConst>"
            "<DampConst>0</DampConst></Joint>\n</PMML>\n")


def test_pmml_physics_are_the_defaults_and_keywords_override_them():
    # The file: ρ = 2 kg/m², g down, actor 2 held. At scale 0.5 actor 1 weighs 0.5 kg, its centroid
    # 0.25 m from the hinge; actor 2 twice as heavy, twice as far.
    physics = "  <Density>2</Density>\n  <Gravity>0 0 -9.81</Gravity>\n  <FixedActor>2</FixedActor>\n"
    p = foldkit.parse_pmml(unequal_panels(physics), "panels.pmml")
    seq = foldkit.sequence_to(p, np.array([math.radians(-60)]), speed=math.radians(30))
    lift = 0.5 * G * 0.25

    def needed(limit, **kwargs):
        r = foldkit.simulate(p, seq, model="dynamic", scale=0.5, max_torque=limit, **kwargs)
        assert r.status.code == "no-progress", r.status
        return r.stalls[0].needed_torque

    assert needed(0.95 * lift) == pytest.approx(lift, rel=0.01)
    r = foldkit.simulate(p, seq, model="dynamic", scale=0.5, max_torque=1.05 * lift)
    assert r.valid and r.potential_energy == pytest.approx(lift * math.sin(math.pi / 3), rel=1e-3)
    assert needed(0.45 * lift, density=1.0) == pytest.approx(0.5 * lift, rel=0.01)
    assert needed(1.05 * lift, gravity=(0, 0, -2 * G)) == pytest.approx(2 * lift, rel=0.01)
    assert needed(1.05 * lift, fixed=1) == pytest.approx(4 * lift, rel=0.01)
    # The kinematic models ignore the file's physics (and refuse it only as keywords).
    assert foldkit.simulate(p, seq).valid
