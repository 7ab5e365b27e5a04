"""python/plot_table5.py on a synthetic comrade-table5 folder (no `chaser` program needed): the runs
past a Table 1 limit are the ones the limits say, the diverged run is left out, the PNG is written,
and a folder without a case is refused with exit status 2."""
import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
import plot_table5 as pt  # noqa: E402
from plot_campaign import RUNS_HEADER  # noqa: E402


def write_case(folder, rows):
    folder.mkdir(parents=True)
    with open(folder / "runs.csv", "w") as f:
        f.write(",".join(RUNS_HEADER) + "\n")
        for i, (status, errors) in enumerate(rows):
            row = {name: "0" for name in RUNS_HEADER}
            row.update({"run": str(i), "seed": str(100 + i), "case": "none", "status": status})
            row.update(dict(zip(("final_position_error_m", "final_speed_mps", "final_attitude_error_deg",
                                 "final_rate_error_deg_s"), (repr(e) for e in errors))))
            f.write(",".join(row[name] for name in RUNS_HEADER) + "\n")


def test_runs_past_a_limit_and_the_plot(tmp_path):
    write_case(tmp_path / "S1", [("ok", (0.05, 0.002, 0.5, 0.05)),     # inside every limit
                                 ("ok", (0.10, 0.002, 0.5, 0.05)),     # at the position limit: missed
                                 ("ok", (0.05, 0.002, 2.5, 0.05)),     # pointing past 2 deg
                                 ("diverged", (5.0, 1.0, 90.0, 9.0))])  # did not fly: left out
    write_case(tmp_path / "comrade_assist", [("ok", (0.001, 1e-4, 0.02, 0.005))])
    cases = pt.case_runs(tmp_path)
    assert list(cases) == ["S1", "comrade_assist"]
    assert len(cases["S1"]["run"]) == 3
    np.testing.assert_array_equal(pt.missed(cases["S1"]), [False, True, True])
    assert not pt.missed(cases["comrade_assist"]).any()
    assert pt.main([str(tmp_path)]) == 0
    assert (tmp_path / "table5_scatter.png").stat().st_size > 10_000
    assert math.isclose(pt.PAPER["final_position_error_m"][0], 0.067)


def test_a_folder_without_cases_is_refused(tmp_path, capsys):
    assert pt.main([str(tmp_path)]) == 2
    assert "no case folder with a runs.csv" in capsys.readouterr().err
