"""chaser.Simulation: the run of chaser.run advanced period by period, read between periods, faults
injected at run time, and periods flown by a Python flight callback that sees no truth."""
import numpy as np
import pytest

import chaser
from conftest import MSR, assert_same_bits, without_wall

T8_STUCK_OPEN = {"faults": [{"thruster": "T8", "kind": "stuck_open", "onset_s": 1000}]}
# What a flight callback may see: the sensors' measurements, the time, and the LVLH frame of the
# flight software's own orbit model. Anything else (a truth key) fails the test.
FLIGHT_KEYS = {"t_s", "period", "r_lvlh_m", "lidar_valid", "q_inertial_from_body", "omega_body_radps", "propellant_used_kg",
               "q_inertial_from_lvlh"}


def assert_same_result(a, b):
    assert list(a.telemetry) == list(b.telemetry)
    for name in a.telemetry:
        assert_same_bits(a.telemetry[name], b.telemetry[name], name)
    assert without_wall(a.summary) == without_wall(b.summary)


@pytest.fixture(scope="module")
def t8_scenario():
    return chaser.load_scenario(str(MSR), overrides=T8_STUCK_OPEN)


@pytest.fixture(scope="module")
def t8_run(t8_scenario):
    return chaser.run(t8_scenario, seed=7)


def stepped(scenario, piece, seed=7):
    sim = chaser.Simulation(scenario, seed=seed)
    while not sim.done:
        sim.step(piece)
    return sim


def test_stepped_to_the_end_equals_run_bit_for_bit(t8_scenario, t8_run):
    sim = stepped(t8_scenario, 12000)
    assert (sim.period, sim.t, sim.done) == (12000, 1200.0, True)
    result = sim.result()
    assert isinstance(result, chaser.RunResult) and sim.result() is result
    assert_same_result(result, t8_run)
    assert result.summary["fdir"]["isolated_thruster"] == "T8"


@pytest.mark.parametrize("piece", [1, 7])
def test_pieces_of_any_size_give_the_same_run(t8_scenario, t8_run, piece):
    assert_same_result(stepped(t8_scenario, piece).result(), t8_run)


def test_time_truth_estimate_and_command_between_periods():
    scenario = chaser.load_scenario(str(MSR), overrides={"duration_s": 10.0})
    sim = chaser.Simulation(scenario, seed=3)
    assert (sim.t, sim.period, sim.done, sim.thruster_count, sim.control_period_s) == (0.0, 0, False, 16, 0.1)
    assert sim.estimate() is None and sim.command() is None
    start = sim.truth()
    assert np.allclose(start["r_lvlh_m"], [0.0, -20.0, 0.0]) and start["mass_kg"] == 2500.0
    sim.step(5)
    assert (sim.period, sim.t) == (5, 0.5)
    truth, estimate, command = sim.truth(), sim.estimate(), sim.command()
    assert truth["t_s"] == 0.5 and estimate["t_s"] == command["t_s"] == 0.4
    assert np.linalg.norm(estimate["r_lvlh_m"] - truth["r_lvlh_m"]) < 0.01  # a filtered LIDAR
    assert command["on_times"].shape == (16,) and np.all((command["on_times"] >= 0) & (command["on_times"] <= 1))
    assert np.all(command["on_times"][8:] == 0)  # branch B stands by
    with pytest.raises(RuntimeError, match="not finished"):
        sim.result()
    sim.step(1000)  # past the end: stops there
    assert sim.done and sim.period == 100
    with pytest.raises(ValueError):
        sim.step(-1)


def test_a_fault_injected_at_run_time_is_the_scenario_s_fault_with_that_onset():
    scenario = chaser.load_scenario(str(MSR), overrides={"duration_s": 600.0})
    sim = chaser.Simulation(scenario, seed=5)
    sim.step(4000)
    sim.inject_fault(thruster="T3", kind="stuck_closed")  # now: 400 s
    sim.step(1000)
    sim.inject_fault(thruster="T5", kind="leak", size=0.3, onset_s=550.0, leak_slope_per_s=0.05)
    sim.step(1000)
    given = chaser.load_scenario(str(MSR), overrides={"duration_s": 600.0, "faults": [
        {"thruster": "T3", "kind": "stuck_closed", "onset_s": 400.0},
        {"thruster": "T5", "kind": "leak", "onset_s": 550.0, "leak_size": 0.3, "leak_slope_per_s": 0.05}]})
    expected = chaser.run(given, seed=5)
    result = sim.result()
    assert_same_result(result, expected)
    assert [f["thruster"] for f in result.summary["faults"]] == ["T3", "T5"]


def test_inject_fault_is_checked_as_the_scenario_s_faults_section():
    sim = chaser.Simulation(chaser.load_scenario(str(MSR), overrides=T8_STUCK_OPEN), seed=1)
    sim.step(10)
    with pytest.raises(chaser.ScenarioError) as error:
        sim.inject_fault(thruster="T17", kind="loss", size=1.5)
    assert {path for path, _ in error.value.errors} == {"faults.1.thruster", "faults.1.loss_size"}
    with pytest.raises(chaser.ScenarioError, match="faults.1.kind: must be one of stuck_open"):
        sim.inject_fault(thruster="T2", kind="sticky")
    with pytest.raises(chaser.ScenarioError, match="duplicate fault on T8"):
        sim.inject_fault(thruster="T8", kind="stuck_closed")
    with pytest.raises(chaser.ScenarioError, match=r"faults.1.onset_s: must be in \[0, duration_s\]"):
        sim.inject_fault(thruster="T2", kind="stuck_closed", onset_s=5000.0)
    with pytest.raises(ValueError, match="onset_s: must be >= the simulation's time"):
        sim.inject_fault(thruster="T2", kind="stuck_closed", onset_s=0.5)
    with pytest.raises(chaser.ScenarioError, match="faults.1.leak_slope_per_s: missing key"):
        sim.inject_fault(thruster="T2", kind="leak", size=0.2)
    with pytest.raises(ValueError, match="size: only for leak"):
        sim.inject_fault(thruster="T2", kind="stuck_open", size=0.5)


def test_the_callback_sees_the_measurements_and_never_the_truth():
    sim = chaser.Simulation(chaser.load_scenario(str(MSR), overrides={"duration_s": 2.0}), seed=2)
    seen = []

    def flight(measurements):
        seen.append((measurements, sim.truth()))
        return np.zeros(6)

    sim.step(20, flight=flight)
    assert len(seen) == 20 and sim.done
    truth_only = set(seen[0][1]) - FLIGHT_KEYS  # v_lvlh_mps, mass_kg: what no sensor gives
    assert truth_only >= {"v_lvlh_mps", "mass_kg"}
    for k, (measurements, truth) in enumerate(seen):
        assert set(measurements) == FLIGHT_KEYS  # the allow-list, exactly
        assert not set(measurements) & truth_only
        assert measurements["period"] == k and measurements["t_s"] == truth["t_s"] == k * 0.1
        # Measured, not true: LIDAR noise of 1 mm.
        assert not np.array_equal(measurements["r_lvlh_m"], truth["r_lvlh_m"])
        assert np.linalg.norm(measurements["r_lvlh_m"] - truth["r_lvlh_m"]) < 0.01


def test_on_times_go_straight_to_the_thrusters_and_a_wrench_through_the_allocation():
    scenario = chaser.load_scenario(str(MSR), overrides={"duration_s": 1.0})
    sim = chaser.Simulation(scenario, seed=1)
    ton = np.zeros(16)
    ton[2] = 0.5
    sim.step(3, flight=lambda m: ton)
    assert_same_bits(sim.command()["on_times"], ton, "on_times")
    sim.step(3, flight=lambda m: {"wrench": [0.0, 10.0, 0.0, 0.0, 0.0, 0.0]})
    command = sim.command()
    assert command["commanded_wrench"][1] > 5.0 and np.all(command["on_times"][8:] == 0)
    # The same periods flown with the same callbacks repeat to the bit.
    again = chaser.Simulation(scenario, seed=1)
    again.step(3, flight=lambda m: ton)
    again.step(3, flight=lambda m: [0.0, 10.0, 0.0, 0.0, 0.0, 0.0])
    for key in ("r_lvlh_m", "v_lvlh_mps", "q_inertial_from_body", "omega_body_radps"):
        assert_same_bits(again.truth()[key], sim.truth()[key], key)


@pytest.mark.parametrize("returned, error, match", [
    (np.zeros(5), ValueError, r"shape \(5,\)"),
    (np.zeros((2, 3)), ValueError, r"shape \(2,3\)"),
    ([0.0, 0.0, np.nan, 0.0, 0.0, 0.0], ValueError, r"wrench\[2\] is not finite"),
    (np.full(16, 1.5), ValueError, r"on_times\[0\] \(T1\) must be in \[0, 1\]"),
    (-np.ones(16), ValueError, r"must be in \[0, 1\]"),
    ({"wrench": np.zeros(16)}, ValueError, "wrench has 6 values"),
    ({"force": np.zeros(6)}, ValueError, "one key, 'wrench' or 'on_times'"),
    (None, TypeError, "not numbers"),
    ("fast", TypeError, "not numbers"),
])
def test_a_bad_return_raises_and_the_period_can_be_flown_again(returned, error, match):
    scenario = chaser.load_scenario(str(MSR), overrides={"duration_s": 1.0})
    sim = chaser.Simulation(scenario, seed=4)
    sim.step(2, flight=lambda m: np.zeros(6))
    with pytest.raises(error, match=match):
        sim.step(1, flight=lambda m: returned)
    assert sim.period == 2
    # The failed period's measurements are kept (sensed once): flying it again repeats the run.
    sim.step(8, flight=lambda m: np.zeros(6))
    clean = chaser.Simulation(scenario, seed=4)
    clean.step(10, flight=lambda m: np.zeros(6))
    assert_same_bits(sim.result().telemetry["r_lvlh_x_m"], clean.result().telemetry["r_lvlh_x_m"], "r_lvlh_x_m")


def test_an_exception_in_the_callback_comes_out():
    sim = chaser.Simulation(chaser.load_scenario(str(MSR), overrides={"duration_s": 1.0}))

    def flight(measurements):
        raise KeyError("mine")

    with pytest.raises(KeyError, match="mine"):
        sim.step(1, flight=flight)


def test_phase_is_the_mission_phase_of_the_next_period_and_the_summary_lists_those_flown():
    scenario = chaser.load_scenario(str(MSR))
    sim = chaser.Simulation(scenario, seed=3)
    assert sim.phase == "line"
    while sim.phase == "line":
        sim.step()
    switched_at = sim.t
    while not sim.done:
        sim.step(1000)
    flown = sim.result().summary["phases_flown"]
    assert [p["name"] for p in flown] == ["line", "capture_point_hold"]
    assert flown[1]["start_s"] == pytest.approx(switched_at, abs=1e-9)
    assert flown[0]["end_reason"] == "time" and flown[1]["end_reason"] == "run end"
    assert flown[1]["end_s"] == 1200.0


def test_the_capture_steps_like_its_run_with_the_arm_in_its_telemetry():
    # comrade_capture cut 3 s into its reach: the multibody plant and the joint loop at 1 kHz stepped
    # from Python give chaser.run's bits, and the joints and the gripper are telemetry channels.
    path = MSR.parent / "comrade_capture.yaml"
    scenario = chaser.load_scenario(str(path), overrides={"duration_s": 2763.0})
    ran = chaser.run(scenario)
    sim = stepped(scenario, 5000, seed=None)
    assert_same_result(ran, sim.result())
    tel = ran.telemetry
    for name in ["q_arm_1_rad", "tau_arm_7_Nm", "gripper_err_x_m", "gripper_rate_z_radps"]:
        assert name in tel
    awake = np.isfinite(tel["gripper_err_x_m"])
    assert awake.sum() == 30  # the reach's 3 s of 0.1 s periods
    assert ran.summary["reach"]["flown"]
    assert ran.summary["phases_flown"][-1]["name"] == "reach"
    grasp = ran.summary["reach"]["grasp"]
    assert not grasp["attempted"] and grasp["at_closure"] is None and grasp["captured_s"] is None
