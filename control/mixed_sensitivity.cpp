#include "control/mixed_sensitivity.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace chaser::control {

using Eigen::Index;
using Eigen::MatrixXd;

StateSpace performance_weight(double peak_m, double bandwidth_radps, double low_freq_gain_a) {
  // w_P = (1/M) (s + M omega_B) / (s + omega_B A) = 1/M + (omega_B - omega_B A / M) / (s + omega_B A).
  StateSpace w;
  w.a = MatrixXd::Constant(1, 1, -bandwidth_radps * low_freq_gain_a);
  w.b = MatrixXd::Constant(1, 1, 1.0);
  w.c = MatrixXd::Constant(1, 1, bandwidth_radps * (1.0 - low_freq_gain_a / peak_m));
  w.d = MatrixXd::Constant(1, 1, 1.0 / peak_m);
  return w;
}

namespace {

void check_weight(const std::optional<StateSpace>& w, const char* name, Index inputs, const char* on,
                  std::vector<std::string>& problems) {
  if (!w) return;
  for (std::string& s : validate(*w, name)) problems.push_back(std::move(s));
  if (w->inputs() != inputs)
    problems.push_back(std::string(name) + ": must have " + std::to_string(inputs) + " inputs (" + on + "), got " +
                       std::to_string(w->inputs()));
  if (w->outputs() == 0) problems.push_back(std::string(name) + ": has no outputs");
}

void validate_inputs(const StateSpace& g, const MixedSensitivityWeights& w) {
  std::vector<std::string> problems = validate(g, "plant G");
  if (g.inputs() == 0 || g.outputs() == 0) problems.push_back("plant G: needs at least one input and one output");
  check_weight(w.w_s, "W_S", g.outputs(), "one per output of G: it weighs e", problems);
  check_weight(w.w_ks, "W_KS", g.inputs(), "one per input of G: it weighs u", problems);
  check_weight(w.w_t, "W_T", g.outputs(), "one per output of G: it weighs y", problems);
  check_weight(w.w_d, "W_d", g.inputs(), "one per input of G: it shapes the input disturbance", problems);
  if (w.w_d && w.w_d->outputs() != g.inputs())
    problems.push_back("W_d: must have " + std::to_string(g.inputs()) + " outputs (one per input of G), got " +
                       std::to_string(w.w_d->outputs()));
  if (!w.w_s && !w.w_ks && !w.w_t) problems.push_back("no weight given: at least one of W_S, W_KS, W_T");
  if (problems.empty()) return;
  std::string all = "mixed_sensitivity_plant: invalid input:";
  for (const std::string& s : problems) all += "\n  " + s;
  throw std::invalid_argument(all);
}

const StateSpace kAbsent{MatrixXd(0, 0), MatrixXd(0, 0), MatrixXd(0, 0), MatrixXd(0, 0)};

}  // namespace

namespace {

// The plant of the header without W_d: inputs [r; u].
GeneralisedPlant reference_plant(const StateSpace& g, const MixedSensitivityWeights& weights) {
  const StateSpace& ws = weights.w_s ? *weights.w_s : kAbsent;
  const StateSpace& wks = weights.w_ks ? *weights.w_ks : kAbsent;
  const StateSpace& wt = weights.w_t ? *weights.w_t : kAbsent;
  const Index ny = g.outputs(), nu = g.inputs();
  const Index ng = g.states(), ns = ws.states(), nks = wks.states(), nt = wt.states();
  const Index n = ng + ns + nks + nt;
  const Index ps = ws.outputs(), pks = wks.outputs(), pt = wt.outputs();
  // Row and column offsets: states [x_G; x_S; x_KS; x_T], inputs [r; u], outputs [z1; z2; z3; e].
  const Index is = ng, iks = ng + ns, it = ng + ns + nks;
  const Index z2 = ps, z3 = ps + pks, ze = ps + pks + pt;

  GeneralisedPlant out;
  StateSpace& p = out.p;
  p.a = MatrixXd::Zero(n, n);
  p.b = MatrixXd::Zero(n, ny + nu);
  p.c = MatrixXd::Zero(ze + ny, n);
  p.d = MatrixXd::Zero(ze + ny, ny + nu);
  // G: x_G' = A_G x_G + B_G u, y = C_G x_G + D_G u.
  p.a.block(0, 0, ng, ng) = g.a;
  p.b.block(0, ny, ng, nu) = g.b;
  // W_S on e = r - y: x_S' = A_S x_S + B_S (r - C_G x_G - D_G u), z1 = C_S x_S + D_S (r - ...).
  if (weights.w_s) {
    p.a.block(is, is, ns, ns) = ws.a;
    p.a.block(is, 0, ns, ng) = -ws.b * g.c;
    p.b.block(is, 0, ns, ny) = ws.b;
    p.b.block(is, ny, ns, nu) = -ws.b * g.d;
    p.c.block(0, is, ps, ns) = ws.c;
    p.c.block(0, 0, ps, ng) = -ws.d * g.c;
    p.d.block(0, 0, ps, ny) = ws.d;
    p.d.block(0, ny, ps, nu) = -ws.d * g.d;
  }
  // W_KS on u.
  if (weights.w_ks) {
    p.a.block(iks, iks, nks, nks) = wks.a;
    p.b.block(iks, ny, nks, nu) = wks.b;
    p.c.block(z2, iks, pks, nks) = wks.c;
    p.d.block(z2, ny, pks, nu) = wks.d;
  }
  // W_T on y = C_G x_G + D_G u.
  if (weights.w_t) {
    p.a.block(it, it, nt, nt) = wt.a;
    p.a.block(it, 0, nt, ng) = wt.b * g.c;
    p.b.block(it, ny, nt, nu) = wt.b * g.d;
    p.c.block(z3, it, pt, nt) = wt.c;
    p.c.block(z3, 0, pt, ng) = wt.d * g.c;
    p.d.block(z3, ny, pt, nu) = wt.d * g.d;
  }
  // The measurement e = r - C_G x_G - D_G u.
  p.c.block(ze, 0, ny, ng) = -g.c;
  p.d.block(ze, 0, ny, ny) = MatrixXd::Identity(ny, ny);
  p.d.block(ze, ny, ny, nu) = -g.d;
  out.n_meas = static_cast<int>(ny);
  out.n_ctrl = static_cast<int>(nu);
  return out;
}

}  // namespace

GeneralisedPlant mixed_sensitivity_plant(const StateSpace& g, const MixedSensitivityWeights& weights) {
  validate_inputs(g, weights);
  GeneralisedPlant out = reference_plant(g, weights);
  if (!weights.w_d) return out;
  // d = W_d w_d reaches everything u reaches except W_KS (which weighs the controller's u alone):
  // its column block in [r; u]'s P is u's with W_KS's rows cleared. With W_d's states appended:
  // x_d' = A_d x_d + B_d w_d, d = C_d x_d + D_d w_d, so d's column into P is P_u (C_d x_d + D_d w_d).
  const StateSpace& wd = *weights.w_d;
  const Index ny = g.outputs(), nu = g.inputs(), nd = wd.inputs(), nwd = wd.states();
  const StateSpace& p0 = out.p;
  const Index n0 = p0.states();
  const Index ps = weights.w_s ? weights.w_s->outputs() : 0, pks = weights.w_ks ? weights.w_ks->outputs() : 0;
  const Index iks = g.states() + (weights.w_s ? weights.w_s->states() : 0);
  const Index nks = weights.w_ks ? weights.w_ks->states() : 0;
  MatrixXd b_u = p0.b.rightCols(nu);  // u's column block: state rows and output rows
  MatrixXd d_u = p0.d.rightCols(nu);
  b_u.middleRows(iks, nks).setZero();
  d_u.middleRows(ps, pks).setZero();
  StateSpace p;
  p.a = MatrixXd::Zero(n0 + nwd, n0 + nwd);
  p.a.topLeftCorner(n0, n0) = p0.a;
  p.a.block(0, n0, n0, nwd) = b_u * wd.c;
  p.a.bottomRightCorner(nwd, nwd) = wd.a;
  p.b = MatrixXd::Zero(n0 + nwd, ny + nd + nu);
  p.b.topLeftCorner(n0, ny) = p0.b.leftCols(ny);
  p.b.block(0, ny, n0, nd) = b_u * wd.d;
  p.b.block(n0, ny, nwd, nd) = wd.b;
  p.b.topRightCorner(n0, nu) = p0.b.rightCols(nu);
  p.c = MatrixXd::Zero(p0.outputs(), n0 + nwd);
  p.c.leftCols(n0) = p0.c;
  p.c.rightCols(nwd) = d_u * wd.c;
  p.d = MatrixXd::Zero(p0.outputs(), ny + nd + nu);
  p.d.leftCols(ny) = p0.d.leftCols(ny);
  p.d.middleCols(ny, nd) = d_u * wd.d;
  p.d.rightCols(nu) = p0.d.rightCols(nu);
  out.p = p;
  return out;
}

}  // namespace chaser::control
