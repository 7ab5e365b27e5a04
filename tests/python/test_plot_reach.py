"""python/plot_reach.py on a small synthetic run directory (no `chaser` program needed).

Run: /usr/bin/python3 -m pytest tests/python/test_plot_reach.py -q (part of make test)
"""
import json
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
import plot_reach as pr  # noqa: E402

SCENARIO = """
name: fake_reach
chaser:
  arm:
    torque_repeated_peak_Nm: 176.0
    torque_momentary_Nm: 314.0
    links:
""" + "".join("      - {lower_deg: -120, upper_deg: 120}\n" for _ in range(7))


def fake_run(run_dir):
    """100 periods: the arm wakes at row 20 (the gripper's channels NaN before), the gripper closing in on
    the pose as 8 mm, 4 mm, 2 mm times exp(-t/10)."""
    run_dir.mkdir(parents=True)
    t = 0.1 * np.arange(100)
    awake = np.arange(100) >= 20
    columns = {"t_s": t}
    for j in range(1, 8):
        columns[f"q_arm_{j}_rad"] = np.radians(10.0 * j) + 0.0 * t
        columns[f"tau_arm_{j}_Nm"] = np.where(awake, 5.0 * np.sin(t + j), 0.0)
    decay = np.exp(-(t - 2.0) / 10.0)
    for k, (c, size) in enumerate(zip("xyz", (0.008, 0.004, 0.002))):
        for name, value in ((f"gripper_err_{c}_m", size * decay), (f"gripper_v_{c}_mps", -size / 10.0 * decay),
                            (f"gripper_att_err_{c}_rad", 0.001 * decay), (f"gripper_rate_{c}_radps", -1e-4 * decay)):
            columns[name] = np.where(awake, value, np.nan)
    header = ",".join(columns)
    np.savetxt(run_dir / "telemetry.csv", np.column_stack(list(columns.values())), delimiter=",", header=header,
               comments="")
    (run_dir / "summary.json").write_text(json.dumps({"scenario": "fake_reach",
                                                      "reach": {"flown": True, "hold_from_s": 5.0}}))
    scenario = run_dir.parent / "fake_reach.yaml"
    scenario.write_text(SCENARIO)
    return scenario


def test_the_reach_rows_are_those_with_a_gripper():
    t = {"gripper_err_x_m": np.array([np.nan, np.nan, 0.1, 0.2])}
    assert list(pr.reach_rows(t)) == [False, False, True, True]


def test_the_envelope_exceedance_is_the_largest_value_over_its_limit():
    values = np.array([[5.0, -30.0, 1.0], [-9.0, 11.0, 2.0]])
    np.testing.assert_allclose(pr.envelope_exceedance(values, pr.ENVELOPE_MM), [0.9, 30.0 / 22.0, 2.0 / 22.0])


def test_the_arms_limits_come_from_the_scenario(tmp_path):
    import yaml
    scenario = yaml.safe_load(fake_run(tmp_path / "run").read_text())
    lower, upper, repeated, momentary = pr.arm_limits(scenario)
    assert lower == [-120.0] * 7 and upper == [120.0] * 7 and (repeated, momentary) == (176.0, 314.0)


def test_both_pngs_are_written_and_the_envelope_use_printed(tmp_path, capsys):
    scenario = fake_run(tmp_path / "run")
    out = tmp_path / "plots"
    pr.main([str(tmp_path / "run"), "--scenario", str(scenario), "--out", str(out)])
    assert (out / "reach_joints.png").stat().st_size > 10_000
    assert (out / "reach_gripper.png").stat().st_size > 10_000
    # Over the hold (t >= 5 s) the largest x error is 8 mm exp(-0.3) = 5.9 mm: 59 % of 10 mm.
    assert "59%" in capsys.readouterr().out


def test_a_run_without_a_reach_is_refused(tmp_path):
    run = tmp_path / "run"
    run.mkdir()
    (run / "summary.json").write_text(json.dumps({"scenario": "x", "reach": None}))
    with pytest.raises(SystemExit, match="has no reach"):
        pr.main([str(run)])
