"""plan(..., experience_framework=...): the same name and meaning as `foldkit plan --experience-framework`
(issue 38, item 4): Thunder recalls from a database the CLI wrote with Lightning, and an unknown
framework is refused before anything is planned or written."""
import pytest

import foldkit


def test_thunder_recalls_from_the_clis_database(cli_experience):
    p, pmml, g8, db = cli_experience
    r = foldkit.plan(p, foldkit.fold(p, fraction=0.7).states[-1], experience=str(db), experience_framework="thunder", seed=2)
    assert r.solved and r.replay.valid
    e = r.experience
    assert e["framework"] == "thunder" and e["recalled"] and e["loaded"] == 1 and e["paths"] == 2
    assert e["states"] >= 2 and e["load_seconds"] >= 0.0 and e["bytes"] == db.stat().st_size
    before = db.read_bytes()
    with pytest.raises(ValueError, match="unknown experience framework 'storm'"):
        foldkit.plan(p, foldkit.fold(p, fraction=0.7).states[-1], experience=str(db), experience_framework="storm")
    assert db.read_bytes() == before
