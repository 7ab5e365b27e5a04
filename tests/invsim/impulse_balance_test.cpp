// A whole run against its momentum: the opening times a run reports are the thrust its plant flew.
//
// With the orbit's gravity taken out (mu = 1 m^3/s^2: n = 5.7e-11 rad/s, gravity and Coriolis
// below 1e-10 m/s^2, 2e-8 m/s over the 1,300 s) and the attitude held at the Hill frame's (every
// translation group balanced about the centre of mass, so no torque, and the phase-plane
// controller never fires), eq. 2 reduces to v' = F / m on each axis, and the run's velocity change
// must be the groups' impulses from its reported opening times:
//   v_hill(T) - v_hill(0) = (F+ t+ - F- t-) / m,
// independently of how the inverse link commanded them. This holds the carried openings' bookkeeping
// (an opening past the step flown in the next steps, the remaining one shortened by a command the
// other way) to the plant, which the unit tests of invsim/carried_opening check only in closed form.
// Tolerance 1e-7 m/s: the residue measured is 2e-12 m/s on x and y (rounding) and 1.0e-8 m/s on z
// (the Coriolis term 2 n x' over the run); 1e-4 s more or less in one opening of a 60 N thruster on
// 8,000 kg is 7.5e-7 m/s, and an opening reported past the step that the plant flies only within it
// (tried: the flown opening left uncapped in invsim/carried_opening.cpp) misses by 0.08-3.9 m/s.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "invsim/inverse_simulation.hpp"
#include "io/invsim_loader.hpp"

namespace chaser::invsim {
namespace {

struct Flight {
  model::InvSimParams params;
  model::InvSimFaultSet faults;
  InvSimResult result;
  std::vector<InvSimSample> history;
};

// The shipped scenario under the paper reading without noise and with the orbit switched off. With
// e1 lost, e2 is moved onto its group's line of action (0, 1.4, 0): the halved y- group then fires
// without a moment (in the shipped layout every healthy pair is balanced).
Flight fly(const std::string& opening, const std::string& faults) {
  const auto loaded = io::load_invsim_file(
      "scenarios/manual_rvd.yaml",
      {"pulses.reading=paper", "pulses.paper.opening=" + opening, "pulses.paper.measurement_noise.draws=1",
       "pulses.paper.measurement_noise.angle_sigma_deg=0", "pulses.paper.measurement_noise.range_sigma_m=0",
       "faults=[" + faults + "]"});
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  Flight f{*loaded.params, loaded.faults, {}, {}};
  f.params.mu_m3ps2 = 1.0;
  if (faults == "e1")
    for (model::InvSimThruster& t : f.params.thrusters)
      if (t.name == "e2") t.position_body_m = Vec3(0.0, 1.4, 0.0);
  f.result = run_inverse_simulation(f.params, f.faults, &f.history);
  return f;
}

// Summed healthy thrust [N] of the translation group firing `sign` on body `axis`.
double group_thrust_N(const Flight& f, int axis, int sign) {
  double thrust = 0.0;
  for (std::size_t i = 0; i < f.params.thrusters.size(); ++i) {
    const model::InvSimThruster& t = f.params.thrusters[i];
    if (t.role == model::InvSimThrusterRole::kTranslation && t.axis == axis && t.sign == sign && !f.faults.failed(i))
      thrust += t.thrust_N;
  }
  return thrust;
}

void expect_momentum_balance(const Flight& f, const std::string& what) {
  const InvSimResult& r = f.result;
  ASSERT_FALSE(r.diverged) << what;
  EXPECT_LT(r.peak_attitude_rad.cwiseAbs().maxCoeff(), 1e-12) << what << ": the attitude must stay at the Hill frame's";
  const Vec3 dv = r.final_v_hill_mps - f.params.v0_hill_mps;
  for (int axis = 0; axis < 3; ++axis) {
    const std::array<double, 2>& t = r.pulses[axis].on_time_s;
    const double impulse_mps =
        (group_thrust_N(f, axis, 1) * t[0] - group_thrust_N(f, axis, -1) * t[1]) / f.params.mass_kg;
    EXPECT_NEAR(dv(axis), impulse_mps, 1e-7) << what << " axis " << axis << " (opening times " << t[0] << " s, "
                                             << t[1] << " s)";
  }
}

TEST(ImpulseBalance, TheReportedOpeningTimesAreTheThrustTheRunFlew) {
  for (const char* opening : {"carried", "capped"})
    for (const char* faults : {"", "e1"}) expect_momentum_balance(fly(opening, faults), std::string(opening) + " [" + faults + "]");
}

// The balance above reaches the carried openings: with y held at 0 from y' = 0.131 m/s the first
// commands ask for several times a group's thrust. A step's command counts ceil(dtau / w) pulses
// (w = 0.1 s), so more than step / w = 10 in one step is an opening commanded past the step; capped,
// never more. (Without noise the two rules fly alike to 12 digits here: capped, the next step asks
// again for what was cut. They part with the measurement noise: docs/invsim.md, "Predictions".)
TEST(ImpulseBalance, OpeningsPastTheStepAreCommandedInTheseFlights) {
  const auto most_in_a_step = [](const Flight& f) {
    int most = 0;
    for (const InvSimSample& s : f.history) most = std::max(most, s.pulse_count[1]);
    return most;
  };
  const double per_step = 1.0 / 0.1;  // step / w
  ASSERT_EQ(fly("carried", "").params.pulses.paper.pulse_width_s, 0.1);
  for (const char* faults : {"", "e1"}) {
    EXPECT_GT(most_in_a_step(fly("carried", faults)), per_step) << faults;
    EXPECT_LE(most_in_a_step(fly("capped", faults)), per_step) << faults;
  }
}

// The halved y- group (e1 lost: 60 of 120 N) opens about twice as long as the whole one: 2.21 times
// here, a little more than the same impulse would need because the slower stop of the initial drift
// costs some correction (docs/invsim.md, "Predictions": the y start).
TEST(ImpulseBalance, TheHalvedGroupOpensAboutTwiceAsLong) {
  const Flight halved = fly("carried", "e1"), whole = fly("carried", "");
  ASSERT_EQ(group_thrust_N(whole, 1, -1), 120.0);
  ASSERT_EQ(group_thrust_N(halved, 1, -1), 60.0);
  EXPECT_NEAR(halved.result.pulses[1].on_time_s[1] / whole.result.pulses[1].on_time_s[1], 2.2, 0.1);
}

}  // namespace
}  // namespace chaser::invsim
