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
