#!/usr/bin/env python3
"""Plots of `chaser fmea ... --history`, in the style of Zhou 2018, Figs. 6-16.

Usage: /usr/bin/python3 python/plot_invsim.py DIR [--modes LABEL ...] [--configuration NAME]
                                                  [--out PLOTDIR] [--jobs N] [--verbose]

DIR is the output directory of `chaser fmea SCENARIO --out DIR --history`: fmea.csv (one row per
layout and fault mode: pulses, k_p, limits, risk class), history/index.csv (configuration, mode,
file; optional draws, draw_seed) and one history CSV per layout and mode (one row per 1 s
inverse-simulation step). With several noise draws per mode (the `paper` reading) a row of fmea.csv
combines them (mean counts, worst deviation) and its history is one draw, the one its class comes
from: the title names it, the legend's totals are that draw's, and they are not checked against
fmea.csv's means.

Per mode of the index (all by default; --modes keeps these mode labels, --configuration this
layout), PLOTDIR/<configuration>/<history file stem>.png (default PLOTDIR = DIR/plots), four panels:
 1. trajectory in the paper's Hill frame (x along the target's velocity, z to the Earth) against
    time, the desired one dashed: x on its own axis (100 -> 10 m), y and z on another (Fig. 6);
 2. attitude: roll, pitch, yaw against the +-attitude limit (Figs. 7-8, 13-14, 16);
 3. line of sight: azimuth and elevation against the field of view; the band outside it shaded,
    and the times the target is out of view shaded red across the panel (Figs. 7-16);
 4. pulses: CUMULATIVE count of each body axis' translation pulses (the history's count_x.. under
    the scenario's reading; without them, the steps in which the group fired), per
    direction (x+ solid, x- dashed, ...; the legend's totals are the Table 4/5 entries of fmea.csv,
    and a mismatch is warned about on stderr) (Fig. 6).
The title carries the layout, the mode, the failed thrusters, the risk class, k_p and docking.
Per layout plotted, PLOTDIR/<configuration>/overview.png: k_p per mode in fmea.csv order, coloured
by risk class (I green, II orange, III red), the nominal k_p dashed (Tables 4-6). When fmea.csv has
several layouts and --configuration is not given, PLOTDIR/configurations.png: fault modes per class
(stacked, nominal excluded) and propellant summed over all modes, per layout (section 5).

--jobs N draws the mode plots in N processes (about 0.3 s each in one). Prints one summary line
(with --verbose, one line per file). Exit status 2, with every problem named, when DIR is not an
fmea output (missing directory, file or column, a number that is not one, a history file the index
lists but that is absent or unreadable: the other modes are still drawn) or --modes /
--configuration names something that is not there.
"""
import argparse
import csv
import multiprocessing
import sys
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

CLASS_COLOURS = {"I": "tab:green", "II": "tab:orange", "III": "tab:red"}
AXIS_COLOURS = {"x": "tab:blue", "y": "tab:orange", "z": "tab:green"}
# Written by cli/fmea_history.cpp; the plots read HISTORY_COLUMNS only.
HISTORY_HEADER = ("t_s", "x_m", "y_m", "z_m", "vx_mps", "vy_mps", "vz_mps", "x_desired_m", "y_desired_m",
                  "z_desired_m", "roll_deg", "pitch_deg", "yaw_deg", "azimuth_deg", "elevation_deg", "ux_mps2",
                  "uy_mps2", "uz_mps2", "pulse_x", "pulse_y", "pulse_z", "count_x", "count_y", "count_z")
# Pulses counted in the step under the scenario's reading (docs/invsim.md, "Readings of App. B");
# optional: without them a fired step counts one (the smooth reading).
COUNT_COLUMNS = ("count_x", "count_y", "count_z")
HISTORY_COLUMNS = ("t_s", "x_m", "y_m", "z_m", "x_desired_m", "y_desired_m", "z_desired_m", "roll_deg",
                   "pitch_deg", "yaw_deg", "azimuth_deg", "elevation_deg", "pulse_x", "pulse_y", "pulse_z")
INDEX_COLUMNS = ("configuration", "mode", "file")  # and, optional: draws, draw_seed (noise draws)
FMEA_NUMBERS = ("k_p", "azimuth_limit_deg", "elevation_limit_deg", "attitude_limit_deg", "propellant_kg")
FMEA_COLUMNS = ("configuration", "mode", "failed", "risk_class", "docked", *FMEA_NUMBERS)
PULSE_COLUMNS = ("x_pos", "x_neg", "y_pos", "y_neg", "z_pos", "z_neg")  # optional: checked when present
PROG = "plot_invsim"


def warn(text):
    print(f"{PROG}: warning: {text}", file=sys.stderr)


def fail(problems):
    for problem in problems:
        print(f"{PROG}: error: {problem}", file=sys.stderr)
    sys.exit(2)


def read_table(path, required, hint, problems):
    """Rows of a CSV file as dicts; None (and a problem) if it is missing or lacks a column."""
    if not path.is_file():
        problems.append(f"{path}: not found ({hint})")
        return None
    with path.open(newline="") as f:
        reader = csv.DictReader(f)
        if not reader.fieldnames:
            problems.append(f"{path}: empty (no header line)")
            return None
        missing = [c for c in required if c not in reader.fieldnames]
        if missing:
            problems.append(f"{path}: missing column(s) {', '.join(missing)}")
            return None
        return list(reader)


def load_fmea(path, problems):
    """fmea.csv rows, FMEA_NUMBERS and PULSE_COLUMNS as floats; None when unusable."""
    rows = read_table(path, FMEA_COLUMNS, "is DIR a `chaser fmea --out DIR` output?", problems)
    if rows is None:
        return None
    if not rows:
        problems.append(f"{path}: no fault mode (header only)")
    for line, row in enumerate(rows, start=2):
        for column in FMEA_NUMBERS + tuple(c for c in PULSE_COLUMNS if c in row):
            try:
                row[column] = float(row[column])
            except (TypeError, ValueError):
                problems.append(f"{path} line {line} ({row['configuration']} {row['mode']}): "
                                f"{column} is {row[column]!r}, not a number")
    return rows


def select(index, fmea, args, problems):
    """The index entries to plot, after --configuration and --modes; every unknown name is a problem."""
    configurations = list(dict.fromkeys(r["configuration"] for r in fmea))
    if args.configuration is not None and args.configuration not in configurations:
        problems.append(f"--configuration {args.configuration}: not in fmea.csv "
                        f"(its configurations: {', '.join(configurations)})")
        return []
    entries = [e for e in index if args.configuration in (None, e["configuration"])]
    if args.modes:
        known = list(dict.fromkeys(e["mode"] for e in entries))
        in_fmea = set(r["mode"] for r in fmea if args.configuration in (None, r["configuration"]))
        where = f"configuration {args.configuration}" if args.configuration else "any configuration"
        for label in dict.fromkeys(args.modes):
            if label not in known:
                why = "has a row in fmea.csv but" if label in in_fmea else "is not a mode of fmea.csv and has"
                listed = ", ".join(known[:12]) + (", ..." if len(known) > 12 else "")
                problems.append(f"--modes {label}: {why} no history for {where} in history/index.csv "
                                f"(modes there: {listed})")
        entries = [e for e in entries if e["mode"] in args.modes]
    if not entries and not problems:
        problems.append("history/index.csv lists no mode" + (f" of {args.configuration}" if args.configuration else ""))
    keys = set((r["configuration"], r["mode"]) for r in fmea)
    for e in entries:
        if (e["configuration"], e["mode"]) not in keys:
            problems.append(f"fmea.csv: no row for configuration {e['configuration']}, mode {e['mode']} "
                            "(listed in history/index.csv)")
    return entries


def check_history_header(path, problems):
    """A problem if the history file is missing or its header lacks a column the plots need."""
    if not path.is_file():
        problems.append(f"{path}: not found (listed in history/index.csv)")
        return
    with path.open(newline="") as f:
        header = next(csv.reader(f), [])
    missing = [c for c in HISTORY_COLUMNS if c not in header]
    if missing:
        problems.append(f"{path}: missing column(s) {', '.join(missing)}")


def load_history(path):
    """{column: float array} of one history file; raises ValueError naming the file when unreadable."""
    with path.open(newline="") as f:
        header = next(csv.reader(f), [])
    columns = HISTORY_COLUMNS + tuple(c for c in COUNT_COLUMNS if c in header)
    try:
        with warnings.catch_warnings():  # a header-only file is reported below, not warned about
            warnings.simplefilter("ignore", UserWarning)
            data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2,
                              usecols=[header.index(c) for c in columns])
    except ValueError as e:
        raise ValueError(f"{path}: unreadable, cut mid-write? ({e})") from None
    if data.shape[0] == 0:
        raise ValueError(f"{path}: no step (header only)")
    return {c: data[:, i] for i, c in enumerate(columns)}


def yes_no(text):
    return "yes" if text.strip().lower() == "true" else ("no" if text.strip().lower() == "false" else text)


def draws_of(row):
    """The noise draws the fmea.csv row combines (1 when the index does not say)."""
    try:
        return max(1, int(row.get("draws") or 1))
    except ValueError:
        return 1


def title_of(row):
    failed = row["failed"].strip() or "none"
    title = (f"{row['configuration']}: mode {row['mode']} (failed: {failed})\n"
             f"risk class {row['risk_class']}, k_p {row['k_p']:.4f}, docked: {yes_no(row['docked'])}, "
             f"propellant {row['propellant_kg']:.2f} kg  (after Zhou 2018, Figs. 6-16)")
    if draws_of(row) > 1:
        title += (f"\nhistory: the noise draw of seed {row.get('draw_seed') or '?'}, the worst of "
                  f"{draws_of(row)} (k_p and propellant: their mean)")
    return title


def outside_legend(ax, **kw):
    """Legend right of the panel: the signals may be anywhere in it."""
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8, frameon=False, **kw)


def finite_peak(values):
    """max |value| over the finite ones (a diverged run may end in nan or inf), 0 if none."""
    finite = np.abs(values[np.isfinite(values)])
    return float(finite.max()) if finite.size else 0.0


def panel_title(ax, text):
    # A fixed y skips matplotlib's search for tick labels above the panel: a tenth of the drawing time.
    ax.set_title(text, fontsize=9, y=1.0)


def plot_trajectory(ax_x, ax_yz, h):
    t = h["t_s"]
    ax_x.plot(t, h["x_m"], color=AXIS_COLOURS["x"], lw=1.0, label="x")
    ax_x.plot(t, h["x_desired_m"], color="k", lw=0.8, ls="--", label="x desired")
    ax_x.set_ylabel("x [m]")
    panel_title(ax_x, "1. trajectory, Hill frame (x along the target's velocity, z to the Earth); desired dashed")
    outside_legend(ax_x)
    for name in ("y", "z"):
        ax_yz.plot(t, h[f"{name}_m"], color=AXIS_COLOURS[name], lw=1.0, label=name)
        ax_yz.plot(t, h[f"{name}_desired_m"], color=AXIS_COLOURS[name], lw=0.8, ls="--", label=f"{name} desired")
    ax_yz.set_ylabel("y, z [m]")
    outside_legend(ax_yz)


def plot_attitude(ax, h, limit, row):
    peaks = []
    for name in ("roll", "pitch", "yaw"):
        ax.plot(h["t_s"], h[f"{name}_deg"], lw=0.9, label=name)
        peaks.append(finite_peak(h[f"{name}_deg"]))
    ax.axhline(limit, color="tab:red", lw=0.9, ls="--", label=f"+-{limit:g} deg limit")
    ax.axhline(-limit, color="tab:red", lw=0.9, ls="--")
    top = max(1.5 * limit, 1.08 * max(peaks))
    ax.set_ylim(-top, top)
    ax.set_ylabel("attitude [deg]")
    within = yes_no(row.get("attitude_within_limits", "")) or ("yes" if max(peaks) <= limit else "no")
    within = "within the limit" if within == "yes" else "LIMIT EXCEEDED"
    panel_title(ax, f"2. attitude: peak |roll| {peaks[0]:.2f}, |pitch| {peaks[1]:.2f}, |yaw| {peaks[2]:.2f} deg, "
                    f"{within}")
    outside_legend(ax)


def step_spans(t, flag, dt):
    """(start, width) of each run of steps with flag set, a step lasting until the next one (dt)."""
    edges = np.diff(np.concatenate([[0], flag.astype(np.int8), [0]]))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)  # ends: first step after the run
    return [(t[a], t[b - 1] + dt - t[a]) for a, b in zip(starts, ends)]


def plot_line_of_sight(ax, h, az_limit, el_limit):
    t, az, el = h["t_s"], h["azimuth_deg"], h["elevation_deg"]
    ax.plot(t, az, lw=0.9, color="tab:purple", label="azimuth")
    ax.plot(t, el, lw=0.9, color="tab:brown", label="elevation")
    top = max(1.3 * max(az_limit, el_limit), 1.08 * finite_peak(az), 1.08 * finite_peak(el))
    if az_limit == el_limit:
        ax.axhline(az_limit, color="tab:red", lw=0.9, ls="--", label=f"+-{az_limit:g} deg field of view")
        ax.axhline(-az_limit, color="tab:red", lw=0.9, ls="--")
    else:
        for limit, colour, name in ((az_limit, "tab:purple", "azimuth"), (el_limit, "tab:brown", "elevation")):
            ax.axhline(limit, color=colour, lw=0.9, ls="--", label=f"{name} limit +-{limit:g} deg")
            ax.axhline(-limit, color=colour, lw=0.9, ls="--")
    for sign in (1, -1):  # outside the field of view: beyond one angle's limit light, beyond both darker
        ax.axhspan(sign * min(az_limit, el_limit), sign * top, color="tab:red", alpha=0.06, lw=0)
        ax.axhspan(sign * max(az_limit, el_limit), sign * top, color="tab:red", alpha=0.06, lw=0)
    out = (np.abs(az) > az_limit) | (np.abs(el) > el_limit)
    if out.any():
        dt = np.median(np.diff(t)) if t.size > 1 else 1.0
        ax.broken_barh(step_spans(t, out, dt), (0, 1), transform=ax.get_xaxis_transform(), color="tab:red",
                       alpha=0.2, lw=0, label="target out of view")
        what = f"target OUT OF VIEW for {out.sum() * dt:g} s, first at t = {t[out][0]:g} s"
    else:
        what = "target in view throughout"
    ax.set_ylim(-top, top)
    ax.set_ylabel("line of sight [deg]")
    panel_title(ax, f"3. line of sight: {what}")
    outside_legend(ax)


def plot_pulses(ax, h, row):
    totals = []
    for axis in ("x", "y", "z"):
        fired = h[f"pulse_{axis}"]
        per_step = h.get(f"count_{axis}", np.ones_like(fired))
        for sign, style, suffix, column in ((1, "-", "+", f"{axis}_pos"), (-1, "--", "-", f"{axis}_neg")):
            count = np.cumsum(np.where(fired == sign, per_step, 0)).astype(int)
            totals.append(int(count[-1]))
            ax.plot(h["t_s"], count, color=AXIS_COLOURS[axis], ls=style, lw=1.1, drawstyle="steps-post",
                    label=f"{axis}{suffix}: {totals[-1]}")
            if column in row and draws_of(row) == 1 and row[column] != totals[-1]:
                warn(f"{row['configuration']} {row['mode']}: {totals[-1]} {axis}{suffix} pulses in the history, "
                     f"{row[column]:g} in fmea.csv")
    ax.set_ylabel("pulses (cumulative)")
    ax.set_xlabel("t [s]")
    panel_title(ax, f"4. cumulative pulses per body axis and direction (+ solid, - dashed): total {sum(totals)}")
    outside_legend(ax, ncol=2)


def plot_mode(row, h, path):
    """One mode's four panels (trajectory in two axes: x, then y and z)."""
    fig, axes = plt.subplots(5, 1, figsize=(11, 12.5), sharex=True,
                             gridspec_kw={"height_ratios": [1, 1, 1.3, 1.3, 1.3]})
    fig.subplots_adjust(left=0.08, right=0.82, top=0.93 if draws_of(row) == 1 else 0.915, bottom=0.05, hspace=0.32)
    plot_trajectory(axes[0], axes[1], h)
    plot_attitude(axes[2], h, row["attitude_limit_deg"], row)
    plot_line_of_sight(axes[3], h, row["azimuth_limit_deg"], row["elevation_limit_deg"])
    plot_pulses(axes[4], h, row)
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[0].set_xlim(h["t_s"][0], h["t_s"][-1])
    fig.suptitle(title_of(row), fontsize=10)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_history(row, history_path, path):
    """(path, None) once the mode is drawn, (None, why) when its history file is unreadable."""
    try:
        history = load_history(history_path)
    except ValueError as error:  # a file cut mid-write: the others are plotted, then exit 2
        return None, str(error)
    plot_mode(row, history, path)
    return path, None


def class_legend(ax, rows, extra=()):
    handles = [plt.Rectangle((0, 0), 1, 1, color=c) for c in CLASS_COLOURS.values()]
    labels = [f"class {c} ({sum(r['risk_class'] == c for r in rows if not is_nominal(r))} fault modes)"
              for c in CLASS_COLOURS]
    ax.legend(handles + [h for h, _ in extra], labels + [label for _, label in extra], fontsize=8, loc="upper left")


def is_nominal(row):
    return row["mode"] == "nominal" or row.get("table") == "nominal"


def plot_overview(configuration, rows, path):
    """k_p per mode of one layout in fmea.csv order, coloured by risk class; the nominal k_p dashed."""
    k_p = [r["k_p"] for r in rows]
    fig, ax = plt.subplots(figsize=(max(8.0, 2.0 + 0.16 * len(rows)), 5.0))
    ax.bar(range(len(rows)), k_p, color=[CLASS_COLOURS.get(r["risk_class"], "tab:gray") for r in rows])
    extra = []
    nominal = [r["k_p"] for r in rows if is_nominal(r)]
    if nominal:
        extra.append((ax.axhline(nominal[0], color="k", lw=0.9, ls="--"), f"nominal k_p {nominal[0]:.4f}"))
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels([r["mode"] for r in rows], rotation=90, fontsize=6 if len(rows) <= 60 else 5)
    ax.set_xlim(-0.7, len(rows) - 0.3)
    ax.set_ylim(0, 1.25 * max(k_p + [1e-9]))
    ax.set_ylabel("operational amount k_p")
    ax.grid(axis="y", alpha=0.3)
    class_legend(ax, rows, extra)
    ax.set_title(f"{configuration}: k_p per fault mode, coloured by risk class (Zhou 2018, Tables 4-6)", fontsize=10)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_configurations(by_configuration, path):
    """Per layout: fault modes per risk class (stacked, nominal excluded) and propellant over all modes."""
    names = list(by_configuration)
    fig, (ax_c, ax_p) = plt.subplots(1, 2, figsize=(max(10.0, 3.0 * len(names)), 4.5))
    bottom = np.zeros(len(names))
    for risk, colour in CLASS_COLOURS.items():
        counts = np.array([sum(r["risk_class"] == risk for r in by_configuration[n] if not is_nominal(r))
                           for n in names])
        bars = ax_c.bar(names, counts, bottom=bottom, color=colour, label=f"class {risk}")
        ax_c.bar_label(bars, [f"{c}" if c else "" for c in counts], label_type="center", fontsize=8)
        bottom += counts
    ax_c.set_ylim(0, 1.2 * max(bottom.max(), 1))
    ax_c.set_ylabel("fault modes")
    ax_c.legend(fontsize=8, ncol=3, loc="upper center")
    ax_c.set_title("fault modes per risk class", fontsize=10)
    propellant = [sum(r["propellant_kg"] for r in by_configuration[n]) for n in names]
    bars = ax_p.bar(names, propellant, color="tab:blue")
    change = [f", {100 * (p / propellant[0] - 1):+.1f} %" if k and propellant[0] else ""
              for k, p in enumerate(propellant)]
    ax_p.bar_label(bars, [f"{p:.1f} kg{c}\n({len(by_configuration[n])} modes)"
                          for p, c, n in zip(propellant, change, names)], fontsize=8)
    ax_p.set_ylim(0, 1.15 * max(propellant + [1e-9]))
    ax_p.set_ylabel("propellant over all modes [kg]")
    ax_p.set_title(f"total propellant (change against {names[0]})", fontsize=10)
    fig.suptitle("Thruster layouts compared (Zhou 2018, section 5)", fontsize=11)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def load_inputs(args):
    """fmea.csv rows and the selected index entries; exit 2 naming every problem found."""
    problems = []
    if not args.dir.is_dir():
        fail([f"{args.dir}: not a directory (expected the output of `chaser fmea SCENARIO --out DIR --history`)"])
    fmea = load_fmea(args.dir / "fmea.csv", problems)
    index = read_table(args.dir / "history" / "index.csv", INDEX_COLUMNS,
                       "per-step histories are written by `chaser fmea ... --history`", problems)
    if fmea is None or index is None or problems:
        fail(problems)
    entries = select(index, fmea, args, problems)
    for e in entries:
        check_history_header(args.dir / "history" / e["file"], problems)
    if problems:
        fail(problems)
    return fmea, entries


def plot_modes(fmea, entries, args, out):
    """One PNG per index entry; returns the paths written and the unreadable history files."""
    rows = {(r["configuration"], r["mode"]): r for r in fmea}
    jobs = [(dict(rows[(e["configuration"], e["mode"])], draws=e.get("draws"), draw_seed=e.get("draw_seed")),
             args.dir / "history" / e["file"],
             out / e["configuration"] / (Path(e["file"]).stem + ".png")) for e in entries]
    if args.jobs > 1:
        with multiprocessing.Pool(args.jobs) as pool:
            done = pool.starmap(plot_history, jobs, chunksize=4)
    else:
        done = [plot_history(*job) for job in jobs]
    return [path for path, error in done if error is None], [error for _, error in done if error is not None]


def plot_summaries(fmea, entries, args, out):
    """overview.png per layout plotted and, with several layouts and no --configuration, configurations.png."""
    by_configuration = {}
    for r in fmea:
        by_configuration.setdefault(r["configuration"], []).append(r)
    written = []
    for configuration in dict.fromkeys(e["configuration"] for e in entries):
        written.append(out / configuration / "overview.png")
        plot_overview(configuration, by_configuration[configuration], written[-1])
    if len(by_configuration) > 1 and args.configuration is None:
        written.append(out / "configurations.png")
        plot_configurations(by_configuration, written[-1])
    return written


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir", type=Path, help="output directory of `chaser fmea SCENARIO --out DIR --history`")
    ap.add_argument("--modes", nargs="+", metavar="LABEL", help="only these mode labels (e.g. nominal d1/d2~+e2/e1~)")
    ap.add_argument("--configuration", metavar="NAME", help="only this layout (baseline, scheme_I, ...)")
    ap.add_argument("--out", type=Path, metavar="PLOTDIR", help="where the PNGs go (default: DIR/plots)")
    ap.add_argument("--jobs", "-j", type=int, default=1, help="processes drawing the mode plots (default 1)")
    ap.add_argument("--verbose", "-v", action="store_true", help="print one line per file written")
    args = ap.parse_args()
    if args.jobs < 1:
        ap.error(f"--jobs {args.jobs}: must be at least 1")

    fmea, entries = load_inputs(args)
    out = args.out or args.dir / "plots"
    try:
        modes, unreadable = plot_modes(fmea, entries, args, out)
        summaries = plot_summaries(fmea, entries, args, out)
    except OSError as error:  # PLOTDIR not writable
        fail([f"cannot write the plots: {error}"])
    for path in modes + summaries if args.verbose else ():
        print(f"wrote {path}")
    print(f"{PROG}: {len(modes) + len(summaries)} plots written to {out} ({len(modes)} mode plot(s), "
          f"{len(summaries)} overview(s))")
    if unreadable:
        fail(unreadable)


if __name__ == "__main__":
    main()
