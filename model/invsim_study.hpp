#pragma once
// Thruster-layout studies of the manually controlled approach (Zhou 2018, section 4.2): the
// alternative configurations a scenario asks `chaser fmea` to evaluate beside its own layout
// (the paper's Schemes I and II), and the free mounting choices `chaser fmea --optimize` searches.
// A configuration is a list of changes to named thrusters of the scenario; everything else (the
// vehicle, the pilot model, the trajectory) is shared. Loaded and validated by io/invsim_loader.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/invsim.hpp"

namespace chaser::model {

// A changed thruster: only the fields that are set replace the scenario's values.
struct InvSimThrusterChange {
  std::size_t thruster = 0;               // index into InvSimParams::thrusters
  std::optional<double> thrust_N;         // [N]
  std::optional<Vec3> position_body_m;    // [m] from the centre of mass
  std::optional<Vec3> direction_body;     // unit force direction
};

struct InvSimConfiguration {
  std::string name;         // "scheme_I"; for an option of a free choice, its label ("50N")
  std::string description;  // one line for the report
  std::vector<InvSimThrusterChange> changes;
};

// One free mounting choice: exactly one of its options is taken (an option without changes keeps
// the scenario's layout).
struct InvSimFreeChoice {
  std::string name;  // "attitude_thrust"
  std::vector<InvSimConfiguration> options;
};

inline constexpr std::size_t kMaxOptimizeCandidates = 4096;  // product of the choices' sizes

struct InvSimStudy {
  std::vector<InvSimConfiguration> configurations;  // evaluated beside the scenario's layout
  std::vector<InvSimFreeChoice> free_choices;       // searched by --optimize, exhaustively
  int optimize_keep = 5;                            // best candidates reported
};

// The scenario with the configuration's thruster changes applied (directions renormalised).
InvSimParams apply_configuration(const InvSimParams& base, const InvSimConfiguration& c);

// Number of candidates: the product of the choices' option counts (1 without choices), saturated
// at kMaxOptimizeCandidates + 1 so that a caller can report "too many" without overflow.
std::size_t candidate_count(const std::vector<InvSimFreeChoice>& choices);

// Candidate `index` (0 <= index < candidate_count), in mixed radix with the first choice varying
// slowest: named "choice=option, choice=option", its changes those of the options taken in order.
InvSimConfiguration candidate(const std::vector<InvSimFreeChoice>& choices, std::size_t index);

}  // namespace chaser::model
