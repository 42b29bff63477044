"""Shared fixtures: the CLI the module is checked against, and the test data folder."""
import json
import os
import pathlib
import subprocess

import pytest


@pytest.fixture(scope="session")
def data():
    """test/data (FOLDKIT_TEST_DATA, set by ctest)."""
    return pathlib.Path(os.environ.get("FOLDKIT_TEST_DATA", pathlib.Path(__file__).parents[1] / "data"))


@pytest.fixture(scope="session")
def cli():
    """Runs `foldkit ARGS… --json` and returns (exit code, parsed JSON or None, stderr)."""
    exe = os.environ.get("FOLDKIT_CLI")
    if not exe:
        pytest.skip("FOLDKIT_CLI is not set (run through ctest)")

    def run(*args, json_out=True):
        cmd = [exe, *map(str, args)] + (["--json"] if json_out else [])
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=240)
        out = json.loads(p.stdout) if json_out and p.stdout.strip() else None
        return p.returncode, out, p.stderr

    return run


@pytest.fixture
def cli_experience(cli, tmp_path):
    """A Miura 4×4 and an experience database the CLI wrote planning flat → fraction 0.8 (Lightning):
    returns (pattern, pattern file, goal CMML, database path)."""
    import foldkit

    p = foldkit.generators.miura(4, 4)
    pmml, g8, db = tmp_path / "m.pmml", tmp_path / "g8.cmml", tmp_path / "m.db"
    foldkit.write_pmml(str(pmml), p)
    foldkit.write_cmml(str(g8), foldkit.sequence_to(p, foldkit.fold(p, fraction=0.8).states[-1]))
    rc, out, err = cli("plan", pmml, "--goal", g8, "--experience", db, "-o", tmp_path / "p8.cmml")
    assert rc == 0, err
    assert out["experience"]["framework"] == "lightning" and out["experience"]["paths"] == 1
    return p, pmml, g8, db
