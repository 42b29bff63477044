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
