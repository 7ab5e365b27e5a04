"""Reads a run's telemetry, whichever format `chaser run` wrote (--telemetry csv or npy).

Both give a NumPy structured array with one float64 field per channel, indexed by the channel's
name (t["r_lvlh_x_m"]), with the same values: the CSV's numbers are written to read back to the
same doubles, and the .npy holds the doubles themselves.
"""
from pathlib import Path

import numpy as np


def load_telemetry(run_dir):
    run_dir = Path(run_dir)
    npy, csv = run_dir / "telemetry.npy", run_dir / "telemetry.csv"
    if npy.is_file():
        return np.load(npy)
    if csv.is_file():
        return np.genfromtxt(csv, delimiter=",", names=True)
    raise FileNotFoundError(f"{run_dir}: no telemetry.npy or telemetry.csv (was the run made with --telemetry none?)")
