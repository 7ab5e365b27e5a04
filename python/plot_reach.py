#!/usr/bin/env python3
"""Plots of a capture run's reach (docs/servicing.md, "The reach").

Usage: /usr/bin/python3 python/plot_reach.py RUN_DIR [--scenario FILE] [--out DIR] [--show]

Reads RUN_DIR/telemetry.csv or telemetry.npy, RUN_DIR/summary.json (its `reach`) and the scenario the run
flew (--scenario, by default scenarios/<summary's scenario>.yaml: the arm's joint limits and torque limits).
Writes into DIR (default RUN_DIR), over the reach (from the arm's waking to the end):
  - reach_joints.png: each joint's angle against its limits, and its commanded torque against the
    repeated-peak and momentary limits;
  - reach_gripper.png: the gripper against the pre-grasp pose, true values in its axes (x the approach):
    position, velocity, attitude and rate per axis inside COMRADE 2018 Table 2's envelope, the hold the
    summary judges shaded.
"""
import argparse
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402

from chaser_telemetry import load_telemetry  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
JOINTS = 7
XYZ = "xyz"
# COMRADE 2018 Table 2 (sim/reach_result.hpp): per axis, x the approach.
ENVELOPE_MM = (10.0, 22.0, 22.0)
ATTITUDE_DEG, VELOCITY_MMPS, RATE_DEGPS = 2.74, 5.0, 0.1
# model/arm.hpp's default stowed angles when a scenario gives none.
DEFAULT_STOWED_DEG = (0.0, 90.0, 0.0, -110.0, 0.0, -70.0, 0.0)


def arm_limits(scenario):
    """(lower_deg, upper_deg) per joint and the (repeated, momentary) torque limits of chaser.arm."""
    arm = scenario["chaser"]["arm"]
    lower = [float(link["lower_deg"]) for link in arm["links"]]
    upper = [float(link["upper_deg"]) for link in arm["links"]]
    return lower, upper, float(arm["torque_repeated_peak_Nm"]), float(arm["torque_momentary_Nm"])


def reach_rows(t):
    """Boolean mask of the rows where the arm is awake: the gripper's channels are NaN before."""
    return np.isfinite(t["gripper_err_x_m"])


def envelope_exceedance(values, limits):
    """Per axis, the largest |value| over the rows divided by its limit: > 1 where the envelope is left."""
    values = np.abs(np.asarray(values, float))
    return values.max(axis=0) / np.asarray(limits, float)


def plot_joints(t, mask, scenario, out):
    lower, upper, repeated, momentary = arm_limits(scenario)
    time = t["t_s"][mask]
    fig, axes = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    for j in range(JOINTS):
        line, = axes[0].plot(time, np.degrees(t[f"q_arm_{j + 1}_rad"][mask]), label=f"joint {j + 1}")
        axes[0].axhline(lower[j], color=line.get_color(), ls=":", lw=0.8)
        axes[0].axhline(upper[j], color=line.get_color(), ls=":", lw=0.8)
        axes[1].plot(time, t[f"tau_arm_{j + 1}_Nm"][mask], label=f"joint {j + 1}")
    axes[0].set_ylabel("angle [deg] (dotted: limits)")
    axes[0].legend(ncol=4, fontsize=8)
    peak = max(float(np.abs(t[f"tau_arm_{j + 1}_Nm"][mask]).max()) for j in range(JOINTS))
    for sign in (-1, 1):
        axes[1].axhline(sign * repeated, color="k", ls="--", lw=0.8)
        axes[1].axhline(sign * momentary, color="r", ls="--", lw=0.8)
    axes[1].set_ylim(-max(1.2 * peak, 1.0), max(1.2 * peak, 1.0))
    axes[1].set_ylabel(f"torque [N m] (limits {repeated:.0f} / {momentary:.0f} off scale)"
                       if peak < repeated else "torque [N m]")
    axes[1].set_xlabel("t [s]")
    fig.suptitle("The arm's joints over the reach")
    fig.tight_layout()
    fig.savefig(out / "reach_joints.png", dpi=110)
    plt.close(fig)


def plot_gripper(t, mask, hold_from_s, out):
    time = t["t_s"][mask]
    panels = [("gripper_err_{}_m", 1e3, "position [mm]", ENVELOPE_MM),
              ("gripper_v_{}_mps", 1e3, "velocity [mm/s]", (VELOCITY_MMPS,) * 3),
              ("gripper_att_err_{}_rad", np.degrees(1.0), "attitude [deg]", (ATTITUDE_DEG,) * 3),
              ("gripper_rate_{}_radps", np.degrees(1.0), "rate [deg/s]", (RATE_DEGPS,) * 3)]
    fig, axes = plt.subplots(4, 1, figsize=(10, 10), sharex=True)
    for ax, (name, scale, label, limits) in zip(axes, panels):
        for k, c in enumerate(XYZ):
            line, = ax.plot(time, scale * t[name.format(c)][mask], label=c)
            for sign in (-1, 1):
                ax.axhline(sign * limits[k], color=line.get_color(), ls="--", lw=0.8)
        hold = time >= hold_from_s
        if hold.any():
            ax.axvspan(time[hold][0], time[-1], color="0.9", zorder=0)
            lim = 3.0 * max(limits)
            ax.set_ylim(-lim, lim)
        ax.set_ylabel(label)
    axes[0].legend(ncol=3, fontsize=8)
    axes[-1].set_xlabel("t [s] (shaded: the hold judged against Table 2)")
    fig.suptitle("The gripper against the pre-grasp pose (true), COMRADE Table 2's envelope dashed")
    fig.tight_layout()
    fig.savefig(out / "reach_gripper.png", dpi=110)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir")
    parser.add_argument("--scenario", help="the scenario the run flew (default scenarios/<name>.yaml)")
    parser.add_argument("--out", help="output folder (default RUN_DIR)")
    parser.add_argument("--show", action="store_true")
    args = parser.parse_args(argv)
    run_dir = Path(args.run_dir)
    summary = json.loads((run_dir / "summary.json").read_text())
    reach = summary.get("reach")
    if not reach or not reach.get("flown"):
        raise SystemExit(f"{run_dir}: the run has no reach (summary.json's reach is {reach!r})")
    scenario_path = Path(args.scenario) if args.scenario else REPO / "scenarios" / f"{summary['scenario']}.yaml"
    scenario = yaml.safe_load(scenario_path.read_text())
    t = load_telemetry(run_dir)
    mask = reach_rows(t)
    out = Path(args.out) if args.out else run_dir
    out.mkdir(parents=True, exist_ok=True)
    plot_joints(t, mask, scenario, out)
    plot_gripper(t, mask, float(reach["hold_from_s"]), out)
    hold = mask & (t["t_s"] >= float(reach["hold_from_s"]))
    ratio = envelope_exceedance(np.column_stack([t[f"gripper_err_{c}_m"][hold] for c in XYZ]) * 1e3, ENVELOPE_MM)
    print(f"wrote {out / 'reach_joints.png'} and {out / 'reach_gripper.png'}; over the hold the gripper used "
          f"{', '.join(f'{r:.0%}' for r in ratio)} of Table 2's position envelope (x, y, z)")
    if args.show:
        plt.show()


if __name__ == "__main__":
    main()
