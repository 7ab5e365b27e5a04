#include "model/thruster_set_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <coin/ClpSimplex.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "model/positive_span.hpp"

namespace chaser::model {
namespace {

constexpr std::array<std::string_view, kSignedAxes> kAxisNames = {
    "+Fx", "-Fx", "+Fy", "-Fy", "+Fz", "-Fz", "+Cx", "-Cx", "+Cy", "-Cy", "+Cz", "-Cz"};

void validate(const ThrusterSetMatrix& m) {
  if (m.cols() < 1 || m.cols() > kMaxAnalysedThrusters)
    throw std::invalid_argument(fmt::format("thruster set analysis: {} thrusters, expected 1..{}",
                                            m.cols(), kMaxAnalysedThrusters));
  if (!m.allFinite())
    throw std::invalid_argument("thruster set analysis: non-finite configuration matrix entry");
}

struct AxisSolution {
  double t = 0.0;     // attained value, in units of the scaled matrix
  Eigen::VectorXd u;  // on-times
};

// max t s.t. A u - t e_axis = 0, 0 <= u <= 1 (u_lost = 0), t >= 0, with A = M / scale so the
// entries are of order 1 and CLP's absolute tolerances act as relative ones. Scaling is off so
// they hold on the problem as stated. The LP is feasible and bounded, so a failure to prove
// optimality can only be a tolerance CLP cannot meet: retry looser, as tests/flight does.
AxisSolution solve_axis(const Eigen::MatrixXd& a, int axis, int lost) {
  const int n = static_cast<int>(a.cols());
  const int component = axis / 2;
  const double sign = axis % 2 == 0 ? 1.0 : -1.0;
  std::vector<CoinBigIndex> start{0};
  std::vector<int> index;
  std::vector<double> value;
  for (int c = 0; c < n; ++c) {
    for (int r = 0; r < 6; ++r)
      if (a(r, c) != 0.0) index.push_back(r), value.push_back(a(r, c));
    start.push_back(static_cast<CoinBigIndex>(index.size()));
  }
  index.push_back(component), value.push_back(-sign);  // the column of t
  start.push_back(static_cast<CoinBigIndex>(index.size()));

  std::vector<double> col_lb(n + 1, 0.0), col_ub(n + 1, 1.0), obj(n + 1, 0.0);
  if (lost >= 0 && lost < n) col_ub[lost] = 0.0;
  col_ub[n] = COIN_DBL_MAX;
  obj[n] = -1.0;  // CLP minimises
  const std::vector<double> row_bound(6, 0.0);

  for (const double tol : {1e-12, 1e-11, 1e-10}) {
    ClpSimplex model;
    model.setLogLevel(0);
    model.loadProblem(n + 1, 6, start.data(), index.data(), value.data(), col_lb.data(),
                      col_ub.data(), obj.data(), row_bound.data(), row_bound.data());
    model.setPrimalTolerance(tol);
    model.setDualTolerance(tol);
    model.scaling(0);
    model.dual();
    if (!model.isProvenOptimal()) continue;
    const double* x = model.primalColumnSolution();
    AxisSolution out;
    out.u = Eigen::Map<const Eigen::VectorXd>(x, n);
    out.t = x[n];
    return out;
  }
  throw std::runtime_error(fmt::format("thruster set analysis: CLP found no optimum along {}",
                                       kAxisNames[static_cast<std::size_t>(axis)]));
}

Eigen::MatrixXd without_column(const ThrusterSetMatrix& m, int lost) {
  Eigen::MatrixXd out(6, m.cols() - 1);
  for (int c = 0, k = 0; c < m.cols(); ++c)
    if (c != lost) out.col(k++) = m.col(c);
  return out;
}

bool spans(const Eigen::MatrixXd& m) { return m.cols() > 0 && positive_span(m).spans; }

SingleLossAnalysis single_loss(const ThrusterSetMatrix& m, const AttainableAxes& before, int lost,
                               std::string name) {
  SingleLossAnalysis out;
  out.lost = lost;
  out.name = std::move(name);
  out.axes = attainable_axes(m, lost);
  out.spans = spans(without_column(m, lost));
  for (int k = 0; k < kSignedAxes; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (before.value[i] <= 0.0) continue;  // nothing to shrink
    const double ratio = out.axes.value[i] / before.value[i];
    if (out.shrink_axis < 0 || ratio < out.shrink_ratio)
      out.shrink_ratio = ratio, out.shrink_axis = k;
  }
  return out;
}

}  // namespace

std::string_view signed_axis_name(int axis) {
  if (axis < 0 || axis >= kSignedAxes) throw std::out_of_range("signed axis index");
  return kAxisNames[static_cast<std::size_t>(axis)];
}

std::string_view signed_axis_unit(int axis) {
  if (axis < 0 || axis >= kSignedAxes) throw std::out_of_range("signed axis index");
  return axis < 6 ? "N" : "N m";
}

AttainableAxes attainable_axes(const ThrusterSetMatrix& m, int lost) {
  validate(m);
  const double col_max = m.colwise().norm().maxCoeff();  // [N or N m, mixed: only a scale]
  const double scale = col_max > 0.0 ? col_max : 1.0;
  const Eigen::MatrixXd a = m / scale;
  AttainableAxes out;
  for (int k = 0; k < kSignedAxes; ++k) {
    const auto i = static_cast<std::size_t>(k);
    AxisSolution s = solve_axis(a, k, lost);
    if (s.t < kAttainableZeroTolerance) {  // rounding-level push: the axis is not attainable
      out.value[i] = 0.0;
      out.on_times[i] = Eigen::VectorXd::Zero(m.cols());
    } else {
      out.value[i] = s.t * scale;
      out.on_times[i] = std::move(s.u);
    }
  }
  return out;
}

ThrusterSetAnalysis analyse_thruster_set(const ThrusterSetMatrix& m,
                                         std::vector<std::string> names) {
  validate(m);
  const int n = static_cast<int>(m.cols());
  if (names.empty())
    for (int j = 0; j < n; ++j) names.push_back(fmt::format("T{}", j + 1));
  if (static_cast<int>(names.size()) != n)
    throw std::invalid_argument(
        fmt::format("thruster set analysis: {} names for {} thrusters", names.size(), n));

  ThrusterSetAnalysis out;
  out.names = std::move(names);
  out.axes = attainable_axes(m);
  out.spans = spans(m);
  out.tolerates_single_loss = out.spans;
  for (int j = 0; j < n; ++j) {
    out.single_losses.push_back(
        single_loss(m, out.axes, j, out.names[static_cast<std::size_t>(j)]));
    out.tolerates_single_loss = out.tolerates_single_loss && out.single_losses.back().spans;
  }
  return out;
}

namespace {

const char* yes_no(bool b) { return b ? "yes" : "no"; }

// One table of six signed axes (first = 0: forces, 6: torques), a row for the full set and one
// per single loss; a value column is 10 wide, enough for 9999.999 N.
void append_axis_table(std::string& s, const ThrusterSetAnalysis& a, int first) {
  s += fmt::format("\nLargest pure {} [{}] along each signed body axis, on-times in [0, 1]:\n",
                   first == 0 ? "force" : "torque", signed_axis_unit(first));
  s += fmt::format("{:<14}", "set");
  for (int k = first; k < first + 6; ++k) s += fmt::format("{:>10}", signed_axis_name(k));
  s += fmt::format("{:>7}\n", "spans");
  const auto row = [&](const std::string& label, const AttainableAxes& axes, bool spans) {
    s += fmt::format("{:<14}", label);
    for (int k = first; k < first + 6; ++k)
      s += fmt::format("{:>10.3f}", axes.value[static_cast<std::size_t>(k)]);
    s += fmt::format("{:>7}\n", yes_no(spans));
  };
  row("all", a.axes, a.spans);
  for (const SingleLossAnalysis& l : a.single_losses) row("without " + l.name, l.axes, l.spans);
}

}  // namespace

std::string format_thruster_set_analysis(const ThrusterSetAnalysis& a) {
  std::string s =
      fmt::format("Thruster set of {} thrusters (COMRADE 2018, sec. 6 analysis)\n", a.names.size());
  s += fmt::format("Positively spans R^6 (force and torque in every direction): {}\n",
                   yes_no(a.spans));
  s += fmt::format("Tolerates any single thruster loss (every N-1 set spans):  {}\n",
                   yes_no(a.tolerates_single_loss));
  append_axis_table(s, a, 0);
  append_axis_table(s, a, 6);
  s += "\nShrink on single loss: smallest attained_after / attained_before over the 12 axes\n";
  s += fmt::format("{:<12}{:>7}{:>8}{:>6}\n", "lost", "spans", "ratio", "axis");
  for (const SingleLossAnalysis& l : a.single_losses)
    s += fmt::format("{:<12}{:>7}{:>8.3f}{:>6}\n", l.name, yes_no(l.spans), l.shrink_ratio,
                     l.shrink_axis < 0 ? std::string_view("-") : signed_axis_name(l.shrink_axis));
  return s;
}

std::string thruster_set_analysis_json(const ThrusterSetAnalysis& a) {
  using nlohmann::json;
  const auto values = [](const AttainableAxes& axes) {
    return json(std::vector<double>(axes.value.begin(), axes.value.end()));
  };
  json axes = json::array();
  for (int k = 0; k < kSignedAxes; ++k) axes.push_back(std::string(signed_axis_name(k)));
  json losses = json::array();
  for (const SingleLossAnalysis& l : a.single_losses) {
    losses.push_back(
        {{"lost", l.name},
         {"index", l.lost},
         {"attainable", values(l.axes)},
         {"spans", l.spans},
         {"shrink_ratio", l.shrink_ratio},
         {"shrink_axis",
          l.shrink_axis < 0 ? json(nullptr) : json(std::string(signed_axis_name(l.shrink_axis)))}});
  }
  const json j = {{"thrusters", a.names},
                  {"axes", axes},
                  {"units", {{"force", "N"}, {"torque", "N m"}}},
                  {"attainable", values(a.axes)},
                  {"spans", a.spans},
                  {"tolerates_single_loss", a.tolerates_single_loss},
                  {"single_loss", losses}};
  return j.dump(2);
}

}  // namespace chaser::model
