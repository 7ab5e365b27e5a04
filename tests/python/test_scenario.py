"""chaser.load_scenario, load_scenario_text and Scenario.from_dict: the C++ loader's checks and its
text, seen from Python."""
import copy

import pytest
import yaml

import chaser
from conftest import MSR, run_cli


def msr_document():
    return yaml.safe_load(MSR.read_text())


def broken_document():
    """MSR with four problems in three sections."""
    d = msr_document()
    d["chaser"]["mass_kg"] = -5.0
    d["chaser"]["colour"] = "gold"
    d["control_period_s"] = 0.0
    d["faults"] = [{"thruster": "T99", "kind": "stuck_open", "onset_s": 1000.0}]
    return d


def test_a_bad_file_raises_every_problem_with_the_command_lines_text(cli, tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump(broken_document(), sort_keys=False))
    with pytest.raises(chaser.ScenarioError) as caught:
        chaser.load_scenario(str(bad))
    error = caught.value
    keys = [key for key, _ in error.errors]
    for key in ("chaser.mass_kg", "chaser.colour", "control_period_s", "faults.0.thruster"):
        assert any(k.startswith(key) for k in keys), f"{key} not among {keys}"
    assert str(error) == "".join(f"{key}: {message}\n" for key, message in error.errors)

    shown = run_cli(cli, "run", bad, "--out", tmp_path / "out")
    assert shown.returncode == 2
    n = len(error.errors)
    assert shown.stderr == f"chaser: {bad} has {n} problem{'' if n == 1 else 's'}:\n" + str(error)
    assert not (tmp_path / "out" / "summary.json").exists()


def test_from_dict_and_text_report_the_same_problems_as_the_file(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump(broken_document(), sort_keys=False))
    errors = []
    for load in (lambda: chaser.load_scenario(str(bad)),
                 lambda: chaser.load_scenario_text(bad.read_text()),
                 lambda: chaser.Scenario.from_dict(broken_document())):
        with pytest.raises(chaser.ScenarioError) as caught:
            load()
        errors.append(caught.value.errors)
    assert errors[0] == errors[1] == errors[2]
    assert len(errors[0]) >= 4


def test_a_missing_file_and_a_bad_override_are_scenario_errors(tmp_path):
    with pytest.raises(chaser.ScenarioError) as caught:
        chaser.load_scenario(str(tmp_path / "nowhere.yaml"))
    assert caught.value.errors[0][0].endswith("nowhere.yaml")
    with pytest.raises(chaser.ScenarioError) as caught:
        chaser.load_scenario(str(MSR), overrides={"chaser.mass_kg": -1.0, "duration_s": "abc"})
    assert {key for key, _ in caught.value.errors} >= {"chaser.mass_kg", "duration_s"}
    assert isinstance(caught.value, ValueError)


def test_overrides_as_a_dict_or_as_set_strings_give_the_same_document():
    as_dict = chaser.load_scenario(str(MSR), overrides={
        "faults": [{"thruster": "T8", "kind": "stuck_open", "onset_s": 1000}], "seed": 7})
    as_strings = chaser.load_scenario(str(MSR), overrides=[
        "faults=[{thruster: T8, kind: stuck_open, onset_s: 1000}]", "seed=7"])
    plain = chaser.load_scenario(str(MSR))
    assert as_dict.hash == as_strings.hash != plain.hash
    assert as_dict.seed == 7 and plain.seed == 1
    assert as_dict.name == "msr_terminal"


def test_the_hash_is_the_command_lines(cli):
    sets = ["faults=[{thruster: T8, kind: leak, onset_s: 900, leak_size: 0.2, leak_slope_per_s: 0.01}]", "seed=7"]
    shown = run_cli(cli, "validate", MSR, *[a for s in sets for a in ("--set", s)])
    assert shown.returncode == 0, shown.stderr
    scenario = chaser.load_scenario(str(MSR), overrides={
        "faults": [{"thruster": "T8", "kind": "leak", "onset_s": 900, "leak_size": 0.2, "leak_slope_per_s": 0.01}],
        "seed": 7})
    assert f"hash {scenario.hash})" in shown.stdout


def test_from_dict_of_the_file_is_the_file():
    from_file = chaser.load_scenario(str(MSR))
    from_dict = chaser.Scenario.from_dict(msr_document())
    assert yaml.safe_load(from_dict.yaml) == yaml.safe_load(from_file.yaml)
    changed = copy.deepcopy(msr_document())
    changed["chaser"]["mass_kg"] = 2400.0
    assert yaml.safe_load(chaser.Scenario.from_dict(changed).yaml)["chaser"]["mass_kg"] == 2400.0
