#pragma once
// Readers of the scenario's sections and the cross-field validation (internal to io/). Each reader
// reads every key of its section with its type and static range (docs/scenario.md); checks that
// involve more than one key (a delay against the control period, capture against start distance,
// the inertia matrix as a whole, the thruster set's controllability) are in validate_scenario.
#include <optional>
#include <string>
#include <string_view>

#include "io/yaml_reader.hpp"
#include "model/scenario.hpp"

namespace chaser::io {

// Upper bounds that keep every time representable as int64 nanoseconds with margin.
inline constexpr double kMaxDurationS = 1e8;      // [s] about three years
inline constexpr double kMaxControlPeriodS = 10.0;  // [s]
// The clock's tick: a run counts time in whole nanoseconds (core/time.hpp), so a shorter period would
// round to none (and divide by zero wherever a time is counted in periods).
inline constexpr double kMinControlPeriodS = 1e-9;  // [s]
// Thruster positions and the centre of mass lie within this of the layout origin, per axis: no
// spacecraft is 2 km across, and torques stay within a few orders of magnitude of forces.
inline constexpr double kMaxLayoutExtentM = 1e3;  // [m]
// A thruster's thrust: the largest engines ever flown give about 1e7 N.
inline constexpr double kMaxThrustN = 1e7;        // [N]
// Longest campaign run (onset + horizon): each run keeps a per-second GLR record of this length.
inline constexpr double kMaxCampaignRunS = 1e6;     // [s] about 11 days

// The whole document; `source` names the file for root-level problems.
model::Scenario read_scenario(const YAML::Node& root, const std::string& source, Diagnostics& diag);

void read_orbit(MapReader& r, model::OrbitParams& out);
void read_chaser(MapReader& r, model::SpacecraftParams& out);
void read_target(MapReader& r, model::TargetParams& out);
// The optional COMRADE sections orbit.earth and target.body (io/earth_orbit_reader.cpp).
void read_optional_earth_orbit(MapReader& r, std::optional<model::EarthOrbitParams>& out);
void read_optional_target_body(MapReader& r, std::optional<model::TargetBodyParams>& out);
// chaser.slosh, the propellant tanks' slosh (io/slosh_reader.cpp).
void read_optional_slosh(MapReader& r, std::optional<model::SloshParams>& out);
// chaser.arm, the servicer's arm and gripper (io/arm_reader.cpp).
void read_optional_arm(MapReader& r, std::optional<model::ArmParams>& out);
// capture, the arm's reach and its combined controller (io/capture_reader.cpp).
void read_optional_capture(MapReader& r, std::optional<model::CaptureParams>& out);
void read_environment(MapReader& r, model::EnvironmentParams& out);
void read_sensors(MapReader& r, model::SensorParams& out);
void read_thrusters(MapReader& r, model::ThrusterSetParams& out);
// A list of thruster names T1..TN under `key` (campaign.fault_thrusters, fdi.supervisor.thrusters).
void read_thruster_names(MapReader& r, std::string_view key, model::ThrusterMask& out);
void read_faults(MapReader& root, std::vector<model::FaultParams>& out);
void read_navigation(MapReader& r, model::NavigationParams& out);
void read_guidance(MapReader& r, model::GuidanceParams& out);
void read_control(MapReader& r, model::ControlParams& out);
// One loop family of H-infinity weights (control.hinf.translation/rotation, capture.stabilise.hinf),
// its error scale under error_scale_key.
void read_hinf_loop(MapReader& r, const char* error_scale_key, model::HinfLoopWeights& out);
void read_initial(MapReader& r, model::InitialState& out);
void read_fdi(MapReader& r, model::FdiParams& out);
void read_campaign(MapReader& r, model::CampaignParams& out);

// Checks between keys; each runs only if the keys it uses were read without problems.
void validate_scenario(const model::Scenario& s, Diagnostics& diag);
// What the thruster set can do: spanning sets before and after recovery, the FDI's set size,
// single-loss tolerance, fault thrusters that exist (called by validate_scenario).
void validate_thruster_set(const model::Scenario& s, Diagnostics& diag);
// chaser.arm against itself, the target's fixture and the capture point (io/arm_validation.cpp,
// called by validate_scenario).
void validate_arm(const model::Scenario& s, Diagnostics& diag);
// capture against the arm, the run and the synchronisation (io/capture_reader.cpp, called by
// validate_scenario).
void validate_capture(const model::Scenario& s, Diagnostics& diag);
// The campaign run length against the control period (called by validate_scenario).
void validate_campaign(const model::Scenario& s, Diagnostics& diag);

}  // namespace chaser::io
