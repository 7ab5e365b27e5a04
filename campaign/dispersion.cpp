#include "campaign/dispersion.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "core/constants.hpp"
#include "plant/orbit_plant.hpp"

namespace chaser::campaign {

namespace {

constexpr double kTruncationSigmas = 3.0;  // Fonod 2015, Table 1: values are 3-sigma bounds

bool triangle_holds(const Vec3& m) {
  return m(0) + m(1) >= m(2) && m(1) + m(2) >= m(0) && m(0) + m(2) >= m(1);
}

// Principal axes (columns) and moments of the nominal inertia. A diagonal tensor keeps the body
// axes exactly, so a dispersed diagonal tensor stays exactly diagonal.
void principal(const Mat3& inertia, Mat3& axes, Vec3& moments) {
  const bool diagonal = (inertia - Mat3(inertia.diagonal().asDiagonal())).cwiseAbs().maxCoeff() == 0.0;
  if (diagonal) {
    axes = Mat3::Identity();
    moments = inertia.diagonal();
    return;
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
  axes = eig.eigenvectors();
  moments = eig.eigenvalues();
}

Mat3 disperse_inertia(const Mat3& nominal, double three_sigma, RandomStream& rng) {
  Mat3 axes;
  Vec3 moments;
  principal(nominal, axes, moments);
  for (int attempt = 0; attempt < kMaxInertiaDraws; ++attempt) {
    Vec3 drawn;
    for (int i = 0; i < 3; ++i) drawn(i) = moments(i) * dispersed_factor(rng, three_sigma);
    if (triangle_holds(drawn)) return axes * drawn.asDiagonal() * axes.transpose();
  }
  return nominal;
}

}  // namespace

double dispersed_factor(RandomStream& rng, double three_sigma) {
  return 1.0 + rng.truncated_normal(three_sigma / kTruncationSigmas, kTruncationSigmas);
}

model::SpacecraftParams disperse_chaser(const model::SpacecraftParams& nominal, const model::CampaignParams& params,
                                        std::uint64_t run_seed) {
  RandomStream rng(run_seed, "campaign/dispersion");
  model::SpacecraftParams out = nominal;
  out.mass_kg = nominal.mass_kg * dispersed_factor(rng, params.mass_3sigma_rel);
  out.inertia_kgm2 = disperse_inertia(nominal.inertia_kgm2, params.inertia_3sigma_rel, rng);
  for (int i = 0; i < 3; ++i)
    out.com_body_m(i) =
        nominal.com_body_m(i) + rng.truncated_normal(params.com_3sigma_m / kTruncationSigmas, kTruncationSigmas);
  return out;
}

model::TargetParams disperse_target_spin(const model::TargetParams& nominal, const model::CampaignParams& params,
                                         std::uint64_t run_seed) {
  if (!nominal.body || (params.target_spin_rate_3sigma_rel <= 0.0 && params.target_spin_axis_3sigma_rad <= 0.0))
    return nominal;
  RandomStream rng(run_seed, "campaign/target_spin");
  const plant::TargetSpin spin = plant::initial_target_spin(nominal);
  const Vec3 omega_inertial = spin.q_inertial_from_target * spin.omega_target_body_radps;
  const double factor = dispersed_factor(rng, params.target_spin_rate_3sigma_rel);
  const double tilt_rad = rng.truncated_normal(params.target_spin_axis_3sigma_rad / kTruncationSigmas, kTruncationSigmas);
  const double phase_rad = rng.uniform(0.0, 2.0 * kPi);
  // A unit vector perpendicular to the rate, turned about it by the phase.
  const Vec3 axis = omega_inertial.norm() > 0.0 ? omega_inertial.normalized() : Vec3::UnitZ();
  const Vec3 any = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 perpendicular = Eigen::AngleAxisd(phase_rad, axis) * axis.cross(any).normalized();
  const Quat tilt(Eigen::AngleAxisd(tilt_rad, perpendicular));
  model::TargetParams out = nominal;
  out.q_inertial_from_target = (tilt * spin.q_inertial_from_target).normalized();
  out.omega_inertial_radps = tilt * (factor * omega_inertial);
  out.body->spin_case = model::SpinCase::given;
  return out;
}

void disperse_initial(model::InitialState& initial, const model::CampaignParams& params, std::uint64_t run_seed) {
  if (params.initial_position_3sigma_m <= 0.0 && params.initial_velocity_3sigma_mps <= 0.0) return;
  RandomStream rng(run_seed, "campaign/initial");
  for (int i = 0; i < 3; ++i)
    initial.offset_r_lvlh_m(i) = rng.truncated_normal(params.initial_position_3sigma_m / kTruncationSigmas, kTruncationSigmas);
  for (int i = 0; i < 3; ++i)
    initial.offset_v_lvlh_mps(i) =
        rng.truncated_normal(params.initial_velocity_3sigma_mps / kTruncationSigmas, kTruncationSigmas);
}

}  // namespace chaser::campaign
