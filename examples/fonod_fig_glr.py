#!/usr/bin/env python3
"""Fonod 2015's GLR figure: the statistic S(k) and the alarm of both schemes, stuck-open T8.

Usage: PYTHONPATH=build/python /usr/bin/python3 examples/fonod_fig_glr.py [--out DIR] [--quick]

One MSR run with T8 stuck open at 1000 s (--quick: at 100 s of a 200 s run), without recovery as
in the paper's campaigns (fdi.recovery: none, as `chaser campaign --preset fonod2015-table2`), flown
by chaser.run; the figure is python/plot_fdi.py's, for the position and the attitude scheme only
(the paper's two), from 20 s before the onset to 80 s after: the GLR statistic against J_th
(eqs. 40-41), the alarm, and the candidate and confirmed thruster (eqs. 42-45).
Writes DIR/fonod_fig_glr.png (default: the current folder).
"""
import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import chaser  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "python"))
from plot_fdi import plot_scheme  # noqa: E402


def fly(quick, seed=1):
    onset, duration = (100.0, 200.0) if quick else (1000.0, 1200.0)
    overrides = {"duration_s": duration, "fdi.recovery": "none",
                 "faults": [{"thruster": "T8", "kind": "stuck_open", "onset_s": onset}]}
    scenario = chaser.load_scenario(str(REPO / "scenarios" / "msr_terminal.yaml"), overrides=overrides)
    return chaser.run(scenario, seed=seed)


def plot(result, path, before=20.0, after=80.0):
    t, summary = result.telemetry, result.summary
    fault = summary["faults"][0]
    shown = (t["t_s"] >= fault["onset_s"] - before) & (t["t_s"] <= fault["onset_s"] + after)
    threshold = summary["fdir"]["glr_threshold"]
    fig, axes = plt.subplots(3, 2, figsize=(14, 7.5), sharex=True, constrained_layout=True,
                             gridspec_kw={"height_ratios": [2, 1, 2]})
    for col, scheme in enumerate(("position", "attitude")):
        plot_scheme(axes[:, col], t, shown, scheme, summary, threshold, fault, legend=col == 1)
        for ax in axes[:, col]:
            ax.grid(alpha=0.3)
            ax.axvline(fault["onset_s"], color="k", lw=0.8, ls=":")
    fig.suptitle(f"{summary['scenario']}, seed {summary['seed']}: T8 stuck open at {fault['onset_s']:g} s (dotted), "
                 "no recovery (Fonod 2015, Figs. 9-10)")
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", type=Path, default=Path("."))
    ap.add_argument("--quick", action="store_true", help="onset at 100 s of a 200 s run (tests)")
    args = ap.parse_args()
    result = fly(args.quick)
    for scheme in ("position", "attitude"):
        s = result.summary["fdir"][f"{scheme}_scheme"]
        print(f"{scheme} scheme: alarm {s['detection_time_s']:.1f} s after onset, {s['isolated_thruster']} "
              f"confirmed {s['isolation_time_s']:.1f} s after onset; largest S(k) {np.max(result.telemetry[f'glr_{scheme}']):.3g}")
    args.out.mkdir(parents=True, exist_ok=True)
    plot(result, args.out / "fonod_fig_glr.png")
    print(f"wrote {args.out / 'fonod_fig_glr.png'}")


if __name__ == "__main__":
    main()
