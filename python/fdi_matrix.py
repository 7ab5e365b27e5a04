#!/usr/bin/env python3
"""In-loop FDI matrix: every active thruster x every fault case, plus fault-free runs.

Usage: /usr/bin/python3 python/fdi_matrix.py SCENARIO [--out DIR] [--set KEY=VALUE ...] [--seeds K]

Runs build/cli/chaser with a fault on each of T1..T8 (stuck open; stuck closed; leak 0.2 with
slope 0.1 /s; loss 0.65: the middle of Fonod 2015's ranges) at --onset (1000 s), with recovery
off so that both schemes are scored over the rest of the run (32 runs), and K fault-free runs with
seeds 1..K. Every --set is passed to every run, after the matrix's own settings (a later --set
wins), e.g. --set fdi.isolation_method=signature --set fdi.isolation_settle=60.

Writes DIR/matrix.csv (one row per run), DIR/matrix.md (the tables) and keeps each run's
telemetry.csv (t_s and the GLR statistics only) and summary.json in DIR/runs/NAME/. The CSV's *_glr_max is the
largest GLR statistic before the onset (whole run when fault-free). A run that fails (the
binary exits non-zero) makes the script exit with status 1 after the others have finished.
"""
import argparse
import csv
import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parent.parent
THRUSTERS = [f"T{i}" for i in range(1, 9)]
CASES = {  # name -> the fault's extra keys (Fonod 2015, section V: middle of the ranges)
    "stuck_open": "kind: stuck_open",
    "stuck_closed": "kind: stuck_closed",
    "leak": "kind: leak, leak_size: 0.2, leak_slope_per_s: 0.1",
    "loss": "kind: loss, loss_size: 0.65",
}
SCHEMES = ("position", "attitude", "deficit")


def run_one(binary, scenario, run_dir, sets, seed=None):
    """Fly one run; returns (summary or None, error text)."""
    # Only the channels glr_max reads (the whole telemetry is ~9 MB a run).
    cmd = [str(binary), "run", str(scenario), "--out", str(run_dir), "--channels", "t_s,glr_*"]
    if seed is not None:
        cmd += ["--seed", str(seed)]
    for s in sets:
        cmd += ["--set", s]
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True)
    except OSError as e:  # binary missing or being rebuilt
        return None, f"{' '.join(cmd)}\n  {e}"
    if proc.returncode != 0:
        return None, f"{' '.join(cmd)}\n  exit {proc.returncode}: {proc.stderr.strip()}"
    return json.loads((run_dir / "summary.json").read_text()), ""


def glr_max(run_dir, until_s=None):
    """Largest GLR statistic per scheme in the run (before until_s if given)."""
    with (run_dir / "telemetry.csv").open() as f:
        header = f.readline().strip().split(",")
    cols = [header.index("t_s")] + [header.index(f"glr_{s}") for s in SCHEMES]
    data = np.loadtxt(run_dir / "telemetry.csv", delimiter=",", skiprows=1, usecols=cols)
    if until_s is not None:
        data = data[data[:, 0] < until_s]
    return {s: float(np.max(data[:, 1 + i])) for i, s in enumerate(SCHEMES)}


def score(summary, thruster, onset_s):
    """Per scheme: detection and isolation times after the onset, isolated thruster, verdict.
    An alarm before the onset, or in a fault-free run, is a false alarm (it latches and hides the fault)."""
    row = {}
    for s in SCHEMES:
        f = summary["fdir"][f"{s}_scheme"]
        det, iso, who = f["detection_time_s"], f["isolation_time_s"], f["isolated_thruster"]
        false_alarm = f["alarm_s"] is not None and (thruster is None or f["alarm_s"] < onset_s)
        row[f"{s}_detected"] = int(det is not None and not false_alarm)
        row[f"{s}_false_alarm"] = int(false_alarm)
        row[f"{s}_detection_s"] = "" if det is None else round(det, 1)
        row[f"{s}_isolated"] = who or ""
        row[f"{s}_isolation_s"] = "" if iso is None else round(iso, 1)
        row[f"{s}_correct"] = int(thruster is not None and who == thruster and not false_alarm)
    return row


def cell(row, s):
    if row[f"{s}_false_alarm"]:
        return f"FA {row[f'{s}_detection_s']}"
    if not row[f"{s}_detected"]:
        return "-"
    who = row[f"{s}_isolated"]
    iso = "-" if not who else f"{row[f'{s}_isolation_s']} " + ("ok" if row[f"{s}_correct"] else f"**{who}**")
    return f"{row[f'{s}_detection_s']} / {iso}"


def mean(values):
    return f"{np.mean(values):.1f}" if values else "-"


def markdown(rows, free, sets, onset):
    out = [f"# FDI matrix\n\nFault at {onset:g} s, recovery off. Extra settings: "
           + (", ".join(f"`{s}`" for s in sets) or "none") + ".",
           "Cell: detection time / isolation time [s after the onset], `ok` = right thruster, "
           "**Tn** = wrong thruster named; `-` = none; `FA t` = alarm before the onset (false alarm).\n"]
    for s in SCHEMES:
        out += [f"## {s} scheme\n", "| case | " + " | ".join(THRUSTERS) + " | detected | mean t_d | right | mean t_i (right) |",
                "|---" * (len(THRUSTERS) + 5) + "|"]
        for case in CASES:
            cr = [r for r in rows if r["case"] == case]
            det = [r[f"{s}_detection_s"] for r in cr if r[f"{s}_detected"]]
            ok = [r[f"{s}_isolation_s"] for r in cr if r[f"{s}_correct"]]
            out.append(f"| {case} | " + " | ".join(cell(r, s) for r in cr)
                       + f" | {len(det)}/{len(cr)} | {mean(det)} | {len(ok)}/{len(cr)} | {mean(ok)} |")
        out.append("")
    if not free:
        return "\n".join(out) + "\n"
    out.append(f"## Fault-free runs (seeds 1..{len(free)})\n")
    out.append("| scheme | runs with an alarm | max GLR statistic S over all runs | median of per-run max |\n|---|---|---|---|")
    for s in SCHEMES:
        alarms = sum(1 for r in free if r[f"{s}_false_alarm"])
        peaks = [r[f"{s}_glr_max"] for r in free]
        out.append(f"| {s} | {alarms}/{len(free)} | {max(peaks):.1f} | {np.median(peaks):.1f} |")
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scenario", type=Path)
    ap.add_argument("--out", type=Path, default=Path("fdi-matrix"))
    ap.add_argument("--set", dest="sets", action="append", default=[], metavar="KEY=VALUE")
    ap.add_argument("--seeds", type=int, default=20, help="fault-free runs, seeds 1..K")
    ap.add_argument("--onset", type=float, default=1000.0, help="fault time [s]")
    ap.add_argument("--binary", type=Path, default=REPO / "build" / "cli" / "chaser")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    jobs = []  # (name, thruster, case, seed, sets)
    for case, keys in CASES.items():
        for t in THRUSTERS:
            fault = f"faults=[{{thruster: {t}, {keys}, onset_s: {args.onset}}}]"
            jobs.append((f"{case}_{t}", t, case, None, [fault, "fdi.recovery=none"] + args.sets))
    for seed in range(1, args.seeds + 1):
        jobs.append((f"fault_free_seed{seed}", None, "fault_free", seed, ["faults=[]", "fdi.recovery=none"] + args.sets))

    def work(job):
        name, thruster, case, seed, sets = job
        run_dir = args.out / "runs" / name
        summary, err = run_one(args.binary, args.scenario, run_dir, sets, seed)
        if summary is None:
            return None, err
        row = {"run": name, "thruster": thruster or "", "case": case, "seed": summary["seed"]}
        row.update(score(summary, thruster, args.onset))
        peaks = glr_max(run_dir, args.onset if thruster else None)  # fault-free part only
        row.update({f"{s}_glr_max": round(peaks[s], 2) for s in SCHEMES})
        return row, ""

    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(work, jobs))
    errors = [err for row, err in results if row is None]
    rows = [row for row, _ in results if row is not None]
    if rows:
        with (args.out / "matrix.csv").open("w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
    if errors:
        print(f"{len(errors)} of {len(jobs)} runs failed:\n" + "\n".join(errors), file=sys.stderr)
        return 1
    faulty = [r for r in rows if r["thruster"]]
    free = [r for r in rows if not r["thruster"]]
    (args.out / "matrix.md").write_text(markdown(faulty, free, args.sets, args.onset))
    print((args.out / "matrix.md").read_text())
    print(f"wrote {args.out / 'matrix.csv'} and {args.out / 'matrix.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
