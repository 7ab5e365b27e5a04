#include "control/hinf_synthesis.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

// SB10AD (SLICOT 5.0, src/SB10AD.f): Fortran 77, every argument by reference, arrays column-major
// (Eigen's default), INTEGER = int, LOGICAL = int (gfortran's default kinds), no CHARACTER
// argument and hence no hidden string lengths.
extern "C" void sb10ad_(const int* job, const int* n, const int* m, const int* np, const int* ncon,
                        const int* nmeas, double* gamma, double* a, const int* lda, double* b, const int* ldb,
                        double* c, const int* ldc, double* d, const int* ldd, double* ak, const int* ldak,
                        double* bk, const int* ldbk, double* ck, const int* ldck, double* dk, const int* lddk,
                        double* ac, const int* ldac, double* bc, const int* ldbc, double* cc, const int* ldcc,
                        double* dc, const int* lddc, double* rcond, const double* gtol, const double* actol,
                        int* iwork, const int* liwork, double* dwork, const int* ldwork, int* bwork,
                        const int* lbwork, int* info);

namespace chaser::control {

using Eigen::MatrixXd;

namespace {

constexpr int kJobBisection = 1;   // JOB = 1: bisection from GAMMA down (see the header)
constexpr int kJobSuboptimal = 4;  // JOB = 4: the central controller at GAMMA itself
// ACTOL: a gamma is kept only if every closed-loop pole has real part below this. Zero: stable.
constexpr double kClosedLoopPoleBound = 0.0;

struct Sizes {
  std::int64_t n, m, np, m2, np2, m1, np1;
};

// SB10AD's minimum LDWORK (its argument list, LDWORK), in 64 bits so that overflow is caught.
std::int64_t min_ldwork(const Sizes& s) {
  using std::max, std::min;
  const std::int64_t n = s.n, m = s.m, np = s.np, m1 = s.m1, m2 = s.m2, np1 = s.np1, np2 = s.np2;
  const std::int64_t nd1 = np1 - m2, nd2 = m1 - np2;
  const std::int64_t lw1 = n * m + np * n + np * m + m2 * m2 + np2 * np2;
  const std::int64_t lw2 =
      max({(n + np1 + 1) * (n + m2) + max(3 * (n + m2) + n + np1, 5 * (n + m2)),
           (n + np2) * (n + m1 + 1) + max(3 * (n + np2) + n + m1, 5 * (n + np2)),
           m2 + np1 * np1 + max({np1 * max(n, m1), 3 * m2 + np1, 5 * m2}),
           np2 + m1 * m1 + max({max(n, np1) * m1, 3 * np2 + m1, 5 * np2})});
  const std::int64_t lw3 = max(nd1 * m1 + max(4 * min(nd1, m1) + max(nd1, m1), 6 * min(nd1, m1)),
                               np1 * nd2 + max(4 * min(np1, nd2) + max(np1, nd2), 6 * min(np1, nd2)));
  const std::int64_t lw4 = 2 * m * m + np * np + 2 * m * n + m * np + 2 * n * np;
  const std::int64_t lw5 = 2 * n * n + m * n + n * np;
  const std::int64_t lw6 = max(m * m + max(2 * m1, 3 * n * n + max(n * m, 10 * n * n + 12 * n + 5)),
                               np * np + max(2 * np1, 3 * n * n + max(n * np, 10 * n * n + 12 * n + 5)));
  const std::int64_t lw7 =
      m2 * np2 + np2 * np2 + m2 * m2 +
      max({nd1 * nd1 + max(2 * nd1, (nd1 + nd2) * np2), nd2 * nd2 + max(2 * nd2, nd2 * m2), 3 * n,
           n * (2 * np2 + m2) +
               max(2 * n * m2, m2 * np2 + max(m2 * m2 + 3 * m2, np2 * (2 * np2 + m2 + max(np2, n))))});
  return lw1 + max({std::int64_t{1}, lw2, lw3, lw4, lw5 + max(lw6, lw7)});
}

std::int64_t min_liwork(const Sizes& s) {
  return std::max(2 * std::max({s.n, s.m1, s.np1, s.m2, s.np2}), s.n * s.n);
}

HinfResult refuse(HinfStatus status, std::string message, int info = 0) {
  HinfResult r;
  r.status = status;
  r.message = std::move(message);
  r.slicot_info = info;
  return r;
}

// Every problem SB10AD would refuse with INFO < 0 (and XERBLA's STOP), and the degenerate sizes for
// which it returns INFO = 0 without computing anything (its "quick return").
std::vector<std::string> validate_inputs(const StateSpace& p, int n_meas, int n_ctrl, double gamma_max,
                                         double tol) {
  std::vector<std::string> problems = validate(p, "plant P");
  const auto require = [&](bool ok, const std::string& what) {
    if (!ok) problems.push_back(what);
  };
  const auto str = [](auto v) { return std::to_string(v); };
  const std::int64_t n_w = p.inputs() - n_ctrl, n_z = p.outputs() - n_meas;
  require(p.states() >= 1, "plant P: needs at least one state (SB10AD returns no controller for n = 0)");
  require(n_ctrl >= 1 && n_w >= 1, "n_ctrl must be in 1.." + str(p.inputs() - 1) + " (P has " + str(p.inputs()) +
                                       " inputs [w; u]; got " + str(n_ctrl) + ")");
  require(n_meas >= 1 && n_z >= 1, "n_meas must be in 1.." + str(p.outputs() - 1) + " (P has " + str(p.outputs()) +
                                       " outputs [z; y]; got " + str(n_meas) + ")");
  // (A2) needs D12 (n_z x n_ctrl) tall and D21 (n_meas x n_w) wide; SB10AD refuses otherwise.
  require(n_z >= n_ctrl, "need at least as many performance outputs z as controls u for D12 to have full "
                         "column rank (n_z = " + str(n_z) + ", n_ctrl = " + str(n_ctrl) + ")");
  require(n_w >= n_meas, "need at least as many exogenous inputs w as measurements y for D21 to have full "
                         "row rank (n_w = " + str(n_w) + ", n_meas = " + str(n_meas) + ")");
  require(std::isfinite(gamma_max) && gamma_max > 0.0, "gamma_max must be finite and > 0 (got " + str(gamma_max) + ")");
  require(std::isfinite(tol) && tol > 0.0, "tol must be finite and > 0 (got " + str(tol) + ")");
  return problems;
}

// (A2) checked here before SLICOT, with SB10PD's own test (smallest over largest singular value
// at most sqrt(eps)). SB10PD computes that ratio as 0 / 0 = NaN for an all-zero D12 or D21, and
// NaN <= tol is false, so SLICOT 5.0 lets a zero D12 through and fails later with INFO = 12
// (measured: the S-only design of a strictly proper plant).
bool full_rank(const MatrixXd& m) {
  const Eigen::VectorXd s = Eigen::JacobiSVD<MatrixXd>(m).singularValues();
  return s(0) > 0.0 && s(s.size() - 1) / s(0) > std::sqrt(std::numeric_limits<double>::epsilon());
}

// SB10AD's INFO = 1..12, in order.
constexpr std::array<HinfStatus, 12> kStatusOfInfo = {
    HinfStatus::kA3RankDeficient,    HinfStatus::kA4RankDeficient,   HinfStatus::kD12RankDeficient,
    HinfStatus::kD21RankDeficient,   HinfStatus::kSvdFailed,         HinfStatus::kGammaTooSmall,
    HinfStatus::kXRiccatiFailed,     HinfStatus::kYRiccatiFailed,    HinfStatus::kSingularTransform,
    HinfStatus::kD11SingularValuesFailed, HinfStatus::kIllPosedLoop, HinfStatus::kNoStabilisingController};

}  // namespace

const char* to_string(HinfStatus status) {
  switch (status) {
    case HinfStatus::kOk: return "ok";
    case HinfStatus::kInvalidInput: return "invalid input";
    case HinfStatus::kA3RankDeficient:
      return "[A - jwI, B2; C1, D12] has not full column rank on the imaginary axis (assumption A3: a "
             "plant or weight pole or zero on the axis, e.g. an integrator in W_S)";
    case HinfStatus::kA4RankDeficient:
      return "[A - jwI, B1; C2, D21] has not full row rank on the imaginary axis (assumption A4)";
    case HinfStatus::kD12RankDeficient:
      return "D12 has not full column rank (assumption A2: every control must reach z directly, e.g. a "
             "W_KS with full-rank feedthrough)";
    case HinfStatus::kD21RankDeficient:
      return "D21 has not full row rank (assumption A2: every measurement must see w directly)";
    case HinfStatus::kSvdFailed: return "an SVD in SB10AD did not converge";
    case HinfStatus::kGammaTooSmall:
      return "gamma_max is too small: the controller is not admissible (gamma_max at or below the D11 bound)";
    case HinfStatus::kXRiccatiFailed:
      return "the X-Riccati equation could not be solved (gamma too small, (A, B2) not stabilisable, or "
             "numerical difficulties)";
    case HinfStatus::kYRiccatiFailed:
      return "the Y-Riccati equation could not be solved (gamma too small, (C2, A) not detectable, or "
             "numerical difficulties)";
    case HinfStatus::kSingularTransform: return "Im2 + Tu D11hat Ty D22 is singular";
    case HinfStatus::kD11SingularValuesFailed: return "the singular values of the D11 blocks could not be computed";
    case HinfStatus::kIllPosedLoop: return "Inp2 - D22 DK or Im2 - DK D22 is singular: the loop is ill posed";
    case HinfStatus::kNoStabilisingController:
      return "no stabilising controller for any gamma up to gamma_max (gamma_max too small, or assumption A1 "
             "violated: (A, B2) not stabilisable or (C2, A) not detectable)";
    case HinfStatus::kSlicotArgumentError: return "SB10AD refused an argument";
  }
  return "unknown";
}

namespace {

HinfResult run_sb10ad(int job, const StateSpace& p, int n_meas, int n_ctrl, double gamma_max, double tol) {
  const std::vector<std::string> problems = validate_inputs(p, n_meas, n_ctrl, gamma_max, tol);
  if (!problems.empty()) {
    std::string all = "synthesise: invalid input:";
    for (const std::string& s : problems) all += "\n  " + s;
    return refuse(HinfStatus::kInvalidInput, all);
  }
  const Eigen::Index n_z = p.outputs() - n_meas, n_w = p.inputs() - n_ctrl;
  if (!full_rank(p.d.block(0, n_w, n_z, n_ctrl)))
    return refuse(HinfStatus::kD12RankDeficient,
                  std::string("synthesise (checked before SB10AD): ") + to_string(HinfStatus::kD12RankDeficient));
  if (!full_rank(p.d.block(n_z, 0, n_meas, n_w)))
    return refuse(HinfStatus::kD21RankDeficient,
                  std::string("synthesise (checked before SB10AD): ") + to_string(HinfStatus::kD21RankDeficient));
  const Sizes s{p.states(), p.inputs(), p.outputs(), n_ctrl, n_meas, p.inputs() - n_ctrl, p.outputs() - n_meas};
  const std::int64_t ldwork64 = min_ldwork(s), liwork64 = min_liwork(s);
  constexpr std::int64_t kIntMax = std::numeric_limits<int>::max();
  if (ldwork64 > kIntMax || liwork64 > kIntMax || 4 * s.n * s.n > kIntMax)
    return refuse(HinfStatus::kInvalidInput, "synthesise: plant P too large for SB10AD's 32-bit workspace sizes (n = " +
                                                 std::to_string(s.n) + ")");

  const int n = static_cast<int>(s.n), m = static_cast<int>(s.m), np = static_cast<int>(s.np);
  const int ldwork = static_cast<int>(ldwork64), liwork = static_cast<int>(liwork64), lbwork = 2 * n;
  const int n2 = 2 * n, np1 = static_cast<int>(s.np1), m1 = static_cast<int>(s.m1);
  const int ld_np1 = std::max(1, np1), ld_ncon = std::max(1, n_ctrl);
  // SB10AD documents A, B, C, D as input only; they are passed as copies all the same.
  MatrixXd a = p.a, b = p.b, c = p.c, d = p.d;
  MatrixXd ak(n, n), bk(n, n_meas), ck(n_ctrl, n), dk(n_ctrl, n_meas);
  MatrixXd ac(n2, n2), bc(n2, m1), cc(ld_np1, n2), dc(ld_np1, m1);
  std::vector<int> iwork(static_cast<std::size_t>(liwork)), bwork(static_cast<std::size_t>(lbwork));
  std::vector<double> dwork(static_cast<std::size_t>(ldwork));
  double gamma = gamma_max, gtol = tol, actol = kClosedLoopPoleBound;
  std::array<double, 4> rcond{};
  int info = 0;
  sb10ad_(&job, &n, &m, &np, &n_ctrl, &n_meas, &gamma, a.data(), &n, b.data(), &n, c.data(), &np, d.data(), &np,
          ak.data(), &n, bk.data(), &n, ck.data(), &ld_ncon, dk.data(), &ld_ncon, ac.data(), &n2, bc.data(), &n2,
          cc.data(), &ld_np1, dc.data(), &ld_np1, rcond.data(), &gtol, &actol, iwork.data(), &liwork, dwork.data(),
          &ldwork, bwork.data(), &lbwork, &info);

  if (info < 0 || info > static_cast<int>(kStatusOfInfo.size()))
    return refuse(HinfStatus::kSlicotArgumentError,
                  "SB10AD returned INFO = " + std::to_string(info) + " (a validation gap in synthesise)", info);
  if (info > 0) {
    const HinfStatus status = kStatusOfInfo[static_cast<std::size_t>(info - 1)];
    HinfResult r =
        refuse(status, std::string("SB10AD INFO = ") + std::to_string(info) + ": " + to_string(status), info);
    r.rcond = rcond;
    return r;
  }
  HinfResult r;
  r.status = HinfStatus::kOk;
  r.gamma = gamma;
  r.rcond = rcond;
  r.controller = StateSpace{ak, bk, ck, dk};
  r.closed_loop = StateSpace{ac, bc, cc.topRows(np1), dc.topRows(np1)};
  return r;
}

}  // namespace

HinfResult synthesise(const StateSpace& p, int n_meas, int n_ctrl, double gamma_max, double tol) {
  return run_sb10ad(kJobBisection, p, n_meas, n_ctrl, gamma_max, tol);
}

HinfResult synthesise_at(const StateSpace& p, int n_meas, int n_ctrl, double gamma) {
  return run_sb10ad(kJobSuboptimal, p, n_meas, n_ctrl, gamma, gamma);  // GTOL unused by JOB = 4
}

}  // namespace chaser::control
