"""python/plot_servicing.py on a small synthetic run directory (no `chaser` program needed).

Run: /usr/bin/python3 -m pytest tests/python/test_plot_servicing.py -q (part of make test)
"""
import json
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
import plot_servicing as ps  # noqa: E402

C = np.sqrt(0.5)
N_QUARTER = np.pi / 200.0  # [rad/s] LVLH turns 90 deg in 100 s
PNGS = ["servicing_lvlh.png", "servicing_target.png", "servicing_sync.png", "servicing_thrusters.png",
        "servicing_slosh.png"]
SCENARIO = f"""
name: fake_servicing
orbit: {{mu_m3ps2: {N_QUARTER ** 2!r}, body_radius_m: 0.5, altitude_m: 0.5}}   # a = 1 m: n = pi / 200 rad/s
chaser: {{keep_out_radius_m: 0.5}}
target:
  body:
    capture_point_target_m: [2.0, 0.0, 0.0]
    keep_out:
      - {{centre_target_m: [0.0, 0.0, 0.0], half_extents_m: [1.0, 1.0, 1.0]}}
"""


def test_the_target_frame_point_is_the_hand_computed_one():
    # t = 0: LVLH is the inertial frame; the target turned +90 deg about z takes its +x to inertial +y,
    # so the chaser at LVLH (0, 1, 0) is at target (1, 0, 0).
    # t = 100 s: LVLH has turned +90 deg about z (LVLH +x is inertial +y); the target turned -90 deg about
    # x takes its +z to inertial +y, so the chaser at LVLH (1, 0, 0) is at target (0, 0, 1).
    t = np.array([0.0, 100.0])
    q_lvlh = ps.q_inertial_from_lvlh(t, N_QUARTER)
    np.testing.assert_allclose(q_lvlh[1], [C, 0.0, 0.0, C], atol=1e-15)
    q_target = np.array([[C, 0.0, 0.0, C], [C, -C, 0.0, 0.0]])
    r_lvlh = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0]])
    p = ps.lvlh_to_target(r_lvlh, q_lvlh, q_target)
    np.testing.assert_allclose(p, [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], atol=1e-12)


def test_a_chaser_holding_a_point_of_the_spinning_target_has_no_relative_motion():
    # Target spinning at 2.5 deg/s about its axis (1, 2, 2)/3 from a tilted start; the chaser holds target
    # point (7.4, 0, 0.6) and turns with it: its speed in the target frame and its relative rate are zero.
    t = np.linspace(0.0, 300.0, 31)
    w = np.radians(2.5)
    axis = np.array([1.0, 2.0, 2.0]) / 3.0
    q0 = np.array([np.cos(0.3), np.sin(0.3), 0.0, 0.0])
    spin = np.column_stack([np.cos(0.5 * w * t), np.outer(np.sin(0.5 * w * t), axis)])
    q_target = hamilton(np.broadcast_to(q0, spin.shape), spin)
    omega_target_body = np.broadcast_to(w * axis, (len(t), 3))
    n = 0.00105
    q_lvlh = ps.q_inertial_from_lvlh(t, n)
    p = np.array([7.4, 0.0, 0.6])
    r_inertial = ps.rotation_matrices(q_target) @ p
    r_lvlh = np.einsum("nji,nj->ni", ps.rotation_matrices(q_lvlh), r_inertial)
    omega_target_inertial = np.einsum("nij,nj->ni", ps.rotation_matrices(q_target), omega_target_body)
    v_lvlh = (np.einsum("nji,nj->ni", ps.rotation_matrices(q_lvlh), np.cross(omega_target_inertial, r_inertial))
              - np.cross([0.0, 0.0, n], r_lvlh))
    np.testing.assert_allclose(ps.lvlh_to_target(r_lvlh, q_lvlh, q_target), np.broadcast_to(p, (len(t), 3)), atol=1e-12)
    v = ps.velocity_in_target_frame(r_lvlh, v_lvlh, q_lvlh, q_target, omega_target_body, n)
    np.testing.assert_allclose(v, 0.0, atol=1e-14)
    q_body = hamilton(q_target, np.broadcast_to([C, 0.0, C, 0.0], q_target.shape))  # fixed in the target's frame
    omega_body = np.einsum("nji,nj->ni", ps.rotation_matrices(q_body), omega_target_inertial)
    np.testing.assert_allclose(ps.rate_relative_to_target(q_body, omega_body, q_target, omega_target_body), 0.0,
                               atol=1e-16)


def test_keep_out_distance_is_model_keep_outs():
    boxes = [{"centre_target_m": [0.0, 0.0, 0.0], "half_extents_m": [1.0, 2.0, 3.0]},
             {"centre_target_m": [10.0, 0.0, 0.0], "half_extents_m": [1.0, 1.0, 1.0]}]
    points = np.array([[4.0, 0.0, 0.0], [2.0, 3.0, 3.0], [0.5, 0.0, 0.0], [7.0, 0.0, 0.0]])
    np.testing.assert_allclose(ps.keep_out_distance(boxes, points), [3.0, np.sqrt(2.0), -0.5, 2.0])


def hamilton(a, b):
    w1, x1, y1, z1 = np.moveaxis(np.asarray(a, float), -1, 0)
    w2, x2, y2, z2 = np.moveaxis(np.asarray(b, float), -1, 0)
    return np.stack([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2], axis=-1)


def fake_run(run_dir, drop=()):
    """20 rows, 10 s apart: the target keeps LVLH's attitude (it turns with LVLH at n), so its axes are
    LVLH's and the chaser, flying in along LVLH x from 4 m to 2 m, is at the same point in both."""
    run_dir.mkdir()
    t = np.arange(20) * 10.0
    x = np.linspace(4.0, 2.0, len(t))
    cols = {"t_s": t}
    zero, one = np.zeros_like(t), np.ones_like(t)
    for c, v in zip("xyz", (x, zero, zero)):
        cols[f"r_lvlh_{c}_m"] = v
        cols[f"r_ref_lvlh_{c}_m"] = v + (0.01 if c == "y" else 0.0)
        cols[f"v_lvlh_{c}_mps"] = np.full_like(t, -2.0 / 190.0) if c == "x" else zero
        cols[f"omega_target_body_{c}_radps"] = N_QUARTER * one if c == "z" else zero
        cols[f"omega_body_{c}_radps"] = N_QUARTER * one if c == "z" else zero
        cols[f"att_err_body_{c}_rad"] = 0.001 * one
    q = ps.q_inertial_from_lvlh(t, N_QUARTER)
    for i, c in enumerate("wxyz"):
        cols[f"q_inertial_from_target_{c}"] = q[:, i]
        cols[f"q_inertial_from_body_{c}"] = q[:, i]
    for name in ("target_est_att_err_rad", "target_est_rate_err_radps", "target_est_att_sigma_rad"):
        cols[name] = 0.01 * np.exp(-t / 50.0) + 1e-4
    for i in range(1, 25):
        cols[f"ton_real_{i}"] = 0.05 * (i % 3) * one
    for k in (1, 2):
        for c in "xyz":
            cols[f"slosh{k}_s_body_{c}_m"] = 1e-3 * k * np.sin(0.1 * t)
    names = [n for n in cols if n not in drop]
    np.savetxt(run_dir / "telemetry.csv", np.column_stack([cols[n] for n in names]), delimiter=",",
               header=",".join(names), comments="")
    # Least clearance: at the end, 2 m from the centre of a box 1 m wide, less the chaser's 0.5 m.
    summary = {"scenario": "fake_servicing", "min_target_clearance_m": 0.5, "min_target_clearance_at_s": 190.0,
               "final_position_error_m": 0.01, "final_speed_mps": 0.0, "final_attitude_error_deg": 0.1,
               "propellant_used_kg": 1.0}
    (run_dir / "summary.json").write_text(json.dumps(summary))
    scenario = run_dir.parent / "fake_servicing.yaml"
    scenario.write_text(SCENARIO)
    return scenario


def test_the_fake_runs_target_frame_is_lvlh_and_its_clearance_is_the_summarys(tmp_path):
    scenario = fake_run(tmp_path / "run")
    telemetry = ps.load_telemetry(tmp_path / "run")
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    flight = ps.Flight(telemetry, summary, ps.load_scenario(scenario))
    assert flight.n == pytest.approx(N_QUARTER, rel=1e-12)
    np.testing.assert_allclose(flight.p, flight.r, atol=1e-12)
    assert flight.clearance.min() == pytest.approx(summary["min_target_clearance_m"], abs=1e-12)
    assert flight.time[np.argmin(flight.clearance)] == summary["min_target_clearance_at_s"]


def test_every_png_is_written(tmp_path, capsys):
    scenario = fake_run(tmp_path / "run")
    out = tmp_path / "plots"
    ps.main([str(tmp_path / "run"), "--scenario", str(scenario), "--out", str(out)])
    for name in PNGS:
        assert (out / name).stat().st_size > 10_000, name
    assert "least clearance: 0.500 m at 190.0 s here, 0.500 m at 190.0 s in summary.json" in capsys.readouterr().out


def test_a_missing_channel_is_named_not_a_traceback(tmp_path):
    scenario = fake_run(tmp_path / "run", drop=("q_inertial_from_target_y",))
    with pytest.raises(SystemExit) as e:
        ps.main([str(tmp_path / "run"), "--scenario", str(scenario)])
    assert "no channel q_inertial_from_target_y" in str(e.value.code)
    assert not list((tmp_path / "run").glob("*.png"))


def test_a_run_without_slosh_channels_writes_the_other_plots(tmp_path):
    scenario = fake_run(tmp_path / "run", drop=tuple(f"slosh{k}_s_body_{c}_m" for k in (1, 2) for c in "xyz"))
    ps.main([str(tmp_path / "run"), "--scenario", str(scenario)])
    assert sorted(p.name for p in (tmp_path / "run").glob("*.png")) == sorted(PNGS[:-1])


def test_a_run_without_the_pose_sensor_draws_all_but_the_estimator(tmp_path):
    # The V-bar leg of comrade_envisat.yaml has no sensors.target_pose, so no target_est_* channels.
    scenario = fake_run(tmp_path / "run", drop=ps.ESTIMATOR)
    ps.main([str(tmp_path / "run"), "--scenario", str(scenario)])
    assert sorted(p.name for p in (tmp_path / "run").glob("*.png")) == sorted(PNGS)
