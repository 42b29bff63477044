"""Bad input raises foldkit.ParseError (a ValueError) with the CLI's FILE:LINE: message."""
import numpy as np
import pytest

import foldkit

BAD_PATTERNS = ["non-integer-id.pmml", "truncated.pmml", "huge-number.pmml", "empty.pmml", "degenerate.pmml", "binary.pmml"]
BAD_SEQUENCES = ["nan-angle.cmml", "negative-velocity.cmml", "fractional-event.cmml", "empty.cmml"]
BAD_FOLDS = ["bad-index.fold", "truncated.fold", "huge-number.fold", "binary.fold"]


def first_problem(stderr):
    return stderr.strip().splitlines()[0]


@pytest.mark.parametrize("name", BAD_PATTERNS + BAD_SEQUENCES + BAD_FOLDS)
def test_same_message_as_cli_validate(name, data, cli):
    path = str(data / "bad" / name)
    rc, _, err = cli("validate", path, json_out=False)
    assert rc == 1
    read = {"pmml": foldkit.read_pmml, "cmml": foldkit.read_cmml, "fold": foldkit.read_fold}[name.rsplit(".", 1)[1]]
    with pytest.raises(ValueError) as e:
        read(path)
    assert isinstance(e.value, foldkit.ParseError)
    assert e.value.file == path
    assert str(e.value) == f"{e.value.file}:{e.value.line}: {e.value.message}" or e.value.line == 0
    assert str(e.value) in err, (str(e.value), err)


def test_line_points_at_the_element(data):
    with pytest.raises(foldkit.ParseError) as e:
        foldkit.read_pmml(str(data / "bad" / "non-integer-id.pmml"))
    assert e.value.line == 3 and "must be an integer" in e.value.message


@pytest.mark.parametrize("name", ["nan-force.loadcase", "unknown-actor.loadcase", "truncated.loadcase", "unknown-kind.loadcase"])
def test_bad_load_cases(name, data):
    with pytest.raises(ValueError):
        foldkit.stiffness(foldkit.generators.cube_sheet(1), str(data / "bad" / name))


def test_missing_file():
    with pytest.raises(foldkit.ParseError) as e:
        foldkit.read_cmml("/no/such/file.cmml")
    assert e.value.file == "/no/such/file.cmml" and "cannot open" in str(e.value)


def test_sequence_with_unknown_joint_names_file_and_line(tmp_path):
    p = foldkit.generators.strip(2)
    seq = foldkit.FoldSequence([foldkit.FoldEvent(1, [foldkit.FoldCommand(p.joint_ids[0], 0.2)]),
                                foldkit.FoldEvent(2, [foldkit.FoldCommand(77, 0.5)])])
    path = tmp_path / "bad.cmml"
    foldkit.write_cmml(str(path), seq)
    line = next(i for i, text in enumerate(path.read_text().splitlines(), 1) if ">77<" in text)
    with pytest.raises(foldkit.ParseError) as e:
        foldkit.simulate(p, foldkit.read_cmml(str(path)))
    assert e.value.file == str(path) and str(e.value).startswith(f"{path}:")
    assert abs(e.value.line - line) <= 3  # the <Fold> element that names joint 77
    with pytest.raises(foldkit.ParseError) as e2:
        foldkit.read_state(p, str(path))
    assert e2.value.line == e.value.line


def test_bad_states():
    p = foldkit.generators.miura(1, 2)
    n = len(p.joint_ids)
    for bad in [np.zeros(n + 1), np.full(n, np.nan), np.zeros((2, n)), "flat"]:
        with pytest.raises((ValueError, TypeError)):
            foldkit.dof(p, bad)
        with pytest.raises((ValueError, TypeError)):
            foldkit.project(p, bad)


def test_bad_options():
    p = foldkit.generators.miura(3, 3)
    with pytest.raises(ValueError):
        foldkit.fold(p, fraction=1.5)
    with pytest.raises(ValueError):
        foldkit.fold(p, max_step=2.0)
    with pytest.raises(ValueError):
        foldkit.simulate(p, foldkit.sequence_to(p, p.flat()), model="teleport")
    with pytest.raises(ValueError):
        foldkit.plan(p, p.flat(), planner="NoSuchPlanner")
    with pytest.raises(ValueError):
        foldkit.carpenter(np.array([[0, 0], [1, 0], [0, 0], [1, 0]]))  # not simple
    with pytest.raises(ValueError):
        foldkit.hamiltonian(np.ones(4, dtype=bool))
