"""chaser.run against `chaser run`: the same scenario and seed give the same bits, in memory and in
the files."""
import numpy as np
import pytest

import chaser
from conftest import MSR, assert_same_bits, read_summary, run_cli, without_wall

T8_STUCK_OPEN = "faults=[{thruster: T8, kind: stuck_open, onset_s: 1000}]"


@pytest.fixture(scope="module")
def cli_run(cli, tmp_path_factory):
    """The command line's MSR run with seed 7 and its T8 fault, telemetry as .npy."""
    out = tmp_path_factory.mktemp("cli")
    shown = run_cli(cli, "run", MSR, "--out", out, "--telemetry", "npy", "--seed", 7, "--set", T8_STUCK_OPEN)
    assert shown.returncode == 0, shown.stderr
    return out


@pytest.fixture(scope="module")
def py_run():
    return chaser.run(chaser.load_scenario(str(MSR), overrides=[T8_STUCK_OPEN]), seed=7)


def test_run_equals_the_command_line_bit_for_bit(cli_run, py_run):
    table = np.load(cli_run / "telemetry.npy")
    assert list(py_run.telemetry) == list(table.dtype.names)
    assert len(table) == 12000
    for name in table.dtype.names:
        assert py_run.telemetry[name].dtype == np.float64
        assert_same_bits(py_run.telemetry[name], table[name], name)
    expected = read_summary(cli_run)
    assert without_wall(py_run.summary) == without_wall(expected)
    assert py_run.summary["seed"] == 7
    assert py_run.summary.keys() == expected.keys()  # the timings are there too


def test_the_fault_is_flown_isolated_and_recovered(py_run):
    fdir = py_run.summary["fdir"]
    assert fdir["isolated_thruster"] == "T8" and fdir["recovered_thruster"] == "T8"
    t, confirmed = py_run.telemetry["t_s"], py_run.telemetry["confirmed_deficit"]
    assert t[0] == 0.0 and t[1] == 0.1 and len(t) == 12000
    assert np.all(confirmed[t < 1000.0] == 0) and 8 in confirmed[t > 1000.0]


def test_out_writes_the_files_of_the_command_line(cli, tmp_path):
    cli_out, py_out = tmp_path / "cli", tmp_path / "py"
    (py_out).mkdir()
    (py_out / "telemetry.npy").write_bytes(b"an earlier run's")  # removed first, as by chaser run
    shown = run_cli(cli, "run", MSR, "--out", cli_out, "--telemetry", "csv", "--channels", "r_lvlh_*,glr_*")
    assert shown.returncode == 0, shown.stderr
    result = chaser.run(chaser.load_scenario(str(MSR)), out=str(py_out), telemetry="csv", channels=["r_lvlh_*", "glr_*"])
    assert (py_out / "telemetry.csv").read_bytes() == (cli_out / "telemetry.csv").read_bytes()
    assert not (py_out / "telemetry.npy").exists()
    assert without_wall(read_summary(py_out)) == without_wall(read_summary(cli_out))
    assert read_summary(py_out) == result.summary
    assert list(result.telemetry)[0] == "t_s" and all(n == "t_s" or n.startswith(("r_lvlh_", "glr_")) for n in result.telemetry)


def test_the_seed_changes_the_draws_and_a_run_repeats():
    scenario = chaser.load_scenario(str(MSR), overrides={"duration_s": 20.0})
    a, b, c = chaser.run(scenario, seed=3), chaser.run(scenario, seed=3), chaser.run(scenario, seed=4)
    assert len(a.telemetry["t_s"]) == 200
    assert_same_bits(a.telemetry["r_lvlh_x_m"], b.telemetry["r_lvlh_x_m"], "r_lvlh_x_m")
    assert not np.array_equal(a.telemetry["r_lvlh_x_m"], c.telemetry["r_lvlh_x_m"])
    assert (a.summary["seed"], c.summary["seed"]) == (3, 4)


def test_bad_run_arguments_raise():
    scenario = chaser.load_scenario(str(MSR), overrides={"duration_s": 1.0})
    with pytest.raises(ValueError):
        chaser.run(scenario, telemetry="xls")
    with pytest.raises(ValueError, match="nonesuch"):
        chaser.run(scenario, channels=["nonesuch_*"])
