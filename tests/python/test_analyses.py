"""chaser.thrusters and chaser.fdi_design against the JSON files of `chaser thrusters --json` and
`chaser fdi design --out`: the same figures, number arrays as NumPy arrays."""
import json

import numpy as np
import pytest

import chaser
from conftest import MSR, run_cli


def assert_same_document(got, expected, where="$"):
    """A Python document (NumPy arrays for the number arrays) equal to the JSON one, to the bit."""
    if isinstance(got, np.ndarray):
        want = np.asarray(expected)
        assert got.shape == want.shape and got.dtype == (np.int64 if want.dtype.kind == "i" else np.float64), where
        assert got.tobytes() == want.astype(got.dtype).tobytes(), where
    elif isinstance(got, dict):
        assert isinstance(expected, dict) and list(got) == list(expected), where
        for key in got:
            assert_same_document(got[key], expected[key], f"{where}.{key}")
    elif isinstance(got, list):
        assert isinstance(expected, list) and len(got) == len(expected), where
        for i, (g, e) in enumerate(zip(got, expected)):
            assert_same_document(g, e, f"{where}[{i}]")
    else:
        assert type(got) is type(expected) and got == expected, (where, got, expected)


def test_thrusters_are_the_command_lines_json(cli, tmp_path):
    shown = run_cli(cli, "thrusters", MSR, "--json", tmp_path / "t.json")
    assert shown.returncode == 0, shown.stderr
    expected = json.loads((tmp_path / "t.json").read_text())
    got = chaser.thrusters(chaser.load_scenario(str(MSR)))
    assert_same_document(got, expected)
    start = got["sets"][0]
    assert start["configuration_matrix_columns"].shape == (len(start["thrusters"]), 6)
    assert start["attainable"].shape == (12,) and start["attainable"].dtype == np.float64
    assert len(got["sets"]) == 2  # MSR: the set at the start and branch B after a switch


def test_fdi_design_is_the_command_lines_json(cli, tmp_path):
    shown = run_cli(cli, "fdi", "design", MSR, "--model", "attitude", "--out", tmp_path / "d.json")
    assert shown.returncode == 0, shown.stderr
    expected = json.loads((tmp_path / "d.json").read_text())
    got = chaser.fdi_design(str(MSR), model="attitude")
    assert_same_document(got, expected)
    assert got["inputs"]["name"] == "attitude"
    assert got["L"].ndim == 2 and got["A_bar"].shape[0] == got["A_bar"].shape[1]
    assert chaser.fdi_design(str(MSR))["inputs"]["name"] == "position"


def test_bad_analysis_arguments_raise():
    with pytest.raises(ValueError, match="model: position or attitude"):
        chaser.fdi_design(str(MSR), model="orbit")
    with pytest.raises(TypeError, match="scenario"):
        chaser.thrusters(None)
    with pytest.raises(chaser.ScenarioError):
        chaser.thrusters(str(MSR) + ".missing")
