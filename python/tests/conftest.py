"""Shared helpers of the Python tests: the command to compare with, and its output."""

import csv
import json
import os
import pathlib
import subprocess

import pytest


@pytest.fixture(scope="module")
def cli():
    """Path of the `hypergas` command (ctest sets HYPERGAS_CLI)."""
    path = os.environ.get("HYPERGAS_CLI")
    if not path:
        here = pathlib.Path(__file__).resolve().parents[2]
        path = str(here / "build" / "sim" / "hypergas")
    if not os.path.exists(path):
        pytest.fail(f"the hypergas command is not built: {path}")
    return path


def run_cli(cli, out, *args):
    """Runs `hypergas run ... --out out --json`; returns (summary, moments rows, histogram)."""
    r = subprocess.run([cli, "run", *map(str, args), "--out", str(out), "--json"],
                       capture_output=True, text=True, check=True)
    summary = json.loads(r.stdout.strip().splitlines()[-1])
    with open(out / "moments.csv") as f:
        rows = list(csv.DictReader(f))
    with open(out / "speed_histogram.csv") as f:
        hist = list(csv.DictReader(f))
    return summary, rows, hist
