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


FIGURE_SCENARIO = """
thrusters:
  list:
    - {name: T1, position_body_m: [1.0, 1.0, 1.25]}
    - {name: T2, position_body_m: [-1.0, -1.0, -1.25]}
target:
  body:
    grasp_point_target_m: [3.9, 0.0, 0.6]
    keep_out:
      - {centre_target_m: [-1.1, 0.0, 0.0], half_extents_m: [5.0, 2.0, 2.0]}
"""


def fake_run(run_dir, figure=False, stabilisation=False, escape=False):
    """100 periods: the arm wakes at row 20 (the gripper's channels NaN before), the gripper closing in on
    the pose as 8 mm, 4 mm, 2 mm times exp(-t/10). With figure, the arm's figure too: the hub at
    (7.4, 0, 0.6) m turned 90 deg about z, the joints on a line to the tool, which moves from 6 m to 4.05 m
    in x over the run."""
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
    if figure:
        half = np.sqrt(0.5)
        for c, v in zip("xyz", (7.4, 0.0, 0.6)):
            columns[f"hub_target_{c}_m"] = np.where(awake, v, np.nan)
        for c, v in zip("wxyz", (half, 0.0, 0.0, half)):
            columns[f"q_target_from_hub_{c}"] = np.where(awake, v, np.nan)
        tool_x = 6.0 - (6.0 - 4.05) * t / t[-1]
        for j in range(1, 9):
            name = f"joint{j}_target" if j < 8 else "tool_target"
            share = j / 8.0
            for c, hub, tool in zip("xyz", (7.4, 0.0, 0.6), (tool_x, 0.0, 0.6)):
                columns[f"{name}_{c}_m"] = np.where(awake, hub + share * (tool - hub), np.nan)
    if stabilisation:  # braked at 9 s: the target's rate 3, 4, 0 (x 0.01 rad/s) falling linearly to zero at 10 s
        share = np.clip(10.0 - t, 0.0, 1.0)
        for c, v in zip("xyz", (0.03, 0.04, 0.0)):
            columns[f"omega_target_body_{c}_radps"] = v * share
        for j in range(1, 8):
            columns[f"load_arm_{j}_Nm"] = np.where(t >= 9.0, 10.0 * j * share, 0.0)
    if escape:  # the chaser from 7.4 m out to 30 m from the target's centre along LVLH y
        columns["r_lvlh_x_m"], columns["r_lvlh_z_m"] = 0.0 * t, 0.0 * t
        columns["r_lvlh_y_m"] = 7.4 + (30.0 - 7.4) * np.clip((t - 3.0) / 6.0, 0.0, 1.0)
    header = ",".join(columns)
    np.savetxt(run_dir / "telemetry.csv", np.column_stack(list(columns.values())), delimiter=",", header=header,
               comments="")
    (run_dir / "summary.json").write_text(json.dumps({
        "scenario": "fake_reach", "phases_flown": [{"name": "reach", "start_s": 2.0}, {"name": "capture", "start_s": 7.0}],
        "reach": {"flown": True, "hold_from_s": 5.0, "grasp": {"closure_s": 8.55},
                  **({"rigidisation": {"start_s": 8.6, "brakes_s": 9.0},
                      "stabilisation": {"start_s": 9.0, "goal_rate_deg_s": 0.5, "peak_joint_load_Nm": 70.0}}
                     if stabilisation else {}),
                  **({"escape": {"flown": True, "trigger": "command", "start_s": 3.0, "desynchronise_s": 6.0,
                                 "hold_s": 9.0, "safe_distance_m": 30.0}} if escape else {})}}))
    scenario = run_dir.parent / "fake_reach.yaml"
    scenario.write_text(SCENARIO + FIGURE_SCENARIO if figure else SCENARIO)
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


def test_the_quaternions_matrix_turns_x_to_y_for_90_deg_about_z():
    half = np.sqrt(0.5)
    np.testing.assert_allclose(pr.quat_matrix(half, 0.0, 0.0, half) @ [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], atol=1e-15)
    r = pr.quat_matrix(0.5, 0.5, -0.5, 0.5)  # any unit quaternion: an orthonormal matrix of determinant 1
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-15)
    assert np.linalg.det(r) == pytest.approx(1.0)


def test_the_hubs_outline_is_the_box_its_thrusters_sit_on():
    import yaml
    edges = pr.hub_box_edges(yaml.safe_load(FIGURE_SCENARIO))
    assert len(edges) == 12
    lengths = sorted(round(float(np.linalg.norm(e[1] - e[0])), 12) for e in edges)
    assert lengths == [2.0] * 8 + [2.5] * 4


def test_the_key_instants_are_the_waking_the_hold_the_approach_the_closure_and_the_end(tmp_path):
    fake_run(tmp_path / "run", figure=True)
    t = pr.load_telemetry(tmp_path / "run")
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    instants = pr.key_instants(t, pr.reach_rows(t), summary)
    assert [row for _, row in instants] == [20, 50, 70, 86, 99]  # 2.0, 5.0, 7.0, 8.55 -> 8.6, 9.9 s
    assert instants[3][0] == "8.6 s: the jaws close"


def test_after_a_rigidisation_the_brakes_are_a_key_instant_too(tmp_path):
    fake_run(tmp_path / "run", figure=True)
    t = pr.load_telemetry(tmp_path / "run")
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    summary["reach"]["rigidisation"] = {"start_s": 8.8, "brakes_s": 9.42}
    instants = pr.key_instants(t, pr.reach_rows(t), summary)
    assert [label for label, _ in instants][-2:] == ["9.5 s: the brakes engage", "9.9 s: the end"]


def test_the_stick_figures_are_drawn_where_the_telemetry_has_the_arms_figure(tmp_path, capsys):
    scenario = fake_run(tmp_path / "run", figure=True)
    t = pr.load_telemetry(tmp_path / "run")
    points = pr.chain_points(t, 99)
    np.testing.assert_allclose(points[0], [7.4, 0.0, 0.6])
    np.testing.assert_allclose(points[-1], [4.05, 0.0, 0.6])
    outline = pr.hub_outline(t, 99, pr.hub_box_edges(yaml_load(scenario)))
    corners = np.vstack(outline)
    # Turned 90 deg about z: the box's 2 m x-y square stays square, its 1.25 m half-height along z.
    np.testing.assert_allclose(corners.min(axis=0), [6.4, -1.0, -0.65], atol=1e-12)
    out = tmp_path / "plots"
    pr.main([str(tmp_path / "run"), "--scenario", str(scenario), "--out", str(out)])
    assert (out / "reach_figures.png").stat().st_size > 10_000
    assert "reach_figures.png" in capsys.readouterr().out


def test_an_older_telemetry_without_the_figure_draws_no_stick_figures(tmp_path, capsys):
    scenario = fake_run(tmp_path / "run")
    pr.main([str(tmp_path / "run"), "--scenario", str(scenario), "--out", str(tmp_path / "plots")])
    assert not (tmp_path / "plots" / "reach_figures.png").exists()
    assert "reach_figures.png" not in capsys.readouterr().out


def yaml_load(path):
    import yaml
    return yaml.safe_load(Path(path).read_text())


def test_the_hold_ends_where_the_approach_begins():
    assert pr.approach_start_s({"phases_flown": [{"name": "reach", "start_s": 2760.0},
                                                 {"name": "capture", "start_s": 2850.0}]}) == 2850.0
    assert pr.approach_start_s({"phases_flown": [{"name": "reach", "start_s": 2760.0}]}) == float("inf")


def test_the_composite_rate_is_the_targets_rate_magnitude(tmp_path):
    fake_run(tmp_path / "run", stabilisation=True)
    t = pr.load_telemetry(tmp_path / "run")
    rows = t["t_s"] >= 9.0 - 1e-9
    # |(0.03, 0.04, 0)| = 0.05 rad/s = 2.865 deg/s at the brakes, falling linearly to zero at 10 s.
    rate = pr.rate_magnitude_degps(t, rows)
    np.testing.assert_allclose(rate[0], np.degrees(0.05), rtol=1e-12)
    np.testing.assert_allclose(rate[5], np.degrees(0.05) * 0.5, rtol=1e-9)


def test_after_a_stabilisation_its_rates_and_loads_are_drawn(tmp_path, capsys):
    scenario = fake_run(tmp_path / "run", stabilisation=True)
    out = tmp_path / "plots"
    pr.main([str(tmp_path / "run"), "--scenario", str(scenario), "--out", str(out)])
    assert (out / "reach_stabilisation.png").stat().st_size > 10_000
    assert "reach_stabilisation.png" in capsys.readouterr().out


def test_without_a_stabilisation_nothing_of_it_is_drawn(tmp_path, capsys):
    scenario = fake_run(tmp_path / "run")
    pr.main([str(tmp_path / "run"), "--scenario", str(scenario), "--out", str(tmp_path / "plots")])
    assert not (tmp_path / "plots" / "reach_stabilisation.png").exists()
    assert "reach_stabilisation.png" not in capsys.readouterr().out


def test_the_joint_rates_are_the_angles_difference_per_period(tmp_path):
    fake_run(tmp_path / "run")
    t = pr.load_telemetry(tmp_path / "run")
    t["q_arm_3_rad"][:] = np.radians(0.5) * t["t_s"]  # 0.5 deg/s
    rates = pr.joint_rates_degps(t, t["t_s"] >= 0.0)
    np.testing.assert_allclose(rates[:, 2], 0.5, rtol=1e-9)
    np.testing.assert_allclose(rates[:, 0], 0.0, atol=1e-9)


def test_after_a_rigidisation_its_joints_are_drawn(tmp_path, capsys):
    scenario = fake_run(tmp_path / "run", stabilisation=True)
    out = tmp_path / "plots"
    pr.main([str(tmp_path / "run"), "--scenario", str(scenario), "--out", str(out)])
    assert (out / "reach_rigidisation.png").stat().st_size > 10_000
    assert "reach_rigidisation.png" in capsys.readouterr().out
    # Without a rigidisation nothing is drawn.
    plain = fake_run(tmp_path / "plain")
    pr.main([str(tmp_path / "plain"), "--scenario", str(plain), "--out", str(tmp_path / "plain-plots")])
    assert not (tmp_path / "plain-plots" / "reach_rigidisation.png").exists()


def test_the_keep_out_boxes_are_projected_on_the_axes_asked_for():
    scenario = yaml_load_text(FIGURE_SCENARIO)
    (corner, width, height), = pr.keep_out_rectangles(scenario, (0, 2))
    assert corner == pytest.approx((-6.1, -2.0)) and width == pytest.approx(10.0) and height == pytest.approx(4.0)
    assert pr.keep_out_rectangles({"target": {}}, (0, 1)) == []


def test_after_an_escape_its_paths_and_distance_are_drawn(tmp_path, capsys):
    scenario = fake_run(tmp_path / "run", figure=True, escape=True)
    out = tmp_path / "plots"
    pr.main([str(tmp_path / "run"), "--scenario", str(scenario), "--out", str(out)])
    assert (out / "reach_escape.png").stat().st_size > 10_000
    assert "reach_escape.png" in capsys.readouterr().out
    # Without an escape nothing is drawn.
    plain = fake_run(tmp_path / "plain", figure=True)
    pr.main([str(tmp_path / "plain"), "--scenario", str(plain), "--out", str(tmp_path / "plain-plots")])
    assert not (tmp_path / "plain-plots" / "reach_escape.png").exists()


def yaml_load_text(text):
    import yaml
    return yaml.safe_load(text)
