#pragma once
// The motion a replay draws, read from a run's telemetry (docs/view.md): per row the chaser's
// position and attitude and the target's attitude in LVLH, the guidance reference, the attitude
// error and, with an arm, the arm's figure; and the rows kept for the page (decimation).
//
// Attitudes in telemetry are in the run's inertial frame, which is LVLH at t = 0; LVLH turns about
// its z axis (the orbit normal) at the mean motion n, so q_lvlh_from_x(t) = Rz(-n t) q_inertial_from_x(t)
// (model/target_orbit.hpp: exact for the circular orbit; with orbit.earth the perturbed frame's
// turn departs from n t by what J2 and drag add, a fraction of a degree over an hour).
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/types.hpp"
#include "sim/telemetry.hpp"

namespace chaser::view {

// The arm's figure (sim/telemetry_channels.cpp): the hub, joints 1 to 7 and the tool point, target axes.
inline constexpr int kArmPoints = 9;
using ArmFigure = std::array<Vec3, kArmPoints>;

struct ReplayTrack {
  std::vector<double> t_s;
  std::vector<Vec3> r_lvlh_m;
  std::vector<Quat> q_lvlh_from_body;
  std::vector<Quat> q_lvlh_from_target;
  std::vector<Vec3> r_ref_lvlh_m;         // the guidance reference (NaN without the channel)
  std::vector<double> attitude_error_rad;  // |att_err_body| (NaN without the channel)
  std::vector<std::optional<ArmFigure>> arm;  // empty without the arm's channels; nullopt before it wakes
};

// The rotation LVLH has turned through since t = 0, about its z axis: q_inertial_from_lvlh(t).
Quat q_inertial_from_lvlh(double mean_motion_radps, double t_s);

// Reads the track; throws ViewInputError naming `file` and the first channel it needs that the
// telemetry lacks (t_s, r_lvlh_*_m, q_inertial_from_body_*, q_inertial_from_target_*).
ReplayTrack replay_track(const sim::TelemetryRows& telemetry, double mean_motion_radps, const std::string& file);

// How far the page may draw from the telemetry between kept rows.
struct DecimationTolerance {
  double position_m = 0.005;        // [m] the chaser's position, the reference and the arm's points
  double attitude_rad = 0.0035;     // [rad] (0.2 deg) either body's attitude
  double max_gap_s = 20.0;          // [s] at most this long between kept rows
};

// The rows the page keeps: the first and the last, every row in `forced` (an event's), and enough
// others that linear interpolation of positions and slerp of attitudes between kept rows stays
// within `tol` of every dropped row. Increasing row indices.
std::vector<std::size_t> decimate(const ReplayTrack& track, const DecimationTolerance& tol,
                                  const std::vector<std::size_t>& forced);

// The track's row at time t interpolated between rows a < b as the page does it.
Vec3 lerp_position(const std::vector<Vec3>& v, std::size_t a, std::size_t b, double t, const std::vector<double>& t_s);
Quat slerp_attitude(const std::vector<Quat>& q, std::size_t a, std::size_t b, double t, const std::vector<double>& t_s);

}  // namespace chaser::view
