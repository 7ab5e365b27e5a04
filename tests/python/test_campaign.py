"""chaser.campaign against `chaser campaign`: the same scenario, runs and seed give the same rows,
summary and files; threads and the progress display change nothing."""
import csv
import json
import math
import os
import signal
import sys
import threading
import time
import types
from pathlib import Path

import numpy as np
import pytest

import chaser
from conftest import MSR, SHORT_CAMPAIGN, run_cli, set_args

TARGETS = ["P_nd<=0.5@0.9", "capture_rate>=0.5@0.9"]
FILES = ["campaign.json", "runs.csv", "glr_runs.csv", "summary.csv", "summary.md", "glr_envelope.csv"]


@pytest.fixture(scope="module")
def short_msr():
    return chaser.load_scenario(str(MSR), overrides=SHORT_CAMPAIGN)


@pytest.fixture(scope="module")
def cli_campaign(cli, tmp_path_factory):
    """The command line's campaign: every case, 2 runs each, seed 5, two threads."""
    out = tmp_path_factory.mktemp("cli") / "campaign"
    shown = run_cli(cli, "campaign", MSR, *set_args(SHORT_CAMPAIGN), "--runs", 2, "--seed", 5, "--threads", 2,
                    "--out", out, "--target", TARGETS[0], "--target", TARGETS[1])
    assert shown.returncode == 0, shown.stderr
    return out


@pytest.fixture(scope="module")
def py_campaign(short_msr, tmp_path_factory):
    out = tmp_path_factory.mktemp("py") / "campaign"
    return chaser.campaign(short_msr, runs=2, seed=5, threads=2, out=str(out), progress=False, targets=TARGETS)


def csv_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def same_value(expected_text, value):
    """A runs.csv field against the array's value: numbers to the bit (nan as nan), flags as bools."""
    if isinstance(value, (bool, np.bool_)):
        return expected_text == ("1" if value else "0")
    if isinstance(value, (np.floating, float)):
        expected = float(expected_text)
        return (math.isnan(expected) and math.isnan(value)) or np.float64(expected).tobytes() == np.float64(value).tobytes()
    if isinstance(value, (np.integer, int)):
        return int(expected_text) == int(value)
    return expected_text == str(value)


def test_the_runs_are_the_command_lines_runs_csv(cli_campaign, py_campaign):
    rows = csv_rows(cli_campaign / "runs.csv")
    runs = py_campaign.runs
    assert list(runs.dtype.names) == list(rows[0].keys())
    assert len(runs) == len(rows) == 10
    for i, row in enumerate(rows):
        for name, text in row.items():
            assert same_value(text, runs[name][i]), (i, name, text, runs[name][i])
    assert runs.dtype["seed"] == np.uint64 and runs.dtype["run"] == np.int64
    assert runs.dtype["capture"] == np.bool_ and runs.dtype["onset_s"] == np.float64
    assert list(runs["case"][::2]) == ["none", "stuck_open", "stuck_closed", "leak", "loss"]


def test_the_directory_holds_the_command_lines_bytes(cli_campaign, py_campaign):
    for name in FILES:
        assert (cli_campaign / name).read_bytes() == (Path(py_campaign.out) / name).read_bytes(), name


def test_the_summary_is_summary_csv_and_campaign_json(cli_campaign, py_campaign):
    rows = csv_rows(cli_campaign / "summary.csv")
    assert sum(len(cases) for cases in py_campaign.summary.values()) == len(rows) == 30  # 6 schemes x 5 cases
    for row in rows:
        got = py_campaign.summary[row["scheme"]][row["case"]]
        assert list(got) == [k for k in row if k not in ("scheme", "case")]
        for name, value in got.items():
            assert same_value(row[name], value), (row["scheme"], row["case"], name)
        assert isinstance(got["runs"], int) and isinstance(got["P_f"], float)
    assert py_campaign.campaign == json.loads((cli_campaign / "campaign.json").read_text())
    assert py_campaign.summary_md == (cli_campaign / "summary.md").read_text()
    assert py_campaign.campaign["campaign_seed"] == 5
    assert "### Targets (--target)" in py_campaign.summary_md and "`P_nd<=0.5@0.9`: P_nd <= 50 %" in py_campaign.summary_md


def test_two_shards_are_the_whole_campaign(short_msr, py_campaign):
    shards = [chaser.campaign(short_msr, runs=2, seed=5, threads=1, progress=False, shard=f"{i}/2") for i in (0, 1)]
    assert [len(s.runs) for s in shards] == [5, 5]
    assert np.concatenate([s.runs for s in shards]).tobytes() == py_campaign.runs.tobytes()
    assert shards[1].campaign["shard"] == [1, 2]


def test_resume_finishes_a_cut_campaign_with_the_same_files(short_msr, py_campaign, tmp_path):
    whole = Path(py_campaign.out)
    cut = tmp_path / "cut"
    chaser.campaign(short_msr, runs=2, seed=5, threads=2, out=str(cut), progress=False, targets=TARGETS)
    text = (cut / "runs.csv").read_text()
    lines = text.splitlines(keepends=True)
    (cut / "runs.csv").write_text("".join(lines[:5]) + lines[5][:40])  # header, 4 rows, a torn 5th
    (cut / "summary.csv").unlink()
    resumed = chaser.campaign(short_msr, runs=2, seed=5, threads=2, out=str(cut), progress=False, targets=TARGETS,
                              resume=True)
    for name in FILES:
        assert (cut / name).read_bytes() == (whole / name).read_bytes(), name
    assert resumed.runs.tobytes() == py_campaign.runs.tobytes()


def test_keep_telemetry_keeps_the_first_runs_files(short_msr, tmp_path):
    chaser.campaign(short_msr, runs=1, cases="none,leak", threads=1, out=str(tmp_path / "c"), progress=False,
                    keep_telemetry=1)
    assert (tmp_path / "c" / "runs" / "0" / "telemetry.csv").is_file()
    assert (tmp_path / "c" / "runs" / "0" / "summary.json").is_file()
    assert not (tmp_path / "c" / "runs" / "1").exists()


def test_campaign_run_is_the_campaigns_run(cli, short_msr, py_campaign, tmp_path):
    """chaser.campaign_run(scenario, I, ...) flies run I of that campaign alone: its figures are the
    campaign's row to the bit, and its summary and telemetry are those of `chaser campaign ... --rerun I`."""
    for i in (0, 7):  # fault-free, and a stuck-closed run
        r = chaser.campaign_run(short_msr, i, runs=2, seed=5)
        row = py_campaign.runs[i]
        assert np.float64(r.summary["propellant_used_kg"]).tobytes() == np.float64(row["propellant_kg"]).tobytes()
        assert r.summary["seed"] == int(row["seed"])
        assert r.summary["capture_achieved"] == bool(row["capture"])
    out = tmp_path / "rerun"
    shown = run_cli(cli, "campaign", MSR, *set_args(SHORT_CAMPAIGN), "--runs", 2, "--seed", 5, "--rerun", 7,
                    "--out", out)
    assert shown.returncode == 0, shown.stderr
    summary = json.loads((out / "summary.json").read_text())
    for key in ("propellant_used_kg", "final_position_error_m", "fdir", "active_check_pulses"):
        assert summary[key] == json.loads(json.dumps(r.summary[key], default=float)), key
    with open(out / "telemetry.csv", newline="") as f:
        header = next(csv.reader(f))
    assert list(r.telemetry.keys()) == header
    with pytest.raises(ValueError, match=r"run: must be in \[0, 9\] for this campaign \(got 10\)"):
        chaser.campaign_run(short_msr, 10, runs=2, seed=5)


def test_one_thread_and_two_give_the_same_runs(short_msr):
    one = chaser.campaign(short_msr, runs={"none": 2, "leak": 2}, seed=9, threads=1, progress=False)
    two = chaser.campaign(short_msr, runs="none=2,leak=2", seed=9, threads=2, progress=False)
    assert one.runs.tobytes() == two.runs.tobytes()
    assert one.summary == two.summary or json.dumps(one.summary) == json.dumps(two.summary)  # nan != nan
    assert one.out is None and list(one.runs["case"]) == ["none", "none", "leak", "leak"]
    three = chaser.campaign(short_msr, runs=2, cases=["leak"], seed=10, threads=2, progress=False)
    assert three.runs["seed"].tolist() != one.runs["seed"][2:].tolist()


def test_a_progress_function_is_called_and_changes_nothing(short_msr):
    calls = []
    seen = chaser.campaign(short_msr, runs=1, seed=3, threads=2, progress=lambda *c: calls.append(c))
    plain = chaser.campaign(short_msr, runs=1, seed=3, threads=2, progress=False)
    assert seen.runs.tobytes() == plain.runs.tobytes()
    assert calls and calls[-1][:2] == (5, 5)
    assert [done for done, _, _ in calls] == sorted(done for done, _, _ in calls)


def test_the_progress_line_goes_to_sys_stderr_when_asked(short_msr, capsys):
    chaser.campaign(short_msr, runs=1, cases="none", threads=1, progress=True)
    err = capsys.readouterr().err
    assert err.startswith("\rcampaign: ") and "1/1 runs" in err and err.endswith("diverged   \n")
    chaser.campaign(short_msr, runs=1, cases="none", threads=1)  # stderr is not a terminal here
    assert capsys.readouterr().err == ""


def test_an_exception_in_the_progress_function_is_raised_after_the_runs(short_msr, tmp_path):
    def fail(done, total, diverged):
        raise RuntimeError("display broke")

    with pytest.raises(RuntimeError, match="display broke"):
        chaser.campaign(short_msr, runs=1, seed=3, threads=2, out=str(tmp_path / "c"), progress=fail)
    plain = chaser.campaign(short_msr, runs=1, seed=3, threads=2, progress=False)
    assert len(csv_rows(tmp_path / "c" / "runs.csv")) == 5
    assert (tmp_path / "c" / "summary.md").read_text() == plain.summary_md


def test_python_threads_run_while_the_campaign_does(short_msr):
    done, ticks = [], 0
    worker = threading.Thread(target=lambda: done.append(
        chaser.campaign(short_msr, runs=12, seed=3, threads=1, progress=False)))
    start = time.perf_counter()
    worker.start()
    while worker.is_alive():
        ticks += 1
        time.sleep(0.001)
    elapsed = time.perf_counter() - start
    assert done and len(done[0].runs) == 60
    # With the GIL held for the campaign this thread would not run until it returned: 4 ticks in
    # 0.07 s when tried, against one per millisecond or so with it released.
    assert ticks >= 15, (ticks, elapsed)


def test_ctrl_c_stops_the_runs_and_resume_finishes_them(short_msr, tmp_path):
    """SIGINT while the GIL is released: the campaign stops taking runs and raises KeyboardInterrupt;
    its rows are a prefix of the whole campaign's, and resume=True writes the whole one's files."""
    stopped, whole = tmp_path / "stopped", tmp_path / "whole"
    timer = threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt, match="stopped after"):
            chaser.campaign(short_msr, runs=40, seed=8, threads=2, out=stopped, progress=False)
    finally:
        timer.cancel()
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    done = (stopped / "runs.csv").read_text()
    chaser.campaign(short_msr, runs=40, seed=8, threads=2, out=whole, progress=False)
    assert len(done.splitlines()) < 201 and (whole / "runs.csv").read_text().startswith(done)
    assert not (stopped / "summary.csv").exists()
    chaser.campaign(short_msr, runs=40, seed=8, threads=2, out=stopped, progress=False, resume=True)
    for name in FILES:
        assert (stopped / name).read_bytes() == (whole / name).read_bytes(), name


def test_out_may_be_a_path_object(short_msr, tmp_path):
    result = chaser.campaign(short_msr, runs=1, cases="none", threads=1, out=tmp_path / "c", progress=False)
    assert result.out == str(tmp_path / "c") and (tmp_path / "c" / "runs.csv").is_file()


def test_bad_arguments_raise_clear_errors(short_msr, tmp_path):
    with pytest.raises(ValueError, match="--runs"):
        chaser.campaign(short_msr, runs=0)
    with pytest.raises(ValueError, match="nonesuch"):
        chaser.campaign(short_msr, cases="none,nonesuch")
    with pytest.raises(ValueError, match="threads: must be >= 1"):
        chaser.campaign(short_msr, runs=1, threads=0)
    with pytest.raises(TypeError, match="runs"):
        chaser.campaign(short_msr, runs=True)
    with pytest.raises(TypeError, match="progress"):
        chaser.campaign(short_msr, runs=1, progress="yes")
    with pytest.raises(TypeError, match="scenario"):
        chaser.campaign(42, runs=1)
    with pytest.raises(chaser.ScenarioError):
        chaser.campaign(str(tmp_path / "nowhere.yaml"), runs=1)
    with pytest.raises(ValueError, match="--shard"):
        chaser.campaign(short_msr, runs=1, shard="2/2")
    with pytest.raises(ValueError, match="keep_telemetry: must be >= 0"):
        chaser.campaign(short_msr, runs=1, out=str(tmp_path / "k"), keep_telemetry=-1)
    with pytest.raises(ValueError, match="--target"):
        chaser.campaign(short_msr, runs=1, targets=["P_nd is small"])
    with pytest.raises(ValueError, match="need out=DIR"):
        chaser.campaign(short_msr, runs=1, resume=True)
    with pytest.raises(TypeError):
        chaser.campaign(short_msr, 1, None, 1, 1, None, False, "0/1")  # the command's rarer options: keywords only
    chaser.campaign(short_msr, runs=1, cases="none", out=str(tmp_path / "c"), progress=False)
    with pytest.raises(ValueError, match="already holds a campaign"):
        chaser.campaign(short_msr, runs=1, cases="none", out=str(tmp_path / "c"), progress=False)


def test_a_path_is_loaded_as_load_scenario_loads_it(tmp_path):
    short = tmp_path / "short.yaml"
    text = MSR.read_text()
    short.write_text(text)
    by_path = chaser.campaign(short, runs=1, cases="leak", seed=4, threads=1, progress=False)
    loaded = chaser.campaign(chaser.load_scenario(str(short)), runs=1, cases="leak", seed=4, threads=1, progress=False)
    assert by_path.campaign == loaded.campaign


def test_to_pandas_says_what_it_needs_without_pandas(short_msr, monkeypatch):
    result = chaser.campaign(short_msr, runs=1, cases="none", threads=1, progress=False)
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas now raises ImportError
    with pytest.raises(ImportError, match="python3-pandas"):
        result.to_pandas()


def test_to_pandas_hands_the_runs_array_to_pandas_dataframe(short_msr, monkeypatch):
    """Where pandas is not installed (Debian: python3-pandas), a stand-in shows what is called."""
    result = chaser.campaign(short_msr, runs=1, cases="none", threads=1, progress=False)
    monkeypatch.setitem(sys.modules, "pandas", types.SimpleNamespace(DataFrame=lambda table: ("frame", table)))
    frame = result.to_pandas()
    assert frame[0] == "frame" and frame[1] is result.runs


def test_to_pandas_is_the_runs_table(short_msr):
    pandas = pytest.importorskip("pandas")
    result = chaser.campaign(short_msr, runs=1, threads=1, progress=False)
    frame = result.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == list(result.runs.dtype.names) and len(frame) == 5
    assert frame["seed"].tolist() == result.runs["seed"].tolist()


def test_a_capture_campaigns_runs_have_the_reachs_fields(tmp_path):
    """A scenario with a capture section: runs.csv has the reach's columns, and so has the array,
    value for value (one run cut to 30 s of the reach)."""
    capture = chaser.load_scenario(str(MSR.parent / "comrade_capture.yaml"),
                                   overrides=["duration_s=2790", "campaign.horizon_after_onset_s=1290"])
    c = chaser.campaign(capture, runs=1, cases="none", threads=1, out=str(tmp_path / "c"), progress=False)
    rows = csv_rows(tmp_path / "c" / "runs.csv")
    assert "reach_max_rate_z_deg_s" in c.runs.dtype.names
    assert list(c.runs.dtype.names) == list(rows[0].keys())
    for name in ("reach_final_error_x_m", "reach_peak_joint_torque_Nm", "reach_table2_met", "grasp_captured_s",
                 "grasp_table2_met"):
        assert same_value(rows[0][name], c.runs[name][0]), name
    assert 0 < c.runs["reach_peak_joint_torque_Nm"][0] < 176
    assert np.isnan(c.runs["grasp_captured_s"][0])  # cut before the approach: no grasp
