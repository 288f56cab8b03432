"""Shared fixtures of the Python suite: the built module (PYTHONPATH=build/python) and the
command-line program beside it (CLUMPKIT_BINARY), whose outputs the module must equal bit for
bit."""
import json
import os
import subprocess

import pytest

SOURCE = os.environ.get("CLUMPKIT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


@pytest.fixture(scope="session")
def cli():
    binary = os.environ.get("CLUMPKIT_BINARY")
    if not binary:
        pytest.skip("CLUMPKIT_BINARY not set (ctest sets it)")

    def run(*args, as_json=False):
        out = subprocess.run([binary, *map(str, args)], check=True, capture_output=True, text=True)
        return json.loads(out.stdout) if as_json else out.stdout

    return run


@pytest.fixture(scope="session")
def recipes():
    return os.path.join(SOURCE, "assets", "recipes")


def read_clump_csv(path):
    """Rows x, y, z, r of a clump CSV (comment lines start with #)."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip() or line[0].isalpha():
                continue
            rows.append([float(v) for v in line.split(",")])
    return rows
