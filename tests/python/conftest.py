"""Shared by the pytest tests of the Python module: the source folder, and the command line run as a
user runs it (the built `motostab`, MOTOSTAB_BINARY), its CSV and JSON outputs read back."""
import csv
import json
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("MOTOSTAB_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
WHIPPLE = SOURCE / "scenarios" / "whipple-benchmark.yaml"
ENDURO = SOURCE / "scenarios" / "enduro.yaml"
SUPERSPORT = SOURCE / "scenarios" / "supersport.yaml"
SAMPLE_TIR = SOURCE / "tests" / "data" / "reference" / "MF61-sample-tir" / "sample_MF61_ExternData.tir"


def run_cli(*args, cwd, expect=0):
    """Runs `motostab args...` in `cwd`; asserts its exit code; returns stdout + stderr."""
    binary = os.environ.get("MOTOSTAB_BINARY", str(SOURCE / "build" / "apps" / "motostab"))
    run = subprocess.run([binary, *map(str, args)], cwd=cwd, capture_output=True, text=True, timeout=240)
    assert run.returncode == expect, f"motostab {' '.join(map(str, args))}: exit {run.returncode}\n{run.stdout}{run.stderr}"
    return run.stdout + run.stderr


def read_csv(path):
    """The rows of a CSV file as dicts of text (numbers as the file writes them)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_json(path):
    with open(path) as f:
        return json.load(f)


@pytest.fixture(scope="session")
def motostab():
    import motostab as module
    return module
