#pragma once
// The target's orbit as the rest of the core asks it: where the target's LVLH frame is, and how it
// turns, at a time t of the run. The flight software (guidance, the LVLH force demand, the FDI's
// frame), the plant (the relative motion and the thrust's rotation into LVLH) and the mission
// monitor all ask one of these and never compute the frame from n t themselves.
//
// Today's one model is the circular Keplerian orbit of Fonod 2015 (eqs. 6-7): radius a, mean
// motion n = sqrt(mu / a^3), and LVLH (MSR convention: x zenith, y along-track, z orbit normal)
// turning about its z axis at the constant rate n, so that the run's inertial frame is LVLH at
// t = 0. A perturbed Earth orbit (J2, drag; the COMRADE platform) is the next model: it answers the
// same questions with a frame whose rate and radius vary. The linear designs (the HCW models of
// navigation, position control and FDI) assume the circle and ask for mean_motion_radps().
#include "core/types.hpp"
#include "model/orbit.hpp"

namespace chaser::model {

// The target's LVLH frame at one instant, relative to the run's inertial frame.
struct LvlhFrame {
  Quat q_inertial_from_lvlh = Quat::Identity();
  Vec3 omega_lvlh_radps = Vec3::Zero();       // [rad/s] LVLH's angular velocity w.r.t. inertial, LVLH axes
  Vec3 omega_dot_lvlh_radps2 = Vec3::Zero();  // [rad/s^2] its time derivative, LVLH axes
  double target_radius_m = 0.0;               // [m] the target's distance from the central body's centre
};

class TargetOrbit {
 public:
  TargetOrbit() = default;
  explicit TargetOrbit(const OrbitParams& params);
  TargetOrbit(double mu_m3ps2, double radius_m);  // a circle of radius a about a body of parameter mu

  LvlhFrame lvlh_at(double t_s) const;
  Quat q_inertial_from_lvlh(double t_s) const;  // lvlh_at(t_s).q_inertial_from_lvlh, alone

  // Argument of latitude travelled since t = 0, u(t) - u(0) [rad]: the angle LVLH has turned about
  // the orbit normal. The plant's propagator steps it through its RK4 stages (plant/propagator.cpp).
  double argument_of_latitude_rad(double t_s) const { return mean_motion_radps_ * t_s; }

  double mu_m3ps2() const { return mu_m3ps2_; }
  double radius_m() const { return radius_m_; }                    // a
  double mean_motion_radps() const { return mean_motion_radps_; }  // n, Fonod 2015, eq. 7

 private:
  double mu_m3ps2_ = 0.0;
  double radius_m_ = 1.0;
  double mean_motion_radps_ = 0.0;
};

}  // namespace chaser::model
