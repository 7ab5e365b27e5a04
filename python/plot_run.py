#!/usr/bin/env python3
"""Plots of one Chaser run: trajectory in the approach corridor, attitude errors, thruster on-times.

Usage: /usr/bin/python3 python/plot_run.py RUN_DIR
Reads RUN_DIR/telemetry.csv or telemetry.npy and RUN_DIR/summary.json; writes trajectory.png, attitude.png and
thrusters.png into RUN_DIR, and target.png (the target's body rates, and each tank's slosh displacement where
the chaser has sloshing tanks) where the telemetry has the target's rates.
"""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from chaser_telemetry import load_telemetry  # noqa: E402


def load(run_dir):
    telemetry = load_telemetry(run_dir)
    summary = json.loads((run_dir / "summary.json").read_text())
    return telemetry, summary


def fault_lines(ax, summary):
    for fault in summary["faults"]:
        ax.axvline(fault["onset_s"], color="tab:red", ls="--", lw=0.8)


def corridor_frame(summary):
    """Unit vectors: the approach axis and two lateral axes orthogonal to it."""
    axis = np.array(summary["approach_axis_lvlh"], float)
    axis /= np.linalg.norm(axis)
    helper = np.array([0.0, 0.0, 1.0]) if abs(axis[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    lat1 = np.cross(helper, axis)
    lat1 /= np.linalg.norm(lat1)
    lat2 = np.cross(axis, lat1)
    return axis, lat1, lat2


def plot_trajectory(t, summary, run_dir):
    r = np.column_stack([t["r_lvlh_x_m"], t["r_lvlh_y_m"], t["r_lvlh_z_m"]])
    axis, lat1, lat2 = corridor_frame(summary)
    along, side1, side2 = r @ axis, r @ lat1, r @ lat2
    half = np.radians(summary["corridor_half_angle_deg"])
    cone_range = np.linspace(0.0, max(along.max(), 1.0) * 1.05, 50)
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), constrained_layout=True)
    for ax, side, name in ((axes[0], side1, "lateral 1"), (axes[1], side2, "lateral 2")):
        ax.fill_between(cone_range, -np.tan(half) * cone_range, np.tan(half) * cone_range, color="0.9",
                        label=f"corridor ({summary['corridor_half_angle_deg']:.0f} deg)")
        ax.plot(along, side, lw=1.0, label="chaser (truth)")
        ax.plot(along[0], side[0], "go", label="start")
        ax.plot(along[-1], side[-1], "rs", label="end")
        ax.axvline(summary["capture_distance_m"], color="k", lw=0.6, ls=":", label="capture point")
        ax.set_xlabel("distance along the approach axis [m]")
        ax.set_ylabel(f"{name} offset [m]")
        ax.invert_xaxis()
        ax.grid(True, lw=0.3)
    axes[0].legend(loc="best", fontsize=8)
    fig.suptitle(f"{summary['scenario']}: trajectory in the approach corridor")
    fig.savefig(run_dir / "trajectory.png", dpi=110)
    plt.close(fig)


def plot_attitude(t, summary, run_dir):
    fig, axes = plt.subplots(2, 1, figsize=(10, 6), sharex=True, constrained_layout=True)
    for c in "xyz":
        axes[0].plot(t["t_s"], np.degrees(t[f"att_err_body_{c}_rad"]), lw=0.8, label=f"body {c}")
    axes[0].set_ylabel("attitude error [deg]")
    pos_err = np.sqrt(sum((t[f"r_lvlh_{c}_m"] - t[f"r_ref_lvlh_{c}_m"]) ** 2 for c in "xyz"))
    axes[1].semilogy(t["t_s"], np.maximum(pos_err, 1e-6), lw=0.8, color="tab:purple")
    axes[1].set_ylabel("position error [m]")
    axes[1].set_xlabel("time [s]")
    for ax in axes:
        fault_lines(ax, summary)
        ax.grid(True, lw=0.3)
    axes[0].legend(loc="best", fontsize=8)
    fig.suptitle(f"{summary['scenario']}: attitude and position errors against the guidance reference")
    fig.savefig(run_dir / "attitude.png", dpi=110)
    plt.close(fig)


def plot_thrusters(t, summary, run_dir):
    # One panel per thruster T1..TN (N from the telemetry's ton_cmd_<i> columns), eight per column.
    n = sum(1 for name in t.dtype.names if name.startswith("ton_cmd_"))
    cols = (n + 7) // 8
    rows = min(n, 8)
    fig, axes = plt.subplots(rows, cols, figsize=(10 * max(1, cols / 1.5), 9), sharex=True, squeeze=False,
                             constrained_layout=True)
    # Nominal on-times are a few per cent of the period: scale to the largest one seen.
    top = max(0.1, max(max(t[f"ton_cmd_{i}"].max(), t[f"ton_real_{i}"].max()) for i in range(1, n + 1)))
    for i in range(1, n + 1):
        ax = axes[(i - 1) % 8][(i - 1) // 8]
        ax.plot(t["t_s"], t[f"ton_real_{i}"], lw=0.6, color="tab:orange", label="realised")
        ax.plot(t["t_s"], t[f"ton_cmd_{i}"], lw=0.6, color="tab:blue", label="commanded")
        ax.set_ylim(-0.05 * top, 1.05 * top)
        ax.set_ylabel(f"T{i}", rotation=0, labelpad=12)
        fault_lines(ax, summary)
    for j in range(n, rows * cols):
        axes[j % 8][j // 8].set_visible(False)
    axes[0][0].legend(loc="upper left", fontsize=7, ncol=2)
    for c in range(cols):
        axes[rows - 1][c].set_xlabel("time [s]")
    fig.suptitle(f"{summary['scenario']}: thruster on-times (fraction of the period)")
    fig.savefig(run_dir / "thrusters.png", dpi=110)
    plt.close(fig)


def plot_target_and_slosh(t, summary, run_dir):
    """The target's inertial rate in its body axes; below it, each slosh mass's lateral swing."""
    tanks = sorted({int(name[5:name.index("_")]) for name in t.dtype.names
                    if name.startswith("slosh") and name.endswith("_s_body_x_m")})
    fig, axes = plt.subplots(2 if tanks else 1, 1, figsize=(10, 6 if tanks else 3.5), sharex=True, squeeze=False,
                             constrained_layout=True)
    axes = axes[:, 0]
    for c in "xyz":
        axes[0].plot(t["t_s"], np.degrees(t[f"omega_target_body_{c}_radps"]), lw=0.8, label=f"body {c}")
    axes[0].set_ylabel("target rate [deg/s]")
    for i in tanks:
        for c in "xyz":
            axes[1].plot(t["t_s"], 1e3 * t[f"slosh{i}_s_body_{c}_m"], lw=0.8, label=f"tank {i}, body {c}")
    if tanks:
        axes[1].set_ylabel("slosh mass displacement [mm]")
    axes[-1].set_xlabel("time [s]")
    for ax in axes:
        fault_lines(ax, summary)
        ax.grid(True, lw=0.3)
        ax.legend(loc="best", fontsize=7, ncol=2)
    fig.suptitle(f"{summary['scenario']}: the target's rotation" + (" and the propellant's slosh" if tanks else ""))
    fig.savefig(run_dir / "target.png", dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    run_dir = Path(sys.argv[1])
    telemetry, summary = load(run_dir)
    plot_trajectory(telemetry, summary, run_dir)
    plot_attitude(telemetry, summary, run_dir)
    plot_thrusters(telemetry, summary, run_dir)
    written = [run_dir / name for name in ("trajectory.png", "attitude.png", "thrusters.png")]
    if "omega_target_body_x_radps" in telemetry.dtype.names:
        plot_target_and_slosh(telemetry, summary, run_dir)
        written.append(run_dir / "target.png")
    print("  plots: " + ", ".join(str(p) for p in written))


if __name__ == "__main__":
    main()
