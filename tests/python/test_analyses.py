"""chaser.thrusters and chaser.fdi_design against the JSON files of `chaser thrusters --json` and
`chaser fdi design --out`: the same figures, number arrays as NumPy arrays."""
import csv
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


def test_rate_model_is_the_command_lines_json(cli, tmp_path):
    sync = MSR.parent / "comrade_sync.yaml"
    shown = run_cli(cli, "fdi", "design", sync, "--model", "rate", "--out", tmp_path / "r.json")
    assert shown.returncode == 0, shown.stderr
    got = chaser.fdi_design(str(sync), model="rate")
    assert_same_document(got, json.loads((tmp_path / "r.json").read_text()))
    assert got["reduced"]["order"] == 9 and got["full"]["A"].shape == (11, 11)
    with pytest.raises(ValueError, match="chaser.slosh"):
        chaser.fdi_design(str(MSR), model="rate")


def test_observer_bank_is_the_command_lines_json(cli, tmp_path):
    sync = MSR.parent / "comrade_sync.yaml"
    shown = run_cli(cli, "fdi", "design", sync, "--model", "uio-bank", "--out", tmp_path / "b.json")
    assert shown.returncode == 0, shown.stderr
    got = chaser.fdi_design(str(sync), model="uio-bank")
    assert_same_document(got, json.loads((tmp_path / "b.json").read_text()))
    assert len(got["observers"]) == 24 and got["nominal"]["thruster"] == 0
    assert all(o["gamma_sweep"] <= o["gamma"] for o in got["observers"] + [got["nominal"]])
    assert list(got["closest"][0]["blind"]) == [10, 13, 22]  # T1's torque line (docs/fdi_design.md)
    with pytest.raises(ValueError, match="chaser.slosh"):
        chaser.fdi_design(str(MSR), model="uio-bank")


def test_bad_analysis_arguments_raise():
    with pytest.raises(ValueError, match="model: position, attitude, rate or uio-bank"):
        chaser.fdi_design(str(MSR), model="orbit")
    with pytest.raises(TypeError, match="scenario"):
        chaser.thrusters(None)
    with pytest.raises(chaser.ScenarioError):
        chaser.thrusters(str(MSR) + ".missing")


MANUAL_RVD = MSR.parent / "manual_rvd.yaml"


def test_fmea_is_the_command_lines_fmea_csv_and_md(cli, tmp_path):
    shown = run_cli(cli, "fmea", MANUAL_RVD, "--out", tmp_path, "--threads", 2)
    assert shown.returncode == 0, shown.stderr
    with open(tmp_path / "fmea.csv", newline="") as f:
        expected = list(csv.DictReader(f))
    got = chaser.fmea(str(MANUAL_RVD), threads=2)
    rows = got["rows"]
    assert list(rows.dtype.names) == list(expected[0]) and len(rows) == len(expected) == 3 * 41
    for i, row in enumerate(expected):
        for name, text in row.items():
            value = rows[name][i]
            if rows.dtype[name] == np.bool_:
                assert text == ("true" if value else "false"), (i, name)
            elif rows.dtype[name].kind in "if":
                assert float(text) == value, (i, name, text, value)
            else:
                assert text == value, (i, name)
    assert rows.dtype["k_p"] == np.float64 and rows.dtype["risk_rank"] == np.int64
    assert got["markdown"] == (tmp_path / "fmea.md").read_text()
    baseline = got["layouts"]["baseline"]
    assert f"baseline: class I {baseline['class_I']}, class II {baseline['class_II']}, class III {baseline['class_III']}; " \
           f"propellant {baseline['propellant_kg']:.1f} kg" in shown.stdout
    assert list(got["layouts"]) == ["baseline", "scheme_I", "scheme_II"]


def test_fmea_rows_do_not_depend_on_threads_and_overrides_act():
    one = chaser.fmea(str(MANUAL_RVD), threads=1)["rows"]
    assert one.tobytes() == chaser.fmea(str(MANUAL_RVD), threads=2)["rows"].tobytes()
    three_axis = chaser.fmea(str(MANUAL_RVD), threads=2, three_axis=True)["rows"]
    assert len(three_axis) == 3 * 105 and "three_axis" in set(three_axis["table"])
    weaker = chaser.fmea(str(MANUAL_RVD), overrides={"thrusters.1.thrust_N": 50}, threads=2)["rows"]
    assert len(weaker) == len(one) and not np.array_equal(weaker["propellant_kg"], one["propellant_kg"])


def test_bad_fmea_arguments_raise(tmp_path):
    with pytest.raises(ValueError, match="threads: must be >= 1"):
        chaser.fmea(str(MANUAL_RVD), threads=0)
    with pytest.raises(chaser.ScenarioError):
        chaser.fmea(str(tmp_path / "nowhere.yaml"))
    with pytest.raises(chaser.ScenarioError):
        chaser.fmea(str(MANUAL_RVD), overrides={"nonesuch.key": 1})
    without_choices = tmp_path / "no_choices.yaml"
    shipped = MANUAL_RVD.read_text()
    without_choices.write_text(shipped[:shipped.index("\noptimize:")] + "\nfaults: []\n")
    with pytest.raises(ValueError, match="marks no free mounting choice"):
        chaser.fmea(str(without_choices), optimize=True)
    assert len(chaser.fmea(str(without_choices), threads=2)["rows"]) == 3 * 41


# The precision of each history column in the file (cli/fmea_history.cpp): half its last digit.
HISTORY_ROUNDING = {"t_s": 0.05, "vx_mps": 5e-7, "vy_mps": 5e-7, "vz_mps": 5e-7}


def test_fmea_optimize_and_history_are_the_command_lines(cli, tmp_path):
    shown = run_cli(cli, "fmea", MANUAL_RVD, "--out", tmp_path, "--threads", 2, "--optimize", "--history")
    assert shown.returncode == 0, shown.stderr
    got = chaser.fmea(str(MANUAL_RVD), threads=2, optimize=True, history=True)
    assert got["markdown"] == (tmp_path / "fmea.md").read_text()
    with open(tmp_path / "optimize.csv", newline="") as f:
        expected = list(csv.DictReader(f))
    ranked = got["optimize"]
    assert list(ranked.dtype.names) == list(expected[0]) and len(ranked) == len(expected) == 48
    for row, want in zip(ranked, expected):
        for name in ranked.dtype.names:
            value = row[name]
            text = ("true" if value else "false") if ranked.dtype[name].kind == "b" else str(value)
            assert (float(text) == float(want[name])) if ranked.dtype[name].kind in "if" else text == want[name], name
    assert ranked["candidate"][0].startswith("attitude_thrust=")
    with open(tmp_path / "history" / "index.csv", newline="") as f:
        index = list(csv.DictReader(f))
    histories = got["histories"]
    assert list(histories) == [(e["configuration"], e["mode"]) for e in index]
    for entry in index[:: 20]:
        h = histories[(entry["configuration"], entry["mode"])]
        assert h["draws"] == int(entry["draws"]) == 1 and h["draw_seed"] is None and entry["draw_seed"] == ""
        with open(tmp_path / "history" / entry["file"], newline="") as f:
            header = next(csv.reader(f))
        table = np.loadtxt(tmp_path / "history" / entry["file"], delimiter=",", skiprows=1)
        samples = h["samples"]
        assert list(samples.dtype.names) == header and len(samples) == len(table) == 1300
        for c, name in enumerate(header):
            if samples.dtype[name].kind == "i":
                assert np.array_equal(samples[name], table[:, c].astype(np.int64)), name
            elif name.startswith("u"):  # written with 7 significant digits
                assert np.allclose(samples[name], table[:, c], rtol=5e-7, atol=0), name
            else:  # positions and angles to 5 decimals
                assert np.max(np.abs(samples[name] - table[:, c])) <= HISTORY_ROUNDING.get(name, 5e-6) * (1 + 1e-9), name


def test_fmea_history_under_noise_draws_is_the_worst_draw():
    overrides = {"pulses.reading": "paper", "pulses.paper.measurement_noise.draws": 3,
                 "pulses.paper.measurement_noise.seed": 4}
    got = chaser.fmea(str(MANUAL_RVD), overrides=overrides, threads=2, history=True)
    rows = {(r["configuration"], r["mode"]): r for r in got["rows"]}
    lost_to_the_view = 0
    for key, h in got["histories"].items():
        assert h["draws"] == 3 and h["draw_seed"] in (4, 5, 6), key
        peak = np.max(np.abs(h["samples"]["azimuth_deg"]))
        # The draw shown is within the row's worst (fmea.csv's peak is the draws' largest, to 4 decimals),
        # and out of view exactly where the row is Class III for the line of sight.
        assert peak <= rows[key]["peak_azimuth_deg"] + 5e-5, key
        if rows[key]["risk_class"] == "III" and rows[key]["docked"]:
            lost_to_the_view += 1
            assert peak > rows[key]["azimuth_limit_deg"] or \
                np.max(np.abs(h["samples"]["elevation_deg"])) > rows[key]["elevation_limit_deg"], key
    assert lost_to_the_view >= 2  # the baseline's d1/d2~+e2/e1~ and d1/d2~+e2/e2~ at least
