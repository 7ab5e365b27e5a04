#!/usr/bin/env python3
"""A synthetic Chaser campaign directory, in the format of docs/campaigns.md ("runs.csv").

Usage: /usr/bin/python3 python/tests/make_fake_campaign.py OUTDIR [--seed S] [--per-case N] [--free N]

For testing python/plot_campaign.py without the C++ engine. Writes OUTDIR/campaign.json, runs.csv
(N runs per fault case, default 80, and --free fault-free runs, default 60), summary.csv and
summary.md computed from those runs, and glr_envelope.csv (when --free > 0). The values are random
but plausible: detection times of a second to a few tens of seconds, the attitude scheme the faster
(Fonod 2015, Fig. 11), a few missed detections, false alarms, wrong isolations, diverged runs and nan.
campaign.json also carries glr_threshold and threshold_margin, which the spec leaves open ("...").
"""
import argparse
import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from plot_campaign import RUNS_HEADER as HEADER  # noqa: E402  the spec's columns, in one place
# case -> (median detection time [s] of the position and attitude schemes, probability of a miss)
CASES = {"stuck_open": ((3.0, 1.2), 0.0), "stuck_closed": ((15.0, 8.0), 0.05),
         "leak": ((25.0, 10.0), 0.08), "loss": ((12.0, 6.0), 0.04)}
ONSET_S, HORIZON_S, MARGIN = 1000.0, 300.0, 1.5
NAN = float("nan")


def truncated_normal(rng, three_sigma):
    """Normal dispersion with the given 3-sigma, truncated at 3 sigma (Fonod 2015, Table 1)."""
    return float(np.clip(rng.normal(0.0, three_sigma / 3.0), -three_sigma, three_sigma))


def scheme(rng, case, thruster, median_s, p_miss, hard):
    """One FDI scheme's outcome: (detection_s, isolation_s, isolated, false_alarm, missed, wrong, glr_max);
    a hard fault (too small to see) is missed by both schemes."""
    false_alarm = int(rng.random() < (0.05 if case == "none" else 0.01))
    glr_max = rng.uniform(22.0, 40.0) if false_alarm else rng.uniform(4.0, 18.0)
    if case == "none":
        isolated = int(rng.integers(1, 9)) if false_alarm and rng.random() < 0.5 else 0
        return NAN, NAN, isolated, false_alarm, 0, int(isolated > 0), glr_max
    missed = int(hard or rng.random() < p_miss)
    if missed or false_alarm:
        return NAN, NAN, 0, false_alarm, missed, 0, glr_max
    detection = median_s * rng.lognormal(0.0, 0.5)
    if rng.random() < 0.05:  # detected, never confirmed
        return detection, NAN, 0, 0, 0, 0, glr_max
    isolated = thruster if rng.random() > 0.07 else int(rng.choice([i for i in range(1, 9) if i != thruster]))
    return detection, detection + rng.lognormal(1.5, 0.4), isolated, 0, 0, int(isolated != thruster), glr_max


def fdir_of(case, thruster, pos, att):
    """The FDIR as a whole: first alarm of either scheme, the earlier confirmation of either scheme."""
    finite_d = [s[0] for s in (pos, att) if np.isfinite(s[0])]
    confirmed = sorted((s for s in (pos, att) if s[2] > 0), key=lambda s: s[1] if np.isfinite(s[1]) else -1)
    isolation, isolated = (confirmed[0][1], confirmed[0][2]) if confirmed else (NAN, 0)
    wrong = int(isolated > 0 and (case == "none" or isolated != thruster))
    return (min(finite_d) if finite_d else NAN, isolation, isolated, max(pos[3], att[3]),
            int(pos[4] and att[4]), wrong)


def make_run(rng, run, case):
    """One row of runs.csv as a dict column -> value."""
    thruster = 0 if case == "none" else int(rng.integers(1, 9))
    size = {"none": 0.0, "leak": rng.uniform(0.1, 0.3), "loss": rng.uniform(0.4, 0.9)}.get(case, 1.0)
    status = rng.choice(["ok", "diverged", "error"], p=[0.975, 0.02, 0.005])
    medians, p_miss = CASES.get(case, ((1.0, 1.0), 0.0))
    hard = rng.random() < p_miss / 2
    pos = scheme(rng, case, thruster, medians[0], p_miss, hard)
    att = scheme(rng, case, thruster, medians[1], p_miss, hard)
    fdir = fdir_of(case, thruster, pos, att)
    good = status == "ok" and not fdir[4] and not fdir[5]
    row = {"run": run, "seed": int(rng.integers(0, 2**63)), "case": case, "status": status,
           "fault_thruster": thruster, "fault_size": size, "onset_s": NAN if case == "none" else ONSET_S,
           "mass_kg": 1000.0 * (1 + truncated_normal(rng, 0.10))}
    for axis, nominal in zip("xyz", (650.0, 700.0, 550.0)):
        row[f"inertia_{axis}{axis}_kgm2"] = nominal * (1 + truncated_normal(rng, 0.20))
    for axis in "xyz":
        row[f"com_{axis}_m"] = truncated_normal(rng, 0.03)
    names = ("detection_s", "isolation_s", "isolated", "false_alarm", "missed", "wrong_isolation")
    for name, values in (("position", pos), ("attitude", att), ("deficit", att), ("fdir", fdir)):
        row.update({f"{name}_{k}": v for k, v in zip(names, values)})
    row["position_glr_max_before_onset"], row["attitude_glr_max_before_onset"] = pos[6], att[6]
    row["deficit_glr_max_before_onset"] = 2.0 * att[6]
    row["recovery_s"] = fdir[1] + rng.uniform(1.0, 3.0) if fdir[2] > 0 and case != "none" else NAN
    row["capture"] = int(status == "ok" and rng.random() < (0.98 if good else 0.6))
    row["corridor_kept"] = int(status == "ok" and rng.random() < (0.97 if good else 0.5))
    row["target_in_view"] = int(rng.random() < 0.99)
    row["propellant_kg"] = rng.uniform(2.0, 3.0) + (0.0 if case == "none" else rng.uniform(0.0, 1.5))
    row["simulated_s"] = ONSET_S + HORIZON_S if status == "ok" else rng.uniform(900.0, 1250.0)
    row["final_position_error_m"] = rng.uniform(0.0, 0.05)
    row["final_speed_mps"] = rng.uniform(0.0, 0.005)
    row["final_attitude_error_deg"] = rng.uniform(0.0, 1.0)
    row["final_rate_error_deg_s"] = rng.uniform(0.0, 0.1)
    row["min_clearance_unsynchronised_m"] = float("nan")  # MSR's target has no keep-out volume
    row["min_clearance_synchronised_m"] = float("nan")
    row["supervisor_switches"], row["supervisor_thruster"] = 0, 0  # no supervisor
    row["supervisor_fault"], row["supervisor_first_switch_s"] = "none", float("nan")
    return row


def text(value):
    """A field as the engine writes it: {:.17g} for reals, nan for no time, integers as they are."""
    return format(value, ".17g") if isinstance(value, float) else str(value)


def sample_stats(x):
    x = x[np.isfinite(x)]
    return (x.mean() if x.size else NAN), (x.std(ddof=1) if x.size > 1 else NAN)


def write_summaries(out, rows, cases, envelope_max):
    """summary.csv (one row per scheme and case) and summary.md, from the runs (spec section 2-3)."""
    columns = "scheme,case,runs,detected,mean_td_s,std_td_s,mean_ti_s,std_ti_s,P_nd,P_f,P_i," \
              "capture_rate,corridor_rate,mean_propellant_kg"
    lines, md = [columns], ["# Fake campaign summary", ""]
    for s in ("position", "attitude", "deficit", "fdir"):
        md += [f"## {s}", "", "| criterion | " + " | ".join(cases) + " |", "|---" * (len(cases) + 1) + "|"]
        cells = {}
        for case in cases:
            sel = [r for r in rows if r["case"] == case]
            col = lambda k: np.array([r[k] for r in sel], float)  # noqa: E731
            n = len(sel)
            td, ti = col(f"{s}_detection_s"), col(f"{s}_isolation_s")
            right = (col(f"{s}_isolated") == col("fault_thruster")) & (col(f"{s}_isolated") > 0)
            stats = (*sample_stats(td), *sample_stats(ti)) if case != "none" else (NAN,) * 4
            values = [s, case, n, int(np.isfinite(td).sum()), *stats, col(f"{s}_missed").sum() / n,
                      col(f"{s}_false_alarm").sum() / n, right.sum() / n, col("capture").mean(),
                      col("corridor_kept").mean(), col("propellant_kg").mean()]
            lines.append(",".join(text(float(v)) if isinstance(v, np.floating) else text(v) for v in values))
            cells[case] = values
        for k, name in ((4, "mean t_d [s]"), (6, "mean t_i [s]"), (8, "P_nd"), (9, "P_f"), (10, "P_i")):
            md.append(f"| {name} | " + " | ".join(f"{cells[c][k]:.3g}" for c in cases) + " |")
        md.append("")
    if envelope_max:
        md.append(f"Threshold selection (Fonod 2015, Fig. 8 method), margin {MARGIN:g}:")
        for s, peak in envelope_max.items():
            md.append(f"- {s}: envelope max {peak:.4g}, suggested J_th = {MARGIN * peak:.4g}")
    (out / "summary.csv").write_text("\n".join(lines) + "\n")
    (out / "summary.md").write_text("\n".join(md) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--per-case", type=int, default=80, help="runs per fault case")
    ap.add_argument("--free", type=int, default=60, help="fault-free runs (case none)")
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    counts = {"none": args.free, **{c: args.per_case for c in CASES}}
    cases = [c for c, n in counts.items() if n > 0]
    args.out.mkdir(parents=True, exist_ok=True)
    campaign = {"chaser_version": "fake", "scenario": "msr_terminal", "scenario_hash": "0" * 16,
                "campaign_seed": args.seed, "cases": {c: counts[c] for c in cases},
                "total_runs": sum(counts.values()), "shard": [0, 1], "horizon_after_onset_s": HORIZON_S,
                "glr_threshold": 20.0, "threshold_margin": MARGIN}
    (args.out / "campaign.json").write_text(json.dumps(campaign, indent=2) + "\n")
    order = [c for c in cases for _ in range(counts[c])]
    rows = [make_run(rng, run, case) for run, case in enumerate(rng.permutation(order))]
    with open(args.out / "runs.csv", "w") as f:
        f.write(",".join(HEADER) + "\n")
        for row in rows:
            f.write(",".join(text(row[k]) for k in HEADER) + "\n")
    envelope_max = {}
    if args.free > 0:
        t = np.arange(0.0, ONSET_S + HORIZON_S)
        env = {s: np.maximum.reduce([rng.gamma(k, 0.6, t.size) for _ in range(5)]) + 6.0 * np.exp(-t / 40.0)
               for s, k in (("position", 5.0), ("attitude", 7.0))}
        envelope_max = {s: float(v.max()) for s, v in env.items()}
        with open(args.out / "glr_envelope.csv", "w") as f:
            f.write("t_s,position_max,attitude_max\n")
            for i in range(t.size):
                f.write(f"{text(t[i])},{text(float(env['position'][i]))},{text(float(env['attitude'][i]))}\n")
    write_summaries(args.out, rows, cases, envelope_max)
    print(f"wrote {len(rows)} runs ({', '.join(f'{c} {counts[c]}' for c in cases)}) in {args.out}")


if __name__ == "__main__":
    main()
