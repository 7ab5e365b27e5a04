#!/usr/bin/env python3
"""Plots of a COMRADE synchronised flight about a tumbling target (docs/gnc.md, "Synchronised final approach").

Usage: /usr/bin/python3 python/plot_servicing.py RUN_DIR [--scenario FILE] [--out DIR] [--show]

Reads RUN_DIR/telemetry.csv or telemetry.npy, RUN_DIR/summary.json and the scenario the run flew (the run
directory does not keep it: --scenario, by default scenarios/<summary's scenario>.yaml; --set overrides of
the run are not in it, so pass a file with them if they changed target.body or orbit). Writes into DIR
(default RUN_DIR):
  - servicing_lvlh.png: the chaser's CoM in LVLH (truth), its reference, the target at the origin;
  - servicing_target.png: the same in the target's body axes, with target.body.keep_out's boxes, the
    capture point and the least clearance of summary.json;
  - servicing_sync.png: position error to the reference, velocity and angular rate relative to the
    target, attitude error to the reference, against COMRADE 2018's Table 1 limits, and the target
    estimator's errors (a run with sensors.target_pose has them);
  - servicing_thrusters.png: each thruster's realised on-time per period, and its mean (duty);
  - servicing_slosh.png: each tank's slosh mass displacement (where the chaser has tanks).

The telemetry has no channel for LVLH's attitude q_inertial_from_lvlh: it is taken as the circular orbit's,
a turn of n t about LVLH z (model/target_orbit.cpp), n from orbit.mu_m3ps2, body_radius_m and altitude_m.
That is the run's frame exactly without orbit.earth; with it (J2, drag) the frame drifts from the circle's
by a small fraction of n t (the least clearance computed here is printed beside summary.json's).
"""
import argparse
import itertools
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402

from chaser_telemetry import load_telemetry  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
XYZ = "xyz"
# COMRADE 2018, Table 1: the synchronisation's accuracy at capture.
LIMIT_POSITION_M, LIMIT_VELOCITY_MPS, LIMIT_ATTITUDE_DEG, LIMIT_RATE_DEGPS = 0.1, 0.01, 2.0, 0.5


def vec(t, prefix, suffix):
    """(N, 3) array of the channels prefix_x_suffix, prefix_y_suffix, prefix_z_suffix."""
    return np.column_stack([t[f"{prefix}_{c}_{suffix}"] for c in XYZ])


def quat(t, prefix):
    """(N, 4) array [w, x, y, z] of the channels prefix_w ... prefix_z."""
    return np.column_stack([t[f"{prefix}_{c}"] for c in "wxyz"])


def rotation_matrices(q):
    """(N, 3, 3) rotation matrices of unit quaternions q (N, 4) [w, x, y, z], Hamilton's product:
    R v = q v q*, so q_a_from_b gives the matrix taking b's axes to a's."""
    q = np.asarray(q, float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], axis=-1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], axis=-1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], axis=-1),
    ], axis=-2)


def q_inertial_from_lvlh(t_s, mean_motion_radps):
    """(N, 4): LVLH's attitude in the run's inertial frame (LVLH at t = 0) on a circular orbit, a turn of
    n t about LVLH z (model/target_orbit.cpp)."""
    half = 0.5 * mean_motion_radps * np.asarray(t_s, float)
    zero = np.zeros_like(half)
    return np.column_stack([np.cos(half), zero, zero, np.sin(half)])


def lvlh_to_target(r_lvlh, q_in_from_lvlh, q_in_from_target):
    """(N, 3): points given in LVLH (from the target's CoM) in the target's body axes,
    p = R(q_inertial_from_target)^T R(q_inertial_from_lvlh) r (sim/mission_monitor.cpp's keep-out check)."""
    r_inertial = np.einsum("nij,nj->ni", rotation_matrices(q_in_from_lvlh), np.asarray(r_lvlh, float))
    return np.einsum("nji,nj->ni", rotation_matrices(q_in_from_target), r_inertial)


def velocity_in_target_frame(r_lvlh, v_lvlh, q_in_from_lvlh, q_in_from_target, omega_target_body, mean_motion_radps):
    """(N, 3): the chaser's velocity as seen in the turning target frame, target axes,
    dp/dt = R_t^T R_l (v + w_lvlh x r) - w_target x p; zero when it holds a point of the target."""
    omega_lvlh = np.array([0.0, 0.0, mean_motion_radps])
    v_inertial = np.einsum("nij,nj->ni", rotation_matrices(q_in_from_lvlh), v_lvlh + np.cross(omega_lvlh, r_lvlh))
    p = lvlh_to_target(r_lvlh, q_in_from_lvlh, q_in_from_target)
    return np.einsum("nji,nj->ni", rotation_matrices(q_in_from_target), v_inertial) - np.cross(omega_target_body, p)


def rate_relative_to_target(q_in_from_body, omega_body, q_in_from_target, omega_target_body):
    """(N, 3): the chaser's angular velocity relative to the target's, chaser body axes."""
    body_from_target = np.einsum("nji,njk->nik", rotation_matrices(q_in_from_body), rotation_matrices(q_in_from_target))
    return omega_body - np.einsum("nij,nj->ni", body_from_target, omega_target_body)


def keep_out_distance(boxes, p):
    """(N,): signed distance from points p (N, 3), target axes, to the union of the boxes (model/keep_out.cpp)."""
    nearest = np.full(len(p), np.inf)
    for box in boxes:
        q = np.abs(p - np.asarray(box["centre_target_m"], float)) - np.asarray(box["half_extents_m"], float)
        nearest = np.minimum(nearest, np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0))
    return nearest


def require(t, names, what):
    missing = [n for n in names if n not in t.dtype.names]
    if missing:
        raise SystemExit(f"plot_servicing: the telemetry has no channel {', '.join(missing)} (needed for {what}); "
                         "was the run made with --channels, or without target.body?")


def tank_numbers(t):
    return sorted({int(n[5:n.index("_")]) for n in t.dtype.names
                   if n.startswith("slosh") and n.endswith("_s_body_x_m")})


def thruster_count(t):
    return sum(1 for n in t.dtype.names if n.startswith("ton_real_"))


ESTIMATOR = ("target_est_att_err_rad", "target_est_rate_err_radps", "target_est_att_sigma_rad")


def check_channels(t):
    require(t, ["t_s"] + [f"{p}_{c}_m" for p in ("r_lvlh", "r_ref_lvlh") for c in XYZ], "the trajectory")
    require(t, [f"v_lvlh_{c}_mps" for c in XYZ] + [f"q_inertial_from_target_{c}" for c in "wxyz"]
            + [f"omega_target_body_{c}_radps" for c in XYZ], "the target frame")
    require(t, [f"q_inertial_from_body_{c}" for c in "wxyz"] + [f"omega_body_{c}_radps" for c in XYZ]
            + [f"att_err_body_{c}_rad" for c in XYZ], "the attitude and rate errors")
    if thruster_count(t) == 0:
        require(t, ["ton_real_1"], "the thruster activity")


def load_scenario(path):
    scenario = yaml.safe_load(Path(path).read_text())
    body = (scenario.get("target") or {}).get("body")
    if not body:
        raise SystemExit(f"plot_servicing: {path} has no target.body (the tumbling target the plots are about)")
    return scenario


def mean_motion_radps(scenario):
    o = scenario["orbit"]
    # float(): PyYAML reads 765.0e3 (no sign after the e) as a string.
    return float(np.sqrt(float(o["mu_m3ps2"]) / (float(o["body_radius_m"]) + float(o["altitude_m"])) ** 3))


class Flight:
    """The telemetry's geometry, once: the chaser and its reference in LVLH and in target axes."""

    def __init__(self, t, summary, scenario):
        self.t, self.summary, self.scenario = t, summary, scenario
        self.time = t["t_s"]
        self.n = mean_motion_radps(scenario)
        self.q_l = q_inertial_from_lvlh(self.time, self.n)
        self.q_t = quat(t, "q_inertial_from_target")
        self.r = vec(t, "r_lvlh", "m")
        self.r_ref = vec(t, "r_ref_lvlh", "m")
        self.p = lvlh_to_target(self.r, self.q_l, self.q_t)
        self.p_ref = lvlh_to_target(self.r_ref, self.q_l, self.q_t)
        self.boxes = scenario["target"]["body"].get("keep_out") or []
        self.chaser_radius_m = float(scenario["chaser"].get("keep_out_radius_m", 0.0))
        self.clearance = keep_out_distance(self.boxes, self.p) - self.chaser_radius_m


def start_end(ax, points):
    ax.scatter(*points[0], color="tab:green", marker="o", s=40, label="start", depthshade=False)
    ax.scatter(*points[-1], color="tab:red", marker="s", s=40, label="end", depthshade=False)


def equal_axes(ax, points):
    lo, hi = points.min(axis=0), points.max(axis=0)
    centre, half = 0.5 * (lo + hi), 0.5 * max((hi - lo).max(), 1.0) * 1.1
    for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        setter(c - half, c + half)
    ax.set_box_aspect((1, 1, 1))


def save(fig, out, name, show):
    path = out / name
    fig.savefig(path, dpi=110)
    if not show:
        plt.close(fig)
    return path


def plot_lvlh(f, out, show):
    fig = plt.figure(figsize=(8, 7), constrained_layout=True)
    ax = fig.add_subplot(projection="3d")
    ax.plot(*f.r_ref.T, "--", color="0.5", lw=0.8, label="reference (flight software)")
    ax.plot(*f.r.T, color="tab:blue", lw=1.0, label="chaser CoM (truth)")
    ax.scatter(0, 0, 0, color="k", marker="*", s=120, label="target CoM", depthshade=False)
    start_end(ax, f.r)
    equal_axes(ax, np.vstack([f.r, f.r_ref, np.zeros((1, 3))]))
    ax.set_xlabel("x (zenith) [m]")
    ax.set_ylabel("y (along-track) [m]")
    ax.set_zlabel("z (orbit normal) [m]")
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title(f"{f.summary['scenario']}: the chaser in LVLH")
    return save(fig, out, "servicing_lvlh.png", show)


def box_edges(centre, half):
    """The 12 edges of a box, each a (2, 3) segment."""
    centre, half = np.asarray(centre, float), np.asarray(half, float)
    signs = list(itertools.product((-1.0, 1.0), repeat=3))
    return [centre + half * np.array([a, b]) for a in signs for b in signs
            if a < b and sum(x != y for x, y in zip(a, b)) == 1]


def plot_target_frame(f, out, show):
    body = f.scenario["target"]["body"]
    fig = plt.figure(figsize=(9, 8), constrained_layout=True)
    ax = fig.add_subplot(projection="3d")
    edges = [e for b in f.boxes for e in box_edges(b["centre_target_m"], b["half_extents_m"])]
    for k, edge in enumerate(edges):
        ax.plot(*edge.T, color="tab:gray", lw=0.8, label="keep-out" if k == 0 else None)
    ax.plot(*f.p_ref.T, "--", color="0.5", lw=0.8, label="reference")
    ax.plot(*f.p.T, color="tab:blue", lw=1.0, label="chaser CoM (truth)")
    start_end(ax, f.p)
    ax.scatter(0, 0, 0, color="k", marker="+", s=60, label="target CoM", depthshade=False)
    points = [f.p, f.p_ref, np.zeros((1, 3))] + edges
    if "capture_point_target_m" in body:
        capture = np.asarray(body["capture_point_target_m"], float)
        ax.scatter(*capture, color="tab:orange", marker="*", s=140, label="capture point", depthshade=False)
        points.append(capture[None, :])
    s = f.summary
    if s.get("min_target_clearance_at_s", -1.0) >= 0.0 and np.isfinite(s.get("min_target_clearance_m", np.inf)):
        i = int(np.argmin(np.abs(f.time - s["min_target_clearance_at_s"])))
        label = f"least clearance {s['min_target_clearance_m']:.2f} m at {s['min_target_clearance_at_s']:.0f} s"
        ax.scatter(*f.p[i], color="tab:purple", marker="D", s=40, depthshade=False, label=label)
        ax.text(*f.p[i], f"  {s['min_target_clearance_m']:.2f} m", color="tab:purple", fontsize=9)
    equal_axes(ax, np.vstack(points))
    ax.set_xlabel("target x [m]")
    ax.set_ylabel("target y [m]")
    ax.set_zlabel("target z [m]")
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title(f"{s['scenario']}: the chaser in the target's body axes\n"
                 f"(clearance = distance to keep-out - chaser radius {f.chaser_radius_m:g} m)")
    return save(fig, out, "servicing_target.png", show)


def plot_sync(f, out, show):
    t, time = f.t, f.time
    pos_err = np.linalg.norm(f.r - f.r_ref, axis=1)
    omega_target = vec(t, "omega_target_body", "radps")
    vel = np.linalg.norm(velocity_in_target_frame(f.r, vec(t, "v_lvlh", "mps"), f.q_l, f.q_t, omega_target, f.n),
                         axis=1)
    att = np.degrees(np.linalg.norm(vec(t, "att_err_body", "rad"), axis=1))
    relative_rate = rate_relative_to_target(quat(t, "q_inertial_from_body"), vec(t, "omega_body", "radps"), f.q_t,
                                            omega_target)
    rate = np.degrees(np.linalg.norm(relative_rate, axis=1))
    panels = [
        (pos_err, LIMIT_POSITION_M, "position error\nto reference [m]", True),
        (vel, LIMIT_VELOCITY_MPS, "speed in the\ntarget frame [m/s]", True),
        (att, LIMIT_ATTITUDE_DEG, "attitude error\nto reference [deg]", False),
        (rate, LIMIT_RATE_DEGPS, "rate relative\nto target [deg/s]", True),
    ]
    fig, axes = plt.subplots(len(panels) + 1, 1, figsize=(10, 11), sharex=True, constrained_layout=True)
    for ax, (y, limit, label, log) in zip(axes, panels):
        (ax.semilogy if log else ax.plot)(time, np.maximum(y, 1e-6) if log else y, lw=0.8)
        ax.axhline(limit, color="tab:red", ls="--", lw=0.8, label=f"COMRADE Table 1: {limit:g}")
        ax.set_ylabel(label)
        ax.legend(loc="upper right", fontsize=7)
    axes[1].set_title("speed in the target frame includes the transfer's planned motion: the limit applies in the hold",
                      fontsize=8)
    est = axes[-1]
    est.set_ylabel("target estimator")
    if all(name in t.dtype.names for name in ESTIMATOR):
        est.plot(time, np.degrees(t["target_est_att_err_rad"]), lw=0.8, label="attitude error [deg]")
        est.plot(time, np.degrees(t["target_est_att_sigma_rad"]), lw=0.8, ls=":", label="attitude 1-sigma [deg]")
        est.plot(time, np.degrees(t["target_est_rate_err_radps"]), lw=0.8, label="rate error [deg/s]")
        est.set_yscale("log")
        est.legend(loc="upper right", fontsize=7)
    else:  # the estimator runs with sensors.target_pose only
        est.text(0.5, 0.5, "no target estimator in this run (no target_est_* channels: no sensors.target_pose)",
                 transform=est.transAxes, ha="center", va="center", fontsize=9)
    est.set_xlabel("time [s]")
    for ax in axes:
        ax.grid(True, lw=0.3, which="both")
    s = f.summary
    fig.suptitle(f"{s['scenario']}: synchronisation errors (summary.json final, against the truth: {s['final_position_error_m']:.3f} m, "
                 f"{s['final_speed_mps']:.4f} m/s, {s['final_attitude_error_deg']:.2f} deg)")
    return save(fig, out, "servicing_sync.png", show)


def plot_thrusters(f, out, show):
    n = thruster_count(f.t)
    ton = np.vstack([f.t[f"ton_real_{i}"] for i in range(1, n + 1)])
    fig, (img, duty) = plt.subplots(1, 2, figsize=(13, 6), sharey=True, gridspec_kw={"width_ratios": [5, 1]},
                                    constrained_layout=True)
    im = img.imshow(ton, aspect="auto", interpolation="nearest", cmap="magma_r", origin="lower",
                    extent=(f.time[0], f.time[-1], 0.5, n + 0.5), vmin=0.0, vmax=max(ton.max(), 1e-3))
    fig.colorbar(im, ax=img, label="realised on-time [fraction of the period]", location="bottom", shrink=0.6)
    img.set_xlabel("time [s]")
    img.set_ylabel("thruster")
    img.set_yticks(range(1, n + 1), [f"T{i}" for i in range(1, n + 1)], fontsize=7)
    duty.barh(range(1, n + 1), ton.mean(axis=1), color="tab:orange")
    duty.set_xlabel("mean duty [-]")
    duty.grid(True, lw=0.3)
    fig.suptitle(f"{f.summary['scenario']}: thruster activity ({f.summary['propellant_used_kg']:.2f} kg used)")
    return save(fig, out, "servicing_thrusters.png", show)


def plot_slosh(f, out, show):
    tanks = tank_numbers(f.t)
    if not tanks:
        return None
    fig, axes = plt.subplots(len(tanks), 1, figsize=(10, 2.5 + 2 * len(tanks)), sharex=True, squeeze=False,
                             constrained_layout=True)
    for ax, k in zip(axes[:, 0], tanks):
        for c in XYZ:
            ax.plot(f.time, 1e3 * f.t[f"slosh{k}_s_body_{c}_m"], lw=0.8, label=f"body {c}")
        ax.set_ylabel(f"tank {k} [mm]")
        ax.grid(True, lw=0.3)
        ax.legend(loc="upper right", fontsize=7, ncol=3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.suptitle(f"{f.summary['scenario']}: slosh mass displacement")
    return save(fig, out, "servicing_slosh.png", show)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir", type=Path, metavar="RUN_DIR")
    parser.add_argument("--scenario", type=Path, help="the scenario the run flew (default scenarios/<name>.yaml)")
    parser.add_argument("--out", type=Path, help="folder for the PNGs (default RUN_DIR)")
    parser.add_argument("--show", action="store_true", help="also open the figures in a window")
    args = parser.parse_args(argv)
    if args.show:
        try:
            plt.switch_backend("TkAgg")
        except ImportError as e:
            raise SystemExit(f"plot_servicing: --show needs a display and a window backend (python3-tk): {e}")
    try:
        telemetry = load_telemetry(args.run_dir)
        summary = json.loads((args.run_dir / "summary.json").read_text())
    except (FileNotFoundError, json.JSONDecodeError) as e:
        raise SystemExit(f"plot_servicing: {e}")
    check_channels(telemetry)
    scenario_path = args.scenario or REPO / "scenarios" / f"{summary['scenario']}.yaml"
    if not scenario_path.is_file():
        raise SystemExit(f"plot_servicing: {scenario_path}: no such scenario file (pass --scenario)")
    flight = Flight(telemetry, summary, load_scenario(scenario_path))
    out = args.out or args.run_dir
    out.mkdir(parents=True, exist_ok=True)
    written = [plot_lvlh(flight, out, args.show), plot_target_frame(flight, out, args.show),
               plot_sync(flight, out, args.show), plot_thrusters(flight, out, args.show),
               plot_slosh(flight, out, args.show)]
    i = int(np.argmin(flight.clearance))
    print(f"  least clearance: {flight.clearance[i]:.3f} m at {flight.time[i]:.1f} s here, "
          f"{summary.get('min_target_clearance_m', float('nan')):.3f} m at "
          f"{summary.get('min_target_clearance_at_s', float('nan')):.1f} s in summary.json")
    print(f"  end in target axes: [{', '.join(f'{x:.3f}' for x in flight.p[-1])}] m")
    print("  plots: " + ", ".join(str(p) for p in written if p is not None))
    if args.show:
        plt.show()


if __name__ == "__main__":
    main()
