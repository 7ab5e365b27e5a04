#!/usr/bin/env python3
"""Plots of `chaser fmea ... --history`, in the style of Zhou 2018, Figs. 6-16.

Usage: /usr/bin/python3 python/plot_invsim.py DIR [--modes LABEL ...] [--configuration NAME]
                                                  [--out PLOTDIR]

DIR is the output directory of `chaser fmea SCENARIO --out DIR --history`: fmea.csv (one row per
layout and mode: class, k_p, limits), history/index.csv (configuration, mode, file) and one history
CSV per layout and mode (one row per inverse-simulation step).

Per mode, PLOTDIR/<configuration>/<history file stem>.png (default PLOTDIR = DIR/plots), four panels:
 1. trajectory: x (left axis) and y, z (right axis) in the paper's Hill frame against time, the
    desired trajectory dashed (Figs. 6-7);
 2. attitude: roll, pitch, yaw against the +-attitude limit (Figs. 7-13);
 3. line of sight: azimuth and elevation against the field of view, outside shaded (Figs. 9-16);
 4. pulses: cumulative count of the steps in which each body axis' translation group fired, per
    direction (x+ ... z-; the totals are Table 4's entries).
The title carries the layout, the mode, the failed thrusters, the risk class, k_p and docking.
Per layout, PLOTDIR/<configuration>/overview.png: k_p per mode in fmea.csv order, coloured by risk
class (I green, II orange, III red), the nominal k_p as a line. With several layouts,
PLOTDIR/configurations.png: fault modes per class (stacked) and propellant over all modes per
layout. Exit 2 with a message when DIR is not an fmea output or a filter matches nothing.
"""
import argparse
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

CLASS_COLOURS = {"I": "tab:green", "II": "tab:orange", "III": "tab:red"}
HISTORY_COLUMNS = ("t_s", "x_m", "y_m", "z_m", "x_desired_m", "y_desired_m", "z_desired_m", "roll_deg",
                   "pitch_deg", "yaw_deg", "azimuth_deg", "elevation_deg", "pulse_x", "pulse_y", "pulse_z")
FMEA_COLUMNS = ("configuration", "mode", "failed", "k_p", "risk_class", "docked", "azimuth_limit_deg",
                "elevation_limit_deg", "attitude_limit_deg", "propellant_kg")


class InputError(Exception):
    """DIR is not what `chaser fmea --history` writes."""


def read_csv(path, required):
    if not path.is_file():
        raise InputError(f"{path}: missing (is the directory a `chaser fmea --history` output?)")
    with path.open(newline="") as f:
        reader = csv.DictReader(f)
        missing = [c for c in required if c not in (reader.fieldnames or [])]
        if missing:
            raise InputError(f"{path}: missing column(s) {', '.join(missing)}")
        return list(reader)


def load_history(path):
    if not path.is_file():
        raise InputError(f"{path}: missing (listed in history/index.csv)")
    data = np.genfromtxt(path, delimiter=",", names=True)
    missing = [c for c in HISTORY_COLUMNS if c not in (data.dtype.names or ())]
    if missing:
        raise InputError(f"{path}: missing column(s) {', '.join(missing)}")
    return np.atleast_1d(data)


def title_of(row):
    failed = row["failed"] or "none"
    return (f"{row['configuration']}: {row['mode']} (failed: {failed}); class {row['risk_class']}, "
            f"k_p {float(row['k_p']):.3f}, docked: {row['docked']}")


def plot_trajectory(ax, h):
    t = h["t_s"]
    ax.plot(t, h["x_m"], color="tab:blue", lw=1.0, label="x")
    ax.plot(t, h["x_desired_m"], color="tab:blue", lw=0.8, ls="--", label="x desired")
    ax.set_ylabel("x [m]")
    right = ax.twinx()
    for name, colour in (("y", "tab:orange"), ("z", "tab:green")):
        right.plot(t, h[f"{name}_m"], color=colour, lw=1.0, label=name)
        right.plot(t, h[f"{name}_desired_m"], color=colour, lw=0.8, ls="--")
    right.set_ylabel("y, z [m]")
    lines = ax.get_legend_handles_labels()
    more = right.get_legend_handles_labels()
    ax.legend(lines[0] + more[0], lines[1] + more[1], loc="upper right", fontsize=7, ncol=4)
    ax.set_title("trajectory (Hill frame: x along the velocity, z to the Earth)", fontsize=9)


def plot_attitude(ax, h, limit):
    for name in ("roll", "pitch", "yaw"):
        ax.plot(h["t_s"], h[f"{name}_deg"], lw=0.8, label=name)
    for sign in (1, -1):
        ax.axhline(sign * limit, color="tab:red", lw=0.8, ls="--")
    ax.set_ylabel("attitude [deg]")
    ax.legend(loc="upper right", fontsize=7, ncol=3)
    ax.set_title(f"attitude against +-{limit:g} deg", fontsize=9)


def plot_line_of_sight(ax, h, az_limit, el_limit):
    ax.plot(h["t_s"], h["azimuth_deg"], lw=0.8, label="azimuth")
    ax.plot(h["t_s"], h["elevation_deg"], lw=0.8, label="elevation")
    limit = max(az_limit, el_limit)
    peak = max(limit * 1.2, float(np.nanmax(np.abs(np.concatenate([h["azimuth_deg"], h["elevation_deg"]])))) * 1.05)
    for sign in (1, -1):
        ax.axhline(sign * az_limit, color="tab:red", lw=0.8, ls="--")
        ax.axhspan(sign * limit, sign * peak, color="tab:red", alpha=0.08)
    ax.set_ylim(-peak, peak)
    ax.set_ylabel("line of sight [deg]")
    ax.legend(loc="upper right", fontsize=7, ncol=2)
    ax.set_title(f"line of sight against the field of view (+-{az_limit:g} / +-{el_limit:g} deg)", fontsize=9)


def plot_pulses(ax, h):
    for axis, colour in (("x", "tab:blue"), ("y", "tab:orange"), ("z", "tab:green")):
        direction = h[f"pulse_{axis}"]
        for sign, style, suffix in ((1, "-", "+"), (-1, "--", "-")):
            count = np.cumsum(direction == sign)
            ax.plot(h["t_s"], count, color=colour, ls=style, lw=1.0, label=f"{axis}{suffix}: {int(count[-1])}")
    ax.set_ylabel("pulses (cumulative)")
    ax.set_xlabel("t [s]")
    ax.legend(loc="upper left", fontsize=7, ncol=3)
    ax.set_title("pulses per body axis and direction", fontsize=9)


def plot_mode(row, history, path):
    fig, axes = plt.subplots(4, 1, figsize=(9, 11), sharex=True)
    plot_trajectory(axes[0], history)
    plot_attitude(axes[1], history, float(row["attitude_limit_deg"]))
    plot_line_of_sight(axes[2], history, float(row["azimuth_limit_deg"]), float(row["elevation_limit_deg"]))
    plot_pulses(axes[3], history)
    fig.suptitle(title_of(row), fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_overview(configuration, rows, path):
    k_p = [float(r["k_p"]) for r in rows]
    colours = [CLASS_COLOURS.get(r["risk_class"], "tab:gray") for r in rows]
    fig, ax = plt.subplots(figsize=(max(8, 0.18 * len(rows)), 4.5))
    ax.bar(range(len(rows)), k_p, color=colours)
    nominal = [float(r["k_p"]) for r in rows if r["mode"] == "nominal"]
    if nominal:
        ax.axhline(nominal[0], color="black", lw=0.8, ls="--", label=f"nominal k_p {nominal[0]:.3f}")
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels([r["mode"] for r in rows], rotation=90, fontsize=6)
    ax.set_ylabel("operational amount k_p")
    handles = [plt.Rectangle((0, 0), 1, 1, color=c) for c in CLASS_COLOURS.values()]
    labels = [f"class {c}" for c in CLASS_COLOURS]
    if nominal:
        extra = ax.get_legend_handles_labels()
        handles, labels = handles + extra[0], labels + extra[1]
    ax.legend(handles, labels, fontsize=7, loc="upper left")
    ax.set_title(f"{configuration}: k_p per fault mode, coloured by risk class", fontsize=10)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_configurations(by_configuration, path):
    names = list(by_configuration)
    fig, (ax_c, ax_p) = plt.subplots(1, 2, figsize=(10, 4))
    bottom = np.zeros(len(names))
    for risk, colour in CLASS_COLOURS.items():
        counts = np.array([sum(1 for r in by_configuration[n] if r["mode"] != "nominal" and r["risk_class"] == risk)
                           for n in names])
        ax_c.bar(names, counts, bottom=bottom, color=colour, label=f"class {risk}")
        bottom += counts
    ax_c.set_ylabel("fault modes")
    ax_c.legend(fontsize=7)
    ax_c.set_title("fault modes per risk class", fontsize=10)
    ax_p.bar(names, [sum(float(r["propellant_kg"]) for r in by_configuration[n]) for n in names], color="tab:blue")
    ax_p.set_ylabel("propellant over all modes [kg]")
    ax_p.set_title("propellant", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", type=Path, help="output directory of `chaser fmea ... --history`")
    parser.add_argument("--modes", nargs="+", help="only these mode labels (e.g. nominal d1/d2~+e2/e1~)")
    parser.add_argument("--configuration", help="only this layout (baseline, scheme_I, ...)")
    parser.add_argument("--out", type=Path, help="plot directory (default DIR/plots)")
    args = parser.parse_args(argv)
    try:
        fmea = read_csv(args.dir / "fmea.csv", FMEA_COLUMNS)
        index = read_csv(args.dir / "history" / "index.csv", ("configuration", "mode", "file"))
        rows = {(r["configuration"], r["mode"]): r for r in fmea}
        selected = [e for e in index
                    if (args.configuration is None or e["configuration"] == args.configuration)
                    and (args.modes is None or e["mode"] in args.modes)]
        if not selected:
            raise InputError(f"no mode of {args.dir / 'history' / 'index.csv'} matches --configuration "
                             f"{args.configuration} --modes {' '.join(args.modes or [])}")
        out = args.out or args.dir / "plots"
        for entry in selected:
            key = (entry["configuration"], entry["mode"])
            if key not in rows:
                raise InputError(f"{args.dir / 'fmea.csv'}: no row for {key[0]} / {key[1]}")
            history = load_history(args.dir / "history" / entry["file"])
            plot_mode(rows[key], history, out / entry["configuration"] / (Path(entry["file"]).stem + ".png"))
        by_configuration = {}
        for r in fmea:
            by_configuration.setdefault(r["configuration"], []).append(r)
        for configuration, layout_rows in by_configuration.items():
            if args.configuration is None or configuration == args.configuration:
                plot_overview(configuration, layout_rows, out / configuration / "overview.png")
        if len(by_configuration) > 1 and args.configuration is None:
            plot_configurations(by_configuration, out / "configurations.png")
    except InputError as e:
        print(f"plot_invsim.py: {e}", file=sys.stderr)
        return 2
    print(f"plot_invsim.py: {len(selected)} mode plot(s) and the overviews written to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
