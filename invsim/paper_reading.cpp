#include "invsim/paper_reading.hpp"

#include <algorithm>
#include <cmath>

namespace chaser::invsim {

namespace {
// An opening within this fraction of a whole number of widths counts that number (rounding of
// dtau = |u| tau / u_max must not add a pulse).
constexpr double kWidthRoundingTolerance = 1e-9;
}  // namespace

int counted_pulses(const model::InvSimPulseParams& p, const Pulse& pulse) {
  if (pulse.direction == 0) return 0;
  if (p.reading == model::InvSimReading::kSmooth) return 1;
  const double widths = pulse.on_time_s / p.paper.pulse_width_s;
  return std::max(1, static_cast<int>(std::ceil(widths - kWidthRoundingTolerance)));
}

const std::array<double, 6>& reading_state_weights(const model::InvSimParams& p) {
  return p.pulses.reading == model::InvSimReading::kPaper ? p.pulses.paper.state_weights
                                                          : p.inverse.state_weights;
}

const model::InvSimPaperReadingParams& flight_choices(const model::InvSimParams& p) {
  static const model::InvSimPaperReadingParams kSmoothFlight{};
  return p.pulses.reading == model::InvSimReading::kPaper ? p.pulses.paper : kSmoothFlight;
}

std::string_view reading_name(model::InvSimReading r) {
  return r == model::InvSimReading::kPaper ? "paper" : "smooth";
}

}  // namespace chaser::invsim
