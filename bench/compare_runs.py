#!/usr/bin/env python3
"""Whole `chaser run` processes of two builds, interleaved: what a user waits for.

Usage: /usr/bin/python3 bench/compare_runs.py BASE_CHASER NEW_CHASER SCENARIO [--base-scenario FILE]
       [--runs N] [--telemetry none|npy|csv]

Runs BASE and NEW alternately N times (default 30) on SCENARIO and prints, for each, the minimum and
the median of the loop's wall time (summary.json's wall_loop_s), the process's wall time and its
CPU time (user + system, getrusage), with simulated seconds per second. The VM's speed drifts by
20-40 % within an hour, so only builds measured interleaved, in the same minutes, compare
(docs/performance.md). --base-scenario gives BASE its own copy of the scenario where the file's
keys changed between the builds (e.g. `git show REV:scenarios/X.yaml > /tmp/x_base.yaml`).
"""
import argparse
import json
import resource
import subprocess
import tempfile
import time
from pathlib import Path


def one_run(chaser, scenario, telemetry, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([chaser, "run", scenario, "--telemetry", telemetry, "--out", str(out)],
                   stdout=subprocess.DEVNULL, check=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    summary = json.loads((out / "summary.json").read_text())
    return summary["simulated_s"], {"loop": summary["wall_loop_s"], "wall": wall, "cpu": cpu}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("scenario")
    parser.add_argument("--base-scenario", help="the scenario file for BASE (default: SCENARIO)")
    parser.add_argument("--runs", type=int, default=30)
    parser.add_argument("--telemetry", default="none", choices=("none", "npy", "csv"))
    args = parser.parse_args()
    builds = {"base": (args.base, args.base_scenario or args.scenario), "new": (args.new, args.scenario)}
    times = {name: {"loop": [], "wall": [], "cpu": []} for name in builds}
    simulated = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(args.runs):
            for name, (chaser, scenario) in builds.items():
                simulated, t = one_run(chaser, scenario, args.telemetry, Path(tmp) / name)
                for key, value in t.items():
                    times[name][key].append(value)
    for name in builds:
        for key in ("loop", "wall", "cpu"):
            xs = sorted(times[name][key])
            lo, med = xs[0], xs[len(xs) // 2]
            print(f"{name:4} {key:4}  min {lo * 1e3:7.2f} ms  median {med * 1e3:7.2f} ms  "
                  f"({simulated / lo:8.0f} / {simulated / med:8.0f} simulated s per s)")


if __name__ == "__main__":
    main()
