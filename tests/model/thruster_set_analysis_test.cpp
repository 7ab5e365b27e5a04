#include "model/thruster_set_analysis.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "core/random.hpp"
#include "model/thruster_geometry.hpp"
#include "tests/support/msr_branch_a.hpp"

namespace chaser::model {
namespace {

using Eigen::Vector3d;

struct Thruster {
  Vector3d position_m;  // [m] from the centre of mass, body axes
  Vector3d direction;   // thrust direction (normalised here)
  double thrust_N;      // [N]
};

// Column j = [F; r x F] of thruster j at full thrust: the definition of M in the header.
ThrusterSetMatrix matrix_of(const std::vector<Thruster>& set) {
  ThrusterSetMatrix m(6, static_cast<Eigen::Index>(set.size()));
  for (std::size_t j = 0; j < set.size(); ++j) {
    const Vector3d f = set[j].thrust_N * set[j].direction.normalized();
    m.col(static_cast<Eigen::Index>(j)) << f, set[j].position_m.cross(f);
  }
  return m;
}

double scale_of(const ThrusterSetMatrix& m) { return m.colwise().norm().maxCoeff(); }

// Closed-form set: for each force axis, two thrusters per sign at opposite lever arms d, so their
// torques cancel in pairs. x-pushers sit at +-d y (torque about z), y-pushers at +-d z (torque
// about x), z-pushers at +-d x (torque about y). Only the two thrusters pushing along +Fk have a
// positive Fk, and only two thrusters have a torque of a given sign about each axis, so the
// attainable values are exactly: +-Fk = 2 f_k, +-Cz = 2 d f_x, +-Cx = 2 d f_y, +-Cy = 2 d f_z.
constexpr double kD = 1.5;                   // [m]
constexpr double kF[3] = {10.0, 20.0, 5.0};  // [N] thrust of the x-, y-, z-pushers
std::vector<Thruster> axis_pair_set() {
  std::vector<Thruster> set;
  for (int k = 0; k < 3; ++k) {
    const Vector3d arm = kD * Vector3d::Unit((k + 1) % 3);
    for (const double sign : {1.0, -1.0})
      for (const double side : {1.0, -1.0})
        set.push_back({side * arm, sign * Vector3d::Unit(k), kF[k]});
  }
  return set;
}

// Every value of a, checked against its own certificate: on-times in [0, 1] and M u equal to the
// value along the axis and zero elsewhere. CLP's tolerances are 1e-12 of the column scale (the
// LP is solved on M / max column norm), so 1e-9 of the scale has three decades of margin.
void expect_certificates(const ThrusterSetMatrix& m, const AttainableAxes& a) {
  const double tol = 1e-9 * scale_of(m);
  for (int k = 0; k < kSignedAxes; ++k) {
    const auto i = static_cast<std::size_t>(k);
    ASSERT_EQ(a.on_times[i].size(), m.cols());
    EXPECT_GE(a.on_times[i].minCoeff(), -1e-9) << signed_axis_name(k);
    EXPECT_LE(a.on_times[i].maxCoeff(), 1.0 + 1e-9) << signed_axis_name(k);
    Eigen::Matrix<double, 6, 1> expected = Eigen::Matrix<double, 6, 1>::Zero();
    expected(k / 2) = (k % 2 == 0 ? 1.0 : -1.0) * a.value[i];
    EXPECT_LE((m * a.on_times[i] - expected).norm(), tol) << signed_axis_name(k);
  }
}

TEST(ThrusterSetAnalysis, AxisPairSetMatchesClosedForm) {
  const ThrusterSetMatrix m = matrix_of(axis_pair_set());
  const ThrusterSetAnalysis a = analyse_thruster_set(m);
  const double closed[6] = {2 * kF[0],      2 * kF[1],      2 * kF[2],
                            2 * kD * kF[1], 2 * kD * kF[2], 2 * kD * kF[0]};
  for (int k = 0; k < kSignedAxes; ++k)
    EXPECT_NEAR(a.axes.value[static_cast<std::size_t>(k)], closed[k / 2], 1e-9 * scale_of(m))
        << signed_axis_name(k);
  expect_certificates(m, a.axes);
  EXPECT_TRUE(a.spans);
  ASSERT_EQ(a.names.size(), 12u);
  EXPECT_EQ(a.names.front(), "T1");
  EXPECT_EQ(a.names.back(), "T12");
}

// Losing one thruster of the axis-pair set leaves its partner (same push, opposite torque) with
// no way to cancel its torque, so exactly two signed axes drop to zero: the thruster's own force
// axis and the sign of torque it supplied. The other ten keep their value (no other optimum used
// the lost thruster's column). Hence the set is not single-loss tolerant.
TEST(ThrusterSetAnalysis, AxisPairSetLosesTwoAxesPerThruster) {
  const ThrusterSetMatrix m = matrix_of(axis_pair_set());
  const ThrusterSetAnalysis a = analyse_thruster_set(m);
  EXPECT_FALSE(a.tolerates_single_loss);
  ASSERT_EQ(a.single_losses.size(), 12u);
  for (const SingleLossAnalysis& l : a.single_losses) {
    EXPECT_FALSE(l.spans) << l.name;
    EXPECT_EQ(l.shrink_ratio, 0.0) << l.name;
    const int force_axis = 2 * (l.lost / 4) + (m(l.lost / 4, l.lost) > 0 ? 0 : 1);
    const int torque_component = 3 + (l.lost / 4 + 2) % 3;  // x-pushers torque about z, ...
    const int torque_axis = 2 * torque_component + (m(torque_component, l.lost) > 0 ? 0 : 1);
    for (int k = 0; k < kSignedAxes; ++k) {
      const auto i = static_cast<std::size_t>(k);
      const bool lost_axis = k == force_axis || k == torque_axis;
      EXPECT_NEAR(l.axes.value[i], lost_axis ? 0.0 : a.axes.value[i], 1e-9 * scale_of(m))
          << l.name << " " << signed_axis_name(k);
    }
    expect_certificates(m, l.axes);
    for (int k = 0; k < kSignedAxes; ++k)  // held closed: CLP keeps a [0, 0] column at its bound
      EXPECT_EQ(l.axes.on_times[static_cast<std::size_t>(k)][l.lost], 0.0);
  }
}

// No column has a negative x force, so no combination pushes along -x: -Fx must be exactly 0
// (reported as 0, not a rounding residue) and the set cannot span, with or without any loss.
TEST(ThrusterSetAnalysis, SetThatCannotPushMinusXDoesNotSpan) {
  RandomStream rng(7, "thruster_set_analysis/no_minus_x");
  ThrusterSetMatrix m(6, 10);
  for (int j = 0; j < 10; ++j)
    for (int r = 0; r < 6; ++r) m(r, j) = 20.0 * rng.normal();
  m.row(0) = m.row(0).cwiseAbs();
  const ThrusterSetAnalysis a = analyse_thruster_set(m);
  EXPECT_FALSE(a.spans);
  EXPECT_EQ(a.axes.value[1], 0.0);  // -Fx
  EXPECT_TRUE(a.axes.on_times[1].isZero(0.0));
  EXPECT_FALSE(a.tolerates_single_loss);
  for (const SingleLossAnalysis& l : a.single_losses) EXPECT_EQ(l.axes.value[1], 0.0);
  expect_certificates(m, a.axes);
}

// The minimal positive spanning set {e_1..e_6, -(e_1+..+e_6)} (times 22): 7 = n + 1 vectors, the
// fewest that can span R^6 positively, so every loss breaks the span. Closed form (solving
// M u = t e_k by hand): all twelve values are 22; without e_k, +e_k and every -e_j (j != k) are 0
// and the rest stay 22; without the seventh column, every negative axis is 0.
TEST(ThrusterSetAnalysis, MinimalSpanningSetBreaksOnEveryLoss) {
  ThrusterSetMatrix m(6, 7);
  m << 22.0 * Eigen::Matrix<double, 6, 6>::Identity(), Eigen::Matrix<double, 6, 1>::Constant(-22.0);
  const ThrusterSetAnalysis a = analyse_thruster_set(m);
  EXPECT_TRUE(a.spans);
  EXPECT_FALSE(a.tolerates_single_loss);
  const double tol = 1e-9 * scale_of(m);
  for (int k = 0; k < kSignedAxes; ++k)
    EXPECT_NEAR(a.axes.value[static_cast<std::size_t>(k)], 22.0, tol);
  for (const SingleLossAnalysis& l : a.single_losses) {
    EXPECT_FALSE(l.spans) << l.name;
    EXPECT_EQ(l.shrink_ratio, 0.0) << l.name;
    for (int k = 0; k < kSignedAxes; ++k) {
      const bool positive = k % 2 == 0;
      const bool zero = l.lost == 6 ? !positive : (positive ? k / 2 == l.lost : k / 2 != l.lost);
      EXPECT_NEAR(l.axes.value[static_cast<std::size_t>(k)], zero ? 0.0 : 22.0, tol)
          << l.name << " " << signed_axis_name(k);
    }
  }
}

// The same fact on random minimal sets: six random columns B and a seventh -B w, w > 0, span R^6
// positively (B w + (-B w) = 0 with positive weights, rank 6) and no six of them do.
TEST(ThrusterSetAnalysis, RandomMinimalSpanningSetsBreakOnEveryLoss) {
  RandomStream rng(11, "thruster_set_analysis/minimal");
  for (int trial = 0; trial < 10; ++trial) {
    ThrusterSetMatrix m(6, 7);
    for (int j = 0; j < 6; ++j)
      for (int r = 0; r < 6; ++r) m(r, j) = 20.0 * rng.normal();
    Eigen::Matrix<double, 6, 1> w;
    for (int j = 0; j < 6; ++j) w(j) = rng.uniform(0.5, 2.0);
    m.col(6) = -m.leftCols(6) * w;
    const ThrusterSetAnalysis a = analyse_thruster_set(m);
    EXPECT_TRUE(a.spans) << trial;
    EXPECT_FALSE(a.tolerates_single_loss) << trial;
    for (int k = 0; k < kSignedAxes; ++k) EXPECT_GT(a.axes.value[static_cast<std::size_t>(k)], 0.0);
    for (const SingleLossAnalysis& l : a.single_losses) {
      EXPECT_FALSE(l.spans) << trial << " " << l.name;
      EXPECT_EQ(l.shrink_ratio, 0.0) << trial << " " << l.name;
    }
  }
}

// Second method, exact and independent of CLP: the optimum of a bounded feasible LP is attained
// at a vertex of its feasible set, and (when the equality rows have full rank r) every vertex is a
// basic solution: r "basic" on-times solve the equalities with the others each at 0 or 1. Here the
// equalities are the five wrench components other than the axis's (rank 5 almost surely for
// Gaussian columns), and t is the axis component of M u, so enumerating all C(N, 5) 2^(N-5) basic
// solutions and keeping the feasible ones gives the LP optimum exactly (up to 5x5 solve rounding).
// `lost` >= 0 holds that on-time at 0 (it is never basic).
double vertex_optimum(const ThrusterSetMatrix& m, int axis, int lost) {
  const int n = static_cast<int>(m.cols());
  const int c = axis / 2;
  const double sign = axis % 2 == 0 ? 1.0 : -1.0;
  Eigen::Matrix<double, 5, Eigen::Dynamic> rows(5, n);
  for (int r = 0, k = 0; r < 6; ++r)
    if (r != c) rows.row(k++) = m.row(r);
  double best = 0.0;  // u = 0 is always a vertex
  for (int basis = 0; basis < (1 << n); ++basis) {
    if (__builtin_popcount(static_cast<unsigned>(basis)) != 5 || (lost >= 0 && (basis >> lost) & 1))
      continue;
    Eigen::Matrix<double, 5, 5> b;
    for (int j = 0, k = 0; j < n; ++j)
      if ((basis >> j) & 1) b.col(k++) = rows.col(j);
    const Eigen::PartialPivLU<Eigen::Matrix<double, 5, 5>> lu(b);
    if (std::abs(lu.determinant()) < 1e-12 * std::pow(scale_of(m), 5)) continue;
    for (int at_one = 0; at_one < (1 << n); ++at_one) {
      if ((at_one & basis) != 0 || (lost >= 0 && (at_one >> lost) & 1)) continue;
      Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
      for (int j = 0; j < n; ++j) u(j) = (at_one >> j) & 1;
      const Eigen::Matrix<double, 5, 1> ub = lu.solve(-rows * u);
      if (ub.minCoeff() < -1e-12 || ub.maxCoeff() > 1.0 + 1e-12) continue;
      for (int j = 0, k = 0; j < n; ++j)
        if ((basis >> j) & 1) u(j) = ub(k++);
      best = std::max(best, sign * m.row(c).dot(u));
    }
  }
  return best;
}

// CLP's values equal the vertex optimum to 1e-9 of the column scale (both are exact up to rounding
// and CLP's 1e-12 tolerances; a wrong vertex would differ by a sizeable fraction of a column). A
// relative-to-scale bound is used because many values are 0, where a relative-to-value one is
// meaningless. Half the sets cannot push along -x (row 0 made non-negative) so zeros are covered.
TEST(ThrusterSetAnalysis, LpMatchesVertexEnumeration) {
  RandomStream rng(3, "thruster_set_analysis/vertices");
  for (int trial = 0; trial < 12; ++trial) {
    const int n = 6 + trial % 5;  // 6..10 thrusters
    ThrusterSetMatrix m(6, n);
    for (int j = 0; j < n; ++j)
      for (int r = 0; r < 6; ++r) m(r, j) = 20.0 * rng.normal();
    if (trial % 2 == 1) m.row(0) = m.row(0).cwiseAbs();
    const int lost = trial % 3 == 0 ? -1 : trial % n;
    const AttainableAxes a = attainable_axes(m, lost);
    expect_certificates(m, a);
    bool all_positive = true;
    for (int k = 0; k < kSignedAxes; ++k) {
      const double v = a.value[static_cast<std::size_t>(k)];
      EXPECT_NEAR(v, vertex_optimum(m, k, lost), 1e-9 * scale_of(m))
          << "trial " << trial << " " << signed_axis_name(k);
      all_positive = all_positive && v > 0.0;
    }
    // The cone of the columns holds every +-e_k iff it is all of R^6: the two tests must agree.
    if (lost < 0) {
      EXPECT_EQ(analyse_thruster_set(m).spans, all_positive) << "trial " << trial;
    }
  }
}

// MSR branch A (scenarios/msr_terminal.yaml, Fonod 2015 sec. II.B), from the shared test layout
// and the product's own configuration matrix: 22 N thrusters, centre of mass at the layout origin.
// T5..T8 mirror T1..T4 through the origin (same torque, opposite force), so the attainable set is
// symmetric under F -> -F: +Fk and -Fk must be equal (to the 1e-9 comparison tolerance above).
// The figures are printed for the record.
TEST(ThrusterSetAnalysis, MsrBranchASpans) {
  const ThrusterSetMatrix m = configuration_columns(testing::msr_branch_a_thrusters(), first_thrusters(8), Vec3::Zero());
  const ThrusterSetAnalysis a = analyse_thruster_set(m);
  EXPECT_TRUE(a.spans);
  expect_certificates(m, a.axes);
  for (int k = 0; k < kSignedAxes; ++k) EXPECT_GT(a.axes.value[static_cast<std::size_t>(k)], 0.0);
  for (int k = 0; k < 6; k += 2)
    EXPECT_NEAR(a.axes.value[k], a.axes.value[k + 1], 1e-9 * scale_of(m));
  for (int k = 0; k < kSignedAxes; ++k)  // the second method on this structured set too
    EXPECT_NEAR(a.axes.value[static_cast<std::size_t>(k)], vertex_optimum(m, k, -1),
                1e-9 * scale_of(m))
        << signed_axis_name(k);
  for (const SingleLossAnalysis& l : a.single_losses) {
    expect_certificates(m, l.axes);
    // positive_span (NNLS) and the twelve LPs are two methods for one fact: they must agree.
    const bool all_positive =
        std::all_of(l.axes.value.begin(), l.axes.value.end(), [](double v) { return v > 0.0; });
    EXPECT_EQ(l.spans, all_positive) << l.name;
  }
  // Both methods (NNLS span test and the LPs, which agree above) find losses that break the span:
  // one branch of eight has no spare thruster in every direction.
  EXPECT_FALSE(a.tolerates_single_loss);
  std::cout << format_thruster_set_analysis(a);
}

TEST(ThrusterSetAnalysis, JsonCarriesTheDocumentedKeys) {
  ThrusterSetMatrix m(6, 7);
  m << 22.0 * Eigen::Matrix<double, 6, 6>::Identity(), Eigen::Matrix<double, 6, 1>::Constant(-22.0);
  const ThrusterSetAnalysis a = analyse_thruster_set(m, {"A1", "A2", "A3", "A4", "A5", "A6", "A7"});
  const nlohmann::json j = nlohmann::json::parse(thruster_set_analysis_json(a));
  EXPECT_EQ(j.at("thrusters").size(), 7u);
  EXPECT_EQ(j.at("thrusters")[6], "A7");
  EXPECT_EQ(j.at("axes")[11], "-Cz");
  EXPECT_EQ(j.at("units").at("torque"), "N m");
  EXPECT_EQ(j.at("attainable").size(), 12u);
  EXPECT_EQ(j.at("attainable")[3].get<double>(), a.axes.value[3]);  // exact round trip
  EXPECT_TRUE(j.at("spans").get<bool>());
  EXPECT_FALSE(j.at("tolerates_single_loss").get<bool>());
  const nlohmann::json& loss = j.at("single_loss").at(0);
  EXPECT_EQ(loss.at("lost"), "A1");
  EXPECT_EQ(loss.at("index"), 0);
  EXPECT_FALSE(loss.at("spans").get<bool>());
  EXPECT_EQ(loss.at("shrink_ratio").get<double>(), 0.0);
  EXPECT_EQ(loss.at("shrink_axis"), signed_axis_name(a.single_losses[0].shrink_axis));

  const std::string text = format_thruster_set_analysis(a);
  for (const char* expected : {"without A7", "[N]", "[N m]", "+Cz", "Positively spans R^6"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
}

TEST(ThrusterSetAnalysis, RejectsMalformedInput) {
  EXPECT_THROW(analyse_thruster_set(ThrusterSetMatrix(6, 0)), std::invalid_argument);
  EXPECT_THROW(analyse_thruster_set(ThrusterSetMatrix::Ones(6, 33)), std::invalid_argument);
  EXPECT_THROW(analyse_thruster_set(ThrusterSetMatrix::Ones(6, 3), {"a", "b"}),
               std::invalid_argument);
  ThrusterSetMatrix nan = ThrusterSetMatrix::Ones(6, 3);
  nan(2, 1) = std::nan("");
  EXPECT_THROW(attainable_axes(nan), std::invalid_argument);
  EXPECT_THROW(signed_axis_name(12), std::out_of_range);
}

}  // namespace
}  // namespace chaser::model
