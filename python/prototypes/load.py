"""Read a run directory: telemetry.csv as a numpy record array and summary.json."""
import numpy as np, json
from pathlib import Path
def load(d):
    d=Path(d)
    t=np.genfromtxt(d/"telemetry.csv",delimiter=",",names=True)
    return t, json.loads((d/"summary.json").read_text())
def ton(t,kind="cmd"):
    return np.column_stack([t[f"ton_{kind}_{i}"] for i in range(1,9)])
