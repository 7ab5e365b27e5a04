#include "flight/fdi/deficit_isolation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "core/rotation.hpp"
#include "model/thruster_geometry.hpp"
#include "tests/support/deficit_24.hpp"
#include "tests/support/deficit_msr.hpp"

// Independent tests of the impulse-deficit isolation: synthetic windows generated with the model the
// header states (explicit Euler for the attitude, exact double integral for the position), checked
// against a dense weighted least-squares solve, exact recovery on noise-free data, partners, the
// false-alarm level and the decision schedule.
namespace chaser::flight::fdi {
namespace deficit_isolation_test {

using model::FaultKind;
constexpr int kN = 8;  // lanes: MSR branch A

// The MSR chaser's bank parameters (tests/support/deficit_msr.hpp).
DeficitIsolationParams msr_params() { return chaser::testing::msr_deficit_params(); }

struct Fault {
  FaultKind kind = FaultKind::kStuckOpen;
  int thruster = -1;  // -1: no fault
  int onset = 0;      // [sample] first period with the deficit
  double size = 0.0;  // [-] m of the loss (1 - m realised) or of the leak (on-time at least m)
};

double realised_ton(const Fault& f, int k, int i, double ton) {
  if (i != f.thruster || k < f.onset) return ton;
  switch (f.kind) {
    case FaultKind::kStuckOpen: return 1.0;
    case FaultKind::kStuckClosed: return 0.0;
    case FaultKind::kLoss: return (1.0 - f.size) * ton;
    case FaultKind::kLeak: return std::max(ton, f.size);
  }
  return ton;
}

struct Truth {
  int samples = 100;
  Fault fault;
  double command_probability = 0.35;
  std::function<void(int, WatchedTon&)> shape;  // edits the commands of sample k (closed-loop reactions)
  double gyro_sigma_radps = 0.0, lidar_sigma_m = 0.0, pulse_sigma = 0.0;  // truth noise (0: noise-free)
  std::uint64_t seed = 1;
};

// The header's model as truth: omega(k+1) = omega(k) + T I^-1 (M_C ton_real - omega x I omega), positions
// by the exact double integral of R(k) M_F ton_real(k) / m(k), a slow rotation R(k), a mass that drops.
std::vector<DeficitSample> generate(const DeficitIsolationParams& p, const Truth& t) {
  RandomStream cmd(t.seed, "deficit_test/commands"), noise(t.seed, "deficit_test/noise"), init(t.seed, "deficit_test/init");
  const Mat3& I = p.inertia_kgm2;
  const Mat3 I_inv = I.inverse();
  const double T = p.period_s;
  auto rand3 = [&](double s) { return Vec3(init.uniform(-s, s), init.uniform(-s, s), init.uniform(-s, s)); };
  Vec3 omega = rand3(1e-3), r = rand3(20.0), v = rand3(0.02);
  const Vec3 q0_vec = rand3(2.0), spin = Vec3(1.0, 2.0, 3.0).normalized() * 0.02;  // [rad/s] slow rotation
  double mass = p.mass_kg;
  std::vector<DeficitSample> out;
  for (int k = 0; k < t.samples; ++k) {
    WatchedTon ton = WatchedTon::Zero();
    for (int i = 0; i < p.lanes; ++i)
      if (cmd.uniform() < t.command_probability) ton(i) = cmd.uniform(0.05, 0.95);
    if (t.shape) t.shape(k, ton);
    DeficitSample s;
    s.q_lvlh_from_body = quat_from_rotation_vector(spin * (k * T)) * quat_from_rotation_vector(q0_vec);
    s.ton = ton;
    s.mass_kg = mass;
    s.omega_body_radps = omega + t.gyro_sigma_radps * Vec3(noise.normal(), noise.normal(), noise.normal());
    s.r_lvlh_m = r + t.lidar_sigma_m * Vec3(noise.normal(), noise.normal(), noise.normal());
    out.push_back(s);
    WatchedTon real = WatchedTon::Zero();
    for (int i = 0; i < p.lanes; ++i) {
      real(i) = realised_ton(t.fault, k, i, ton(i));
      if (real(i) > 0.0) real(i) *= 1.0 + t.pulse_sigma * noise.normal();
    }
    const Vec3 acc = s.q_lvlh_from_body.toRotationMatrix() * p.force_body_N * real / mass;
    const Vec3 torque = p.torque_body_Nm * real;
    r += T * v + 0.5 * T * T * acc;
    v += T * acc;
    omega += T * I_inv * (torque - omega.cross(I * omega));
    mass -= 2e-3;  // [kg] the measured propellant used, known on board
  }
  return out;
}

// Pushes samples [0, count) as flight/fdir.cpp does: the bank is frozen once the alarm sample is in.
DeficitBankState fill_bank(const DeficitIsolationParams& p, const std::vector<DeficitSample>& s, int count,
                           int freeze_after = 1 << 30) {
  DeficitBankState bank;
  for (int k = 0; k < count; ++k) {
    push_deficit_sample(p, bank, s[k]);
    if (k == freeze_after) bank.frozen = true;
  }
  return bank;
}

Vec3 torque_row(const DeficitIsolationParams& p, const DeficitSample& a, const DeficitSample& b) {
  const Mat3& I = p.inertia_kgm2;
  return I * (b.omega_body_radps - a.omega_body_radps) / p.period_s +
         a.omega_body_radps.cross(I * a.omega_body_radps) - p.torque_body_Nm * a.ton;
}

// sigma_0^2 replicated from the header: EW mean square of the fault-free torque rows, started at and
// never below the gyro floor (I_ii sqrt(2) sigma_gyro / T)^2 (diagonal inertia here).
Vec3 replicate_sigma0_sq(const DeficitIsolationParams& p, const std::vector<DeficitSample>& s, int count,
                         int freeze_after) {
  const double g = std::sqrt(2.0) * p.gyro_sigma_radps / p.period_s;
  const Vec3 floor = p.inertia_kgm2.diagonal().cwiseAbs2() * g * g;
  const double alpha = std::min(1.0, p.period_s / p.noise_time_constant_s);
  Vec3 ms = floor;
  for (int q = 1; q < count && q <= freeze_after; ++q) {  // frozen after pushing freeze_after
    const Vec3 y = torque_row(p, s[q - 1], s[q]);
    ms += alpha * (y.cwiseAbs2() - ms);
  }
  return ms.cwiseMax(floor);
}

struct DenseResult {
  double rss = 0, a = 0, b = 0;
};

// The weighted least-squares problem written out densely: unknowns r0, v0 (6) and those of (a, b) in use
// for hypothesis i with onset kf (window-relative), rows as the header states, solved by QR.
DenseResult dense_fit(const DeficitIsolationParams& p, const std::vector<DeficitSample>& s, int first, int n,
                      const Vec3& sigma0_sq, int i, int kf, bool use_a, bool use_b) {
  const int cols = 6 + use_a + use_b, rows = 3 * n + 3 * (n - 1) + use_a + use_b;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(rows, cols);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(rows);
  const double T = p.period_s, wp = 1.0 / p.lidar_sigma_m;
  const int ca = 6, cb = 6 + use_a;
  int row = 0;
  for (int k = 0; k < n; ++k) {
    Vec3 known = Vec3::Zero(), col_a = Vec3::Zero(), col_b = Vec3::Zero();
    for (int j = 0; j < k; ++j) {
      const DeficitSample& sj = s[first + j];
      const DeficitMat3W f = sj.q_lvlh_from_body.toRotationMatrix() * p.force_body_N / sj.mass_kg;
      const double c = T * T * (k - j - 0.5);
      known += c * f * sj.ton;
      if (j >= kf) col_a += c * f.col(i), col_b += c * f.col(i) * sj.ton(i);
    }
    for (int ax = 0; ax < 3; ++ax, ++row) {
      A(row, ax) = wp, A(row, 3 + ax) = wp * k * T;
      if (use_a) A(row, ca) = wp * col_a(ax);
      if (use_b) A(row, cb) = wp * col_b(ax);
      y(row) = wp * (s[first + k].r_lvlh_m(ax) - known(ax));
    }
  }
  for (int k = 0; k + 1 < n; ++k) {
    const DeficitSample& sk = s[first + k];
    const Vec3 yt = torque_row(p, sk, s[first + k + 1]);
    for (int ax = 0; ax < 3; ++ax, ++row) {
      const double pulse = p.pulse_uncertainty * p.torque_body_Nm.row(ax).cwiseAbs().dot(sk.ton);
      const double w = 1.0 / std::sqrt(sigma0_sq(ax) + pulse * pulse);
      const double c = k >= kf ? p.torque_body_Nm(ax, i) : 0.0;
      if (use_a) A(row, ca) = w * c;
      if (use_b) A(row, cb) = w * c * sk.ton(i);
      y(row) = w * yt(ax);
    }
  }
  if (use_a) A(row++, ca) = 1.0 / p.prior_sigma;  // prior rows, target 0
  if (use_b) A(row++, cb) = 1.0 / p.prior_sigma;
  const Eigen::VectorXd x = A.colPivHouseholderQr().solve(y);
  DenseResult r;
  r.rss = (y - A * x).squaredNorm();
  if (use_a) r.a = x(ca);
  if (use_b) r.b = x(cb);
  return r;
}

// The constrained optimum (a >= 0, b <= 0) by dense solves: interior if feasible, else the best face or 0.
DenseResult dense_constrained_gain(const DeficitIsolationParams& p, const std::vector<DeficitSample>& s, int first,
                                   int n, const Vec3& sigma0_sq, int i, int kf, double rss0) {
  const DenseResult full = dense_fit(p, s, first, n, sigma0_sq, i, kf, true, true);
  if (full.a >= 0.0 && full.b <= 0.0) return {rss0 - full.rss, full.a, full.b};
  DenseResult best{0.0, 0.0, 0.0};
  const DenseResult fa = dense_fit(p, s, first, n, sigma0_sq, i, kf, true, false);
  if (fa.a >= 0.0 && rss0 - fa.rss > best.rss) best = {rss0 - fa.rss, fa.a, 0.0};
  const DenseResult fb = dense_fit(p, s, first, n, sigma0_sq, i, kf, false, true);
  if (fb.b <= 0.0 && rss0 - fb.rss > best.rss) best = {rss0 - fb.rss, 0.0, fb.b};
  return best;
}

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

int best_of(const DeficitVecW& gain, int lanes = kN) {
  int best = 0;
  for (int i = 1; i < lanes; ++i)
    if (gain(i) > gain(best)) best = i;
  return best;
}

double second_of(const DeficitVecW& gain, int lanes = kN) {
  const int best = best_of(gain, lanes);
  double second = -1.0;
  for (int i = 0; i < lanes; ++i)
    if (i != best) second = std::max(second, gain(i));
  return second;
}

// The on-board sequence: push, freeze at the alarm (flight/fdir.cpp), step the decision each period.
struct Flow {
  DeficitBankState bank;
  DeficitDecisionState state;
  std::int64_t decided_at = -1;  // sample index of the period the decision was made
};

Flow run_flow(const DeficitIsolationParams& p, const std::vector<DeficitSample>& s, std::int64_t alarm) {
  Flow f;
  for (int k = 0; k < static_cast<int>(s.size()); ++k) {
    push_deficit_sample(p, f.bank, s[k]);
    if (k == alarm) f.bank.frozen = true;
    const DeficitDecision& d = step_deficit_decision(p, f.bank, f.state, k >= alarm ? alarm : -1);
    if (d.decided) {
      f.decided_at = k;
      break;
    }
  }
  return f;
}

// Sensor noise at the parameters' sigmas and pulse errors at epsilon.
Truth noisy_truth(const DeficitIsolationParams& p, std::uint64_t seed) {
  Truth t;
  t.gyro_sigma_radps = p.gyro_sigma_radps, t.lidar_sigma_m = p.lidar_sigma_m, t.pulse_sigma = p.pulse_uncertainty;
  t.seed = seed;
  return t;
}

// ---------------------------------------------------------------------------------------------------

// sigma_0: the bank's EW estimate equals the header's recursion (started at the gyro floor, stops when
// frozen). Both compute the same sums in nearly the same order: 1e-12 relative.
TEST(DeficitIsolation, NoiseEstimateFollowsHeaderRecursion) {
  DeficitIsolationParams p = msr_params();
  p.noise_time_constant_s = 2.0;
  const std::vector<DeficitSample> s = generate(p, noisy_truth(p, 3));
  for (int freeze : {40, 1 << 30}) {
    const DeficitBankState bank = fill_bank(p, s, 100, freeze);
    const Vec3 expected = replicate_sigma0_sq(p, s, 100, freeze);
    for (int ax = 0; ax < 3; ++ax) EXPECT_NEAR(bank.torque_mean_square(ax), expected(ax), 1e-12 * expected(ax));
    // The torque row noise is I_ii sqrt(2) sigma_gyro / T plus pulse errors: sigma_0 is above the floor.
    EXPECT_GT(expected(0), std::pow(2000.0 * std::sqrt(2.0) * 1e-6 / 0.1, 2));
  }
}

// 1a. Against a dense solve, one onset (last_onset = first): gain = RSS_no_fault - RSS_i with all
// unknowns (r0, v0, a, b) explicit and the prior rows. A stuck-open thruster that is still commanded
// has a = 1, b = -1: the optimum is interior. The closed-form projection and the QR solve differ by
// rounding only: 1e-8 relative to the RSS they subtract.
TEST(DeficitIsolation, GainEqualsDenseRssDropSingleOnset) {
  DeficitIsolationParams p = msr_params();
  p.noise_time_constant_s = 2.0;
  Truth t = noisy_truth(p, 11);
  t.samples = 90, t.fault = {FaultKind::kStuckOpen, 2, 60, 0.0};
  const std::vector<DeficitSample> s = generate(p, t);
  const int alarm = 63, first = 60, n = 90 - first;
  const DeficitBankState bank = fill_bank(p, s, 90, alarm);
  const Vec3 sigma0_sq = replicate_sigma0_sq(p, s, 90, alarm);
  const DeficitHypotheses h = evaluate_deficit_hypotheses(p, bank, first, first);
  const double rss0 = dense_fit(p, s, first, n, sigma0_sq, 0, 0, false, false).rss;
  EXPECT_EQ(h.rows, 3 * n + 3 * (n - 1));
  EXPECT_NEAR(h.rss_no_fault, rss0, 1e-8 * rss0);
  for (int i = 0; i < kN; ++i) {
    const DenseResult full = dense_fit(p, s, first, n, sigma0_sq, i, 0, true, true);
    if (i == 2) {
      ASSERT_TRUE(full.a >= 0.0 && full.b <= 0.0) << "the true hypothesis must be interior";
    }
    if (!(full.a >= 0.0 && full.b <= 0.0)) continue;
    EXPECT_NEAR(h.gain(i), rss0 - full.rss, 1e-8 * rss0) << "thruster " << i;
    EXPECT_NEAR(h.a(i), full.a, 1e-7) << "thruster " << i;
    EXPECT_NEAR(h.b(i), full.b, 1e-7) << "thruster " << i;
    EXPECT_EQ(h.onset[i], first);
  }
  EXPECT_EQ(best_of(h.gain), 2);
  EXPECT_NEAR(h.a(2), 1.0, 0.05);  // noise at the stated sigmas: a, b within a few percent
  EXPECT_NEAR(h.b(2), -1.0, 0.05);
}

// 1b. Same comparison with an onset scan: every hypothesis' gain is the max over onsets of the
// constrained dense optimum (interior, a face, or 0), and for the true one its onset and (a, b) too.
// The same on the 24-thruster set (tests/support/deficit_24.hpp): the lanes past MSR's eight are
// fitted as the first eight are.
void expect_gains_equal_dense_max_over_onsets(DeficitIsolationParams p, const std::vector<Fault>& faults,
                                              double& worst) {
  const int kN = p.lanes;
  p.noise_time_constant_s = 2.0;
  for (const Fault& fault : faults) {
    Truth t = noisy_truth(p, 12);
    t.samples = 95, t.fault = fault;
    t.shape = [&](int k, WatchedTon& ton) {
      if (k == 59 || k == 60) ton(fault.thruster) = 0.8;  // commanded about the onset: identifiable
    };
    const std::vector<DeficitSample> s = generate(p, t);
    const int alarm = 64, first = 44, last_onset = 70, n = 95 - first;
    const DeficitBankState bank = fill_bank(p, s, 95, alarm);
    const Vec3 sigma0_sq = replicate_sigma0_sq(p, s, 95, alarm);
    const DeficitHypotheses h = evaluate_deficit_hypotheses(p, bank, first, last_onset);
    const double rss0 = dense_fit(p, s, first, n, sigma0_sq, 0, 0, false, false).rss;
    for (int i = 0; i < kN; ++i) {
      DenseResult best{-1.0, 0.0, 0.0};
      int best_kf = -1;
      for (int kf = 0; kf <= last_onset - first; ++kf) {
        const DenseResult r = dense_constrained_gain(p, s, first, n, sigma0_sq, i, kf, rss0);
        if (r.rss > best.rss) best = r, best_kf = kf;
      }
      EXPECT_NEAR(h.gain(i), best.rss, 1e-8 * rss0) << "thruster " << i;
      EXPECT_GE(h.gain(i), 0.0);
      worst = std::max(worst, std::abs(h.gain(i) - best.rss) / rss0);
      if (i == fault.thruster) {
        EXPECT_EQ(h.onset[i], first + best_kf);
        EXPECT_NEAR(h.a(i), best.a, 1e-7);
        EXPECT_NEAR(h.b(i), best.b, 1e-7);
      }
    }
    EXPECT_EQ(best_of(h.gain, kN), fault.thruster);
    EXPECT_EQ(h.onset[fault.thruster], 60);
  }
}

TEST(DeficitIsolation, GainEqualsDenseConstrainedMaxOverOnsets) {
  double worst = 0.0;  // largest |gain - dense| / RSS_no_fault
  expect_gains_equal_dense_max_over_onsets(
      msr_params(), {Fault{FaultKind::kStuckOpen, 5, 60, 0.0}, Fault{FaultKind::kLoss, 1, 60, 0.5}}, worst);
  RecordProperty("worst_relative_gain_difference", sci(worst));
}

TEST(DeficitIsolation, TwentyFourThrustersGainEqualsDenseConstrainedMaxOverOnsets) {
  double worst = 0.0;
  expect_gains_equal_dense_max_over_onsets(
      chaser::testing::box_24_deficit_params(),
      {Fault{FaultKind::kStuckOpen, 17, 60, 0.0}, Fault{FaultKind::kLoss, 9, 60, 0.5},
       Fault{FaultKind::kStuckClosed, 23, 60, 0.0}},
      worst);
  RecordProperty("worst_relative_gain_difference", sci(worst));
}

// The ring: a window evaluated after the ring has wrapped (count > kMaxDeficitWindow) equals the same
// samples pushed into a fresh bank (same sigma_0), with sample indices shifted. Same arithmetic on the
// same numbers: 1e-12 relative.
TEST(DeficitIsolation, RingWrapDoesNotChangeTheFit) {
  const DeficitIsolationParams p = msr_params();
  Truth t = noisy_truth(p, 13);
  t.samples = 300, t.fault = {FaultKind::kLoss, 4, 230, 0.6};
  const std::vector<DeficitSample> s = generate(p, t);
  const int shift = 150;
  const DeficitBankState wrapped = fill_bank(p, s, 300, 228);
  DeficitBankState fresh;
  for (int k = shift; k < 300; ++k) push_deficit_sample(p, fresh, s[k]);
  fresh.torque_mean_square = wrapped.torque_mean_square;
  fresh.torque_mean_square_lagged = wrapped.torque_mean_square_lagged;
  const DeficitHypotheses hw = evaluate_deficit_hypotheses(p, wrapped, 210, 240);
  const DeficitHypotheses hf = evaluate_deficit_hypotheses(p, fresh, 210 - shift, 240 - shift);
  EXPECT_EQ(hw.rows, 6 * 90 - 3);
  EXPECT_NEAR(hw.rss_no_fault, hf.rss_no_fault, 1e-12 * hf.rss_no_fault);
  for (int i = 0; i < kN; ++i) {
    EXPECT_NEAR(hw.gain(i), hf.gain(i), 1e-12 * hf.rss_no_fault) << i;
    EXPECT_EQ(hw.onset[i], hf.onset[i] + shift) << i;
  }
  EXPECT_EQ(best_of(hw.gain), 4);
  // A first sample the ring no longer holds is moved up to the oldest one held.
  const DeficitHypotheses clipped = evaluate_deficit_hypotheses(p, wrapped, 0, 240);
  EXPECT_EQ(clipped.rows, 6 * kMaxDeficitWindow - 3);
}

// fit_deficit against the KKT conditions of max 2 g'x - x'Hx over a >= 0, b <= 0 (a convex problem:
// KKT is necessary and sufficient). Random H (positive definite) and g; 1e-9 relative on gradients.
TEST(DeficitIsolation, FitSatisfiesKktConditions) {
  RandomStream rng(5, "deficit_test/kkt");
  for (int n = 0; n < 2000; ++n) {
    const double l1 = rng.uniform(0.01, 100.0), l2 = rng.uniform(0.01, 100.0), th = rng.uniform(0.0, 3.2);
    const double c = std::cos(th), s = std::sin(th);
    DeficitNormal ne{l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c, rng.uniform(-50.0, 50.0),
                     rng.uniform(-50.0, 50.0)};
    const DeficitFit f = fit_deficit(ne);
    const double da = ne.ga - ne.haa * f.a - ne.hab * f.b, db = ne.gb - ne.hab * f.a - ne.hbb * f.b;
    const double tol = 1e-9 * (std::abs(ne.ga) + std::abs(ne.gb) + 100.0);
    ASSERT_GE(f.a, 0.0);
    ASSERT_LE(f.b, 0.0);
    if (f.a > 0.0) EXPECT_NEAR(da, 0.0, tol); else EXPECT_LE(da, tol);
    if (f.b < 0.0) EXPECT_NEAR(db, 0.0, tol); else EXPECT_GE(db, -tol);
    const double value = 2.0 * (ne.ga * f.a + ne.gb * f.b) -
                         (ne.haa * f.a * f.a + 2.0 * ne.hab * f.a * f.b + ne.hbb * f.b * f.b);
    EXPECT_NEAR(f.gain, value, 1e-9 * std::max(1.0, std::abs(value)));
  }
}

// fit_deficits, the detector's fits in one vectorised loop, on every kind of normal equations:
// free optimum feasible, on the a >= 0 face, on the b <= 0 face, at the origin, and singular H (a
// thruster never commanded in the window: hbb = hab = gb = 0). Each lane satisfies the KKT
// conditions above (checked independently, 1e-9 relative) and equals fit_deficit bit for bit: the
// vectorised loop must not change the lane arithmetic (as reassociation or contraction would).
// Every case must be reached. Lane counts: MSR's 8, COMRADE's 24, the capacity 32, and an odd 5
// (a vector loop's remainder).
TEST(DeficitIsolation, EightFitsSatisfyKktAndEqualTheScalarFit) {
  RandomStream rng(7, "fit_deficits");
  std::array<int, 5> reached{};  // free, a face, b face, origin, singular
  for (int trial = 0; trial < 500; ++trial) {
    const int kN = std::array{8, 24, kMaxWatchedThrusters, 5}[static_cast<std::size_t>(trial % 4)];
    DeficitNormalsW normals;
    for (int i = 0; i < kN; ++i) {
      const double u1 = rng.uniform(0.0, 1.0), u2 = rng.uniform(0.0, 1.0), w = rng.uniform(0.1, 10.0);
      const bool never_commanded = (trial + i) % 11 == 0;
      // H = w [1 u; u u^2] summed over two rows: positive definite unless u1 = u2 (or no command).
      const double haa = 2 * w, hab = never_commanded ? 0.0 : w * (u1 + u2);
      const double hbb = never_commanded ? 0.0 : w * (u1 * u1 + u2 * u2);
      normals.row(i) << haa, hab, hbb, rng.uniform(-5.0, 5.0), never_commanded ? 0.0 : rng.uniform(-5.0, 5.0);
    }
    const DeficitFits fits = fit_deficits(normals, kN);
    for (int i = 0; i < kN; ++i) {
      const auto r = normals.row(i);
      const DeficitNormal ne{r(0), r(1), r(2), r(3), r(4)};
      const DeficitFit one = fit_deficit(ne);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(fits.a(i)), std::bit_cast<std::uint64_t>(one.a)) << trial << " " << i;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(fits.b(i)), std::bit_cast<std::uint64_t>(one.b)) << trial << " " << i;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(fits.gain(i)), std::bit_cast<std::uint64_t>(one.gain)) << trial << " " << i;
      const double da = ne.ga - ne.haa * one.a - ne.hab * one.b, db = ne.gb - ne.hab * one.a - ne.hbb * one.b;
      // 1e-9 of the terms that form the gradient: with u1 close to u2, H is nearly singular and
      // (a, b) large, so the gradient is a small difference of large terms.
      const double terms = std::abs(ne.ga) + std::abs(ne.gb) + (ne.haa + 2 * std::abs(ne.hab) + ne.hbb) * (one.a - one.b);
      const double tol = 1e-9 * (terms + 10.0);
      ASSERT_GE(one.a, 0.0);
      ASSERT_LE(one.b, 0.0);
      if (one.a > 0.0) EXPECT_NEAR(da, 0.0, tol); else EXPECT_LE(da, tol);
      if (one.b < 0.0) EXPECT_NEAR(db, 0.0, tol); else EXPECT_GE(db, -tol);
      ++reached[ne.hbb == 0.0 ? 4 : one.a > 0 && one.b < 0 ? 0 : one.a > 0 ? 1 : one.b < 0 ? 2 : 3];
    }
  }
  for (int kind = 0; kind < 5; ++kind) EXPECT_GT(reached[kind], 20) << "case " << kind << " barely tested";
}

struct Case {
  Fault fault;
  bool silence;  // the thruster is not commanded from 3 periods before the onset (closed-loop reaction)
  double a, b;   // expected
};

// 2. Exactness: noise-free windows of the header's model, each fault case on several thrusters: the
// true hypothesis leaves zero residual, so it is isolated with (a, b) and the onset exact. The prior's
// pull is (H + P)^-1 P x with P = 1/prior_sigma^2; at prior_sigma = 1e4 it is far below 1e-6.
TEST(DeficitIsolation, ExactRecoveryNoiseFree) {
  DeficitIsolationParams p = msr_params();
  p.prior_sigma = 1e4;
  const int onset = 50;
  for (int thruster : {0, 3, 5, 6}) {
    const std::vector<Case> cases = {{{FaultKind::kStuckOpen, thruster, onset, 0.0}, true, 1.0, 0.0},
                                     {{FaultKind::kStuckOpen, thruster, onset, 0.0}, false, 1.0, -1.0},
                                     {{FaultKind::kStuckClosed, thruster, onset, 0.0}, false, 0.0, -1.0},
                                     {{FaultKind::kLoss, thruster, onset, 0.4}, false, 0.0, -0.4},
                                     {{FaultKind::kLeak, thruster, onset, 0.2}, true, 0.2, 0.0}};
    for (const Case& c : cases) {
      Truth t;
      t.samples = 80, t.fault = c.fault, t.seed = 100 + thruster;
      t.shape = [&](int k, WatchedTon& ton) {
        if (c.silence && k >= onset - 3) ton(thruster) = 0.0;
        if (!c.silence && (k == onset - 1 || k == onset)) ton(thruster) = 0.6;
      };
      const std::vector<DeficitSample> s = generate(p, t);
      const DeficitBankState bank = fill_bank(p, s, 80, onset);
      const DeficitHypotheses h = evaluate_deficit_hypotheses(p, bank, 30, 62);
      const std::string what = "thruster " + std::to_string(thruster) + " case " +
                               std::string(model::to_string(c.fault.kind)) + (c.silence ? " silenced" : "");
      ASSERT_EQ(best_of(h.gain), thruster) << what;
      EXPECT_NEAR(h.a(thruster), c.a, 1e-6) << what;
      EXPECT_NEAR(h.b(thruster), c.b, 1e-6) << what;
      EXPECT_EQ(h.onset[thruster], onset) << what;
      // Zero residual: the gain is the whole no-fault RSS (less the prior's tiny share).
      EXPECT_NEAR(h.gain(thruster), h.rss_no_fault, 1e-6 * h.rss_no_fault) << what;
      EXPECT_GT(h.gain(thruster) - second_of(h.gain), p.min_margin) << what;
    }
  }
}

// 2b. The same cases through the decision with the default parameters (alarm 2 periods after the
// onset): the fault case and size read from (a, b). Size within 1e-5: the prior's bias
// (H + P)^-1 P x at prior_sigma = 10, with H lowered by the two faulty torque rows that enter sigma_0
// before the freeze, is about 2e-7 here.
TEST(DeficitIsolation, DecisionNamesCaseAndSizeNoiseFree) {
  const DeficitIsolationParams p = msr_params();
  const int onset = 120;
  struct Expect {
    Fault fault;
    bool silence;
    FaultKind kind;
    double size;
  };
  double worst = 0.0;  // largest size error
  for (int thruster : {1, 4, 7}) {
    for (const Expect& e : {Expect{{FaultKind::kStuckOpen, thruster, onset, 0.0}, true, FaultKind::kStuckOpen, 1.0},
                            Expect{{FaultKind::kStuckClosed, thruster, onset, 0.0}, false, FaultKind::kStuckClosed, 1.0},
                            Expect{{FaultKind::kLoss, thruster, onset, 0.5}, false, FaultKind::kLoss, 0.5},
                            Expect{{FaultKind::kLeak, thruster, onset, 0.25}, true, FaultKind::kLeak, 0.25}}) {
      Truth t;
      t.samples = 200, t.fault = e.fault, t.seed = 200 + thruster;
      t.shape = [&](int k, WatchedTon& ton) {
        if (e.silence && k >= onset - 3) ton(thruster) = 0.0;
        if (!e.silence && (k == onset - 1 || k == onset)) ton(thruster) = 0.6;
      };
      const Flow f = run_flow(p, generate(p, t), onset + 2);
      const std::string what = "thruster " + std::to_string(thruster) + " " + std::string(model::to_string(e.kind));
      ASSERT_EQ(f.decided_at, onset + 2 + p.after) << what;
      const DeficitDecision& d = f.state.decision;
      EXPECT_EQ(d.thruster, thruster) << what;
      EXPECT_EQ(d.kind, e.kind) << what;
      EXPECT_NEAR(d.size, e.size, 1e-5) << what;
      worst = std::max(worst, std::abs(d.size - e.size));
      EXPECT_EQ(d.onset_sample, onset) << what;
    }
  }
  RecordProperty("worst_size_error", sci(worst));
}

// 2c. A 24-thruster set (tests/support/deficit_24.hpp), sensor noise at the stated sigmas and pulse
// errors at epsilon, the on-board sequence (push, freeze at the alarm, decide): each fault case on
// thrusters spread over the set, including the last lane, is named, with its kind, and not its
// partner (same torque: only the position rows tell them apart).
TEST(DeficitIsolation, TwentyFourThrustersDecisionNamesTheFaultyThruster) {
  const DeficitIsolationParams p = chaser::testing::box_24_deficit_params();
  ASSERT_TRUE(validate(p).empty());
  const int onset = 120, alarm = 123;
  for (int thruster : {0, 5, 11, 16, 23}) {
    const int partner = chaser::testing::box_24_partner(thruster);
    ASSERT_TRUE(p.torque_body_Nm.col(thruster).isApprox(p.torque_body_Nm.col(partner), 1e-12));
    ASSERT_TRUE(p.force_body_N.col(thruster).isApprox(-p.force_body_N.col(partner), 1e-12));
    for (const Fault& fault : {Fault{FaultKind::kStuckOpen, thruster, onset, 0.0},
                               Fault{FaultKind::kStuckClosed, thruster, onset, 0.0},
                               Fault{FaultKind::kLoss, thruster, onset, 0.6}}) {
      Truth t = noisy_truth(p, 300 + static_cast<std::uint64_t>(thruster));
      t.samples = 320, t.fault = fault;
      const bool open = fault.kind == FaultKind::kStuckOpen;
      t.shape = [&](int k, WatchedTon& ton) {
        if (open && k >= alarm) ton(thruster) = 0.0;  // the controller stops commanding it
        if (!open && k >= onset && k < onset + 30 && k % 3 == 0) ton(thruster) = 0.6;  // it is needed
      };
      const Flow f = run_flow(p, generate(p, t), alarm);
      const std::string what = "T" + std::to_string(thruster + 1) + " " + std::string(model::to_string(fault.kind));
      ASSERT_GE(f.decided_at, 0) << what;
      const DeficitDecision& d = f.state.decision;
      EXPECT_EQ(d.thruster, thruster) << what << " gain " << d.gain << " margin " << d.margin;
      EXPECT_EQ(d.kind, fault.kind) << what << " a " << d.a << " b " << d.b;
    }
  }
}

// 3. Partners (same torque, opposite force): stuck open on i and on i + 4, both silenced by the
// controller from the alarm on so that only the position rows tell them apart, noise at the stated
// sigmas and pulse errors at epsilon; every pair, several seeds.
TEST(DeficitIsolation, PartnersToldApartWithNoise) {
  const DeficitIsolationParams p = msr_params();
  const int onset = 100, alarm = 103;
  double min_margin = 1e300;
  for (std::uint64_t seed : {21u, 22u, 23u}) {
    for (int thruster = 0; thruster < kN; ++thruster) {
      const int partner = (thruster + 4) % kN;
      ASSERT_TRUE(p.torque_body_Nm.col(thruster).isApprox(p.torque_body_Nm.col(partner), 1e-12));
      ASSERT_TRUE(p.force_body_N.col(thruster).isApprox(-p.force_body_N.col(partner), 1e-12));
      Truth t = noisy_truth(p, seed);
      t.samples = 200, t.fault = {FaultKind::kStuckOpen, thruster, onset, 0.0};
      t.shape = [&](int k, WatchedTon& ton) {
        if (k >= alarm) ton(thruster) = ton(partner) = 0.0;
      };
      const Flow f = run_flow(p, generate(p, t), alarm);
      const DeficitDecision& d = f.state.decision;
      ASSERT_TRUE(d.decided);
      EXPECT_EQ(d.thruster, thruster) << "seed " << seed;
      EXPECT_EQ(d.kind, FaultKind::kStuckOpen) << "seed " << seed;
      EXPECT_GE(d.margin, p.min_margin) << "seed " << seed;
      EXPECT_NEAR(d.onset_sample, onset, 1) << "seed " << seed;
      min_margin = std::min(min_margin, d.margin);
    }
  }
  RecordProperty("smallest_partner_margin", sci(min_margin));
}

// 4. No fault, noise at the stated sigmas: each gain is a constrained 2-parameter GLR, at most a
// chi-square(2) variable (tail exp(-x/2)) when the weights are right (they are conservative here);
// over 8 hypotheses x 21 onsets the union bound gives P(max > 50) < 168 e^-25 ~ 2e-9 per window. The
// decision waits for the window to be exhausted and names no thruster.
TEST(DeficitIsolation, NoFaultStaysQuietAndNamesNone) {
  const DeficitIsolationParams p = msr_params();
  const int alarm = 100;  // a spurious alarm
  double worst = 0.0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    Truth t = noisy_truth(p, 300 + seed);
    t.samples = 260;
    const std::vector<DeficitSample> s = generate(p, t);
    const Flow f = run_flow(p, s, alarm);
    const DeficitDecision& d = f.state.decision;
    ASSERT_TRUE(d.decided);
    EXPECT_EQ(d.thruster, -1) << "seed " << seed;
    const std::int64_t first = alarm - p.before;
    // Exhausted: the first evaluation time alarm + after + j reevaluate_every whose window cannot grow.
    std::int64_t expected = alarm + p.after;
    while ((expected + 1 - first) + p.reevaluate_every <= p.max_window) expected += p.reevaluate_every;
    EXPECT_EQ(f.decided_at, expected);
    EXPECT_LT(d.gain, p.min_gain) << "seed " << seed;
    // Every window the decision looked at stays below min_gain, not only the last.
    for (int count = alarm + p.after + 1; count <= f.decided_at + 1; count += 7) {
      const DeficitHypotheses h = evaluate_deficit_hypotheses(p, fill_bank(p, s, count, alarm), first, alarm);
      worst = std::max(worst, h.gain.maxCoeff());
    }
    worst = std::max(worst, d.gain);
  }
  EXPECT_LT(worst, p.min_gain);
  RecordProperty("worst_no_fault_gain", sci(worst));
}

// 5a. No alarm, no decision; before alarm + after, no decision; at alarm + after a clear fault is
// decided; later samples and other alarm values do not change the latched decision.
TEST(DeficitIsolation, DecisionTimingAndLatch) {
  const DeficitIsolationParams p = msr_params();
  const int onset = 80, alarm = 82;
  Truth t = noisy_truth(p, 41);
  t.samples = 200, t.fault = {FaultKind::kStuckOpen, 6, onset, 0.0};
  const std::vector<DeficitSample> s = generate(p, t);
  DeficitBankState bank;
  DeficitDecisionState state;
  for (int k = 0; k < 200; ++k) {
    push_deficit_sample(p, bank, s[k]);
    if (k == alarm) bank.frozen = true;
    const std::int64_t alarm_arg = k >= alarm ? alarm : -1;
    const DeficitDecision before_call = state.decision;
    const DeficitDecision& d = step_deficit_decision(p, bank, state, k > alarm + p.after ? 7 * k : alarm_arg);
    EXPECT_EQ(&d, &state.decision);
    if (k < alarm) {
      EXPECT_EQ(state.alarm_sample, -1);
    }
    if (k < alarm + p.after) {
      EXPECT_FALSE(d.decided) << k;
    } else if (k == alarm + p.after) {
      ASSERT_TRUE(d.decided);
      EXPECT_EQ(d.thruster, 6);
      EXPECT_EQ(state.alarm_sample, alarm);
    } else {  // latched: identical to the previous period, whatever alarm value is passed
      EXPECT_EQ(d.thruster, before_call.thruster);
      EXPECT_EQ(d.a, before_call.a);
      EXPECT_EQ(d.b, before_call.b);
      EXPECT_EQ(d.gain, before_call.gain);
      EXPECT_EQ(d.onset_sample, before_call.onset_sample);
      EXPECT_EQ(state.alarm_sample, alarm);
    }
  }
}

// 5b. The window follows the alarm sample given, even when the alarm is passed late: with the alarm
// at A, onsets are scanned over [A - before, A] and the decision equals the bank's evaluation there. An
// alarm later than onset + before cannot reach the true onset: the estimate is the window's first sample.
TEST(DeficitIsolation, DecisionUsesGivenAlarmSample) {
  const DeficitIsolationParams p = msr_params();
  const int onset = 60;
  Truth t = noisy_truth(p, 42);
  t.samples = 160, t.fault = {FaultKind::kStuckOpen, 3, onset, 0.0};
  const std::vector<DeficitSample> s = generate(p, t);
  for (int alarm : {onset + 2, onset + p.before + 5}) {
    const int now = alarm + p.after + 9;  // the scheme reports its alarm only now
    const DeficitBankState bank = fill_bank(p, s, now + 1, alarm);
    DeficitDecisionState state;
    const DeficitDecision& d = step_deficit_decision(p, bank, state, alarm);
    ASSERT_TRUE(d.decided);
    const DeficitHypotheses h = evaluate_deficit_hypotheses(p, bank, alarm - p.before, alarm);
    const int best = best_of(h.gain);
    EXPECT_EQ(d.thruster, best);
    EXPECT_EQ(d.thruster, 3);
    EXPECT_EQ(d.gain, h.gain(best));
    EXPECT_EQ(d.margin, h.gain(best) - second_of(h.gain));
    EXPECT_EQ(d.onset_sample, h.onset[best]);
    EXPECT_EQ(d.onset_sample, alarm == onset + 2 ? onset : alarm - p.before);
  }
}

// 5c. While ambiguous the decision re-evaluates every reevaluate_every periods (and only then): a weak
// loss whose gain grows with the window, min_gain set between its first and last gain. The expected
// decision time is the first evaluation time at which the bank's own evaluation is clear.
TEST(DeficitIsolation, ReevaluatesWhileAmbiguous) {
  DeficitIsolationParams p = msr_params();
  p.reevaluate_every = 3;
  p.min_a = p.min_b = 0.0;  // the mechanics of re-evaluation, on a loss below the materiality limits
  const int onset = 100, alarm = 104;
  Truth t = noisy_truth(p, 43);
  t.samples = 260, t.fault = {FaultKind::kLoss, 2, onset, 0.03};
  const std::vector<DeficitSample> s = generate(p, t);
  const std::int64_t first = alarm - p.before;
  // Gains at every evaluation time (independent of min_gain).
  std::vector<std::int64_t> times;
  std::vector<DeficitHypotheses> hs;
  for (std::int64_t e = alarm + p.after;; e += p.reevaluate_every) {
    times.push_back(e);
    hs.push_back(evaluate_deficit_hypotheses(p, fill_bank(p, s, static_cast<int>(e + 1), alarm), first, alarm));
    if ((e + 1 - first) + p.reevaluate_every > p.max_window) break;
  }
  const double g0 = hs.front().gain.maxCoeff(), g1 = hs.back().gain.maxCoeff();
  ASSERT_LT(g0 * 1.5, g1) << "the test needs a gain that grows";
  p.min_gain = 0.5 * (g0 + g1), p.min_margin = 0.0;
  std::int64_t expected = times.back();
  for (std::size_t j = 0; j < times.size(); ++j)
    if (hs[j].gain.maxCoeff() >= p.min_gain) {
      expected = times[j];
      break;
    }
  ASSERT_GT(expected, times.front()) << "the first evaluation must be ambiguous";
  DeficitBankState bank;
  DeficitDecisionState state;
  std::int64_t decided_at = -1;
  for (int k = 0; k < 260 && decided_at < 0; ++k) {
    push_deficit_sample(p, bank, s[k]);
    if (k == alarm) bank.frozen = true;
    step_deficit_decision(p, bank, state, k >= alarm ? alarm : -1);
    if (k >= alarm && !state.decision.decided) {  // the next evaluation is the next time on the schedule
      const auto next = std::upper_bound(times.begin(), times.end(), static_cast<std::int64_t>(k));
      if (next != times.end()) {
        EXPECT_EQ(state.next_evaluation, *next) << k;
      }
    }
    if (state.decision.decided) decided_at = k;
  }
  EXPECT_EQ(decided_at, expected);
  EXPECT_EQ(state.decision.thruster, 2);
  RecordProperty("first_gain", sci(g0));
  RecordProperty("last_gain", sci(g1));
}

// 6. classify_deficit: each branch of the rule, and its boundaries (strict comparisons).
TEST(DeficitIsolation, ClassifyEachBranchAndBoundaries) {
  const DeficitIsolationParams p;  // open_a 0.6, leak_a 0.05, closed_b -0.95
  struct Row {
    double a, b;
    FaultKind kind;
    double size;
  };
  for (const Row& r : {Row{1.0, -1.0, FaultKind::kStuckOpen, 1.0}, Row{0.61, 0.0, FaultKind::kStuckOpen, 1.0},
                       Row{0.6, 0.0, FaultKind::kLeak, 0.6}, Row{0.2, -1.0, FaultKind::kLeak, 0.2},
                       Row{0.051, 0.0, FaultKind::kLeak, 0.051}, Row{0.05, -1.0, FaultKind::kStuckClosed, 1.0},
                       Row{0.0, -0.96, FaultKind::kStuckClosed, 1.0}, Row{0.0, -0.95, FaultKind::kLoss, 0.95},
                       Row{0.05, -0.3, FaultKind::kLoss, 0.3}, Row{0.0, 0.0, FaultKind::kLoss, 0.0}}) {
    DeficitDecision d;
    d.a = r.a, d.b = r.b;
    classify_deficit(p, d);
    EXPECT_EQ(d.kind, r.kind) << "a " << r.a << " b " << r.b;
    EXPECT_DOUBLE_EQ(d.size, r.size) << "a " << r.a << " b " << r.b;
  }
}

// 7. validate: the defaults (with a real mass) pass; each invalid field is named.
TEST(DeficitIsolation, ValidateNamesEachField) {
  EXPECT_TRUE(validate(msr_params()).empty());
  EXPECT_TRUE(validate(chaser::testing::box_24_deficit_params()).empty());
  auto names = [](const DeficitIsolationParams& p, const std::string& field) {
    const std::vector<std::string> v = validate(p);
    return v.size() == 1 && v[0].rfind(field, 0) == 0;
  };
  const double nan = std::nan("");
  const std::vector<std::pair<std::string, std::function<void(DeficitIsolationParams&)>>> cases = {
      {"lanes", [](auto& p) { p.lanes = 0; }},
      {"lanes", [](auto& p) { p.lanes = kMaxWatchedThrusters + 1; }},
      {"mass_kg", [](auto& p) { p.mass_kg = 0.0; }},
      {"mass_kg", [&](auto& p) { p.mass_kg = nan; }},
      {"period_s", [](auto& p) { p.period_s = -0.1; }},
      {"before", [](auto& p) { p.before = 0; }},
      {"after", [](auto& p) { p.after = 1; }},
      {"max_window", [](auto& p) { p.max_window = p.before + p.after - 1; }},
      {"max_window", [](auto& p) { p.max_window = kMaxDeficitWindow; }},
      {"reevaluate_every", [](auto& p) { p.reevaluate_every = 0; }},
      {"lidar_sigma_m", [](auto& p) { p.lidar_sigma_m = 0.0; }},
      {"gyro_sigma_radps", [](auto& p) { p.gyro_sigma_radps = 0.0; }},
      {"pulse_uncertainty", [](auto& p) { p.pulse_uncertainty = -0.01; }},
      {"noise_time_constant_s", [](auto& p) { p.noise_time_constant_s = 0.0; }},
      {"min_gain", [](auto& p) { p.min_gain = -1.0; }},
      {"min_gain, min_margin", [](auto& p) { p.min_margin = -1.0; }},
      {"prior_sigma", [](auto& p) { p.prior_sigma = 0.0; }},
  };
  for (const auto& [field, spoil] : cases) {
    DeficitIsolationParams p = msr_params();
    spoil(p);
    EXPECT_TRUE(names(p, field)) << field;
  }
  DeficitIsolationParams edge = msr_params();
  edge.max_window = kMaxDeficitWindow - 1, edge.after = 2, edge.before = 1, edge.pulse_uncertainty = 0.0;
  EXPECT_TRUE(validate(edge).empty());
}

// The awake arm's terms (flight/arm_reaction.hpp) in the torque row, against Euler's equation of
// the whole servicer written out by hand. The hub (inertia I, turning at w) and the arm exchange
// momentum h; a thruster fires with force F and torque tau about the nominal centre of mass, which
// the moving arm has shifted by d. Over one period the servicer's momentum about its shifted centre,
// I w + h, changes by the thruster's torque about it, tau - d x F, less the gyroscopic w x (I w + h):
//   I (w' - w) / T + (h' - h) / T = tau - d x F - w x (I w + h),
// so the hub's rate w' follows, and the row of a healthy thruster is zero (round-off: the rates
// are ~1e-2 rad/s, the torques ~1e2 N m). Without the arm's terms the same samples leave the
// arm's reaction in the row.
TEST(DeficitIsolation, TheArmsMomentumAndShiftedCentreLeaveAHealthyThrustersRowAtZero) {
  const DeficitIsolationParams p = msr_params();
  const double T = p.period_s;
  DeficitSample now, next;
  now.omega_body_radps = Vec3(0.01, -0.02, 0.015);
  now.ton(0) = 0.7;
  now.arm_momentum_Nms = Vec3(3.0, 5.0, 1.5);
  now.com_shift_m = Vec3(0.025, -0.036, 0.029);
  next.arm_momentum_Nms = Vec3(2.9, 5.6, 2.0);
  next.com_shift_m = now.com_shift_m;
  const Vec3 force_N = now.ton(0) * p.force_body_N.col(0);
  const Vec3 torque_Nm = now.ton(0) * p.torque_body_Nm.col(0);
  const Mat3& I = p.inertia_kgm2;
  const Vec3 w = now.omega_body_radps;
  const Vec3 external_Nm = torque_Nm - now.com_shift_m.cross(force_N) - w.cross(I * w + now.arm_momentum_Nms);
  next.omega_body_radps = w + I.inverse() * (T * external_Nm - (next.arm_momentum_Nms - now.arm_momentum_Nms));
  EXPECT_LT(deficit_torque_row(p, now, next).norm(), 1e-9);

  DeficitSample now_blind = now, next_blind = next;
  now_blind.arm_momentum_Nms = next_blind.arm_momentum_Nms = now_blind.com_shift_m = Vec3::Zero();
  // The arm's reaction left in the row: (h' - h) / T alone is |(-0.1, 0.6, 0.5)| / T.
  EXPECT_GT(deficit_torque_row(p, now_blind, next_blind).norm(), 0.5 * (next.arm_momentum_Nms - now.arm_momentum_Nms).norm() / T);
}

}  // namespace deficit_isolation_test
}  // namespace chaser::flight::fdi
