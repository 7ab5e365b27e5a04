#pragma once
// The escape (flight/escape.hpp) judged on the truth against Chaser's requirements for it
// (model/capture.hpp: COMRADE 2018 gives none): the chaser's clearance from the target's keep-out
// volume while it turns with the target (before the desynchronisation) and after, the tool point's
// clearance once retracted (it starts at the fixture, on the volume's face), the target's centre inside the arm camera's field of view (the angle between the
// camera's axis, the tool's x, and the line from its eye to the target's centre), and the distance
// from the target's centre at the end against the plan's safe distance.
#include <limits>

#include "core/types.hpp"
#include "flight/escape.hpp"
#include "model/scenario.hpp"

namespace chaser::sim {

struct EscapeResult {
  bool flown = false;
  const char* trigger = "none";  // flight::to_string(EscapeTrigger)
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double start_s = kNaN;            // [s] triggered
  double refused_s = kNaN;          // [s] commanded with the jaws closed: not flown
  double desynchronise_s = kNaN;    // [s] the plan's desynchronisation begins
  double hold_s = kNaN;             // [s] the plan's hold at the safe distance begins
  double min_clearance_synchronised_m = kNaN, min_clearance_synchronised_at_s = kNaN;      // [m], [s]
  double min_clearance_unsynchronised_m = kNaN, min_clearance_unsynchronised_at_s = kNaN;  // [m], [s]
  double min_tool_clearance_m = kNaN, min_tool_clearance_at_s = kNaN;  // [m], [s] from the retraction's end
  double max_camera_angle_rad = kNaN, max_camera_angle_at_s = kNaN;                        // [rad], [s]
  double final_distance_m = kNaN;   // [m] the chaser's CoM from the target's at the last period
  double brakes_s = kNaN;           // [s] the arm braked at the retraction's end (brake_when_stowed)
  double peak_brake_load_Nm = kNaN; // [N m] the largest braked joint's load from then on (every joint step)
  double final_t_s = kNaN;          // [s] that period
};

// One control period of the run with the escape's state after the flight software ran: its times
// and, once triggered, the figures (clearances NaN without a keep-out volume, the camera's angle NaN
// without an arm camera).
struct EscapeSample {
  double t_s = 0.0;
  double chaser_clearance_m = EscapeResult::kNaN;  // [m]
  double tool_clearance_m = EscapeResult::kNaN;    // [m]
  double camera_angle_rad = EscapeResult::kNaN;    // [rad]
  double distance_m = 0.0;                         // [m]
};
void add_escape_period(EscapeResult& r, const flight::EscapeLawParams& params, const flight::EscapeState& state,
                       const EscapeSample& sample);

// The angle between the camera's axis (the tool's x, at the tool point less setback_m along it) and
// its line to the target's centre, in target axes [rad].
double camera_angle_rad(const Vec3& tool_target_m, const Quat& q_target_from_tool, double setback_m);

// The requirements (model/capture.hpp), each NaN figure counting as unmet except the camera's
// where the scenario has no arm camera (camera_fov_rad NaN) and the brakes' load where the arm was
// not braked: flown to the hold, the clearances, the camera, the distance, and the braked joints'
// loads within load_limit_Nm (the drives' repeated peak, as the stabilisation's).
bool escape_meets_requirements(const EscapeResult& r, double safe_distance_m, double camera_fov_rad,
                               double load_limit_Nm);

// The scenario's arm camera's field of view [rad] (NaN without one), and the requirements with the
// scenario's safe distance, field of view and the arm's repeated peak torque (a scenario with
// capture.escape).
double arm_camera_fov_rad(const model::Scenario& scenario);
bool escape_meets_requirements(const EscapeResult& r, const model::Scenario& scenario);

}  // namespace chaser::sim
