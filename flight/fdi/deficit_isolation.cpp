#include "flight/fdi/deficit_isolation.hpp"

#include <algorithm>
#include <cmath>

#include "flight/fdi/euler_torque.hpp"

namespace chaser::flight::fdi {

namespace {

const WatchedTon kNoCommands = WatchedTon::Zero();  // before the first sample, or past the ring

const DeficitSample& sample_at(const DeficitBankState& bank, std::int64_t index) {
  return bank.ring[static_cast<std::size_t>(index % kMaxDeficitWindow)];
}

// Per axis: the gyro noise alone, through the difference of two readings.
Vec3 torque_noise_floor_sq(const DeficitIsolationParams& p) {
  const double s = std::sqrt(2.0) * p.gyro_sigma_radps / p.period_s;
  return (p.inertia_kgm2.array().square().rowwise().sum() * s * s).matrix();
}

// R M_F / m of sample s into `force_lvlh` (its first p.lanes columns), and the acceleration the
// commands give, R M_F T_on / m. Eight lanes keep the fixed-size products of the eight-lane bank
// (Eigen sums a fixed 3 x 8 product in its own order; MSR's pinned results depend on it); any
// other count sums the lanes in index order.
Vec3 lvlh_forces(const DeficitIsolationParams& p, const DeficitSample& s, DeficitMat3W& force_lvlh) {
  const Mat3 R = s.q_lvlh_from_body.toRotationMatrix();
  if (p.lanes == kSchemeThrusters) {
    const Mat3W f = R * p.force_body_N.leftCols<kSchemeThrusters>() / s.mass_kg;
    const SchemeTon u = s.ton.head<kSchemeThrusters>();
    force_lvlh.leftCols<kSchemeThrusters>() = f;
    return f * u;
  }
  Vec3 acc = Vec3::Zero();
  for (int i = 0; i < p.lanes; ++i) {
    force_lvlh.col(i) = R * p.force_body_N.col(i) / s.mass_kg;
    acc += force_lvlh.col(i) * s.ton(i);
  }
  return acc;
}

// Scratch arrays of one evaluation, sized for the longest window (on the stack: no allocation).
struct Window {
  int n = 0;
  std::array<DeficitMat3W, kMaxDeficitWindow> force_lvlh{};  // [m/s^2 per unit on-time] R M_F / m
  std::array<Vec3, kMaxDeficitWindow> y_pos{};    // [m] position rows, detrended
  std::array<Vec3, kMaxDeficitWindow> y_tau{};    // [N m] torque rows
  std::array<Vec3, kMaxDeficitWindow> w_tau{};    // [1/(N m)^2] torque row weights
  std::array<WatchedTon, kMaxDeficitWindow> ton{};
  double g00 = 0, g01 = 0, g11 = 0;               // Gram matrix of [1, k] over the position rows
  double rss_position = 0, rss_torque = 0;        // [-] weighted RSS of the no-fault fit, by block
};

// p' G^-1 q for the straight-line projection: the part of <x, z> that r0 + v0 t explains.
double line_part(const Window& w, double p0, double p1, double q0, double q1) {
  const double det = w.g00 * w.g11 - w.g01 * w.g01;
  return (p0 * (w.g11 * q0 - w.g01 * q1) + p1 * (w.g00 * q1 - w.g01 * q0)) / det;
}

double build_window(const DeficitIsolationParams& p, const DeficitBankState& bank, std::int64_t first, Window& w) {
  const double T = p.period_s;
  Vec3 pos = Vec3::Zero(), vel = Vec3::Zero();
  WatchedTon previous_ton = deficit_commands_before(bank, first);  // delay spill into the first row
  for (int k = 0; k < w.n; ++k) {
    const DeficitSample& s = sample_at(bank, first + k);
    w.ton[k] = s.ton;
    w.y_pos[k] = s.r_lvlh_m - pos;  // what the commanded forces do not explain
    const Vec3 acc = lvlh_forces(p, s, w.force_lvlh[k]);
    pos += T * vel + 0.5 * T * T * acc;
    vel += T * acc;
    if (k + 1 < w.n) {
      w.y_tau[k] = deficit_torque_row(p, s, sample_at(bank, first + k + 1));
      w.w_tau[k] = deficit_torque_weights(p, bank, s, previous_ton);
    }
    previous_ton = s.ton;
  }
  // No-fault fit: r0 + v0 t per axis; what it leaves are the detrended position rows.
  w.g00 = w.n, w.g01 = 0.5 * w.n * (w.n - 1), w.g11 = (w.n - 1.0) * w.n * (2.0 * w.n - 1.0) / 6.0;
  const double inv_var = 1.0 / (p.lidar_sigma_m * p.lidar_sigma_m);
  double& rss = w.rss_position;
  for (int ax = 0; ax < 3; ++ax) {
    double s0 = 0, s1 = 0;
    for (int k = 0; k < w.n; ++k) s0 += w.y_pos[k](ax), s1 += k * w.y_pos[k](ax);
    const double det = w.g00 * w.g11 - w.g01 * w.g01;
    const double c0 = (w.g11 * s0 - w.g01 * s1) / det, c1 = (w.g00 * s1 - w.g01 * s0) / det;
    for (int k = 0; k < w.n; ++k) {
      w.y_pos[k](ax) -= c0 + c1 * k;
      rss += inv_var * w.y_pos[k](ax) * w.y_pos[k](ax);
    }
  }
  for (int k = 0; k + 1 < w.n; ++k) w.rss_torque += w.y_tau[k].cwiseProduct(w.y_tau[k]).dot(w.w_tau[k]);
  return w.rss_position + w.rss_torque;
}

// Normal equations of hypothesis i with onset kf (window-relative), the position and torque blocks
// weighted by the given scales (1, 1: as the weights say), the prior not included.
DeficitNormal normal_equations(const DeficitIsolationParams& p, const Window& w, int i, int kf, double position_scale,
                               double torque_scale) {
  const double T = p.period_s;
  const double inv_var = position_scale / (p.lidar_sigma_m * p.lidar_sigma_m);
  DeficitNormal n;
  // Position rows: the double integral of the deficit's acceleration from the onset on.
  Vec3 pa = Vec3::Zero(), va = Vec3::Zero(), pb = Vec3::Zero(), vb = Vec3::Zero();
  Vec3 sa0 = Vec3::Zero(), sa1 = Vec3::Zero(), sb0 = Vec3::Zero(), sb1 = Vec3::Zero();
  Vec3 aa = Vec3::Zero(), ab = Vec3::Zero(), bb = Vec3::Zero();
  for (int k = kf; k < w.n; ++k) {  // columns are zero before the onset
    // pa, pb hold the columns' values at row k
    aa += pa.cwiseProduct(pa), ab += pa.cwiseProduct(pb), bb += pb.cwiseProduct(pb);
    n.ga += inv_var * pa.dot(w.y_pos[k]), n.gb += inv_var * pb.dot(w.y_pos[k]);
    sa0 += pa, sa1 += k * pa, sb0 += pb, sb1 += k * pb;
    const Vec3 acc_a = w.force_lvlh[k].col(i), acc_b = acc_a * w.ton[k](i);
    pa += T * va + 0.5 * T * T * acc_a, va += T * acc_a;
    pb += T * vb + 0.5 * T * T * acc_b, vb += T * acc_b;
  }
  for (int ax = 0; ax < 3; ++ax) {  // less what r0 + v0 t absorbs
    n.haa += inv_var * (aa(ax) - line_part(w, sa0(ax), sa1(ax), sa0(ax), sa1(ax)));
    n.hab += inv_var * (ab(ax) - line_part(w, sa0(ax), sa1(ax), sb0(ax), sb1(ax)));
    n.hbb += inv_var * (bb(ax) - line_part(w, sb0(ax), sb1(ax), sb0(ax), sb1(ax)));
  }
  // Torque rows.
  const Vec3 c = p.torque_body_Nm.col(i);
  for (int k = kf; k + 1 < w.n; ++k) {
    const Vec3 wc = torque_scale * w.w_tau[k].cwiseProduct(c);
    const double cc = wc.dot(c), cy = wc.dot(w.y_tau[k]), u = w.ton[k](i);
    n.haa += cc, n.hab += u * cc, n.hbb += u * u * cc;
    n.ga += cy, n.gb += u * cy;
  }
  return n;
}

DeficitNormal with_prior(const DeficitIsolationParams& p, DeficitNormal n) {
  const double prior = 1.0 / (p.prior_sigma * p.prior_sigma);
  n.haa += prior, n.hbb += prior;
  return n;
}

// Reduced chi-square of the torque rows at a fit: sum of squared weighted residuals per row.
double torque_chi2_per_row(const DeficitIsolationParams& p, const Window& w, int i, int kf, double a, double b) {
  const DeficitNormal t = normal_equations(p, w, i, kf, 0.0, 1.0);
  const double rss = w.rss_torque - 2.0 * (a * t.ga + b * t.gb) + (a * a * t.haa + 2.0 * a * b * t.hab + b * b * t.hbb);
  return std::max(rss, 0.0) / (3.0 * (w.n - 1));
}

// The commanded force over the period, body axes: F = sum of ton_i F_i over the commanded lanes.
Vec3 commanded_force_body_N(const DeficitIsolationParams& p, const DeficitSample& now) {
  Vec3 force_N = Vec3::Zero();
  with_lanes(p.lanes, [&](auto lanes) {
    for (int i = 0; i < lanes; ++i)
      if (now.ton(i) > 0.0) force_N += now.ton(i) * p.force_body_N.col(i);
  });
  return force_N;
}

}  // namespace

Vec3 deficit_torque_row(const DeficitIsolationParams& p, const DeficitSample& now, const DeficitSample& next) {
  // Euler's equation over one period, less the commanded torque: what the thrusters did not do.
  Vec3 row = euler_torque_Nm(p.inertia_kgm2, now.omega_body_radps, next.omega_body_radps, p.period_s);
  with_lanes(p.lanes, [&](auto lanes) {
    for (int i = 0; i < lanes; ++i)  // M_C T_on over the commanded thrusters: most periods none
      if (now.ton(i) > 0.0) row -= now.ton(i) * p.torque_body_Nm.col(i);
  });
  // The awake arm (flight/arm_reaction.hpp): dh/dt + w x h + d x F. Zero before the wake, and
  // skipped then, so that the rows stay bit for bit what they were.
  if (!now.arm_momentum_Nms.isZero() || !next.arm_momentum_Nms.isZero() || !now.com_shift_m.isZero())
    row += (next.arm_momentum_Nms - now.arm_momentum_Nms) * (1.0 / p.period_s) +
           now.omega_body_radps.cross(now.arm_momentum_Nms) + now.com_shift_m.cross(commanded_force_body_N(p, now));
  return row;
}

Vec3 deficit_sigma0_sq(const DeficitBankState& bank) {
  return bank.torque_mean_square.cwiseMin(bank.torque_mean_square_lagged).cwiseMax(bank.noise_floor_sq);
}

namespace {

// sigma_0^2 + (epsilon |M_C| T_on)^2 per axis.
Vec3 pulse_variance(const DeficitIsolationParams& p, const DeficitBankState& bank, const WatchedTon& ton) {
  // epsilon |M_C| T_on over the commanded thrusters only: most periods command none.
  Vec3 pulse = Vec3::Zero();
  with_lanes(p.lanes, [&](auto lanes) {
    for (int i = 0; i < lanes; ++i)
      if (ton(i) > 0.0) pulse += ton(i) * p.torque_body_Nm.col(i).cwiseAbs();
  });
  pulse *= p.pulse_uncertainty;
  return deficit_sigma0_sq(bank) + pulse.cwiseProduct(pulse);
}

// Per axis, |u| x |v| with every product counted positive: a bound of (x u) x v's component for
// any x with |x_i| <= 1.
Vec3 abs_cross(const Vec3& u, const Vec3& v) {
  return Vec3(u(1) * v(2) + u(2) * v(1), u(2) * v(0) + u(0) * v(2), u(0) * v(1) + u(1) * v(0));
}

}  // namespace

const WatchedTon& deficit_commands_before(const DeficitBankState& bank, std::int64_t sample) {
  const bool held = sample >= 1 && sample - 1 >= bank.count - kMaxDeficitWindow;
  return held ? sample_at(bank, sample - 1).ton : kNoCommands;
}

Vec3 deficit_model_sigma(const DeficitIsolationParams& p, const DeficitSample& now, const WatchedTon& previous_ton) {
  // Delay spill: only pulses longer than 1 - tau_max / T of the period can end in the next one.
  const double spill_above = 1.0 - p.spill_fraction;
  Vec3 spill = Vec3::Zero();
  // Most periods command no pulse that long (MSR's approach: none): one vectorised test over the
  // whole capacity (the lanes past the set are zero, watched_set.hpp).
  if (now.ton.cwiseMax(previous_ton).maxCoeff() > spill_above) with_lanes(p.lanes, [&](auto lanes) {
    for (int i = 0; i < lanes; ++i) {
      const double out = std::max(now.ton(i) - spill_above, 0.0), in = std::max(previous_ton(i) - spill_above, 0.0);
      if (out + in > 0.0) spill += (out + in) * p.torque_body_Nm.col(i).cwiseAbs();
    }
  });
  Vec3 variance = spill.cwiseAbs2();
  // The two bounds a scenario may leave at zero (MSR) cost nothing then: every period runs this.
  if (p.inertia_uncertainty > 0.0) {
    const Vec3 w = now.omega_body_radps.cwiseAbs();
    variance += (p.inertia_uncertainty * abs_cross(w, p.inertia_kgm2.cwiseAbs() * w)).cwiseAbs2();
  }
  if (p.com_uncertainty_m > 0.0)
    variance += (p.com_uncertainty_m * abs_cross(Vec3::Ones(), commanded_force_body_N(p, now).cwiseAbs())).cwiseAbs2();
  return variance.cwiseSqrt();
}

Vec3 deficit_torque_weights(const DeficitIsolationParams& p, const DeficitBankState& bank, const DeficitSample& now,
                            const WatchedTon& previous_ton) {
  const Vec3 model = deficit_model_sigma(p, now, previous_ton);
  return (pulse_variance(p, bank, now.ton) + model.cwiseProduct(model)).cwiseInverse();
}

namespace {

// Maximise 2 g'x - x'Hx (the drop of the RSS) over a >= 0, b <= 0: every fault case has a
// non-negative constant deficit and a non-positive command-proportional one (docs/fdi.md). The
// optimum is the unconstrained one if feasible, else on the better face (the origin when neither
// gains). At an optimum H x = g in the free coordinates, so the drop is g'x: no cancellation
// between 2 g'x and x'Hx.
//
// One division per lane (three made the fits a tenth of the FDI's time). Each candidate is a
// numerator over one denominator: the free optimum (n_a, n_b) / det, n_a = hbb ga - hab gb,
// n_b = haa gb - hab ga, gain (n_a ga + n_b gb) / det; the a-face max(ga, 0) / haa, gain
// max(ga, 0)^2 / haa; the b-face min(gb, 0) / hbb, gain min(gb, 0)^2 / hbb. The choice is made on
// the numerators' signs (det > 0 where the free optimum is used) and on the faces' gains
// cross-multiplied by haa hbb > 0, then the chosen numerators are divided by the chosen
// denominator. Every candidate is computed and the answer selected without branches, so that
// fit_deficits' loop over the hypotheses vectorises (with -fno-trapping-math, CMakeLists.txt); a
// && would be a branch, hence the nested selects. A singular lane (det or hbb = 0: a thruster never
// commanded) never selects them.
inline DeficitFit fit_lane(double haa, double hab, double hbb, double ga, double gb) {
  const double det = haa * hbb - hab * hab;
  const double n_a = hbb * ga - hab * gb, n_b = haa * gb - hab * ga;
  const double free_gain = n_a * ga + n_b * gb;
  const double ga_pos = std::max(ga, 0.0), gb_neg = std::min(gb, 0.0);  // the faces' optima, times haa or hbb
  const double a_gain = ga_pos * ga_pos, b_gain = gb_neg * gb_neg;       // their gains, times haa or hbb
  const bool b_face = hbb > 0.0 ? b_gain * haa > a_gain * hbb : false;
  const double face_den = b_face ? hbb : (haa > 0.0 ? haa : 1.0);  // the origin (haa = 0): 0 / 1
  const double face_a = b_face ? 0.0 : ga_pos, face_b = b_face ? gb_neg : 0.0;
  const double face_gain = b_face ? b_gain : a_gain;
  const bool free_ok = det > 0.0 ? (n_a >= 0.0 ? n_b <= 0.0 : false) : false;
  const double inv = 1.0 / (free_ok ? det : face_den);
  return DeficitFit{(free_ok ? n_a : face_a) * inv, (free_ok ? n_b : face_b) * inv, (free_ok ? free_gain : face_gain) * inv};
}

}  // namespace

DeficitFit fit_deficit(const DeficitNormal& n) { return fit_lane(n.haa, n.hab, n.hbb, n.ga, n.gb); }

// Compiled twice, for AVX2 (four lanes a vector, blends) and for the x86-64 baseline (two lanes,
// and/andnot/or selects), the one the CPU runs chosen at load time. The lanes' arithmetic is
// element by element, without reductions, so both give the same bits (tested against fit_deficit).
__attribute__((target_clones("avx2", "default")))
DeficitFits fit_deficits(const DeficitNormalsW& normals, int lanes) {
  const double* haa = normals.col(0).data();
  const double* hab = normals.col(1).data();
  const double* hbb = normals.col(2).data();
  const double* ga = normals.col(3).data();
  const double* gb = normals.col(4).data();
  DeficitFits f{DeficitVecW(), DeficitVecW(), DeficitVecW()};  // the lanes' entries are written below: no zeroing
  for (int i = 0; i < lanes; ++i) {
    const DeficitFit fit = fit_lane(haa[i], hab[i], hbb[i], ga[i], gb[i]);
    f.a(i) = fit.a, f.b(i) = fit.b, f.gain(i) = fit.gain;
  }
  return f;
}

std::vector<std::string> validate(const DeficitIsolationParams& p) {
  std::vector<std::string> problems;
  if (p.lanes < 1 || p.lanes > kMaxWatchedThrusters)
    problems.push_back("lanes: must be in [1, " + std::to_string(kMaxWatchedThrusters) + "]");
  if (!(p.mass_kg > 0.0)) problems.push_back("mass_kg: must be > 0");
  if (!(p.period_s > 0.0)) problems.push_back("period_s: must be > 0");
  if (p.before < 1) problems.push_back("before: must be >= 1 period");
  if (p.after < 2) problems.push_back("after: must be >= 2 periods");
  if (p.max_window < p.before + p.after || p.max_window > kMaxDeficitWindow - 1)
    problems.push_back("max_window: must be in [before + after, " + std::to_string(kMaxDeficitWindow - 1) + "]");
  if (p.reevaluate_every < 1) problems.push_back("reevaluate_every: must be >= 1");
  if (!(p.lidar_sigma_m > 0.0)) problems.push_back("lidar_sigma_m: must be > 0");
  if (!(p.gyro_sigma_radps > 0.0)) problems.push_back("gyro_sigma_radps: must be > 0");
  if (!(p.pulse_uncertainty >= 0.0)) problems.push_back("pulse_uncertainty: must be >= 0");
  if (!(p.spill_fraction >= 0.0 && p.spill_fraction <= 1.0)) problems.push_back("spill_fraction: must be in [0, 1]");
  if (!(p.inertia_uncertainty >= 0.0) || !(p.com_uncertainty_m >= 0.0))
    problems.push_back("inertia_uncertainty, com_uncertainty_m: must be >= 0");
  if (!(p.noise_time_constant_s > 0.0)) problems.push_back("noise_time_constant_s: must be > 0");
  if (p.noise_snapshot_periods < 1) problems.push_back("noise_snapshot_periods: must be >= 1");
  if (!(p.min_gain >= 0.0) || !(p.min_margin >= 0.0)) problems.push_back("min_gain, min_margin: must be >= 0");
  if (!(p.prior_sigma > 0.0)) problems.push_back("prior_sigma: must be > 0");
  return problems;
}

void set_deficit_columns(DeficitIsolationParams& p, const Eigen::Ref<const Eigen::Matrix<double, 6, Eigen::Dynamic>>& M) {
  p.lanes = static_cast<int>(M.cols());
  p.force_body_N.setZero(), p.torque_body_Nm.setZero();
  p.force_body_N.leftCols(p.lanes) = M.topRows<3>();
  p.torque_body_Nm.leftCols(p.lanes) = M.bottomRows<3>();
}

void push_deficit_sample(const DeficitIsolationParams& p, DeficitBankState& bank) {
  const DeficitSample& sample = next_deficit_sample(bank);
  if (bank.count == 0) bank.torque_mean_square = bank.noise_floor_sq = torque_noise_floor_sq(p);
  if (bank.count > 0) bank.last_torque_row = deficit_torque_row(p, sample_at(bank, bank.count - 1), sample);
  if (bank.count > 0 && !bank.frozen) {
    const Vec3& y = bank.last_torque_row;
    const double alpha = std::min(1.0, p.period_s / p.noise_time_constant_s);
    bank.torque_mean_square += alpha * (y.cwiseProduct(y) - bank.torque_mean_square);
    if (bank.snapshot_phase == 0) {
      bank.torque_mean_square_lagged = bank.torque_mean_square_snapshot;
      bank.torque_mean_square_snapshot = bank.torque_mean_square;
    }
  }
  ++bank.count;
  bank.snapshot_phase = bank.snapshot_phase + 1 < p.noise_snapshot_periods ? bank.snapshot_phase + 1 : 0;
}

DeficitHypotheses evaluate_deficit_hypotheses(const DeficitIsolationParams& p, const DeficitBankState& bank,
                                              std::int64_t first, std::int64_t last_onset) {
  DeficitHypotheses h;
  first = std::max({first, std::int64_t{0}, bank.count - kMaxDeficitWindow});
  Window w;
  w.n = static_cast<int>(bank.count - first);
  if (w.n < 3) return h;
  h.rss_no_fault = build_window(p, bank, first, w);
  h.rows = 3 * w.n + 3 * (w.n - 1);
  const int last_kf = static_cast<int>(std::clamp<std::int64_t>(last_onset - first, 0, w.n - 2));
  auto fit_all = [&](double torque_scale) {
    for (int i = 0; i < p.lanes; ++i) {
      h.gain(i) = -1.0;
      for (int kf = 0; kf <= last_kf; ++kf) {
        const DeficitFit fit = fit_deficit(with_prior(p, normal_equations(p, w, i, kf, 1.0, torque_scale)));
        if (fit.gain > h.gain(i)) h.gain(i) = fit.gain, h.a(i) = fit.a, h.b(i) = fit.b, h.onset[i] = first + kf;
      }
    }
  };
  fit_all(1.0);
  // Model misfit: when even the best hypothesis leaves the torque rows far above their noise (a
  // leak's ramp fitted as a step, a dispersed centre of mass or inertia), those rows would decide
  // between hypotheses by how each bends a wrong model, not by evidence; partners, alike in torque,
  // would be told apart by chance. Their weights are then divided by the misfit (the Birge ratio),
  // so the position rows carry the choice between partners, and the fit is redone.
  int best = 0;
  for (int i = 1; i < p.lanes; ++i)
    if (h.gain(i) > h.gain(best)) best = i;
  const double chi2 = torque_chi2_per_row(p, w, best, static_cast<int>(h.onset[best] - first), h.a(best), h.b(best));
  if (chi2 > p.misfit_rescale_above) {
    h.torque_scale = 1.0 / chi2;
    h.rss_no_fault = w.rss_position + w.rss_torque * h.torque_scale;
    fit_all(h.torque_scale);
  }
  return h;
}

void classify_deficit(const DeficitIsolationParams& p, DeficitDecision& d) {
  if (d.a > p.open_a) {
    d.kind = model::FaultKind::kStuckOpen, d.size = 1.0;
  } else if (d.a > p.leak_a) {
    d.kind = model::FaultKind::kLeak, d.size = d.a;
  } else if (d.b < p.closed_b) {
    d.kind = model::FaultKind::kStuckClosed, d.size = 1.0;
  } else {
    d.kind = model::FaultKind::kLoss, d.size = -d.b;
  }
}

const DeficitDecision& step_deficit_decision(const DeficitIsolationParams& p, const DeficitBankState& bank,
                                             DeficitDecisionState& state, std::int64_t alarm_sample) {
  DeficitDecision& d = state.decision;
  if (d.decided || alarm_sample < 0) return d;
  if (state.alarm_sample < 0) state.alarm_sample = alarm_sample, state.next_evaluation = alarm_sample + p.after;
  const std::int64_t now = bank.count - 1;
  if (now < state.next_evaluation) return d;

  const std::int64_t first = std::max<std::int64_t>(state.alarm_sample - p.before, 0);
  const DeficitHypotheses h = evaluate_deficit_hypotheses(p, bank, first, state.alarm_sample);
  int best = 0;
  for (int i = 1; i < p.lanes; ++i)
    if (h.gain(i) > h.gain(best)) best = i;
  double second = -1.0;
  for (int i = 0; i < p.lanes; ++i)
    if (i != best) second = std::max(second, h.gain(i));
  const bool material = h.a(best) >= p.min_a || h.b(best) <= -p.min_b;
  const bool named = h.gain(best) >= p.min_gain && material;
  const bool clear = named && h.gain(best) - second >= p.min_margin;
  const bool last_chance = (bank.count - first) + p.reevaluate_every > p.max_window;
  if (!clear && !last_chance) {
    state.next_evaluation = now + p.reevaluate_every;
    return d;
  }
  d.decided = true;
  d.gain = h.gain(best), d.margin = h.gain(best) - second;
  if (!named) return d;  // no thruster's fault explains the alarm: name none
  d.thruster = best, d.a = h.a(best), d.b = h.b(best), d.onset_sample = h.onset[best];
  classify_deficit(p, d);
  return d;
}

}  // namespace chaser::flight::fdi
