#include "cli/fmea_report.hpp"

#include <fmt/format.h>

#include "core/constants.hpp"
#include "invsim/thruster_set.hpp"
#include "invsim/zhou2018_tables.hpp"

namespace chaser::cli {
namespace {

using invsim::FmeaRow;
using invsim::FmeaTable;

double deg(double rad) { return rad / kDegToRad; }
const char* yes_no(bool b) { return b ? "true" : "false"; }

std::string pulse_cells(const invsim::InvSimResult& r, const char* sep) {
  std::string out;
  for (int axis = 0; axis < 3; ++axis)
    for (int d = 0; d < 2; ++d) out += fmt::format("{}{}", sep, r.pulses[axis].count[d]);
  return out;
}

// "d1/d2~+e2/e1~" -> ("d1/d2~", "e2/e1~")
std::pair<std::string, std::string> split_multi(const std::string& label) {
  const auto plus = label.find('+');
  if (plus == std::string::npos) return {label, ""};
  return {label.substr(0, plus), label.substr(plus + 1)};
}

// Table 6's header cell: the pair and the moments its failed thrusters leave ("d1/d1~ Mz+/Mz-").
std::string moment_label(const model::InvSimParams& p, const std::string& pair) {
  std::string moments;
  std::size_t start = 0;
  while (start <= pair.size()) {
    const auto slash = pair.find('/', start);
    const std::string name = pair.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
    const auto i = invsim::find_thruster(p, name);
    // The paper's layout disturbs yaw only; another layout may turn a lost thruster's moment to
    // roll or pitch (Scheme II), so the label names the dominant axis.
    const Vec3 m = i ? invsim::fault_disturbing_moment(p, *i) : Vec3::Zero();
    Eigen::Index axis = 2;
    if (m.cwiseAbs().maxCoeff(&axis) == 0.0) axis = 2;
    if (!moments.empty()) moments += '/';
    moments += fmt::format("M{}{}", static_cast<char>('x' + axis), m(axis) > 0.0 ? "+" : (m(axis) < 0.0 ? "-" : "0"));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return pair + " " + moments;
}

// Cells "ours (paper)" for Zhou 2018's published figures (invsim/zhou2018_tables.hpp); the paper's
// ratio to nominal from its pulse counts, ours from our k_p.
struct PaperCells {
  std::string pulses, k_p, ratio, paper_class;
};

PaperCells paper_cells(const FmeaRow& row, double nominal_k_p) {
  const auto paper = invsim::zhou2018_row(row.fmea_case.table == FmeaTable::kNominal ? "nominal" : row.fmea_case.mode.label);
  const auto& r = row.result;
  const double ratio = nominal_k_p > 0.0 ? r.k_p / nominal_k_p : 0.0;
  PaperCells c;
  if (!paper || !paper->controllable) {
    const std::string mark = paper ? " (---)" : "";  // a row the paper prints as `---`, or does not print
    for (int axis = 0; axis < 3; ++axis)
      for (int d = 0; d < 2; ++d) c.pulses += fmt::format(" | {}{}", r.pulses[axis].count[d], mark);
    c.k_p = fmt::format("{:.3f}{}", r.k_p, mark);
    c.ratio = fmt::format("{:.2f}{}", ratio, mark);
    c.paper_class = paper ? "uncontrollable (`---`)" : "";
    return c;
  }
  const auto nominal = *invsim::zhou2018_row("nominal");
  int total = 0, nominal_total = 0;
  for (int i = 0; i < 6; ++i) {
    total += paper->pulses[static_cast<std::size_t>(i)];
    nominal_total += nominal.pulses[static_cast<std::size_t>(i)];
    c.pulses += fmt::format(" | {} ({})", row.result.pulses[i / 2].count[i % 2], paper->pulses[static_cast<std::size_t>(i)]);
  }
  c.k_p = fmt::format("{:.3f} ({:.2f})", r.k_p, paper->k_p);
  c.ratio = fmt::format("{:.2f} ({:.2f})", ratio, static_cast<double>(total) / nominal_total);
  c.paper_class = "controllable";
  return c;
}

double nominal_k_p(const std::vector<FmeaRow>& rows) {
  for (const FmeaRow& row : rows)
    if (row.fmea_case.table == FmeaTable::kNominal) return row.result.k_p;
  return 0.0;
}

constexpr const char* kPaperNote =
    "Each cell: ours (Zhou 2018's published figure, invsim/zhou2018_tables.hpp). Ratio: k_p over the "
    "nominal k_p (the paper's from its pulse counts). The paper prints no classes for Table 4 and "
    "`---` for its four uncontrollable Table 5 rows.\n\n";

void table4(std::string& md, const std::vector<FmeaRow>& rows) {
  md += "## Table 4: single-axis faults (pulses per body axis and direction, operational amount)\n\n";
  md += kPaperNote;
  md += "| Fault thrusters | x+ | x- | y+ | y- | z+ | z- | Operational amount k_p | / nominal | Class | Paper |\n";
  md += "|---|---|---|---|---|---|---|---|---|---|---|\n";
  const double k_nominal = nominal_k_p(rows);
  for (const FmeaRow& row : rows) {
    const FmeaTable t = row.fmea_case.table;
    if (t != FmeaTable::kNominal && t != FmeaTable::kSingleAxis) continue;
    const std::string name = t == FmeaTable::kNominal ? "—" : row.fmea_case.mode.label;
    const PaperCells c = paper_cells(row, k_nominal);
    md += fmt::format("| {}{} | {} | {} | {} | {} |\n", name, c.pulses, c.k_p, c.ratio,
                      invsim::risk_class_roman(row.risk), c.paper_class.empty() ? "not in Table 4" : c.paper_class);
  }
  md += "\n";
}

void table5(std::string& md, const std::vector<FmeaRow>& rows) {
  md += "## Table 5: multi-axis faults\n\n";
  md += kPaperNote;
  md += "| x-axis | y-axis | x+ | x- | y+ | y- | z+ | z- | Operational rate k_p | / nominal | Class | Paper |\n";
  md += "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const double k_nominal = nominal_k_p(rows);
  for (const FmeaRow& row : rows) {
    const FmeaTable t = row.fmea_case.table;
    if (t != FmeaTable::kNominal && t != FmeaTable::kMultiAxis) continue;
    const auto [x, y] = t == FmeaTable::kNominal ? std::pair<std::string, std::string>{"—", "—"}
                                                  : split_multi(row.fmea_case.mode.label);
    const PaperCells c = paper_cells(row, k_nominal);
    md += fmt::format("| {} | {}{} | {} | {} | {} | {} |\n", x, y, c.pulses, c.k_p, c.ratio,
                      invsim::risk_class_roman(row.risk), c.paper_class);
  }
  md += "\n(The paper prints `---` for its uncontrollable rows; we keep the figures and mark them Class III.)\n\n";
}

// Table 6: the 4 x 4 grid of x-axis pairs (rows) and y-axis pairs (columns), in Table 5's order.
}  // namespace

void append_table6(std::string& md, const model::InvSimParams& p, const std::vector<FmeaRow>& rows, const std::string& title) {
  std::vector<const FmeaRow*> multi;
  for (const FmeaRow& row : rows)
    if (row.fmea_case.table == FmeaTable::kMultiAxis) multi.push_back(&row);
  if (multi.size() != 16) return;
  md += title + "|";
  for (int c = 0; c < 4; ++c) md += " | " + moment_label(p, split_multi(multi[c]->fmea_case.mode.label).second);
  md += " |\n|---|---|---|---|---|\n";
  for (int r = 0; r < 4; ++r) {
    md += "| " + moment_label(p, split_multi(multi[4 * r]->fmea_case.mode.label).first);
    for (int c = 0; c < 4; ++c) md += fmt::format(" | {}", invsim::risk_class_roman(multi[4 * r + c]->risk));
    md += " |\n";
  }
  md += "\n";
}

namespace {

// The three-axis modes (ours): Table 5's 16 x-y modes down, the four z pairs across, the class.
void three_axis_grid(std::string& md, const std::vector<FmeaRow>& rows) {
  std::vector<const FmeaRow*> modes;
  for (const FmeaRow& row : rows)
    if (row.fmea_case.table == FmeaTable::kThreeAxis) modes.push_back(&row);
  if (modes.size() != 64) return;
  int controllable = 0;
  for (const FmeaRow* row : modes) controllable += row->controllable ? 1 : 0;
  md += fmt::format("## Three-axis faults (six failed thrusters; ours): {} of 64 controllable\n\n| x + y |", controllable);
  const auto z_pair = [](const FmeaRow* row) {
    const std::string& label = row->fmea_case.mode.label;
    return label.substr(label.rfind('+') + 1);
  };
  for (int c = 0; c < 4; ++c) md += fmt::format(" {} |", z_pair(modes[static_cast<std::size_t>(c)]));
  md += "\n|---|---|---|---|---|\n";
  for (std::size_t r = 0; r < 16; ++r) {
    const std::string& label = modes[4 * r]->fmea_case.mode.label;
    md += fmt::format("| {} |", label.substr(0, label.rfind('+')));
    for (std::size_t c = 0; c < 4; ++c) md += fmt::format(" {} |", invsim::risk_class_roman(modes[4 * r + c]->risk));
    md += "\n";
  }
  md += "\n";
}

void ranking(std::string& md, const std::vector<FmeaRow>& rows) {
  md += "## Ranking by risk (most severe first)\n\n";
  md += "| Rank | Mode | Class | k_p | peak az [deg] | peak el [deg] | peak attitude [deg] | deviation ratio | "
        "docked | propellant [kg] |\n";
  md += "|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i : invsim::risk_order(rows)) {
    const FmeaRow& row = rows[i];
    const auto& r = row.result;
    md += fmt::format("| {} | {} | {} ({}) | {:.3f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {} | {:.2f} |\n", row.rank,
                      row.fmea_case.mode.label, invsim::risk_class_roman(row.risk),
                      invsim::risk_class_name(row.risk), r.k_p, deg(r.peak_azimuth_rad),
                      deg(r.peak_elevation_rad), deg(r.peak_attitude_rad.maxCoeff()), row.deviation_ratio,
                      r.docked ? "yes" : "no", r.propellant_kg);
  }
}

}  // namespace

std::string fmea_options_problem(const io::InvSimLoadResult& loaded, const std::string& scenario_path,
                                 const FmeaOptions& options) {
  if (options.nominal_only && (options.optimize || options.three_axis))
    return "--nominal-only flies the nominal case alone: not with --optimize or --three-axis";
  if (options.optimize && loaded.study.free_choices.empty())
    return fmt::format("--optimize: {} marks no free mounting choice (optimize.choices)", scenario_path);
  return "";
}

FmeaStudy run_fmea_study(const io::InvSimLoadResult& loaded, const FmeaOptions& options) {
  FmeaStudy study;
  study.layouts.push_back({"baseline", "the scenario's thrusters", *loaded.params, {}});
  for (const model::InvSimConfiguration& c : loaded.study.configurations)
    study.layouts.push_back({c.name, c.description, model::apply_configuration(*loaded.params, c), {}});
  std::vector<model::InvSimParams> params;
  for (const FmeaLayout& layout : study.layouts) params.push_back(layout.params);
  std::vector<invsim::FmeaCase> cases = invsim::fmea_cases(*loaded.params, loaded.faults, options.three_axis);
  if (options.nominal_only) cases.resize(1);  // fmea_cases puts the nominal case first
  // The layouts are configurations of one scenario: a flight they share is flown once, unless every
  // pair's history is asked for.
  std::vector<std::vector<invsim::FmeaRow>> rows;
  if (options.history) {
    rows = invsim::run_fmea(params, cases, options.threads, &study.histories);
    study.flights = params.size() * cases.size();
  } else {
    rows = invsim::run_fmea_of_configurations(params, cases, options.threads, &study.flights);
  }
  for (std::size_t l = 0; l < study.layouts.size(); ++l) study.layouts[l].rows = std::move(rows[l]);
  if (options.optimize)
    study.optimized = invsim::search_layouts(*loaded.params, loaded.study.free_choices, cases, options.threads,
                                             &study.search_flights);
  return study;
}

std::vector<std::pair<std::string, std::string>> fmea_files(const FmeaStudy& study, int keep) {
  const std::vector<invsim::LayoutCandidate>* optimized = study.optimized ? &*study.optimized : nullptr;
  std::vector<std::pair<std::string, std::string>> files{{"fmea.csv", fmea_csv(study.layouts)},
                                                         {"fmea.md", fmea_markdown(study.layouts, optimized, keep)}};
  if (optimized != nullptr) files.emplace_back("optimize.csv", optimize_csv(*optimized));
  return files;
}

std::string fmea_csv(const std::vector<FmeaLayout>& layouts) {
  std::string csv =
      "configuration,mode,table,failed,x_pos,x_neg,y_pos,y_neg,z_pos,z_neg,total_pulses,k_p,"
      "peak_azimuth_deg,azimuth_limit_deg,peak_elevation_deg,elevation_limit_deg,"
      "peak_roll_deg,peak_pitch_deg,peak_yaw_deg,attitude_limit_deg,deviation_ratio,"
      "target_always_in_view,attitude_within_limits,docked,diverged,propellant_kg,"
      "attitude_propellant_kg,roll_on_time_s,pitch_on_time_s,yaw_on_time_s,controllable,risk_class,risk_rank\n";
  for (const FmeaLayout& layout : layouts) {
    const model::InvSimParams& p = layout.params;
    for (const FmeaRow& row : layout.rows) {
      const auto& r = row.result;
      csv += fmt::format("{},{},{},{}{},{},{:.4f},", layout.name, row.fmea_case.mode.label,
                         invsim::table_name(row.fmea_case.table), invsim::failed_names(p, row.fmea_case.mode.faults),
                         pulse_cells(r, ","), r.total_pulses, r.k_p);
      csv += fmt::format("{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},",
                         deg(r.peak_azimuth_rad), deg(p.sensor.azimuth_limit_rad), deg(r.peak_elevation_rad),
                         deg(p.sensor.elevation_limit_rad), deg(r.peak_attitude_rad.x()),
                         deg(r.peak_attitude_rad.y()), deg(r.peak_attitude_rad.z()),
                         deg(p.sensor.attitude_limit_rad), row.deviation_ratio);
      csv += fmt::format("{},{},{},{},{:.4f},{:.4f},{:.2f},{:.2f},{:.2f},{},{},{}\n", yes_no(r.target_always_in_view),
                         yes_no(r.attitude_within_limits), yes_no(r.docked), yes_no(r.diverged), r.propellant_kg,
                         r.attitude_propellant_kg, r.attitude_on_time_s.x(), r.attitude_on_time_s.y(),
                         r.attitude_on_time_s.z(), yes_no(row.controllable), invsim::risk_class_roman(row.risk),
                         row.rank);
    }
  }
  return csv;
}

namespace {

// fmea.md's first words: what one pulse is under the scenario's reading, and the paper reading's
// flight choices (docs/invsim.md, "Readings of App. B").
std::string reading_paragraph(const model::InvSimParams& p) {
  if (p.pulses.reading != model::InvSimReading::kPaper)
    return "Reading `smooth` (docs/invsim.md): a pulse is a step in which a body axis' translation group fired in "
           "that direction. ";
  const model::InvSimPaperReadingParams& paper = p.pulses.paper;
  const model::InvSimMeasurementNoise& noise = paper.measurement_noise;
  const std::string model = paper.inverse_model == model::InvSimInverseModel::kFaulted
                                ? "the inverse model flies the faulted spacecraft (a weakened group opens longer)"
                                : "the inverse model flies the nominal spacecraft (the pilot does not know the fault)";
  std::string measured = "measurement perfect";
  if (noise.enabled()) {
    const std::string draws = noise.draws > 1 ? fmt::format("seeds {} to {}, each row the mean workload and the worst "
                                                            "deviation over the {} draws",
                                                            noise.seed, noise.seed + noise.draws - 1, noise.draws)
                                              : fmt::format("seed {}", noise.seed);
    measured = fmt::format("measured range and angles with 1-sigma errors {:g} m and {:g} deg ({})", noise.range_sigma_m,
                           deg(noise.angle_sigma_rad), draws);
  }
  const std::string opening = paper.opening == model::InvSimOpening::kCarried
                                  ? "an opening longer than the step is carried into the next steps"
                                  : "an opening is cut at the step";
  // The loader accepts a brake only with a return (io/invsim_reader.cpp).
  const std::string back = fmt::format("return to the axis with a {:g} s time constant", paper.lateral_time_constant_s);
  std::string lateral = "y and z held at 0";
  if (paper.lateral_brake_mps2 > 0.0)
    lateral = fmt::format("y and z brake their initial drift at {:g} m/s^2, then {}", paper.lateral_brake_mps2, back);
  else if (paper.lateral_time_constant_s > 0.0)
    lateral = "y and z " + back;
  return fmt::format("Reading `paper` (docs/invsim.md): a pulse is one valve opening of at most {} s, a step's opening "
                     "dtau counting ceil(dtau / {} s); {}; {}; {}; {}. ",
                     paper.pulse_width_s, paper.pulse_width_s, model, opening, lateral, measured);
}

}  // namespace

std::string fmea_markdown(const std::vector<FmeaLayout>& layouts,
                          const std::vector<invsim::LayoutCandidate>* optimized, int keep) {
  const model::InvSimParams& p = layouts.front().params;
  const std::vector<FmeaRow>& rows = layouts.front().rows;
  std::string md = fmt::format("# FMEA of scenario '{}' (Zhou 2018, inverse simulation)\n\n", p.name);
  md += reading_paragraph(p);
  md += fmt::format(
      "k_p = P / {:.0f} (eq. 22). "
      "Classes (docs/invsim.md): III uncontrollable (not docked, or the target left the {:.1f}/{:.1f} deg field "
      "of view); II controllable with a large deviation (peak |az| or |el| above {:.0f}% of its limit, or the "
      "attitude beyond +-{:.1f} deg); I the other controllable modes. Tables 4-6 and the ranking are for the "
      "scenario's own layout (`baseline`).\n\n",
      p.pulses.basic_pulse_amount, deg(p.sensor.azimuth_limit_rad), deg(p.sensor.elevation_limit_rad),
      100.0 * invsim::kLargeDeviationFraction, deg(p.sensor.attitude_limit_rad));
  table4(md, rows);
  table5(md, rows);
  append_table6(md, p, rows, "## Table 6: risk classes of the multi-axis faults\n\n");
  three_axis_grid(md, rows);
  ranking(md, rows);
  if (layouts.size() > 1) append_reconfiguration(md, layouts);
  if (optimized != nullptr) append_optimization(md, layouts, *optimized, keep);
  return md;
}

}  // namespace chaser::cli
