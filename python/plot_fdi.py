#!/usr/bin/env python3
"""FDI signals of one Chaser run, in the style of Fonod 2015, Figs. 9-10.

Usage: /usr/bin/python3 python/plot_fdi.py RUN_DIR [--threshold J_TH] [--before S] [--after S]

One column per scheme (position, attitude, and the deficit detector when it ran); rows: the GLR
statistic S(k) with the threshold J_th (eq. 41; from summary.json, --threshold overrides the
position/attitude one), the alarm
(eq. 40) with the over-consumption flag of the event resolution (Remark 2), and the candidate
sigma^N(k) and confirmed thruster (eqs. 42-45) against the faulty one. Zoomed on the first fault's
onset (from 20 s before to 80 s after by default); the whole run when there is no fault.
Writes RUN_DIR/fdi.png.
"""
import argparse
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from chaser_telemetry import load_telemetry  # noqa: E402

SCHEMES = ("position", "attitude", "deficit")


def load(run_dir):
    telemetry = load_telemetry(run_dir)
    summary = json.loads((run_dir / "summary.json").read_text())
    return telemetry, summary


def scheme_title(name, fdir, fault):
    if not fdir.get("enabled", True):
        return f"{name} scheme: disabled"
    if fdir["detection_time_s"] is None:
        return f"{name} scheme: no alarm"
    text = f"{name} scheme: alarm {fdir['detection_time_s']:+.1f} s"
    if fdir["isolated_thruster"]:
        text += f", {fdir['isolated_thruster']} confirmed {fdir['isolation_time_s']:+.1f} s"
        if fault is not None:
            text += " (right)" if fdir["isolated_thruster"] == fault["thruster"] else " (WRONG)"
    diagnosis = fdir.get("diagnosis")
    if diagnosis:
        text += f"\nread as {diagnosis['fault']} {diagnosis['size']:.2f} from {diagnosis['onset_s']:.1f} s"
    return text


def plot_scheme(axes, t, m, name, summary, threshold, fault, legend):
    time = t["t_s"][m]
    ax_s, ax_a, ax_i = axes
    ax_s.plot(time, np.maximum(t[f"glr_{name}"][m], 1e-2), color="tab:blue", lw=0.8, label="S(k)")
    ax_s.axhline(threshold, color="tab:red", lw=1.0, ls="--", label=f"J_th = {threshold:g}")
    ax_s.set_yscale("log")
    ax_s.set_ylim(1e-2, max(10 * threshold, 2 * np.nanmax(t[f"glr_{name}"][m])))
    ax_s.set_ylabel("GLR S(k)")
    ax_s.set_title(scheme_title(name, summary["fdir"][f"{name}_scheme"], fault), fontsize=10)
    if legend:  # outside, right of the last column: the data may be anywhere
        ax_s.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)

    ax_a.step(time, t[f"alarm_{name}"][m], where="post", color="tab:red", label="alarm")
    ax_a.step(time, 0.5 * t["over_consumption"][m], where="post", color="tab:orange", ls="--",
              label="over-consumption (0.5)")
    ax_a.set_ylim(-0.1, 1.2)
    ax_a.set_yticks([0, 0.5, 1])
    ax_a.set_ylabel("alarm")
    if legend:  # outside, right of the last column: the data may be anywhere
        ax_a.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)

    cand = t[f"candidate_{name}"][m]
    shown = cand > 0
    ax_i.plot(time[shown], cand[shown], ".", ms=2.5, color="tab:gray", label="candidate\nsigma^N(k)")
    ax_i.step(time, t[f"confirmed_{name}"][m], where="post", color="tab:green", lw=2, label="confirmed")
    if fault is not None:
        ax_i.axhline(int(fault["thruster"][1:]), color="tab:red", ls="--", lw=1,
                     label=f"faulty: {fault['thruster']}")
    ax_i.set_ylim(-0.5, 8.5)
    ax_i.set_yticks(range(9), ["none"] + [f"T{i}" for i in range(1, 9)], fontsize=8)
    ax_i.set_ylabel("thruster")
    ax_i.set_xlabel("time [s]")
    if legend:  # outside, right of the last column: the data may be anywhere
        ax_i.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir", type=Path)
    ap.add_argument("--threshold", type=float, default=None,
                    help="J_th of the position/attitude schemes (default: summary.json)")
    ap.add_argument("--before", type=float, default=20.0, help="seconds shown before the onset")
    ap.add_argument("--after", type=float, default=80.0, help="seconds shown after the onset")
    args = ap.parse_args()

    t, summary = load(args.run_dir)
    fault = summary["faults"][0] if summary["faults"] else None
    m = np.ones(len(t), bool)
    if fault is not None:
        m = (t["t_s"] >= fault["onset_s"] - args.before) & (t["t_s"] <= fault["onset_s"] + args.after)
    fdir = summary["fdir"]
    schemes = [s for s in SCHEMES if f"{s}_scheme" in fdir and f"glr_{s}" in t.dtype.names
               and fdir[f"{s}_scheme"].get("enabled", True)]
    thresholds = {s: args.threshold or fdir.get("glr_threshold", 20.0) for s in ("position", "attitude")}
    thresholds["deficit"] = fdir.get("deficit_threshold", 100.0)
    fig, axes = plt.subplots(3, len(schemes), figsize=(7 * len(schemes), 7.5), sharex=True,
                             constrained_layout=True, gridspec_kw={"height_ratios": [2, 1, 2]}, squeeze=False)
    for col, name in enumerate(schemes):
        plot_scheme(axes[:, col], t, m, name, summary, thresholds[name], fault, legend=col == len(schemes) - 1)
        for ax in axes[:, col]:
            ax.grid(alpha=0.3)
            if fault is not None:
                ax.axvline(fault["onset_s"], color="k", lw=0.8, ls=":")
    what = "no fault" if fault is None else f"{fault['thruster']} {fault['kind']} at {fault['onset_s']:g} s (dotted)"
    fig.suptitle(f"{summary['scenario']}, seed {summary['seed']}: {what}")
    out = args.run_dir / "fdi.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
