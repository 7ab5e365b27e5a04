#include "campaign/dispersion.hpp"

#include <Eigen/Eigenvalues>

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

}  // namespace chaser::campaign
