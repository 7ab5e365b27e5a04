#!/usr/bin/env python3
"""The per-period cost of Python in the loop: chaser.Simulation.step with and without a flight callback.

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/time_python_callback.py [--periods 10000]

MSR from its start, each way a fresh simulation: the median over PERIODS periods of one
sim.step(1) call (time.perf_counter_ns around it), for Chaser's flight software (C++), for a
callback that returns constant on-times (the plant and the round trip to Python only), for one
that returns a constant wrench (plus Chaser's TMU and allocation), and for the PD controller of
examples/python_pd_controller.py; and, for scale, the C++ loop alone (one sim.step(PERIODS) call).
"""
import argparse
import sys
import time
from pathlib import Path

import numpy as np
import yaml

import chaser

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "examples"))
from python_pd_controller import PDController  # noqa: E402


def per_period_us(scenario, periods, flight):
    sim = chaser.Simulation(scenario, seed=1)
    times = np.empty(periods)
    for i in range(periods):
        start = time.perf_counter_ns()
        sim.step(1, flight=flight)
        times[i] = time.perf_counter_ns() - start
    return np.median(times) / 1e3, np.mean(times) / 1e3


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--periods", type=int, default=10000)
    args = ap.parse_args()
    scenario = chaser.load_scenario(str(REPO / "scenarios" / "msr_terminal.yaml"))
    n = args.periods
    sim = chaser.Simulation(scenario, seed=1)
    start = time.perf_counter_ns()
    sim.step(n)
    print(f"C++ loop, one step({n}) call:        {(time.perf_counter_ns() - start) / 1e3 / n:6.2f} us per period")
    ton, wrench = np.zeros(16), np.zeros(6)
    ways = [("C++ flight software, step(1)", None),
            ("callback: constant on-times", lambda m: ton),
            ("callback: constant wrench", lambda m: wrench),
            ("callback: PD controller (example)", PDController(yaml.safe_load(scenario.yaml)))]
    for name, flight in ways:
        median, mean = per_period_us(scenario, n, flight)
        print(f"{name:<36} median {median:6.2f} us, mean {mean:6.2f} us per period")


if __name__ == "__main__":
    main()
