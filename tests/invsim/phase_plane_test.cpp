#include "invsim/phase_plane.hpp"

#include <gtest/gtest.h>

#include "core/constants.hpp"

namespace chaser::invsim {
namespace {

constexpr double kA0 = 0.01;  // [rad/s^2]

model::InvSimPhasePlaneParams params() {
  model::InvSimPhasePlaneParams p;
  p.period_s = 0.25;
  p.d_rad = 0.5 * kDegToRad;                  // 8.727e-3
  p.delta_rad = 0.25 * kDegToRad;             // d - delta = 4.363e-3
  p.rate_border_s_radps = 0.2 * kDegToRad;    // 3.491e-3
  p.rate_border_t_radps = 0.02 * kDegToRad;   // 3.491e-4
  p.btc1 = 0.0;
  p.btc2 = 0.2;
  p.btc3 = 1.0;
  return p;
}

struct Case {
  double theta, rate;
  PhasePlaneArea area;
  int direction;
  double on_time_s;
};

// Hand-computed states, sigma = theta + rate |rate| / (2 a0) (App. A's lines are sigma = d and
// sigma = d - delta), one or more per area, and each mirrored through the origin onto the
// positive side. Opening times are btc * dT exactly.
TEST(PhasePlane, HandComputedStatesFallInTheirAreas) {
  const model::InvSimPhasePlaneParams p = params();
  const Case cases[] = {
      {0.0, 5e-3, PhasePlaneArea::kR11, -1, 0.25},       // rate beyond theta'_s
      {9e-3, 1e-3, PhasePlaneArea::kR11, -1, 0.25},      // sigma 9.05e-3 > d, moving out
      {1e-2, 0.0, PhasePlaneArea::kR12, -1, 0.05},       // sigma 1e-2 > d, still
      {1e-2, 3e-4, PhasePlaneArea::kR12, -1, 0.05},      // |rate| below theta'_t
      {6e-3, 1e-3, PhasePlaneArea::kR13, -1, 0.05},      // d - delta < sigma 6.05e-3 <= d, moving out
      {1e-2, -1e-3, PhasePlaneArea::kR0, 0, 0.0},        // beyond d but returning
      {3e-3, 0.0, PhasePlaneArea::kR0, 0, 0.0},          // inside the dead band
      {6e-3, 2e-4, PhasePlaneArea::kR0, 0, 0.0},         // band, slower than theta'_t
  };
  for (const Case& c : cases) {
    const PhasePlaneCommand cmd = step_phase_plane(p, kA0, c.theta, c.rate);
    EXPECT_EQ(cmd.area, c.area) << c.theta << " " << c.rate;
    EXPECT_EQ(cmd.direction, c.direction) << c.theta << " " << c.rate;
    EXPECT_DOUBLE_EQ(cmd.on_time_s, c.on_time_s);
    const PhasePlaneCommand mirror = step_phase_plane(p, kA0, -c.theta, -c.rate);
    EXPECT_EQ(mirror.direction, -c.direction);
    EXPECT_DOUBLE_EQ(mirror.on_time_s, c.on_time_s);
    const PhasePlaneArea mirrored = c.area == PhasePlaneArea::kR11   ? PhasePlaneArea::kR21
                                    : c.area == PhasePlaneArea::kR12 ? PhasePlaneArea::kR22
                                    : c.area == PhasePlaneArea::kR13 ? PhasePlaneArea::kR23
                                                                     : PhasePlaneArea::kR0;
    EXPECT_EQ(mirror.area, mirrored);
  }
}

// The negative opening line DE, theta'^2 = -2 a0 (theta - d), is the boundary between the step
// decelerate area R13 (on and inside it) and full opening R11 (just outside).
TEST(PhasePlane, OpeningLineSeparatesR13FromR11) {
  const model::InvSimPhasePlaneParams p = params();
  const double rate = 2e-3;
  const double theta_on_line = p.d_rad - rate * rate / (2.0 * kA0);
  EXPECT_EQ(phase_plane_area(p, kA0, theta_on_line - 1e-9, rate), PhasePlaneArea::kR13);
  EXPECT_EQ(phase_plane_area(p, kA0, theta_on_line + 1e-9, rate), PhasePlaneArea::kR11);
}

// R13's inner bound is the level set sigma = d - delta: on theta' <= 0 it is the closing line BC,
// theta'^2 = 2 a0 (theta - d + delta); on theta' > 0 (where R13 lies) it is DE shifted by delta.
TEST(PhasePlane, ShiftedLineBoundsR13) {
  const model::InvSimPhasePlaneParams p = params();
  const double rate = 1e-3;
  const double theta_on_line = p.d_rad - p.delta_rad - rate * rate / (2.0 * kA0);
  EXPECT_EQ(phase_plane_area(p, kA0, theta_on_line - 1e-9, rate), PhasePlaneArea::kR0);
  EXPECT_EQ(phase_plane_area(p, kA0, theta_on_line + 1e-9, rate), PhasePlaneArea::kR13);
}

}  // namespace
}  // namespace chaser::invsim
