#include "core/hill_frames.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "core/linear_models.hpp"
#include "core/rotation.hpp"

namespace chaser {
namespace {

constexpr double kN = 1.1313e-3;  // [rad/s] mean motion of a 400 km circular LEO
constexpr double kEps = std::numeric_limits<double>::epsilon();

// The axes as the papers define them: Hill x is along-track (LVLH y), Hill z points to the planet
// (LVLH -x, LVLH x being radial out), Hill y completes the right-handed triad and is therefore the
// negative orbit normal (LVLH -z). Exact: the map is a signed permutation.
TEST(HillFrames, AxesFollowTheirDefinitions) {
  EXPECT_EQ(lvlh_from_hill(Vec3::UnitX()), Vec3::UnitY());
  EXPECT_EQ(lvlh_from_hill(Vec3::UnitY()), -Vec3::UnitZ());
  EXPECT_EQ(lvlh_from_hill(Vec3::UnitZ()), -Vec3::UnitX());
  EXPECT_EQ(lvlh_from_hill(Vec3::UnitX()).cross(lvlh_from_hill(Vec3::UnitY())), lvlh_from_hill(Vec3::UnitZ()));
}

// The constant quaternion is the same rotation as the vector map, entry for entry: its components
// are +-1/2, so every product in the rotation matrix is exact and the comparison can be too.
TEST(HillFrames, QuaternionIsTheVectorMap) {
  const Mat3 c = q_lvlh_from_hill().toRotationMatrix();
  for (int i = 0; i < 3; ++i) EXPECT_EQ(Vec3(c.col(i)), lvlh_from_hill(Vec3::Unit(i))) << "axis " << i;
  EXPECT_EQ(c.determinant(), 1.0);
  EXPECT_EQ(q_hill_from_lvlh().coeffs(), q_lvlh_from_hill().conjugate().coeffs());
  EXPECT_EQ((q_hill_from_lvlh() * q_lvlh_from_hill()).coeffs(), Quat::Identity().coeffs());
}

// Round trips of positions, velocities and states are exact (no arithmetic, only moves and signs);
// an attitude carried through both quaternions comes back to within a few ulp (each component of a
// Hamilton product by (+-1/2, ...) is a sum of four exact halves, rounded once per addition).
TEST(HillFrames, RoundTrips) {
  const Vec3 r_hill_m(100.038, -0.0167, -0.023), v_hill_mps(-0.0076, 0.131, -0.0087);
  EXPECT_EQ(hill_from_lvlh(lvlh_from_hill(r_hill_m)), r_hill_m);
  EXPECT_EQ(lvlh_from_hill(hill_from_lvlh(v_hill_mps)), v_hill_mps);
  Vec6 x_hill;
  x_hill << r_hill_m, v_hill_mps;
  EXPECT_EQ(hill_state_from_lvlh(lvlh_state_from_hill(x_hill)), x_hill);
  EXPECT_EQ(lvlh_state_from_hill(x_hill).head<3>(), lvlh_from_hill(r_hill_m));
  EXPECT_EQ(lvlh_state_from_hill(x_hill).tail<3>(), lvlh_from_hill(v_hill_mps));
  const Quat q_hill_from_body = quat_from_rotation_vector(Vec3(0.3, -1.1, 0.7));
  const Quat back = q_hill_from_lvlh() * (q_lvlh_from_hill() * q_hill_from_body);
  EXPECT_LT((back.coeffs() - q_hill_from_body.coeffs()).cwiseAbs().maxCoeff(), 4.0 * kEps);
}

// The orbital rate is one vector seen in two frames: (0, -n, 0) in Hill is (0, 0, n) in LVLH,
// the rate at which a circular orbit's LVLH turns (model::TargetOrbit, tests/model).
TEST(HillFrames, OrbitRateIsOneVector) {
  EXPECT_EQ(lvlh_from_hill(omega_hill_in_hill(kN)), Vec3(0.0, 0.0, kN));
  EXPECT_EQ(q_lvlh_from_hill() * omega_hill_in_hill(kN), Vec3(0.0, 0.0, kN));
}

// The classic closed-form CW solution in the along-track / nadir frame (x'' = 2 n z',
// y'' = -n^2 y, z'' = -2 n x' + 3 n^2 z, Zhou 2018, eq. 2), written out independently here.
Vec6 cw_closed_form_hill(const Vec6& x0, double t) {
  const double n = kN, c = std::cos(n * t), s = std::sin(n * t);
  const double x = x0(0), y = x0(1), z = x0(2), vx = x0(3), vy = x0(4), vz = x0(5);
  Vec6 xt;
  xt << (4.0 * vx / n - 6.0 * z) * s - 2.0 * vz / n * c + (6.0 * n * z - 3.0 * vx) * t + x + 2.0 * vz / n,
      y * c + vy / n * s,
      (2.0 * vx / n - 3.0 * z) * c + vz / n * s + 4.0 * z - 2.0 * vx / n,
      (4.0 * vx - 6.0 * n * z) * c + 2.0 * vz * s + 6.0 * n * z - 3.0 * vx,
      -y * n * s + vy * c,
      -(2.0 * vx - 3.0 * n * z) * s + vz * c;
  return xt;
}

// Free HCW motion in the MSR frame (core/linear_models.hpp's transition, a matrix exponential),
// mapped into Hill, equals the Hill-frame closed form: the conversion carries the physics, not just
// the axes. From 1 s to half an orbit; 1e-9 relative is the exponential's rounding on transitions
// of norm up to ~1e4 (the same bound as tests/invsim/cw_transition_test.cpp).
TEST(HillFrames, HcwFreeMotionAgreesAcrossConventions) {
  Vec6 x0_hill;
  x0_hill << 100.038, -0.0167, -0.023, -0.0076, 0.131, -0.0087;  // Zhou 2018, Table 3
  for (const double t : {1.0, 100.0, 1300.0, 2777.0}) {
    const Vec6 x_lvlh = discrete_hcw(kN, t).Ad * lvlh_state_from_hill(x0_hill);
    const Vec6 expected = cw_closed_form_hill(x0_hill, t);
    EXPECT_LT((hill_state_from_lvlh(x_lvlh) - expected).norm(), 1e-9 * expected.norm()) << "t " << t;
  }
}

// The HCW vector field itself, mapped: MSR's x'' = 3 n^2 x + 2 n y' ... becomes eq. 2 of Zhou 2018
// in Hill components (equal to rounding of the single products).
TEST(HillFrames, HcwAccelerationMapsToZhouEq2) {
  const Vec3 r_hill_m(100.0, -2.0, 3.0), v_hill_mps(-0.1, 0.05, -0.02);
  const Vec3 a_hill = hill_from_lvlh(hcw_acceleration(kN, lvlh_from_hill(r_hill_m), lvlh_from_hill(v_hill_mps)));
  const Vec3 eq2(2.0 * kN * v_hill_mps.z(), -kN * kN * r_hill_m.y(),
                 -2.0 * kN * v_hill_mps.x() + 3.0 * kN * kN * r_hill_m.z());
  EXPECT_LT((a_hill - eq2).norm(), 4.0 * kEps * eq2.norm());
}

}  // namespace
}  // namespace chaser
