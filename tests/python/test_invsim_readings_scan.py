"""python/scan_invsim_readings.py's brake mode (docs/invsim.md, "A designed lateral brake"): the
objectives over seed blocks are those flown seed by seed through `chaser fmea` itself, a study's
seed is changed on a copy, and the rule that picks the design whose lever arms are scanned asks for
every one of targets (2) to (5)."""
import copy
import subprocess
import sys

import yaml

from conftest import REPO

sys.path.insert(0, str(REPO / "python"))
import calibrate_invsim as cal  # noqa: E402
import scan_invsim_readings as sr  # noqa: E402

SCENARIO = REPO / "scenarios" / "manual_rvd.yaml"


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
    doc = yaml.safe_load(SCENARIO.read_text())
    doc["pulses"]["paper"]["measurement_noise"]["draws"] = 2
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
