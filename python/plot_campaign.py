#!/usr/bin/env python3
"""Plots of a Chaser Monte Carlo campaign, in the style of Fonod 2015, Figs. 8, 11, 12 and Table 2.

Usage: /usr/bin/python3 python/plot_campaign.py DIR [--out OUTDIR] [--margin M] [--threshold J_TH]

Reads DIR/runs.csv (required; format in docs/campaigns.md, "runs.csv") and, when present, DIR/summary.csv,
DIR/summary.md, DIR/glr_envelope.csv and DIR/campaign.json. Writes into OUTDIR (default DIR):
detection_times.png (Fig. 11) and isolation_times.png (Fig. 12) when a fault case ran, outcome.png
(Table 2 as bars, each with its exact 95 % Clopper-Pearson interval as an error bar: from
summary.csv's *_lo95/*_hi95 columns, or computed here from the counts when an older summary.csv
lacks them) and, when DIR/glr_envelope.csv exists, glr_envelope.png (Fig. 8). A last line
without its newline, or a row with the wrong number of fields or an unreadable number (a campaign
killed mid-write), is skipped with a warning on stderr. Exit status 2 if DIR/runs.csv is missing or
its header is not the spec's.
"""
import argparse
import csv
import json
import re
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RUNS_HEADER = (
    "run,seed,case,status,fault_thruster,fault_size,onset_s,mass_kg,inertia_xx_kgm2,inertia_yy_kgm2,"
    "inertia_zz_kgm2,com_x_m,com_y_m,com_z_m,position_detection_s,position_isolation_s,"
    "position_isolated,position_false_alarm,position_missed,position_wrong_isolation,"
    "position_glr_max_before_onset,attitude_detection_s,attitude_isolation_s,attitude_isolated,"
    "attitude_false_alarm,attitude_missed,attitude_wrong_isolation,attitude_glr_max_before_onset,"
    "deficit_detection_s,deficit_isolation_s,deficit_isolated,deficit_false_alarm,deficit_missed,"
    "deficit_wrong_isolation,deficit_glr_max_before_onset,"
    "bank_detection_s,bank_isolation_s,bank_isolated,bank_false_alarm,bank_missed,"
    "bank_wrong_isolation,bank_glr_max_before_onset,"
    "rate_check_detection_s,rate_check_isolation_s,rate_check_isolated,rate_check_false_alarm,"
    "rate_check_missed,rate_check_wrong_isolation,rate_check_glr_max_before_onset,"
    "fdir_detection_s,fdir_isolation_s,fdir_isolated,fdir_false_alarm,fdir_missed,"
    "fdir_wrong_isolation,recovery_s,capture,corridor_kept,target_in_view,propellant_kg,simulated_s,"
    "final_position_error_m,final_speed_mps,final_attitude_error_deg,final_rate_error_deg_s,"
    "min_clearance_unsynchronised_m,min_clearance_synchronised_m,"
    "supervisor_switches,supervisor_thruster,supervisor_fault,supervisor_first_switch_s"
).split(",")
TEXT_COLUMNS = ("seed", "case", "status", "supervisor_fault")  # words; a 64-bit seed does not fit a double
CASES = ("none", "stuck_open", "stuck_closed", "leak", "loss")
SCHEMES = ("position", "attitude", "deficit", "bank", "rate_check", "fdir")
GLR_SCHEMES = ("position", "attitude")  # the two with a GLR statistic S (eq. 41)
COLORS = {"position": "tab:blue", "attitude": "tab:orange", "deficit": "tab:purple", "bank": "tab:brown",
          "rate_check": "tab:olive", "fdir": "tab:green"}
RATES = ("P_nd", "P_f", "P_i", "capture_rate", "corridor_rate")
BOUNDS = tuple(f"{r}_{side}95" for r in RATES for side in ("lo", "hi"))  # summary.csv's last columns
CONFIDENCE = 0.95  # of every interval Chaser writes (campaign/confidence.hpp)


def warn(text):
    print(f"plot_campaign: warning: {text}", file=sys.stderr)


def to_float(text):
    try:
        return float(text)
    except ValueError:
        return float("nan")


def read_csv(path, expected=None):
    """Header and rows of a CSV file, less a last line cut before its newline and the rows whose
    number of fields is not the header's (both warned about on stderr); no rows if the header is
    not the expected one."""
    text = path.read_text()
    lines = text.splitlines()
    if lines and not text.endswith("\n"):
        warn(f"{path}: last line has no newline (cut off mid-write), skipped: {lines.pop()[:50]!r}...")
    rows = list(csv.reader(lines))
    header = rows[0] if rows else []
    if expected is not None and header != expected:
        return header, []
    bad = [n for n, row in enumerate(rows[1:], start=2) if row and len(row) != len(header)]
    if bad:
        warn(f"{path}: {len(bad)} row(s) without {len(header)} fields skipped, at line(s) {bad[:10]}")
    return header, [row for row in rows[1:] if len(row) == len(header)]


def load_runs(path):
    """DIR/runs.csv as {column: numpy array}: seed, case and status as strings, the rest as floats."""
    header, rows = read_csv(path, RUNS_HEADER) if path.is_file() else (None, [])
    if header != RUNS_HEADER:
        why = "not found" if header is None else next(
            (f"header column {i + 1} is {h!r}, the spec says {s!r}"
             for i, (h, s) in enumerate(zip(header, RUNS_HEADER)) if h != s),
            f"header has {len(header)} columns, the spec {len(RUNS_HEADER)}")
        why = "empty file or no complete header line" if header == [] else why
        print(f"plot_campaign: error: {path}: {why} (see docs/campaigns.md, runs.csv)", file=sys.stderr)
        sys.exit(2)
    parsed = []
    for row in rows:
        try:
            parsed.append([v if name in TEXT_COLUMNS else float(v) for name, v in zip(header, row)])
        except ValueError:
            warn(f"{path}: row of run {row[0]!r} has an unreadable number, skipped")
    columns = list(zip(*parsed)) if parsed else [()] * len(header)
    runs = {name: np.array(col, dtype=str if name in TEXT_COLUMNS else float)
            for name, col in zip(header, columns)}
    for unknown in sorted(set(runs["case"]) - set(CASES)):
        warn(f"{path}: unknown case {unknown!r} ignored")
    return runs


def case_grid(n, title):
    """A figure with one panel per case in two columns; returns the figure and its n axes."""
    ncols = 1 if n == 1 else 2
    nrows = (n + ncols - 1) // ncols
    fig, axes = plt.subplots(nrows, ncols, figsize=(7 * ncols, 3.9 * nrows), squeeze=False, constrained_layout=True)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    fig.suptitle(title)
    return fig, list(axes.flat[:n])


def bin_edges(samples):
    """Common histogram bins for all the samples of one panel (at most 40 bins)."""
    finite = np.concatenate([s[np.isfinite(s)] for s in samples] + [np.zeros(0)])
    if finite.size == 0 or np.ptp(finite) < 1e-9:
        centre = finite[0] if finite.size else 0.5
        return np.array([centre - 0.5, centre + 0.5])
    edges = np.histogram_bin_edges(finite, bins="auto")
    return edges if edges.size <= 41 else np.linspace(finite.min(), finite.max(), 41)


def plot_times(runs, cases, what, path):
    """Fonod 2015, Fig. 11 (what = "detection") or Fig. 12 (what = "isolation"): histograms of the
    detection time t_d or isolation time t_i after the onset, one panel per fault case, the schemes
    overlaid. The legend gives per scheme n, the median and the missed detections (Fig. 11), or the
    right isolations, their median, the wrong and the absent ones (Fig. 12); wrong isolations (another
    thruster confirmed) are drawn dashed, mirrored below the axis."""
    figure = "Fig. 11" if what == "detection" else "Fig. 12: right isolations up, wrong ones dashed, down"
    fig, axes = case_grid(len(cases), f"{what.capitalize()} time after the fault onset (Fonod 2015, {figure})")
    for ax, case in zip(axes, cases):
        m = runs["case"] == case
        times = {s: runs[f"{s}_{what}_s"][m] for s in SCHEMES}
        edges = bin_edges(list(times.values()))
        any_wrong = False
        for s, t in times.items():
            iso, right = runs[f"{s}_isolated"][m], np.isfinite(t)
            if what == "isolation":
                right &= (iso == runs["fault_thruster"][m]) & (iso > 0)
            wrong = np.isfinite(t) & ~right
            any_wrong |= wrong.any()
            median = f"median {np.median(t[right]):.3g} s" if right.any() else "median -"
            label = (f"{s}: n={right.sum()}, {median}, {np.nansum(runs[f'{s}_missed'][m]):.0f} missed"
                     if what == "detection" else
                     f"{s}: right n={right.sum()}, {median}; wrong {wrong.sum()}; not isolated {np.sum(iso <= 0)}")
            ax.stairs(np.histogram(t[right], edges)[0], edges, color=COLORS[s], lw=1.5, label=label)
            if wrong.any():
                ax.stairs(-np.histogram(t[wrong], edges)[0], edges, color=COLORS[s], lw=1.2, ls="--")
        bad = int(np.sum(runs["status"][m] != "ok"))
        ax.set_title(f"{case}: {m.sum()} runs" + (f" ({bad} diverged or error)" if bad else ""), fontsize=10)
        if not np.isfinite(np.concatenate(list(times.values()) + [np.zeros(0)])).any():
            ax.set_ylim(0, 1)
            ax.text(0.5, 0.5, f"no {what}" if m.any() else "no run of this case", ha="center",
                    transform=ax.transAxes)
        ax.set_ylim(bottom=None if any_wrong else 0)
        ax.axhline(0, color="k", lw=0.6)
        ax.set_xlabel(f"{what} time [s]")
        ax.set_ylabel("runs" + (" (wrong below 0)" if what == "isolation" else ""))
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8 if what == "detection" else 7)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def binomial_tail(x, n, p, at_least):
    """P(X <= x), or P(X >= x) when at_least, for X ~ Binomial(n, p): the pmf summed in logs."""
    k = np.arange(x, n + 1) if at_least else np.arange(0, x + 1)
    log_fact = np.concatenate(([0.0], np.cumsum(np.log(np.arange(1, n + 1)))))
    log_pmf = log_fact[n] - log_fact[k] - log_fact[n - k] + k * np.log(p) + (n - k) * np.log1p(-p)
    return float(np.exp(log_pmf).sum())


def clopper_pearson(x, n, confidence=CONFIDENCE):
    """Two-sided exact interval of x events in n runs (Clopper and Pearson 1934), by bisection on its
    defining equations P(X >= x; l) = alpha/2 and P(X <= x; u) = alpha/2; the same interval as
    summary.csv's (Chaser takes Beta quantiles through Boost.Math), without scipy."""
    if n <= 0 or not 0 <= x <= n:
        return np.nan, np.nan
    tail = (1 - confidence) / 2

    def solve(f):  # f increasing in p on (0, 1); 60 halvings: 1e-18
        lo, hi = 0.0, 1.0
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if f(mid) > 0 else (mid, hi)
        return 0.5 * (lo + hi)

    lower = 0.0 if x == 0 else solve(lambda p: binomial_tail(x, n, p, True) - tail)
    upper = 1.0 if x == n else solve(lambda p: tail - binomial_tail(x, n, p, False))
    return lower, upper


def add_intervals(entry):
    """Fills in the *_lo95/*_hi95 bounds of one summary entry from its rates and run count."""
    n = entry.get("runs", np.nan)
    for r in RATES:
        if f"{r}_lo95" in entry:
            continue
        value = entry.get(r, np.nan)
        x = round(value * n) if np.isfinite(value) and np.isfinite(n) else -1
        entry[f"{r}_lo95"], entry[f"{r}_hi95"] = clopper_pearson(int(x), int(n)) if x >= 0 else (np.nan, np.nan)
    return entry


def load_summary(path):
    """DIR/summary.csv as {(scheme, case): {rate: value, bound: value, "runs": n}}; None when absent or
    unusable. Without the bound columns (written before they were added) the bounds are computed."""
    if not path.is_file():
        return None
    header, rows = read_csv(path)
    if not {"scheme", "case", "runs", *RATES} <= set(header):
        warn(f"{path}: columns missing, outcome recomputed from runs.csv")
        return None
    columns = (*RATES, "runs", *(b for b in BOUNDS if b in header))
    return {(r["scheme"], r["case"]): add_intervals({k: to_float(r[k]) for k in columns})
            for r in (dict(zip(header, row)) for row in rows)}


def recompute_outcome(runs, cases):
    """The rates of summary.csv from runs.csv: P_nd = missed / runs, P_f = false alarms / runs,
    P_i = right isolations / runs (Fonod 2015, section V), capture and corridor rates."""
    table = {}
    for case in cases:
        m = runs["case"] == case
        for s in SCHEMES:
            iso = runs[f"{s}_isolated"][m]
            right = (iso == runs["fault_thruster"][m]) & (iso > 0)
            values = (runs[f"{s}_missed"][m], runs[f"{s}_false_alarm"][m], right, runs["capture"][m],
                      runs["corridor_kept"][m])
            table[(s, case)] = {r: np.mean(v) if m.any() else np.nan for r, v in zip(RATES, values)}
            table[(s, case)]["runs"] = m.sum()
            if case == "none":  # no fault to miss or isolate (as summary.csv)
                table[(s, case)].update(P_nd=np.nan, P_i=np.nan)
            add_intervals(table[(s, case)])
    return table


def plot_outcome(table, source, cases, path):
    """Fonod 2015, Table 2 as bars: per case, P_nd, P_f and P_i of each scheme, and the mission
    outcome of the closed-loop FDIR (capture and corridor rates, the same whatever the scheme); each
    bar with its two-sided 95 % Clopper-Pearson interval as an error bar."""
    fig, axes = case_grid(len(cases), f"FDI and mission outcome per case (Fonod 2015, Table 2; {source}; "
                                      "bars: 95 % Clopper-Pearson intervals)")
    for ax, case in zip(axes, cases):
        mission = next((table[(s, case)] for s in ("fdir", *GLR_SCHEMES) if (s, case) in table), {})
        rows = [table.get((s, case), {}) for s in SCHEMES] + [mission]
        for k, (row, color, label) in enumerate(zip(rows, [*COLORS.values(), "0.6"], [*SCHEMES, "mission"])):
            # One bar per scheme (all four, fdir included) for the FDI indices; mission rates once.
            fdi = k < len(SCHEMES)
            rates, x = (RATES[:3], np.arange(3) + (k - 1.5) * 0.2) if fdi else (RATES[3:], np.array([3, 4]))
            values = np.array([row.get(r, np.nan) for r in rates], float)
            lo = np.array([row.get(f"{r}_lo95", np.nan) for r in rates], float)
            hi = np.array([row.get(f"{r}_hi95", np.nan) for r in rates], float)
            yerr = np.nan_to_num(np.vstack([values - lo, hi - values]))  # none where a value is n/a
            bars = ax.bar(x, np.nan_to_num(values), 0.2 if fdi else 0.5, color=color, label=label,
                          yerr=yerr, capsize=2, error_kw={"elinewidth": 0.8, "ecolor": "k"})
            ax.bar_label(bars, ["n/a" if np.isnan(v) else f"{v:.3g}" for v in values], fontsize=6)
        ax.set_xticks(range(5), ["P_nd", "P_f", "P_i", "capture", "corridor"])
        ax.set_ylim(0, 1.2)
        ax.set_title(f"{case}: {rows[-1].get('runs', np.nan):.0f} runs", fontsize=10)
        ax.grid(axis="y", alpha=0.3)
    axes[0].legend(fontsize=8, ncol=4, loc="upper left")
    fig.savefig(path, dpi=110)
    plt.close(fig)


def load_envelope(path):
    """DIR/glr_envelope.csv as {column: float array}; None when its header is not the spec's."""
    header, rows = read_csv(path, ["t_s", "position_max", "attitude_max"])
    if header != ["t_s", "position_max", "attitude_max"]:
        warn(f"{path}: header {header} is not t_s,position_max,attitude_max; no glr_envelope.png")
        return None
    values = np.array([[to_float(v) for v in row] for row in rows], float).reshape(-1, 3)
    return {"t_s": values[:, 0], "position": values[:, 1], "attitude": values[:, 2]}


def suggested_thresholds(campaign_dir, envelope, margin, campaign):
    """The suggested J_th = margin x envelope maximum per scheme (Fonod 2015, Fig. 8 method): as
    summary.md states it (lines "...suggest... = <number>") unless --margin is given, else computed with
    --margin, campaign.json's threshold_margin, or 1.5. Returns ({scheme: J_th}, where it comes from)."""
    md = campaign_dir / "summary.md"
    if margin is None and md.is_file():
        stated = {}
        for line in md.read_text().lower().splitlines():
            numbers = re.findall(r"[-+]?\d+(?:\.\d*)?(?:e[-+]?\d+)?", line.split("=")[-1] if "=" in line else "")
            named = [s for s in GLR_SCHEMES if s in line]
            for s in (named if len(named) == 1 else GLR_SCHEMES) if "suggest" in line and numbers else ():
                stated[s] = float(numbers[-1])
        if stated:
            return stated, "summary.md"
    margin = margin if margin is not None else float(campaign.get("threshold_margin", 1.5))
    peaks = {s: np.nanmax(envelope[s], initial=-np.inf) for s in GLR_SCHEMES}
    return {s: margin * p for s, p in peaks.items() if np.isfinite(p)}, f"{margin:g} x max"


def plot_envelope(envelope, n_free, threshold, suggested, source, path):
    """Fonod 2015, Fig. 8: per second, the largest GLR statistic S over the fault-free runs, one
    panel per scheme, against the scenario's threshold J_th and the suggested one."""
    fig, axes = plt.subplots(1, 2, figsize=(14, 4.5), sharey=True, constrained_layout=True)
    top = 1.0
    for ax, s in zip(axes, GLR_SCHEMES):
        peak = np.nanmax(envelope[s], initial=-np.inf)
        ax.step(envelope["t_s"], envelope[s], where="post", color=COLORS[s], lw=0.8,
                label=f"max of S over the runs (peak {peak:.3g})")
        if threshold is not None:
            ax.axhline(threshold, color="tab:red", ls="--", lw=1.0, label=f"scenario J_th = {threshold:g}")
        if s in suggested:
            ax.axhline(suggested[s], color="k", ls=":", lw=1.0,
                       label=f"suggested J_th = {suggested[s]:.3g} ({source})")
        top = max([top, peak, threshold or 0.0, suggested.get(s, 0.0)])
        ax.set_title(f"{s} scheme", fontsize=10)
        ax.set_xlabel("time [s]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper right")
    axes[0].set_ylim(0, 1.6 * top)  # room for the legend above the thresholds
    axes[0].set_ylabel("GLR S(k), max over the runs")
    fig.suptitle(f"GLR statistic of {n_free} fault-free runs, per-second maximum (Fonod 2015, Fig. 8)")
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir", type=Path, help="campaign directory (holds runs.csv)")
    ap.add_argument("--out", type=Path, help="where the PNGs go (default: DIR)")
    ap.add_argument("--margin", type=float, help="suggested J_th = margin x envelope max "
                    "(default: the value in summary.md, else campaign.json threshold_margin, else 1.5)")
    ap.add_argument("--threshold", type=float, help="scenario J_th (default: campaign.json glr_threshold)")
    args = ap.parse_args()

    runs = load_runs(args.dir / "runs.csv")
    out = args.out or args.dir
    out.mkdir(parents=True, exist_ok=True)
    campaign_path, written = args.dir / "campaign.json", []
    campaign = json.loads(campaign_path.read_text()) if campaign_path.is_file() else {}
    listed = campaign.get("cases") if isinstance(campaign.get("cases"), dict) else {}
    cases = [c for c in CASES if c in listed or np.any(runs["case"] == c)]
    faults = [c for c in cases if c != "none"]
    if not runs["run"].size:
        print(f"{args.dir / 'runs.csv'} has no complete run yet")
    for what in ("detection", "isolation") if faults else ():
        plot_times(runs, faults, what, out / f"{what}_times.png")
        written.append(f"{what}_times.png")
    table = load_summary(args.dir / "summary.csv")
    source = "summary.csv" if table is not None else "recomputed from runs.csv"
    table = table if table is not None else recompute_outcome(runs, cases)
    cases = [c for c in CASES if c in cases or any(key[1] == c for key in table)]
    if cases:
        plot_outcome(table, source, cases, out / "outcome.png")
        written.append("outcome.png")
    envelope_path = args.dir / "glr_envelope.csv"
    envelope = load_envelope(envelope_path) if envelope_path.is_file() else None
    if envelope is not None:
        threshold = args.threshold if args.threshold is not None else campaign.get("glr_threshold")
        threshold = None if threshold is None else float(threshold)
        suggested, source = suggested_thresholds(args.dir, envelope, args.margin, campaign)
        plot_envelope(envelope, np.sum(runs["case"] == "none"), threshold, suggested, source,
                      out / "glr_envelope.png")
        written.append("glr_envelope.png")
    print(f"wrote {', '.join(written) or 'nothing'} in {out}")


if __name__ == "__main__":
    main()
