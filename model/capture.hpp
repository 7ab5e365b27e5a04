#pragma once
// The capture's scenario section (`capture`): when the arm wakes, which combined controller flies
// the servicer's 13 degrees of freedom (COMRADE 2018, sec. 6), the tool's path to the pre-grasp
// pose, and the joints' rate. Read by io/capture_reader.cpp; flown by flight/reach.hpp; the plant
// becomes the multibody one at start_s (sim/simulation.cpp).
#include <string>

namespace chaser::model {

enum class CaptureLaw { kCompliance, kHinf };

struct CaptureParams {
  double start_s = 0.0;            // [s] the arm wakes: the reach begins
  CaptureLaw law = CaptureLaw::kCompliance;
  double path_duration_s = 60.0;   // [s] the tool from its stowed pose to the pre-grasp pose
  double standoff_m = 0.15;        // [m] the pre-grasp pose: the tool this far short of the fixture along its approach
  double joint_rate_hz = 1000.0;   // [Hz] the combined law and the joints' torque commands (COMRADE: 1 kHz)
  // [Hz] the platform's command: the law's force and torque sampled for the thrusters at this rate
  // (COMRADE: 3 Hz), at the first control period at or after each tick, held in between; at most
  // the control rate.
  double platform_rate_hz = 10.0;
  // The tasks' natural frequencies and damping ratio (flight/arm/compliance_control.hpp,
  // compliance_gains; the H-infinity loops' omega_B).
  double hub_bandwidth_radps = 0.5;
  double tool_bandwidth_radps = 3.0;
  double joint_bandwidth_radps = 1.0;
  double damping_ratio = 3.0;
};

inline const char* to_string(CaptureLaw law) { return law == CaptureLaw::kHinf ? "hinf" : "compliance"; }

}  // namespace chaser::model
