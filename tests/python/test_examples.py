"""examples/: each script runs with --quick and writes its figure (so none can rot), and the PD
controller written in Python flies the whole MSR approach to the capture point."""
import importlib.util
import os
import subprocess
import sys

import numpy as np
import pytest

import chaser
from conftest import REPO

EXAMPLES = REPO / "examples"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def load_example(name):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("name, figure", [
    ("fonod_fig_glr", "fonod_fig_glr.png"),
    ("roc_threshold", "roc_threshold.png"),
    ("python_pd_controller", "pd_controller.png"),
])
def test_an_example_runs_and_writes_its_figure(tmp_path, name, figure):
    # Run from another folder, as a user would: the module found by its absolute path.
    env = {**os.environ, "PYTHONPATH": os.path.dirname(chaser.__file__)}
    shown = subprocess.run([sys.executable, str(EXAMPLES / f"{name}.py"), "--quick", "--out", str(tmp_path)],
                           capture_output=True, text=True, env=env, cwd=tmp_path, timeout=120)
    assert shown.returncode == 0, shown.stderr
    png = tmp_path / figure
    assert png.read_bytes()[:8] == PNG_MAGIC and png.stat().st_size > 20_000
    assert f"wrote {png}" in shown.stdout


def test_the_python_pd_controller_reaches_the_capture_point():
    example = load_example("python_pd_controller")
    result = example.fly_pd(example.scenario(quick=False))
    s = result.summary
    assert s["simulated_s"] == 1200.0 and not s["diverged"]
    # Loose: within 0.3 m of the capture point, slower than 2 cm/s, pointing within 3 degrees.
    assert s["final_position_error_m"] < 0.3 and s["final_speed_mps"] < 0.02
    assert s["final_attitude_error_deg"] < 3.0
    assert s["target_out_of_view_s"] == 0.0
    # Flown by the controller, not by Chaser's flight software: its navigation never ran.
    assert np.all(result.telemetry["r_est_lvlh_y_m"] == 0.0)


def test_the_roc_curve_runs_from_no_alarm_to_every_alarm():
    roc = load_example("roc_threshold").roc
    curve, thresholds = roc(np.array([1.0, 2.0, 5.0]), np.array([4.0, 30.0]))
    assert tuple(curve[0]) == (0.0, 0.0) and tuple(curve[-1]) == (1.0, 1.0)
    assert np.all(np.diff(curve[:, 0]) >= 0) and np.all(np.diff(curve[:, 1]) >= 0)
    assert tuple(curve[list(thresholds).index(4.0)]) == (1 / 3, 0.5)  # J_th = 4: 5 false, 30 detected
