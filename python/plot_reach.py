#!/usr/bin/env python3
"""Plots of a capture run's reach (docs/servicing.md, "The reach").

Usage: /usr/bin/python3 python/plot_reach.py RUN_DIR [--scenario FILE] [--out DIR] [--show]

Reads RUN_DIR/telemetry.csv or telemetry.npy, RUN_DIR/summary.json (its `reach`) and the scenario the run
flew (--scenario, by default scenarios/<summary's scenario>.yaml: the arm's joint limits and torque limits).
Writes into DIR (default RUN_DIR), over the reach (from the arm's waking to the end):
  - reach_joints.png: each joint's angle against its limits, and its commanded torque against the
    repeated-peak and momentary limits;
  - reach_gripper.png: the gripper against the pre-grasp pose, and from the approach on (the phase
    `capture`) against the fixture, true values in its axes (x the approach): position, velocity, attitude
    and rate per axis inside COMRADE 2018 Table 2's envelope, the hold the summary judges shaded;
  - reach_figures.png: stick figures of the hub, the arm and the target's face at the fixture, true, in
    the target's axes (a side view, x-z, and a top view, x-y), at the key instants: the arm's waking, the
    end of the path to the pre-grasp pose, the start of the approach, the jaws' closure and the end;
  - reach_rigidisation.png, after a rigidisation (summary.json's reach.rigidisation): from its start to
    10 s after the brakes (or the end), each joint's angle from where the law held it, its rate (the
    angles' difference per period) against the brakes' threshold, and its commanded torque;
  - reach_stabilisation.png, after a stabilisation (summary.json's reach.stabilisation): from the brakes
    on, the target's true rate per axis and its magnitude against COMRADE 2018 Table 3's 0.5 deg/s, and
    each braked joint's load against the drives' repeated and momentary peaks;
  - reach_escape.png, after an escape (summary.json's reach.escape): the chaser's and the tool point's
    paths in the target's axes while they turn with it (side and top views, the keep-out volume
    shaded), and the chaser's distance from the target's centre from the trigger to the end.
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


def approach_start_s(summary):
    """When the phase `capture` began (the gripper is then judged against the fixture); inf without one."""
    starts = [float(p["start_s"]) for p in summary.get("phases_flown", []) if p.get("name") == "capture"]
    return starts[0] if starts else float("inf")


def plot_gripper(t, mask, hold_from_s, hold_to_s, out):
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
        hold = (time >= hold_from_s) & (time < hold_to_s)
        if hold.any():
            ax.axvspan(time[hold][0], time[hold][-1], color="0.9", zorder=0)
            lim = 3.0 * max(limits)
            ax.set_ylim(-lim, lim)
        if np.isfinite(hold_to_s):
            ax.axvline(hold_to_s, color="k", lw=0.8)
        ax.set_ylabel(label)
    axes[0].legend(ncol=3, fontsize=8)
    axes[-1].set_xlabel("t [s] (shaded: the hold judged against Table 2; from the black line on, the approach)")
    fig.suptitle("The gripper against the pre-grasp pose, from the approach on against the fixture (true),\n"
                 "COMRADE Table 2's envelope dashed")
    fig.tight_layout()
    fig.savefig(out / "reach_gripper.png", dpi=110)
    plt.close(fig)


def quat_matrix(w, x, y, z):
    """The rotation matrix of the unit quaternion (w, x, y, z): v' = R v."""
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def chain_points(t, row):
    """The arm's figure at a row, target axes [m]: the hub's origin, joints 1..7, the tool point (9 x 3)."""
    names = ["hub_target"] + [f"joint{j}_target" for j in range(1, JOINTS + 1)] + ["tool_target"]
    return np.array([[t[f"{n}_{c}_m"][row] for c in XYZ] for n in names])


def hub_box_edges(scenario):
    """The hub's outline in its body axes: the box its thrusters sit on (12 edges, each 2 x 3) [m]."""
    positions = np.array([th["position_body_m"] for th in scenario.get("thrusters", {}).get("list", [])], float)
    if positions.size == 0:
        return []
    low, high = positions.min(axis=0), positions.max(axis=0)
    corners = np.array([[(low, high)[(k >> i) & 1][i] for i in range(3)] for k in range(8)])
    return [corners[[a, b]] for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]


def hub_outline(t, row, edges):
    """The hub's edges in target axes at a row."""
    rotation = quat_matrix(*(t[f"q_target_from_hub_{c}"][row] for c in "wxyz"))
    origin = np.array([t[f"hub_target_{c}_m"][row] for c in XYZ])
    return [origin + edge @ rotation.T for edge in edges]


def key_instants(t, mask, summary):
    """(label, row) of the instants drawn: the waking, the path's end, the approach, the closure, the
    brakes (after a rigidisation), the end; a berthing's soft and hard docks for the closure."""
    time = t["t_s"]
    rows = np.flatnonzero(mask)
    if rows.size == 0:
        return []
    reach = summary["reach"]
    wanted = [("the arm wakes", time[rows[0]]), ("at the pre-grasp pose", float(reach["hold_from_s"]))]
    for phase in summary.get("phases_flown", []):
        if phase.get("name") == "capture":
            wanted.append(("the approach begins", float(phase["start_s"])))
    berthing = reach.get("berthing")
    closure = (reach.get("grasp") or {}).get("closure_s")
    if berthing:  # ASSIST's probe: the latches, then the pins
        if berthing.get("soft_dock_s") is not None:
            wanted.append(("the latches close (soft dock)", float(berthing["soft_dock_s"])))
        if berthing.get("hard_dock_s") is not None:
            wanted.append(("the pins engage (hard dock)", float(berthing["hard_dock_s"])))
    elif closure is not None:
        wanted.append(("the jaws close", float(closure)))
    brakes = (reach.get("rigidisation") or {}).get("brakes_s")
    if brakes is not None:
        wanted.append(("the brakes engage", float(brakes)))
    wanted.append(("the end", time[rows[-1]]))
    instants = []
    for label, at_s in wanted:
        row = rows[min(np.searchsorted(time[rows], at_s - 1e-9), rows.size - 1)]
        if all(row != r for _, r in instants):
            instants.append((f"{time[row]:,.1f} s: {label}", row))
    return instants


def plot_figures(t, mask, summary, scenario, out):
    """reach_figures.png; False (nothing written) for a telemetry without the arm's figure."""
    if "joint1_target_x_m" not in t.dtype.names:
        return False
    body = scenario.get("target", {}).get("body", {})
    grasp = np.array(body.get("grasp_point_target_m", (0.0, 0.0, 0.0)), float)
    edges = hub_box_edges(scenario)
    instants = key_instants(t, mask, summary)
    fig, axes = plt.subplots(1, 2, figsize=(13, 6))
    for ax, (a, b) in zip(axes, ((0, 2), (0, 1))):
        for box in body.get("keep_out", []):
            c, h = np.array(box["centre_target_m"], float), np.array(box["half_extents_m"], float)
            ax.add_patch(plt.Rectangle((c[a] - h[a], c[b] - h[b]), 2 * h[a], 2 * h[b], color="0.85", zorder=0))
        ax.plot(grasp[a], grasp[b], "k*", ms=12,
                label="the drogue's socket" if summary["reach"].get("berthing") else "the fixture (grasp point)")
        colours = plt.cm.viridis(np.linspace(0.0, 0.9, max(len(instants), 1)))
        for (label, row), colour in zip(instants, colours):
            points = chain_points(t, row)
            ax.plot(points[:, a], points[:, b], "-o", color=colour, ms=3, lw=1.5, label=label)
            for edge in hub_outline(t, row, edges):
                ax.plot(edge[:, a], edge[:, b], color=colour, lw=0.6)
        every = np.vstack([chain_points(t, row) for _, row in instants] + [grasp[None, :]])
        low, high = every.min(axis=0) - 1.5, every.max(axis=0) + 1.5
        ax.set_xlim(low[a], high[a])
        ax.set_ylim(low[b], high[b])
        ax.set_aspect("equal")
        ax.set_xlabel(f"target {XYZ[a]} [m]")
        ax.set_ylabel(f"target {XYZ[b]} [m]")
        ax.set_title("side view" if b == 2 else "top view")
    axes[0].legend(fontsize=8, loc="best")
    fig.suptitle("Hub, arm and the target's keep-out volume (grey), true, in the target's axes")
    fig.tight_layout()
    fig.savefig(out / "reach_figures.png", dpi=110)
    plt.close(fig)
    return True


def joint_rates_degps(t, rows):
    """Each joint's rate [deg/s] at the rows: the angles' central difference over the periods (one-sided
    at the ends), shape (rows, 7)."""
    time = t["t_s"][rows]
    angles = np.column_stack([np.degrees(t[f"q_arm_{j + 1}_rad"][rows]) for j in range(JOINTS)])
    return np.gradient(angles, time, axis=0)


def plot_rigidisation(t, summary, scenario, out):
    """reach_rigidisation.png; False (nothing written) without a rigidisation."""
    rigidisation = (summary.get("reach") or {}).get("rigidisation")
    if not rigidisation:
        return False
    start_s = float(rigidisation["start_s"])
    brakes_s = rigidisation.get("brakes_s")
    end_s = float(brakes_s) + 10.0 if brakes_s is not None else float(t["t_s"][-1])
    rows = (t["t_s"] >= start_s - 1e-9) & (t["t_s"] <= end_s + 1e-9)
    if rows.sum() < 2:
        return False
    _, _, repeated, momentary = arm_limits(scenario)
    time = t["t_s"][rows]
    held = np.array([np.degrees(t[f"q_arm_{j + 1}_rad"][rows][0]) for j in range(JOINTS)])
    rates = joint_rates_degps(t, rows)
    fig, axes = plt.subplots(3, 1, figsize=(11, 9), sharex=True)
    for j in range(JOINTS):
        axes[0].plot(time, np.degrees(t[f"q_arm_{j + 1}_rad"][rows]) - held[j], lw=1, label=f"joint {j + 1}")
        axes[1].plot(time, rates[:, j], lw=1)
        axes[2].plot(time, t[f"tau_arm_{j + 1}_Nm"][rows], lw=1)
    axes[0].set_ylabel("angle from q_d [deg]")
    axes[0].legend(fontsize=8, ncol=7)
    law = rigidisation.get("law", "")
    axes[0].set_title(f"The rigidisation{f' ({law} law)' if law else ''}: the thrusters inhibited, the arm alone")
    axes[1].set_ylabel("rate [deg/s]")
    axes[1].set_yscale("symlog", linthresh=0.01)
    axes[1].axhline(0.01, color="r", ls="--", lw=0.8)
    axes[1].axhline(-0.01, color="r", ls="--", lw=0.8, label="the brakes' threshold (default 0.01 deg/s)")
    axes[1].legend(fontsize=8)
    peak = max(float(np.abs(t[f"tau_arm_{j + 1}_Nm"][rows]).max()) for j in range(JOINTS))
    if peak > 0.5 * repeated:
        for limit, style in ((repeated, "--"), (momentary, ":")):
            axes[2].axhline(limit, color="r", ls=style, lw=1)
            axes[2].axhline(-limit, color="r", ls=style, lw=1)
    axes[2].set_ylabel(f"torque [N m] (limits {repeated:.0f} / {momentary:.0f}"
                       f"{' off scale' if peak <= 0.5 * repeated else ''})")
    axes[2].set_xlabel("t [s]")
    if brakes_s is not None:
        for axis in axes:
            axis.axvline(float(brakes_s), color="k", ls=":", lw=1)
        axes[2].text(float(brakes_s), axes[2].get_ylim()[1], " brakes", va="top", fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "reach_rigidisation.png", dpi=110)
    plt.close(fig)
    return True


def rate_magnitude_degps(t, rows):
    """The target's true rate [deg/s] at the rows: its magnitude (the composite's, once braked)."""
    w = np.column_stack([t[f"omega_target_body_{c}_radps"][rows] for c in XYZ])
    return np.degrees(np.linalg.norm(w, axis=1))


def plot_stabilisation(t, summary, scenario, out):
    """reach_stabilisation.png; False (nothing written) without a stabilisation or its load channels."""
    stabilisation = (summary.get("reach") or {}).get("stabilisation")
    if not stabilisation or "load_arm_1_Nm" not in t.dtype.names:
        return False
    _, _, repeated, momentary = arm_limits(scenario)
    brakes_s = float((summary["reach"].get("rigidisation") or {}).get("brakes_s") or stabilisation["start_s"])
    rows = t["t_s"] >= brakes_s - 1e-9
    time = t["t_s"][rows]
    fig, axes = plt.subplots(2, 1, figsize=(11, 8), sharex=True)
    for c in XYZ:
        axes[0].plot(time, np.degrees(t[f"omega_target_body_{c}_radps"][rows]), lw=1, label=f"target {c}")
    axes[0].plot(time, rate_magnitude_degps(t, rows), "k", lw=1.5, label="magnitude")
    axes[0].axhline(float(stabilisation["goal_rate_deg_s"]), color="r", ls="--", lw=1, label="Table 3: 0.5 deg/s")
    axes[0].set_ylabel("rate [deg/s]")
    axes[0].legend(fontsize=8, ncol=5)
    axes[0].set_title("The composite's rate (the target's, true, its axes) from the brakes on")
    for j in range(JOINTS):
        axes[1].plot(time, t[f"load_arm_{j + 1}_Nm"][rows], lw=0.8, label=f"joint {j + 1}")
    for limit, style in ((repeated, "--"), (momentary, ":")):
        axes[1].axhline(limit, color="r", ls=style, lw=1)
        axes[1].axhline(-limit, color="r", ls=style, lw=1)
    axes[1].set_ylabel("brake load [N m]")
    axes[1].set_xlabel("t [s]")
    axes[1].legend(fontsize=8, ncol=7)
    axes[1].set_title(f"The braked joints' loads, sampled each period (peak over every step: "
                      f"{float(stabilisation['peak_joint_load_Nm']):.1f} N m)")
    fig.tight_layout()
    fig.savefig(out / "reach_stabilisation.png", dpi=110)
    plt.close(fig)
    return True


def keep_out_rectangles(scenario, axes_pair):
    """The target's keep-out boxes (target.body.keep_out) projected on two target axes: (corner, w, h)."""
    boxes = (scenario.get("target", {}).get("body") or {}).get("keep_out") or []
    out = []
    for box in boxes:
        centre, half = np.array(box["centre_target_m"], float), np.array(box["half_extents_m"], float)
        a, b = axes_pair
        out.append(((centre[a] - half[a], centre[b] - half[b]), 2 * half[a], 2 * half[b]))
    return out


def plot_escape(t, summary, scenario, out):
    """reach_escape.png; False (nothing written) without an escape flown (summary.json's reach.escape)."""
    from matplotlib.patches import Rectangle

    escape = (summary.get("reach") or {}).get("escape")
    if not escape or not escape.get("flown"):
        return False
    start_s, desync_s, hold_s = (float(escape[k]) for k in ("start_s", "desynchronise_s", "hold_s"))
    time = t["t_s"]
    synchronised = (time >= start_s - 1e-9) & (time < desync_s)
    fig, axes = plt.subplots(1, 3, figsize=(15, 5))
    for ax, (a, b) in zip(axes[:2], ((0, 2), (0, 1))):
        for corner, width, height in keep_out_rectangles(scenario, (a, b)):
            ax.add_patch(Rectangle(corner, width, height, color="0.8", label="keep-out"))
        for name, style in (("hub_target", "b-"), ("tool_target", "g-")):
            ax.plot(t[f"{name}_{XYZ[a]}_m"][synchronised], t[f"{name}_{XYZ[b]}_m"][synchronised], style, lw=1.2,
                    label="chaser" if name == "hub_target" else "tool point")
        ax.set_xlabel(f"{XYZ[a]} [m] (target axes)")
        ax.set_ylabel(f"{XYZ[b]} [m]")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title("Turning with the target: retract and withdraw")
    handles, labels = axes[0].get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    axes[0].legend(unique.values(), unique.keys(), fontsize=8)
    rows = time >= start_s - 1e-9
    distance = np.linalg.norm(np.column_stack([t[f"r_lvlh_{c}_m"][rows] for c in XYZ]), axis=1)
    axes[2].plot(time[rows], distance, "b", lw=1.2, label="chaser from the target's centre")
    axes[2].axhline(float(escape["safe_distance_m"]), color="r", ls="--", lw=1, label="safe distance")
    for instant, name in ((desync_s, "desynchronise"), (hold_s, "hold")):
        axes[2].axvline(instant, color="k", ls=":", lw=1)
        axes[2].text(instant, 1.0, f" {name}", rotation=90, va="bottom", fontsize=8)
    axes[2].set_xlabel("t [s]")
    axes[2].set_ylabel("distance [m]")
    axes[2].legend(fontsize=8)
    axes[2].set_title(f"The escape ({escape['trigger']}) from {start_s:.1f} s")
    fig.tight_layout()
    fig.savefig(out / "reach_escape.png", dpi=110)
    plt.close(fig)
    return True


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
    hold_from_s, hold_to_s = float(reach["hold_from_s"]), approach_start_s(summary)
    plot_gripper(t, mask, hold_from_s, hold_to_s, out)
    figures = plot_figures(t, mask, summary, scenario, out)
    rigidisation = plot_rigidisation(t, summary, scenario, out)
    stabilisation = plot_stabilisation(t, summary, scenario, out)
    escape = plot_escape(t, summary, scenario, out)
    hold = mask & (t["t_s"] >= hold_from_s) & (t["t_s"] < hold_to_s)
    ratio = envelope_exceedance(np.column_stack([t[f"gripper_err_{c}_m"][hold] for c in XYZ]) * 1e3, ENVELOPE_MM)
    written = (["reach_joints.png", "reach_gripper.png"] + (["reach_figures.png"] if figures else [])
               + (["reach_rigidisation.png"] if rigidisation else [])
               + (["reach_stabilisation.png"] if stabilisation else [])
               + (["reach_escape.png"] if escape else []))
    print(f"wrote {', '.join(str(out / w) for w in written)}; over the hold the gripper used "
          f"{', '.join(f'{r:.0%}' for r in ratio)} of Table 2's position envelope (x, y, z)")
    if args.show:
        plt.show()


if __name__ == "__main__":
    main()
