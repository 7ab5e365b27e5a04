#!/usr/bin/env python3
"""The ROC curve of the GLR detection threshold J_th, from a small campaign of fault-free and faulty runs.

Usage: PYTHONPATH=build/python /usr/bin/python3 examples/roc_threshold.py [--out DIR] [--runs N] [--quick]

chaser.campaign flies N fault-free runs and N runs of each fault case (stuck open, leak) of MSR,
onset at 100 s, 60 s flown after it, without recovery (fdi.recovery: none), and keeps every run's
telemetry. For each scheme (position, attitude) a run gets one score, the largest GLR statistic S(k)
from the onset time to the end of the run, in the same window for fault-free runs, so that both
rates are over the same length of flight (runs.csv's <scheme>_glr_max_before_onset is a fault-free
run's whole-run maximum, the figure the campaign's threshold suggestion uses). Sweeping J_th over
the scores: the false-alarm rate is the share of fault-free runs with a score above J_th, the
detection rate the share of faulty runs (the paper's alarm test, eq. 40, applied afterwards to the
recorded statistic).
Writes DIR/roc_threshold.png (default: the current folder).
"""
import argparse
import sys
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import chaser  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "python"))
from chaser_telemetry import load_telemetry  # noqa: E402

SCHEMES = ("position", "attitude")
FAULT_CASES = ("stuck_open", "leak")


def fly(runs, horizon_s, out):
    scenario = chaser.load_scenario(str(REPO / "scenarios" / "msr_terminal.yaml"), overrides={
        "fdi.recovery": "none", "campaign.onset_s": 100.0, "campaign.horizon_after_onset_s": horizon_s})
    counts = {"none": runs, **{case: runs for case in FAULT_CASES}}
    return chaser.campaign(scenario, runs=counts, cases=list(counts), seed=11, out=out,
                           keep_telemetry=3 * runs, progress=False)


def scores(campaign, scheme):
    """Each run's largest S(k) from the onset time to its end, by case."""
    runs, onset_s = campaign.runs, campaign.campaign["onset_s"]
    return {case: np.array([after_onset_max(campaign.out, run, onset_s, scheme) for run in runs[runs["case"] == case]["run"]])
            for case in ("none", *FAULT_CASES)}


def after_onset_max(out, run, onset_s, scheme):
    t = load_telemetry(Path(out) / "runs" / str(run))
    return np.max(t[f"glr_{scheme}"][t["t_s"] >= onset_s])


def roc(free, faulty):
    """(false-alarm rate, detection rate) for every threshold between the scores, high to low."""
    thresholds = np.concatenate([[np.inf], np.sort(np.concatenate([free, faulty]))[::-1], [0.0]])
    return np.array([(np.mean(free > j), np.mean(faulty > j)) for j in thresholds]), thresholds


def plot(campaign, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 5), constrained_layout=True)
    flown = campaign.campaign.get("glr_threshold")
    for ax, scheme in zip(axes, SCHEMES):
        s = scores(campaign, scheme)
        for case in FAULT_CASES:
            curve, thresholds = roc(s["none"], s[case])
            ax.step(curve[:, 0], curve[:, 1], where="post", label=f"{case} ({len(s[case])} runs)")
            if flown is not None:
                at = np.mean(s["none"] > flown), np.mean(s[case] > flown)
                ax.plot(*at, "o", color=ax.lines[-1].get_color())
        ax.plot([0, 1], [0, 1], color="0.7", ls=":", lw=0.8)
        ax.set_xlim(-0.02, 1.02)
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlabel(f"false-alarm rate ({len(s['none'])} fault-free runs)")
        ax.set_ylabel("detection rate")
        ax.set_title(f"{scheme} scheme" + (f" (dots: J_th = {flown:g}, as flown)" if flown is not None else ""))
        ax.grid(alpha=0.3)
        ax.legend(loc="lower right", fontsize=8)
    fig.suptitle("MSR: ROC of the GLR threshold, onset at 100 s, no recovery")
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", type=Path, default=Path("."))
    ap.add_argument("--runs", type=int, default=20, help="runs per case (fault-free, stuck open, leak)")
    ap.add_argument("--quick", action="store_true", help="3 runs per case, 20 s after the onset (tests)")
    args = ap.parse_args()
    runs, horizon = (3, 20.0) if args.quick else (args.runs, 60.0)
    with tempfile.TemporaryDirectory() as scratch:
        campaign = fly(runs, horizon, Path(scratch) / "campaign")
        print(f"{len(campaign.runs)} runs in {campaign.wall_s:.1f} s")
        args.out.mkdir(parents=True, exist_ok=True)
        plot(campaign, args.out / "roc_threshold.png")
    print(f"wrote {args.out / 'roc_threshold.png'}")


if __name__ == "__main__":
    main()
