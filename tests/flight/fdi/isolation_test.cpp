#include "flight/fdi/isolation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <limits>

#include "core/random.hpp"
#include "flight/fdi/design/residual_design.hpp"
#include "msr_test_setup.hpp"

namespace chaser::flight::fdi {
namespace isolation_test {

constexpr int kN = kSchemeThrusters;

// Sparse random on-times: each thruster commanded with probability p, on-time uniform in [0.1, 1).
SchemeTon sparse_ton(RandomStream& rng, double p) {
  SchemeTon ton = SchemeTon::Zero();
  for (int i = 0; i < kN; ++i)
    if (rng.uniform() < p) ton(i) = rng.uniform(0.1, 1.0);
  return ton;
}

struct Sample {
  double r;
  SchemeTon ton;
};

// Eqs. 43 and 44 evaluated literally on the last N samples (full window), with the unused
// thrusters of eq. 44 excluded (+inf).
VecW direct_paper_scores(const std::deque<Sample>& w, int window, bool min_case) {
  VecW score;
  for (int i = 0; i < kN; ++i) {
    double sum = 0.0;
    double phi = 0.0;
    for (const Sample& s : w) {
      sum += s.r * s.ton(i);
      phi += s.ton(i) == 0.0 ? 1.0 : 0.0;
    }
    const double omega = 1.0 - phi;
    if (!min_case) {
      score(i) = std::abs(sum / (window + 1));
    } else {
      score(i) = phi == window ? std::numeric_limits<double>::infinity()
                               : std::abs(sum / (window + omega));
    }
  }
  return score;
}

// Eqs. 43-44 against the literal formulas on random signals, with argmax / argmin.
TEST(Isolation, PaperCriteriaMatchDirectComputation) {
  for (bool min_case : {false, true}) {
    IsolationParams p;
    p.window = 10;
    IsolationState state;
    RandomStream rng(21, "isolation/paper");
    std::deque<Sample> w;
    for (int k = 0; k < 200; ++k) {
      const Sample s{rng.normal(), sparse_ton(rng, 0.3)};
      w.push_back(s);
      if (w.size() > 10) w.pop_front();
      const IsolationOutput out = step_isolation(p, state, Vec3(s.r, 0, 0), s.ton, true, min_case);
      if (k < 9) continue;
      const VecW direct = direct_paper_scores(w, 10, min_case);
      int best = -1;
      for (int i = 0; i < kN; ++i) {
        if (std::isinf(direct(i))) {
          EXPECT_TRUE(std::isinf(out.score(i)));
          continue;
        }
        EXPECT_NEAR(out.score(i), direct(i), 1e-14) << "thruster " << i;
        const bool better = best < 0 || (min_case ? direct(i) < direct(best) : direct(i) > direct(best));
        if (better) best = i;
      }
      EXPECT_EQ(out.candidate, best) << "k " << k;
    }
  }
}

// Eq. 43 (blocked / loss): one thruster at a time is commanded and the residual follows thruster
// 2's on-times (r = -2 T_on,2 plus 1 % noise); the others fire only when r is noise, so their
// correlation is small and the argmax finds 2 whenever 2 fired in the window. (With several
// thrusters per period, eq. 43's correlation about zero also credits thrusters that fire together
// with the faulty one: it is not centred.)
TEST(Isolation, MaxCorrelationFindsTheThrusterTheResidualFollows) {
  IsolationParams p;
  p.window = 10;
  p.confirmation = 15;
  IsolationState state;
  RandomStream rng(22, "isolation/max");
  int confirmed_at = -1;
  for (int k = 0; k < 60; ++k) {
    SchemeTon ton = SchemeTon::Zero();
    ton(k % 3 == 0 ? 2 : static_cast<int>(rng.uniform(0.0, 8.0))) = rng.uniform(0.1, 1.0);
    const double r = -2.0 * ton(2) + 0.01 * rng.normal();
    const IsolationOutput out = step_isolation(p, state, Vec3(r, 0, 0), ton, k >= 20, false);
    if (k < 20) {
      EXPECT_EQ(out.candidate, -1) << "no evaluation before the alarm";
      EXPECT_EQ(out.run_length, 0);
    } else {
      EXPECT_EQ(out.candidate, 2) << "k " << k;
    }
    if (confirmed_at < 0 && out.confirmed >= 0) confirmed_at = k;
  }
  EXPECT_EQ(confirmed_at, 20 + 15 - 1) << "eq. 45: confirmed on the N_c-th equal candidate";
}

// Eq. 44 with the penalty: r constant (a stuck-open thruster's DC residual); thruster 3 is
// commanded every period with a small on-time (the smallest correlation among used thrusters);
// thruster 5 is never commanded: its numerator is exactly 0 and as printed (denominator
// N + Omega = 1) it would win the argmin; excluded, it must not.
TEST(Isolation, PenaltyKeepsUnusedThrustersOut) {
  IsolationParams p;
  p.window = 10;
  IsolationState state;
  RandomStream rng(23, "isolation/penalty");
  IsolationOutput out;
  for (int k = 0; k < 30; ++k) {
    SchemeTon ton = sparse_ton(rng, 0.5);
    for (int i = 0; i < kN; ++i)
      if (ton(i) != 0.0) ton(i) = std::max(ton(i), 0.3);
    ton(3) = 0.05;
    ton(5) = 0.0;
    out = step_isolation(p, state, Vec3(1.0, 0, 0), ton, true, true);
  }
  EXPECT_TRUE(std::isinf(out.score(5)));
  EXPECT_EQ(out.candidate, 3);
  EXPECT_NEAR(out.score(3), 10 * 0.05 / (10 + 1), 1e-15) << "N + Omega = 1 + n_on = 11";
}

// Ties go to the lowest index; with nothing commanded in the window there is no candidate.
TEST(Isolation, TiesAndEmptyWindow) {
  for (bool min_case : {false, true}) {
    IsolationParams p;
    p.window = 5;
    IsolationState state;
    IsolationOutput out;
    for (int k = 0; k < 5; ++k) {
      SchemeTon ton = SchemeTon::Zero();
      ton(1) = ton(4) = ton(6) = 0.5;
      out = step_isolation(p, state, Vec3(1.0, 0, 0), ton, true, min_case);
    }
    EXPECT_EQ(out.candidate, 1);
    for (int k = 0; k < 5; ++k)
      out = step_isolation(p, state, Vec3(1.0, 0, 0), SchemeTon::Zero(), true, min_case);
    EXPECT_EQ(out.candidate, -1);
    EXPECT_EQ(out.run_length, 0);
  }
}

// Eq. 45: the run length counts equal consecutive candidates and restarts when the candidate
// changes; confirmation needs N_c of them.
TEST(Isolation, ConfirmationNeedsNcEqualCandidates) {
  IsolationParams p;
  p.window = 1;
  p.confirmation = 3;
  IsolationState state;
  auto step = [&](int active) {
    SchemeTon ton = SchemeTon::Zero();
    ton(active) = 1.0;
    return step_isolation(p, state, Vec3(1.0, 0, 0), ton, true, false);
  };
  EXPECT_EQ(step(4).confirmed, -1);
  EXPECT_EQ(step(4).confirmed, -1);
  EXPECT_EQ(step(6).run_length, 1);
  EXPECT_EQ(step(6).confirmed, -1);
  const IsolationOutput out = step(6);
  EXPECT_EQ(out.run_length, 3);
  EXPECT_EQ(out.confirmed, 6);
}

// Settle: with `evaluate` raised at period 10 and settle = 4, the first candidate comes at period
// 14 (the fifth period with the alarm), and the window still holds the samples before it.
TEST(Isolation, SettleDelaysTheFirstEvaluation) {
  IsolationParams p;
  p.window = 20;
  p.settle = 4;
  IsolationState state;
  for (int k = 0; k < 20; ++k) {
    SchemeTon ton = SchemeTon::Zero();
    if (k < 5) ton(3) = 0.5;  // commanded only long before the alarm, still in the window
    const IsolationOutput out = step_isolation(p, state, Vec3(1.0, 0, 0), ton, k >= 10, false);
    EXPECT_EQ(out.candidate, k >= 14 ? 3 : -1) << "k " << k;
  }
}

struct SignatureSetup {
  ResidualGeneratorParams residual;
  IsolationParams params;
};

SignatureSetup msr_signature_setup(int window) {
  const model::Scenario s = testing::msr_test_scenario();
  const SchemeConfig M = testing::msr_test_configuration(s);
  const ResidualDesign d = design_residual_generator(position_design_inputs(s, M));
  SignatureSetup setup{make_residual_generator(d), {}};
  setup.params.criterion = IsolationCriterion::kSignature;
  setup.params.window = window;
  setup.params.confirmation = 15;
  setup.params.signature = make_signature_filter(setup.residual, M.topRows(3));
  return setup;
}

// The signature criterion against a direct computation: signatures by the error recursion
// z_i(k+1) = A_c z_i + B_bar d_i T_on,i, then the centred correlation over the window. The residual
// is that of a blocked thruster 6 (r = -s_6) plus white noise (2e-5 m, a tenth of a pulse's peak
// signature), so 6 must win whenever it was commanded in the window (when it was not, it does not
// qualify and the residual's decaying tail can fit another thruster's signature: not checked).
TEST(Isolation, SignatureCriterionMatchesDirectComputationAndFindsBlockedThruster) {
  const int window = 60;
  const SignatureSetup setup = msr_signature_setup(window);
  const SignatureFilterParams& f = setup.params.signature;
  IsolationState state;
  RandomStream rng(24, "isolation/signature");
  Mat6W z = Mat6W::Zero();
  std::deque<std::pair<double, VecW>> w;  // r, s
  std::deque<SchemeTon> tons;
  int wrong = 0;
  int evaluated = 0;
  for (int k = 0; k < 400; ++k) {
    const SchemeTon ton = sparse_ton(rng, 0.05);
    const VecW s = (f.QC * z).row(0).transpose();
    const double r = -s(6) + 2e-5 * rng.normal();
    for (int i = 0; i < kN; ++i) z.col(i) = f.A_c * z.col(i) + f.B_thr.col(i) * ton(i);
    w.emplace_back(r, s);
    tons.push_back(ton);
    if (w.size() > static_cast<std::size_t>(window)) {
      w.pop_front();
      tons.pop_front();
    }
    const IsolationOutput out = step_isolation(setup.params, state, Vec3(r, 0, 0), ton, true, false);
    if (k < window) continue;
    double r_mean = 0.0;
    VecW s_mean = VecW::Zero();
    for (const auto& [rj, sj] : w) {
      r_mean += rj / window;
      s_mean += sj / window;
    }
    for (int i = 0; i < kN; ++i) {
      double cross = 0.0, energy = 0.0;
      bool used = false;
      for (std::size_t j = 0; j < w.size(); ++j) {
        cross += (w[j].first - r_mean) * (w[j].second(i) - s_mean(i));
        energy += (w[j].second(i) - s_mean(i)) * (w[j].second(i) - s_mean(i));
        used = used || tons[j](i) != 0.0;
      }
      const double direct = used && cross < 0.0 ? cross * cross / energy : 0.0;
      EXPECT_NEAR(out.score(i), direct, 1e-9 * std::max(direct, 1e-12)) << "k " << k << " i " << i;
    }
    bool six_used = false;
    for (const SchemeTon& t : tons) six_used = six_used || t(6) != 0.0;
    if (six_used && out.candidate != 6) ++wrong;
    if (six_used) ++evaluated;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(evaluated, 250);
}

TEST(Isolation, ValidateNamesTheProblems) {
  IsolationParams p;
  EXPECT_TRUE(validate(p).empty());
  p.window = 0;
  p.confirmation = 0;
  p.criterion = IsolationCriterion::kSignature;
  EXPECT_EQ(validate(p).size(), 3u);
}

}  // namespace isolation_test
}  // namespace chaser::flight::fdi
