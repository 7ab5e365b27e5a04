#include "flight/fdi/isolation.hpp"

#include <algorithm>
#include <limits>

namespace chaser::flight::fdi {

namespace {

constexpr int kThrusters = kSchemeThrusters;

struct Selection {
  VecW score = VecW::Zero();
  int candidate = -1;
};

void store_sample(const IsolationParams& params, IsolationState& state, const Vec3& r,
                  const SchemeTon& ton) {
  const int window = std::clamp(params.window, 1, kMaxIsolationWindow);
  state.residual[state.next] = r;
  state.ton[state.next] = ton;
  if (params.criterion == IsolationCriterion::kSignature) {
    const SignatureFilterParams& f = params.signature;
    state.signature[state.next].noalias() = f.QC * state.signature_state;  // s_i(k)
    const Mat6W driven = f.B_thr * ton.asDiagonal();
    state.signature_state = f.A_c * state.signature_state + driven;  // z_i(k + 1)
  }
  state.next = state.next + 1 < window ? state.next + 1 : 0;
  state.count = std::min(state.count + 1, window);
}

// The sums below run over the ring's stored samples in slot order: their order does not matter.
VecW commanded_samples(const IsolationState& state) {
  VecW n = VecW::Zero();
  for (int j = 0; j < state.count; ++j)
    for (int i = 0; i < kThrusters; ++i)
      if (state.ton[j](i) != 0.0) n(i) += 1.0;
  return n;
}

// Eqs. 43-44; argmax or argmin with ties to the lowest index (strict comparisons).
Selection paper_selection(const IsolationParams& params, const IsolationState& state,
                          bool over_consumption) {
  Mat3W correlation = Mat3W::Zero();
  for (int j = 0; j < state.count; ++j)
    correlation.noalias() += state.residual[j] * state.ton[j].transpose();
  const VecW n_on = commanded_samples(state);
  const double n = params.window;
  Selection sel;
  if (!over_consumption) {  // eq. 43, cases 2 and 4
    sel.score = correlation.colwise().norm().transpose() / (n + 1.0);
    for (int i = 0; i < kThrusters; ++i)
      if (sel.score(i) > 0.0 && (sel.candidate < 0 || sel.score(i) > sel.score(sel.candidate)))
        sel.candidate = i;
    return sel;
  }
  for (int i = 0; i < kThrusters; ++i) {  // eq. 44, cases 1 and 3
    const double zeros = state.count - n_on(i);            // sum_j phi_i(j)
    const double denominator = n + (1.0 - zeros);          // N + Omega_i >= 1
    if (n_on(i) == 0.0) {                                  // unused: excluded (see header)
      sel.score(i) = std::numeric_limits<double>::infinity();
      continue;
    }
    sel.score(i) = correlation.col(i).norm() / denominator;
    if (sel.candidate < 0 || sel.score(i) < sel.score(sel.candidate)) sel.candidate = i;
  }
  return sel;
}

Selection signature_selection(const IsolationState& state) {
  Vec3 r_mean = Vec3::Zero();
  Mat3W s_mean = Mat3W::Zero();
  for (int j = 0; j < state.count; ++j) {
    r_mean += state.residual[j];
    s_mean += state.signature[j];
  }
  r_mean /= state.count;
  s_mean /= state.count;
  VecW cross = VecW::Zero();
  VecW energy = VecW::Zero();
  for (int j = 0; j < state.count; ++j) {
    const Mat3W ds = state.signature[j] - s_mean;
    cross.noalias() += ds.transpose() * (state.residual[j] - r_mean);
    energy += ds.colwise().squaredNorm().transpose();
  }
  const VecW n_on = commanded_samples(state);
  Selection sel;
  for (int i = 0; i < kThrusters; ++i) {
    const bool qualifies = n_on(i) > 0.0 && energy(i) > 0.0 && cross(i) < 0.0;
    sel.score(i) = qualifies ? cross(i) * cross(i) / energy(i) : 0.0;
    if (sel.score(i) > 0.0 && (sel.candidate < 0 || sel.score(i) > sel.score(sel.candidate)))
      sel.candidate = i;
  }
  return sel;
}

}  // namespace

std::vector<std::string> validate(const IsolationParams& params) {
  std::vector<std::string> problems;
  if (params.window < 1 || params.window > kMaxIsolationWindow)
    problems.push_back("isolation.window: must be in 1..128");
  if (params.confirmation < 1) problems.push_back("isolation.confirmation: must be >= 1");
  if (params.settle < 0) problems.push_back("isolation.settle: must be >= 0");
  if (params.criterion == IsolationCriterion::kSignature) {
    const SignatureFilterParams& f = params.signature;
    if (!f.A_c.allFinite() || !f.QC.allFinite() || !f.B_thr.allFinite())
      problems.push_back("isolation.signature: matrices must be finite");
    if (f.QC.isZero(0.0) || f.B_thr.isZero(0.0))
      problems.push_back("isolation.signature: not set (use make_signature_filter)");
  }
  return problems;
}

SignatureFilterParams make_signature_filter(const ResidualGeneratorParams& residual,
                                            const Mat3W& thruster_inputs) {
  SignatureFilterParams f;
  f.A_c = residual.A_c;
  f.QC = residual.Q * residual.C;
  f.B_thr = residual.B_bar * thruster_inputs;
  return f;
}

IsolationOutput step_isolation(const IsolationParams& params, IsolationState& state, const Vec3& r,
                               const SchemeTon& ton, bool evaluate, bool over_consumption) {
  store_sample(params, state, r, ton);
  IsolationOutput out;
  state.evaluated = evaluate ? std::min(state.evaluated + 1, params.settle + 1) : 0;
  if (state.evaluated <= params.settle) {  // before the alarm, or while the onset settles
    state.last_candidate = -1;
    state.run_length = 0;
    return out;
  }
  const Selection sel = params.criterion == IsolationCriterion::kPaper
                            ? paper_selection(params, state, over_consumption)
                            : signature_selection(state);
  out.score = sel.score;
  out.candidate = sel.candidate;
  state.run_length = (sel.candidate >= 0 && sel.candidate == state.last_candidate)
                         ? state.run_length + 1
                         : (sel.candidate >= 0 ? 1 : 0);  // eq. 45
  state.last_candidate = sel.candidate;
  out.run_length = state.run_length;
  if (sel.candidate >= 0 && state.run_length >= params.confirmation) out.confirmed = sel.candidate;
  return out;
}

}  // namespace chaser::flight::fdi
