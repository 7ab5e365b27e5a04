#!/usr/bin/env python3
"""Scatter of COMRADE 2018 Table 1's four errors over a comrade-table5 campaign (docs/campaigns.md).

Usage: /usr/bin/python3 python/plot_table5.py DIR [--out OUTDIR]

DIR is the folder of `chaser campaign ... --preset comrade-table5 --out DIR`: one folder per case
(S1, S2, S3, the ASSIST scenario's name), each with its runs.csv. Writes OUTDIR/table5_scatter.png
(default DIR): per case, the final position error against the pointing error and the velocity error
against the angular-rate error of every run that flew, Table 1's limits as lines, the paper's
Table 5 mean +- 1 sigma as a cross, and the runs that missed a limit circled. Exit status 2 if DIR
has no case folder with a readable runs.csv.
"""
import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from plot_campaign import load_runs  # noqa: E402  runs.csv as the spec has it, in one place

# COMRADE 2018 Table 1 (limits) and Table 5 (mean, 1 sigma; its velocity row says [m]: m/s).
LIMITS = {"final_position_error_m": 0.1, "final_speed_mps": 0.01, "final_attitude_error_deg": 2.0,
          "final_rate_error_deg_s": 0.5}
PAPER = {"final_position_error_m": (0.067, 0.028), "final_speed_mps": (0.006, 0.002),
         "final_attitude_error_deg": (1.544, 0.619), "final_rate_error_deg_s": (0.155, 0.089)}
LABELS = {"final_position_error_m": "position error [m]", "final_speed_mps": "velocity error [m/s]",
          "final_attitude_error_deg": "pointing error [deg]", "final_rate_error_deg_s": "angular-rate error [deg/s]"}
PAIRS = (("final_attitude_error_deg", "final_position_error_m"), ("final_rate_error_deg_s", "final_speed_mps"))


def case_runs(folder):
    """{case name: runs} for every sub-folder with a runs.csv, in name order, only the runs that flew."""
    cases = {}
    for sub in sorted(p for p in Path(folder).iterdir() if (p / "runs.csv").is_file()):
        runs = load_runs(sub / "runs.csv")
        ok = runs["status"] == "ok"
        cases[sub.name] = {name: values[ok] for name, values in runs.items()}
    return cases


def missed(runs):
    """Per run: True where any of the four errors is at or past its Table 1 limit."""
    return np.logical_or.reduce([runs[k] >= limit for k, limit in LIMITS.items()])


def scatter(cases, out_path):
    fig, axes = plt.subplots(2, len(cases), figsize=(4.2 * len(cases), 7.5), squeeze=False)
    for col, (name, runs) in enumerate(cases.items()):
        bad = missed(runs)
        for row, (x_key, y_key) in enumerate(PAIRS):
            ax = axes[row][col]
            ax.scatter(runs[x_key], runs[y_key], s=9, color="tab:blue", label=f"runs ({len(bad)})")
            ax.scatter(runs[x_key][bad], runs[y_key][bad], s=60, facecolors="none", edgecolors="tab:red",
                       label=f"past a limit ({int(bad.sum())})")
            ax.axvline(LIMITS[x_key], color="k", ls="--", lw=1)
            ax.axhline(LIMITS[y_key], color="k", ls="--", lw=1, label="Table 1")
            (mx, sx), (my, sy) = PAPER[x_key], PAPER[y_key]
            ax.errorbar([mx], [my], xerr=[sx], yerr=[sy], color="tab:orange", marker="x", capsize=3,
                        label="COMRADE Table 5")
            ax.set_xlabel(LABELS[x_key])
            ax.set_ylabel(LABELS[y_key])
            ax.set_xlim(0, 1.15 * max(LIMITS[x_key], np.nanmax(runs[x_key], initial=0.0)))
            ax.set_ylim(0, 1.15 * max(LIMITS[y_key], np.nanmax(runs[y_key], initial=0.0)))
            if row == 0:
                ax.set_title(name)
            ax.legend(fontsize=7, loc="upper right")
    fig.suptitle("Errors at the capture point at the end of each run, against COMRADE 2018 Table 1")
    fig.tight_layout()
    fig.savefig(out_path, dpi=110)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dir", type=Path)
    parser.add_argument("--out", type=Path, default=None)
    args = parser.parse_args(argv)
    if not args.dir.is_dir():
        print(f"plot_table5: error: {args.dir}: no such folder", file=sys.stderr)
        return 2
    cases = case_runs(args.dir)
    if not cases:
        print(f"plot_table5: error: {args.dir}: no case folder with a runs.csv (run chaser campaign ... "
              "--preset comrade-table5 --out DIR first)", file=sys.stderr)
        return 2
    out = args.out or args.dir
    out.mkdir(parents=True, exist_ok=True)
    scatter(cases, out / "table5_scatter.png")
    print(f"plot_table5: wrote {out / 'table5_scatter.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
