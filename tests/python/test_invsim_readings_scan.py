"""python/invsim_study/scan_invsim_readings.py's brake mode (docs/invsim.md, "A designed lateral
brake"): the objectives over seed blocks are those flown seed by seed through `chaser fmea` itself, a study's
seed is changed on a copy, and the rule that picks the design whose lever arms are scanned asks for
every one of targets (2) to (5)."""
import copy
import subprocess
import sys

import yaml

from conftest import REPO

sys.path.insert(0, str(REPO / "python" / "invsim_study"))
import calibrate_invsim as cal  # noqa: E402
import scan_invsim_readings as sr  # noqa: E402

SCENARIO = REPO / "scenarios" / "manual_rvd.yaml"


class RowsWritten(list):
    """A csv writer's stand-in that keeps the rows a scan writes."""

    def writerow(self, row):
        self.append(row)


def with_two_draws():
    """The shipped scenario with two noise draws per mode: a scan's whole study in a fraction of a second."""
    doc = yaml.safe_load(SCENARIO.read_text())
    doc["pulses"]["paper"]["measurement_noise"]["draws"] = 2
    return doc


def test_with_seed_changes_a_copy_only():
    doc = yaml.safe_load(SCENARIO.read_text())
    before = copy.deepcopy(doc)
    moved = sr.with_seed(doc, 41)
    assert doc == before
    assert moved["pulses"]["paper"]["measurement_noise"]["seed"] == 41
    moved["pulses"]["paper"]["measurement_noise"]["seed"] = before["pulses"]["paper"]["measurement_noise"]["seed"]
    assert moved == before


def test_the_block_objectives_are_the_objectives_flown_seed_by_seed(cli, tmp_path, monkeypatch):
    monkeypatch.setattr(sr, "SEED_BLOCKS", [1, 7])
    doc = with_two_draws()
    params = dict(cal.shipped(doc), lateral=100.0, brake=0.0075)
    objectives = []
    for seed in (1, 7):
        out = tmp_path / f"seed{seed}"
        sets = ["pulses.reading=paper", "pulses.paper.lateral_brake_mps2=0.0075",
                "pulses.paper.lateral_time_constant_s=100", "pulses.paper.measurement_noise.draws=2",
                f"pulses.paper.measurement_noise.seed={seed}"]
        subprocess.run([str(cli), "fmea", str(SCENARIO), "--nominal-only", "--out", str(out),
                        *[a for s in sets for a in ("--set", s)]], check=True, stdout=subprocess.DEVNULL)
        row = cal.read_layout(out / "fmea.csv")["nominal"]
        objectives.append(cal.objective([int(row[d]) for d in cal.DIRECTIONS], float(row["k_p"])))
    assert objectives[0] != objectives[1]  # the seeds fly different noise
    assert sr.block_objectives(str(cli), doc, params, tmp_path) == objectives


def test_the_fault_targets_rule_needs_every_one_of_2_to_5():
    met = {"k_p_within": 17, "rise_within": 12, "z_doubles_worst": True, "table5_ratios": [1.45, 1.58],
           "table5_in_band": 2}
    assert sr.meets_fault_targets(met)
    for key, value in [("k_p_within", 16), ("rise_within", 11), ("z_doubles_worst", False), ("table5_in_band", 1)]:
        assert not sr.meets_fault_targets(dict(met, **{key: value})), key
    assert not sr.meets_fault_targets(dict(met, table5_ratios=[], table5_in_band=0))  # nothing flown


def test_the_tie_scan_pairs_each_design_with_the_shipped_one_on_the_same_seeds(cli, tmp_path, monkeypatch):
    """`tie` (docs/invsim.md, "Why the nominal row cannot choose the brake"): q_vy is the lowest J on the first block,
    every block's J is the one block_objectives flies, and each design's difference is taken to the
    shipped design's J on the same block (the shipped design's own is zero)."""
    monkeypatch.setattr(sr, "Q_VY_LOOK", [0.6, 1.0])
    monkeypatch.setattr(cal, "BRAKE_GRID", [0.0075])
    monkeypatch.setattr(cal, "BRAKE_RETURN_GRID", [200.0])
    doc = yaml.safe_load(SCENARIO.read_text())
    blocks, draws = [1, 7], 2
    rows = RowsWritten()
    sr.scan_tie(str(cli), doc, tmp_path, rows, draws=draws, blocks=blocks)
    assert [row[:2] for row in rows] == [[0.0, 0.0], [0.0075, 200.0]]  # y held (shipped), then the brake
    have = cal.shipped(doc)
    shipped_js = None
    for row in rows:
        brake, lateral, q_vy, *js = row[:3 + len(blocks)]
        firsts = {q: sr.block_objectives(str(cli), doc, sr.with_lateral_design(have, lateral, brake, q), tmp_path,
                                         blocks[:1], draws)[0] for q in sr.Q_VY_LOOK}
        assert q_vy == min(firsts, key=firsts.get)
        params = sr.with_lateral_design(have, lateral, brake, q_vy)
        assert params["qv"] == [have["qv"][0], q_vy, have["qv"][2]] and params["w"] == have["w"]
        assert js == sr.block_objectives(str(cli), doc, params, tmp_path, blocks, draws)
        if shipped_js is None:  # the shipped design's row comes first
            shipped_js = js
        assert row[-2] == sum(js) / len(js)
        assert row[-1] == sum(sr.paired_differences(js, shipped_js)) / len(js)
    assert rows[0][-1] == 0.0
    assert rows[1][-1] != 0.0  # the brake flies another path


def test_the_four_separation_is_the_paper_fours_least_deviation_over_the_others_largest():
    """four_separation (docs/invsim.md, "The start's lateral drift"): the ratio of the
    smallest deviation ratio among the paper's four lost Table 5 modes to the largest among the
    other Table 5 modes, whatever the Table 4 rows do; above 1 only where a threshold separates them."""
    rows = {m: {"table": "table5", "deviation_ratio": "1.2"} for m in cal.PAPER_LOST}
    rows["d1/d1~+e1/e1~"] = {"table": "table5", "deviation_ratio": "0.8"}
    rows["d2/d2~+e2/e1~"] = {"table": "table5", "deviation_ratio": "0.96"}
    rows["f2/f2~"] = {"table": "table2", "deviation_ratio": "5.0"}  # not Table 5: not compared
    four = sorted(cal.PAPER_LOST)
    rows[four[0]]["deviation_ratio"] = "0.9"
    separation, worst = sr.four_separation(rows)
    assert separation == 0.9 / 0.96 and worst == "d2/d2~+e2/e1~"
    rows[four[0]]["deviation_ratio"] = "1.1"
    assert sr.four_separation(rows) == (1.1 / 0.96, "d2/d2~+e2/e1~")


def test_the_separation_scan_scores_the_study_chaser_fmea_flies(cli, tmp_path, monkeypatch):
    """scan_separation on one brake design (two noise draws): y held first, then the brake, each
    row's separation and targets those of `chaser fmea --set` flown with the same design."""
    monkeypatch.setattr(sr, "SEPARATION_BRAKES", [0.0075])
    monkeypatch.setattr(sr, "SEPARATION_Q_VY", [0.6])
    monkeypatch.setattr(cal, "BRAKE_RETURN_GRID", [200.0])
    doc = with_two_draws()
    rows = RowsWritten()
    sr.scan_separation(str(cli), doc, tmp_path, rows)
    assert [row[:3] for row in rows] == [[0.0, 0.0, 1.0], [0.0075, 200.0, 0.6]]
    out = tmp_path / "direct"
    sets = ["pulses.reading=paper", "pulses.paper.lateral_brake_mps2=0.0075", "pulses.paper.lateral_time_constant_s=200",
            "pulses.paper.state_weights=[1,1,1,10,0.6,0.01]", "pulses.paper.measurement_noise.draws=2"]
    subprocess.run([str(cli), "fmea", str(SCENARIO), "--out", str(out), *[a for s in sets for a in ("--set", s)]],
                   check=True, stdout=subprocess.DEVNULL)
    flown = cal.read_layout(out / "fmea.csv")
    t = cal.targets(flown)
    assert rows[1][3:5] == list(sr.four_separation(flown))
    assert rows[1][5:7] == list(sr.twin_margin(flown))
    assert rows[1][7:] == [t["k_p_within"], t["rise_within"], t["z_doubles_worst"], t["table5_in_band"],
                           len(t["table5_ratios"]), len(t["lost"])]
    assert rows[0][3] != rows[1][3]  # y held turns the chaser otherwise


def test_a_paper_modes_twin_loses_the_other_x_plus_thruster_and_the_margin_is_the_least_over_the_four():
    assert sr.twin("d1/d2~+e2/e1~") == "d2/d2~+e2/e1~" and sr.twin("d2/d2~+e2/e1~") == "d1/d2~+e2/e1~"
    assert sr.twin("d2/d1~+e1/e2~") == "d1/d1~+e1/e2~"
    assert {sr.twin(m) for m in cal.PAPER_LOST}.isdisjoint(cal.PAPER_LOST)  # the twins are flown in the paper
    rows = {}
    for m in cal.PAPER_LOST:
        rows[m] = {"peak_azimuth_deg": "12.0"}
        rows[sr.twin(m)] = {"peak_azimuth_deg": "9.0"}
    rows["d2/d2~+e2/e2~"]["peak_azimuth_deg"] = "11.5"  # the twin of d1/d2~+e2/e2~
    assert sr.twin_margin(rows) == (0.5, "d1/d2~+e2/e2~")


def test_the_lateral_design_option_changes_a_copy_of_the_block_and_goes_with_shipped_only():
    doc = yaml.safe_load(SCENARIO.read_text())
    before = copy.deepcopy(doc)
    moved = sr.with_lateral_block(doc, 200.0, 0.0075)
    assert doc == before
    assert cal.shipped(moved)["lateral"] == 200.0 and cal.shipped(moved)["brake"] == 0.0075
    moved["pulses"]["paper"]["lateral_time_constant_s"] = before["pulses"]["paper"]["lateral_time_constant_s"]
    moved["pulses"]["paper"]["lateral_brake_mps2"] = before["pulses"]["paper"]["lateral_brake_mps2"]
    assert moved == before
    refused = subprocess.run([sys.executable, str(REPO / "python" / "invsim_study" / "scan_invsim_readings.py"), "tie",
                              "--lateral-design", "200,0.0075"], capture_output=True, text=True)
    assert refused.returncode == 2 and "--lateral-design goes with `shipped`" in refused.stderr


def test_the_shipped_scan_reports_each_q_separation_and_the_modes_it_loses(cli, tmp_path, monkeypatch, capsys):
    """scan_shipped on two weight points (two noise draws): each row's separation is the study's
    four_separation, and the summary counts the points above 1 and the sets of modes lost."""
    points = [(10.0, 1.0, 0.01), (1.0, 3.0, 0.01)]
    monkeypatch.setattr(sr, "grid", lambda: points)
    monkeypatch.setattr(cal, "W_GRID", [0.1])
    doc = with_two_draws()
    rows = RowsWritten()
    sr.scan_shipped(str(cli), doc, tmp_path, rows)
    have = cal.shipped(doc)
    separations = []
    for row, qv in zip(rows, points):
        flown = cal.read_layout(cal.run_fmea(str(cli), cal.paper_study(doc, dict(have, qv=list(qv))), tmp_path))
        separations.append(sr.four_separation(flown)[0])
        assert row[:3] == list(qv) and row[-1] == separations[-1]
        assert row[3] == len(cal.targets(flown)["lost"])
    out = capsys.readouterr().out
    assert f"(separation above 1): {sum(v > 1 for v in separations)} Q points" in out
    assert "modes lost, the most frequent sets: " in out
