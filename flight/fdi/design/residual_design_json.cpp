#include "flight/fdi/design/residual_design_json.hpp"

namespace chaser::flight::fdi {

using nlohmann::json;

namespace {

json matrix_json(const Eigen::MatrixXd& m) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

json vector_json(const Eigen::VectorXd& v) {
  return json(std::vector<double>(v.data(), v.data() + v.size()));
}

const char* low_rank_name(LowRankMethod m) {
  return m == LowRankMethod::kTruncateSeenPart ? "truncate_seen_part" : "truncate_whole";
}

const char* weighting_name(WeightingChoice w) {
  return w == WeightingChoice::kMaxWeakestDcGain ? "max_weakest_dc_gain" : "svd_order";
}

json inputs_json(const DesignInputs& in) {
  return {{"name", in.name},
          {"residual_unit", in.residual_unit},
          {"period_s", in.period_s},
          {"delta_min_s", in.delta_min_s},
          {"delta_max_s", in.delta_max_s},
          {"taylor_order", in.taylor_order},
          {"residual_dim", in.residual_dim},
          {"eigenvalues", in.eigenvalues},
          {"use_cayley_hamilton", in.use_cayley_hamilton},
          {"use_taylor", in.use_taylor},
          {"low_rank", low_rank_name(in.low_rank)},
          {"weighting", weighting_name(in.weighting)},
          {"A", matrix_json(in.A)},
          {"B", matrix_json(in.B)},
          {"E_f", matrix_json(in.E_f)}};
}

json figures_json(const DesignFigures& f, const EigenstructureAssignment& a) {
  json eig = json::array();
  for (const auto& z : f.achieved_eigenvalues) eig.push_back({z.real(), z.imag()});
  return {{"achieved_eigenvalues", eig},
          {"assignability_error", a.relative_miss},
          {"p_condition", a.p_condition},
          {"frequency_hz", f.frequency_hz},
          {"unknown_input_gain", vector_json(f.unknown_input_gain)},
          {"unknown_input_gain_max", f.unknown_input_gain_max},
          {"designed_input_gain", vector_json(f.designed_input_gain)},
          {"designed_input_gain_max", f.designed_input_gain_max},
          {"delay_gain", vector_json(f.delay_gain)},
          {"delay_gain_max", f.delay_gain_max},
          {"fault_gain", matrix_json(f.fault_gain)},
          {"fault_gain_dc", vector_json(f.fault_gain_dc)},
          {"command_delay_gain_max", vector_json(f.command_delay_gain_max)}};
}

}  // namespace

json to_json(const ResidualDesign& d) {
  return {{"inputs", inputs_json(d.inputs)},
          {"A_bar", matrix_json(d.A_bar)},
          {"B_bar", matrix_json(d.B_bar)},
          {"C", matrix_json(d.inputs.C)},
          {"E_f_bar", matrix_json(d.E_f_bar)},
          {"L", matrix_json(d.L)},
          {"Q", matrix_json(d.Q)},
          {"unknown_input",
           {{"columns", d.E_d.cols()},
            {"seen_singular_values", vector_json(d.low_rank.singular_values)},
            {"tied_directions", d.low_rank.tied.cols()},
            {"chosen_directions", d.low_rank.choose},
            {"low_rank_error", d.low_rank_error},
            {"low_rank_optimum", d.low_rank_optimum},
            {"E_d_star_rank", d.E_d_factors.E1.cols()},
            {"E_d1", matrix_json(d.E_d_factors.E1)}}},
          {"cayley_hamilton",
           {{"coefficients", vector_json(d.cayley_hamilton.coefficients)},
            {"s_min", vector_json(d.cayley_hamilton.s_min)},
            {"s_max", vector_json(d.cayley_hamilton.s_max)}}},
          {"figures", figures_json(d.figures, d.assignment)}};
}

json to_json(const RateModel& m) {
  json modes = json::array();
  for (const SloshModeFigures& f : m.modes)
    modes.push_back({{"frequency_radps", f.frequency_radps},
                     {"damping_ratio", f.damping_ratio},
                     {"controllability", f.controllability},
                     {"observability", f.observability},
                     {"kept", f.kept}});
  return {{"states", m.state_names},
          {"thrusters", m.thrusters},
          {"full", {{"A", matrix_json(m.A)}, {"B", matrix_json(m.B)}, {"E", matrix_json(m.E)}, {"C", matrix_json(m.C)}}},
          {"reduced",
           {{"order", m.A_reduced.rows()},
            {"A", matrix_json(m.A_reduced)},
            {"B", matrix_json(m.B_reduced)},
            {"E", matrix_json(m.E_reduced)},
            {"C", matrix_json(m.C_reduced)}}},
          {"slosh_modes", modes}};
}

json to_json(const UioBank& b) {
  const auto observer = [](const UioObserver& o) {
    return json{{"thruster", o.thruster + 1},  // 0: the nominal observer, blind to none
                {"gamma_min", o.gamma_min},
                {"gamma", o.gamma},
                {"gamma_sweep", o.gamma_sweep},
                {"spectral_radius", o.spectral_radius},
                {"residual_noise_rms_radps", o.residual_noise_rms},
                {"N", matrix_json(o.N)},
                {"G", matrix_json(o.G)},
                {"L", matrix_json(o.L)},
                {"H", matrix_json(o.H)},
                {"Q", matrix_json(o.Q)}};
  };
  json observers = json::array();
  for (const UioObserver& o : b.observers) observers.push_back(observer(o));
  json closest = json::array();
  for (std::size_t j = 0; j < b.closest.size(); ++j) {
    json blind = json::array();
    for (const int o : b.blind[j]) blind.push_back(o + 1);
    closest.push_back({{"thruster", j + 1}, {"blind", blind}, {"observer", b.closest[j] + 1}, {"snr", b.isolation_snr[j]}});
  }
  return {{"model", {{"Ad", matrix_json(b.Ad)}, {"Bd", matrix_json(b.Bd)}, {"Ed", matrix_json(b.Ed)}, {"C", matrix_json(b.C)}}},
          {"nominal", observer(b.nominal)},
          {"observers", observers},
          {"fault_gain_radps", matrix_json(b.fault_gain)},
          {"closest", closest}};
}

}  // namespace chaser::flight::fdi
