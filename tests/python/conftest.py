"""Shared by the Python module's tests: the repository, the `chaser` program and the MSR scenario.

CTest sets PYTHONPATH to <build>/python (the module) and CHASER_CLI to the program
(tests/python/CMakeLists.txt); by hand: PYTHONPATH=build/python CHASER_CLI=build/cli/chaser
/usr/bin/python3 -m pytest tests/python.
"""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
MSR = REPO / "scenarios" / "msr_terminal.yaml"
# Wall-clock timings: the only summary values two runs of one scenario and seed may differ in.
WALL_KEYS = {"wall_s", "wall_design_s", "wall_loop_s", "wall_files_s", "simulated_s_per_wall_s"}


@pytest.fixture(scope="session")
def cli():
    path = Path(os.environ.get("CHASER_CLI", REPO / "build" / "cli" / "chaser"))
    assert path.is_file(), f"{path}: build the chaser program first (or set CHASER_CLI)"
    return path


def run_cli(cli, *args):
    return subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True)


def without_wall(value):
    """A summary with its wall-clock timings taken out, at any depth."""
    if isinstance(value, dict):
        return {k: without_wall(v) for k, v in value.items() if k not in WALL_KEYS}
    if isinstance(value, list):
        return [without_wall(v) for v in value]
    return value


def read_summary(run_dir):
    return json.loads((Path(run_dir) / "summary.json").read_text())


def assert_same_bits(a, b, name):
    a, b = np.ascontiguousarray(a, dtype=np.float64), np.ascontiguousarray(b, dtype=np.float64)
    assert a.shape == b.shape, f"{name}: {a.shape} rows against {b.shape}"
    differ = np.flatnonzero(a.view(np.uint64) != b.view(np.uint64))
    assert differ.size == 0, f"{name}: {differ.size} values differ, first at row {differ[0]}: {a[differ[0]]!r} != {b[differ[0]]!r}"


# A small campaign, as tests/cli sets them up: 120 s runs (onset at 100 s, 20 s after it).
SHORT_CAMPAIGN = ["campaign.onset_s=100", "campaign.horizon_after_onset_s=20"]


def set_args(overrides):
    """--set arguments for the command line."""
    return [a for s in overrides for a in ("--set", s)]
