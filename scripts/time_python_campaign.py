#!/usr/bin/python3
"""Wall time of one campaign from Python against the same campaign from the command line
(docs/python.md, "Measured"): `chaser campaign S --runs N --threads T --seed 1 --out D` as a
process, and chaser.campaign(S, runs=N, threads=T, seed=1, out=D) in this process, alternated,
REPS times each; prints every wall time (the whole process, the whole call: loading the scenario,
the runs, the files, reading them back), then the minimum and median of each and their ratio.

PYTHONPATH=build/python /usr/bin/python3 scripts/time_python_campaign.py [--runs 8] [--threads 2] [--reps 3]
"""
import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import chaser

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--scenario", default="scenarios/msr_terminal.yaml")
parser.add_argument("--runs", type=int, default=8, help="runs per case (five cases)")
parser.add_argument("--threads", type=int, default=2)
parser.add_argument("--reps", type=int, default=3)
parser.add_argument("--cli", default="build/cli/chaser")
args = parser.parse_args()

times = {"cli": [], "python": []}
with tempfile.TemporaryDirectory() as tmp:
    for rep in range(args.reps):
        for way in (("cli", "python") if rep % 2 == 0 else ("python", "cli")):
            out = Path(tmp) / f"{way}{rep}"
            start = time.perf_counter()
            if way == "cli":
                subprocess.run([args.cli, "campaign", args.scenario, "--runs", str(args.runs), "--threads",
                                str(args.threads), "--seed", "1", "--out", str(out)], capture_output=True, check=True)
            else:
                chaser.campaign(args.scenario, runs=args.runs, threads=args.threads, seed=1, out=str(out), progress=False)
            times[way].append(time.perf_counter() - start)
            print(f"{way:6} rep {rep}: {times[way][-1]:.3f} s", file=sys.stderr)
        assert (Path(tmp) / f"cli{rep}" / "runs.csv").read_bytes() == (Path(tmp) / f"python{rep}" / "runs.csv").read_bytes()

for way in ("cli", "python"):
    print(f"{way:6}: {min(times[way]):.3f} / {statistics.median(times[way]):.3f} s (min / median)")
print(f"python / cli, median: {statistics.median(times['python']) / statistics.median(times['cli']):.3f}")
