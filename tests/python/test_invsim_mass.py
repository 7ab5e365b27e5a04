"""python/invsim_study/scan_invsim_mass.py: the chaser's mass and the x and y groups' lever arms
against Zhou 2018 target (6) (docs/invsim.md, "The chaser's mass").

The layout edits are checked against the shipped scenario (its own positions are the arms 1.4 m and
1.6 m), and two of the document's findings are flown under `smooth` (0.1 s each): the shipped layout
loses exactly the paper's four Table 5 modes at 8,000 kg and none at 2,000 kg. Also
calibrate_invsim.py's --global check (the calibration's descent against the whole grid), on small grids,
and its handling of a designed lateral brake.
"""
import copy
import math
import subprocess
import sys

import pytest
import yaml

from conftest import REPO

sys.path.insert(0, str(REPO / "python" / "invsim_study"))
import calibrate_invsim as cal  # noqa: E402
import scan_invsim_mass as sm  # noqa: E402

SCENARIO = REPO / "scenarios" / "manual_rvd.yaml"
MOVED = {"d1", "d2", "d1~", "d2~", "e1", "e2", "e1~", "e2~"}


def shipped():
    return yaml.safe_load(SCENARIO.read_text())


def test_the_shipped_layout_is_the_arms_of_1_4_and_1_6_m():
    doc = shipped()
    assert sm.with_arms(doc, 1.4, 1.6)["thrusters"] == doc["thrusters"]


def test_with_arms_moves_only_the_lever_arms_of_the_x_and_y_groups():
    doc = shipped()
    before = copy.deepcopy(doc)
    moved = {t["name"]: t["position_body_m"] for t in sm.with_arms(doc, 3.0, 2.5)["thrusters"]}
    assert doc == before  # the input is not touched
    for t in before["thrusters"]:
        p, q = t["position_body_m"], moved[t["name"]]
        if t["name"] not in MOVED:
            assert q == p
        elif t["name"].startswith("d"):  # force along x: only |y| sets the yaw moment
            assert (q[0], abs(q[1]), q[2], q[1] * p[1] > 0) == (p[0], 3.0, p[2], True)
        else:  # force along y: only |x| sets the yaw moment
            assert (abs(q[0]), q[1], q[2], q[0] * p[0] > 0) == (2.5, p[1], p[2], True)


def test_with_mass_changes_the_mass_only():
    doc = shipped()
    heavy = sm.with_mass(doc, 2000.0)
    assert heavy["chaser"]["mass_kg"] == 2000.0 and doc["chaser"]["mass_kg"] == 8000.0
    assert heavy["chaser"]["inertia_kgm2"] == doc["chaser"]["inertia_kgm2"]
    assert {k: v for k, v in heavy.items() if k != "chaser"} == {k: v for k, v in doc.items() if k != "chaser"}


def test_lost_table5_reads_the_multi_axis_rows_only():
    rows = {"nominal": {"table": "nominal", "controllable": "true"},
            "d1": {"table": "table2", "controllable": "false"},
            "d1/d2~+e2/e1~": {"table": "table5", "controllable": "false"},
            "d1/d1~+e1/e1~": {"table": "table5", "controllable": "true"}}
    assert sm.lost_table5(rows) == {"d1/d2~+e2/e1~"}


def lost_under_smooth(cli, doc, workdir):
    study = dict(doc)
    study.pop("configurations")
    study.pop("optimize")
    return sm.lost_table5(cal.read_layout(cal.run_fmea(str(cli), study, workdir)))


def test_the_shipped_layout_loses_the_paper_four_at_8000_kg_and_none_at_2000_kg(cli, tmp_path):
    doc = shipped()
    assert doc["pulses"]["reading"] == "smooth"
    assert lost_under_smooth(cli, doc, tmp_path) == cal.PAPER_LOST
    assert lost_under_smooth(cli, sm.with_mass(doc, 2000.0), tmp_path) == set()


def test_the_global_check_draws_from_the_grids_and_its_descents_only_improve(cli, tmp_path, monkeypatch):
    """calibrate_invsim.global_search on small grids (64 points) with two noise draws per study: every
    point drawn is a grid point, each descent ends no worse than the best drawn point, the ends come
    best first, and a second search with the same seed gives the same ends."""
    monkeypatch.setattr(cal, "W_GRID", [0.06, 0.1])
    monkeypatch.setattr(cal, "Q_GRID", [1.0, 10.0])
    monkeypatch.setattr(cal, "RANGE_GRID", [0.0, 0.01])
    monkeypatch.setattr(cal, "ANGLE_GRID", [0.01])
    monkeypatch.setattr(cal, "LATERAL_GRID", [0.0, 50.0])
    doc = shipped()
    doc["pulses"]["paper"]["measurement_noise"]["draws"] = 2
    ends, drawn, runs = cal.global_search(str(cli), doc, tmp_path, samples=6, seed=3, starts=2, log=lambda _: None)

    def on_the_grids(params):
        return (params["w"] in cal.W_GRID and set(params["qv"]) <= set(cal.Q_GRID) and len(params["qv"]) == 3
                and params["range"] in cal.RANGE_GRID and params["angle"] in cal.ANGLE_GRID
                and params["lateral"] in cal.LATERAL_GRID)
    assert len(drawn) == 6 and all(on_the_grids(p) for _, p in drawn)
    assert [j for j, _ in drawn] == sorted(j for j, _ in drawn)
    # Each descent starts at one of the two best points drawn and only accepts a lower objective.
    assert len(ends) == 2 and ends[0][0] <= ends[1][0] <= drawn[1][0] and ends[0][0] <= drawn[0][0]
    for j, params, counts, k_p in ends:
        assert on_the_grids(params) and len(counts) == 6 and j == cal.objective(counts, k_p)
    assert 6 <= runs <= 64  # the small grids hold 64 points; the cache flies each once
    again, _, _ = cal.global_search(str(cli), doc, tmp_path, samples=6, seed=3, starts=2, log=lambda _: None)
    assert again == ends


def test_a_brake_design_is_written_read_and_flown_as_the_scenario_key(cli, tmp_path):
    """calibrate_invsim with a lateral brake (pulses.paper.lateral_brake_mps2): the designs --lateral
    and --brake leave, a block written into a copy of the scenario and read back as the same
    parameters, and the study's nominal row flown by the calibration equal to `chaser fmea --set`'s."""
    assert cal.lateral_designs() == [(t, 0.0) for t in cal.LATERAL_GRID]
    assert cal.lateral_designs(lateral=20.0) == [(20.0, 0.0)]
    assert cal.lateral_designs(brake=0.0075) == [(t, 0.0075) for t in cal.BRAKE_RETURN_GRID]
    assert cal.lateral_designs(brake=0.0) == [(t, 0.0) for t in cal.LATERAL_GRID]
    assert cal.lateral_designs(lateral=100.0, brake=0.0075) == [(100.0, 0.0075)]
    doc = shipped()
    assert cal.shipped(doc)["brake"] == 0.0
    params = dict(cal.shipped(doc), lateral=100.0, brake=0.0075)
    copy_path = tmp_path / "manual_rvd.yaml"
    copy_path.write_text(SCENARIO.read_text())
    cal.write_block(copy_path, params)
    assert cal.same_params(cal.shipped(yaml.safe_load(copy_path.read_text())), params)
    assert not cal.same_params(cal.shipped(doc), params)
    doc["pulses"]["paper"]["measurement_noise"]["draws"] = 2
    counts, k_p = cal.run_nominal(str(cli), doc, params, tmp_path)
    out = tmp_path / "direct"
    sets = ["pulses.reading=paper", "pulses.paper.lateral_brake_mps2=0.0075", "pulses.paper.lateral_time_constant_s=100",
            "pulses.paper.measurement_noise.draws=2"]
    subprocess.run([str(cli), "fmea", str(SCENARIO), "--nominal-only", "--out", str(out),
                    *[a for s in sets for a in ("--set", s)]], check=True, stdout=subprocess.DEVNULL)
    row = cal.read_layout(out / "fmea.csv")["nominal"]
    assert [int(row[d]) for d in cal.DIRECTIONS] == counts and float(row["k_p"]) == k_p
    held, _ = cal.run_nominal(str(cli), doc, cal.shipped(shipped()), tmp_path)
    assert held != counts  # the brake flies another path


def test_the_thorough_calibration_adds_the_brakes_and_a_second_descent_from_the_best(cli, tmp_path, monkeypatch):
    """calibrate_invsim.calibrate(thorough=True) on small grids (two noise draws): it tries the brake
    designs beside the lateral grid, descends a second time for every design from the first round's
    best point, ends no worse than any descent of the default procedure on the same grids, and flies
    each of the grids' points at most once."""
    monkeypatch.setattr(cal, "W_GRID", [0.1])
    monkeypatch.setattr(cal, "Q_GRID", [1.0, 10.0])
    monkeypatch.setattr(cal, "FINE_Q_GRID", [0.5, 1.0, 10.0])
    monkeypatch.setattr(cal, "RANGE_GRID", [0.01])
    monkeypatch.setattr(cal, "ANGLE_GRID", [0.01])
    monkeypatch.setattr(cal, "LATERAL_GRID", [0.0])
    monkeypatch.setattr(cal, "BRAKE_GRID", [0.0075])
    monkeypatch.setattr(cal, "BRAKE_RETURN_GRID", [100.0])
    monkeypatch.setattr(cal, "START", dict(cal.START, range=0.01, angle=0.01))
    doc = shipped()
    doc["pulses"]["paper"]["measurement_noise"]["draws"] = 2
    assert cal.lateral_designs(thorough=True) == [(0.0, 0.0), (100.0, 0.0075)]
    lines = []
    params, (j, counts, k_p), runs = cal.calibrate(str(cli), doc, tmp_path, log=lines.append, thorough=True)
    starts = [line for line in lines if line.startswith("-- descent")]
    assert len(starts) == 4 and sum("first round's best" in line for line in starts) == 2
    assert sum("(100.0, 0.0075)" in line for line in starts) == 2
    assert params["qv"][0] in cal.FINE_Q_GRID and j == cal.objective(counts, k_p)
    assert runs <= 2 * 3 ** 3  # two designs x the fine grid's 27 weight triples
    default, (j_default, _, _), _ = cal.calibrate(str(cli), doc, tmp_path, log=lambda _: None)
    assert default["brake"] == 0.0 and j <= j_default


def test_a_tie_in_the_nominal_objective_goes_to_the_design_with_fewer_free_choices():
    """calibrate_invsim.pick: the lowest J wins unless a simpler lateral design (y held: none; a
    return: one; a brake and its return: two) is within TIE_J, the objective's resolution."""
    held = dict(cal.START)
    ret = dict(cal.START, lateral=100.0)
    brake = dict(cal.START, lateral=100.0, brake=0.0075)
    assert [cal.free_choices(p) for p in (held, ret, brake)] == [0, 1, 2]

    def ends(j_held, j_return, j_brake):
        return [(held, (j_held, [], 0.0)), (ret, (j_return, [], 0.0)), (brake, (j_brake, [], 0.0))]

    assert cal.pick(ends(0.0731, 0.0800, 0.0710))[0] is brake  # 0.0021 apart: not a tie
    assert cal.pick(ends(0.0720, 0.0800, 0.0710))[0] is held  # 0.0010 apart: the simpler
    assert cal.pick(ends(0.0740, 0.0715, 0.0710))[0] is ret  # the return ties, y held does not
    assert cal.pick(ends(0.0710, 0.0800, 0.0710))[0] is held
    assert cal.pick(ends(0.0800, 0.0700, 0.0710))[0] is ret  # the lowest, and simpler than the brake


def test_the_tie_width_is_one_whole_pulse_of_x_at_the_calibrated_nominal():
    """TIE_J is the objective's resolution: fmea.csv counts whole pulses, and at the calibrated
    nominal (docs/invsim.md: 98/90/228/316/327/471, k_p 0.510) one pulse more of x+ moves J by
    d/dc ln(c / 164)^2 at c = 188.5 (x+ + x- against the paper's 164), 0.0015; the tie must be no narrower than that (else a
    rounding decides it) and not much wider (else real differences would be called ties)."""
    counts, k_p = [98, 90, 228, 316, 327, 471], 0.510
    one_pulse = cal.objective([99] + counts[1:], k_p) - cal.objective(counts, k_p)
    assert one_pulse == pytest.approx(2 * math.log(188.5 / 164) / 188.5, rel=0.01)
    assert one_pulse <= cal.TIE_J <= 1.1 * one_pulse
