// The design-time analyses of the command line, from Python: chaser.thrusters (`chaser thrusters
// --json`) and chaser.fdi_design (`chaser fdi design --out`) return the JSON document the command
// writes, made by the same C++ function, as Python values with NumPy arrays for matrices;
// chaser.fmea (`chaser fmea`) runs the command's study and returns fmea.csv as a structured array,
// with optimize.csv and the per-step histories when asked for.
#include <algorithm>
#include <cstring>
#include <cstdint>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "campaign/csv.hpp"
#include "cli/fmea_report.hpp"
#include "core/worker_threads.hpp"
#include "flight/fdi/design/residual_design.hpp"
#include "flight/fdi/design/residual_design_json.hpp"
#include "flight/fdir.hpp"
#include "model/thruster_sets_report.hpp"
#include "python/module/module.hpp"

namespace chaser::python {

namespace {

bool numbers_only(const nlohmann::json& array) {
  return std::all_of(array.begin(), array.end(), [](const nlohmann::json& v) { return v.is_number(); });
}

bool integers_only(const nlohmann::json& array) {
  return std::all_of(array.begin(), array.end(),
                     [](const nlohmann::json& v) { return v.is_number_integer() || v.is_number_unsigned(); });
}

// A non-empty array of numbers, or a non-empty array of equal-length non-empty arrays of numbers.
bool is_matrix(const nlohmann::json& array) {
  if (array.empty()) return false;
  if (numbers_only(array)) return true;
  const nlohmann::json& first = array.front();
  return first.is_array() && !first.empty() && std::all_of(array.begin(), array.end(), [&](const nlohmann::json& row) {
           return row.is_array() && row.size() == first.size() && numbers_only(row);
         });
}

template <typename T>
py::object numpy_array(const nlohmann::json& array) {
  const bool nested = array.front().is_array();
  const auto rows = static_cast<py::ssize_t>(array.size());
  const std::vector<py::ssize_t> shape =
      nested ? std::vector<py::ssize_t>{rows, static_cast<py::ssize_t>(array.front().size())}
             : std::vector<py::ssize_t>{rows};
  py::array_t<T> out(shape);
  T* values = out.mutable_data();
  for (const nlohmann::json& v : array)
    if (nested)
      for (const nlohmann::json& x : v) *values++ = x.get<T>();
    else
      *values++ = v.get<T>();
  return out;
}

py::object matrix(const nlohmann::json& array) {
  bool integers = true;
  if (array.front().is_array())
    for (const nlohmann::json& row : array) integers = integers && integers_only(row);
  else
    integers = integers_only(array);
  return integers ? numpy_array<std::int64_t>(array) : numpy_array<double>(array);
}

// `chaser thrusters SCENARIO --json F`'s document.
py::object thrusters(const py::object& scenario_arg) {
  const Scenario scenario = scenario_argument(scenario_arg);
  nlohmann::json report;
  {
    py::gil_scoped_release released;
    report = model::thruster_sets_json(scenario.scenario, model::thruster_set_reports(scenario.scenario));
  }
  return json_to_python(report);
}

// `chaser fdi design SCENARIO --model M --out F`'s document.
py::object fdi_design(const py::object& scenario_arg, const std::string& model) {
  if (model != "position" && model != "attitude" && model != "rate" && model != "uio-bank")
    throw py::value_error("model: position, attitude, rate or uio-bank (got '" + model + "')");
  const Scenario scenario = scenario_argument(scenario_arg);
  nlohmann::json design;
  std::string problem;
  if (model == "rate" || model == "uio-bank") {  // flight/fdi/design/rate_model.hpp, uio_bank.hpp
    try {
      design = model == "rate" ? flight::fdi::to_json(flight::fdi::rate_model(scenario.scenario))
                               : flight::fdi::to_json(flight::fdi::design_uio_bank(scenario.scenario));
    } catch (const std::invalid_argument& e) {
      problem = e.what();
    }
  } else {
    py::gil_scoped_release released;
    const flight::fdi::DesignInputs inputs = flight::scheme_design_inputs(
        scenario.scenario, model == "position" ? flight::FdiModel::kPosition : flight::FdiModel::kAttitude);
    try {
      design = flight::fdi::to_json(flight::fdi::design_residual_generator(inputs));
    } catch (const std::invalid_argument& e) {  // the command's exit code 2
      problem = e.what();
    }
  }
  if (!problem.empty()) throw py::value_error(problem);
  return json_to_python(design);
}

// A CSV text of our own writing (fields as campaign::split_fields reads them) as a structured array:
// a column whose fields are all true/false is bool, all integers int64, all numbers float64,
// otherwise a string as wide as its longest field.
py::object csv_table(const std::string& text) {
  std::istringstream in(text);
  std::string header_line;
  std::getline(in, header_line);
  const std::vector<std::string_view> header = campaign::split_fields(header_line);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::vector<std::vector<std::string_view>> cells;
  for (const std::string& line : lines) {
    cells.push_back(campaign::split_fields(line));
    if (cells.back().size() != header.size()) throw std::runtime_error("a malformed row: " + line);
  }
  const py::module_ np = py::module_::import("numpy");
  py::list fields;
  std::vector<py::list> columns(header.size());
  for (std::size_t c = 0; c < header.size(); ++c) {
    const auto all = [&](auto test) {
      return std::all_of(cells.begin(), cells.end(), [&](const auto& row) { return test(row[c]); });
    };
    std::size_t width = 1;
    for (const auto& row : cells) width = std::max(width, row[c].size());
    if (all([](std::string_view f) { return f == "true" || f == "false"; })) {
      fields.append(py::make_tuple(std::string(header[c]), "?"));
      for (const auto& row : cells) columns[c].append(row[c] == "true");
    } else if (all([](std::string_view f) { return campaign::parse_integer(f).has_value(); })) {
      fields.append(py::make_tuple(std::string(header[c]), "<i8"));
      for (const auto& row : cells) columns[c].append(*campaign::parse_integer(row[c]));
    } else if (all([](std::string_view f) { return campaign::parse_number(f).has_value(); })) {
      fields.append(py::make_tuple(std::string(header[c]), "<f8"));
      for (const auto& row : cells) columns[c].append(*campaign::parse_number(row[c]));
    } else {
      fields.append(py::make_tuple(std::string(header[c]), fmt::format("<U{}", width)));
      for (const auto& row : cells) columns[c].append(py::str(std::string(row[c])));
    }
  }
  py::object table = np.attr("zeros")(cells.size(), np.attr("dtype")(fields));
  for (std::size_t c = 0; c < header.size(); ++c) table[py::str(std::string(header[c]))] = columns[c];
  return table;
}

// One history (cli::kHistoryColumns) as a structured array: the file's columns, whole values.
py::object history_table(const std::vector<invsim::InvSimSample>& samples) {
  const py::module_ np = py::module_::import("numpy");
  py::list fields;
  const std::size_t first_integer = cli::kHistoryColumns.size() - cli::kHistoryIntegerColumns;
  for (std::size_t c = 0; c < cli::kHistoryColumns.size(); ++c)
    fields.append(py::make_tuple(std::string(cli::kHistoryColumns[c]), c < first_integer ? "<f8" : "<i8"));
  py::array table = np.attr("zeros")(samples.size(), np.attr("dtype")(fields));
  // Packed record of 18 doubles and 6 int64, filled in place.
  auto* record = static_cast<char*>(table.mutable_data());
  for (const invsim::InvSimSample& s : samples) {
    const auto values = cli::history_values(s);
    for (std::size_t c = 0; c < values.size(); ++c) {
      char* field = record + 8 * c;
      if (c < first_integer) {
        std::memcpy(field, &values[c], sizeof(double));
      } else {
        const auto integer = static_cast<std::int64_t>(values[c]);
        std::memcpy(field, &integer, sizeof(integer));
      }
    }
    record += 8 * values.size();
  }
  return table;
}

// `chaser fmea SCENARIO --set ... --threads K [--three-axis] [--optimize] [--history]`: fmea.csv,
// fmea.md, the per-layout figures the command prints, optimize.csv and the histories.
py::dict fmea(const std::string& path, const py::object& overrides, std::optional<int> threads, bool three_axis,
              bool optimize, bool history) {
  if (threads && *threads < 1) throw py::value_error(fmt::format("threads: must be >= 1 (got {})", *threads));
  const std::vector<std::string> sets = override_strings(overrides);
  io::InvSimLoadResult loaded;
  cli::FmeaStudy study;
  std::vector<std::pair<std::string, std::string>> files;  // the command's files by name
  std::string problem;
  {
    py::gil_scoped_release released;
    loaded = io::load_invsim_file(path, sets);
    if (loaded.errors.empty() && loaded.params) {
      const cli::FmeaOptions options{three_axis, optimize, history, false,
                                     threads.value_or(default_worker_threads())};
      problem = cli::fmea_options_problem(loaded, path, options);
      if (problem.empty()) {
        study = cli::run_fmea_study(loaded, options);
        files = cli::fmea_files(study, loaded.study.optimize_keep);
      }
    }
  }
  if (!loaded.errors.empty() || !loaded.params) raise_scenario_error(loaded.errors);
  if (!problem.empty()) throw py::value_error(problem);
  const auto file = [&](const std::string& name) {
    return std::find_if(files.begin(), files.end(), [&](const auto& f) { return f.first == name; })->second;
  };
  py::dict summaries;
  for (const cli::FmeaLayout& layout : study.layouts) {
    const invsim::LayoutSummary s = invsim::summarize_layout(layout.rows);
    summaries[py::str(layout.name)] =
        py::dict(py::arg("description") = layout.description, py::arg("class_I") = s.per_class[0],
                 py::arg("class_II") = s.per_class[1], py::arg("class_III") = s.per_class[2],
                 py::arg("propellant_kg") = s.propellant_kg);
  }
  py::dict out(py::arg("rows") = csv_table(file("fmea.csv")), py::arg("layouts") = summaries,
               py::arg("markdown") = file("fmea.md"));
  if (optimize) out["optimize"] = csv_table(file("optimize.csv"));
  if (history) {
    py::dict by_mode;  // (configuration, mode) -> the history, in index.csv's order
    for (std::size_t l = 0; l < study.layouts.size(); ++l)
      for (std::size_t i = 0; i < study.layouts[l].rows.size(); ++i) {
        const invsim::FmeaHistory& h = study.histories[l][i];
        by_mode[py::make_tuple(study.layouts[l].name, study.layouts[l].rows[i].fmea_case.mode.label)] =
            py::dict(py::arg("draws") = h.draws,
                     py::arg("draw_seed") = h.seed ? py::object(py::int_(*h.seed)) : py::object(py::none()),
                     py::arg("samples") = history_table(h.samples));
      }
    out["histories"] = by_mode;
  }
  return out;
}

}  // namespace

py::object json_to_python(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::object: {
      py::dict out;
      for (const auto& [key, item] : value.items()) out[py::str(key)] = json_to_python(item);
      return out;
    }
    case nlohmann::json::value_t::array: {
      if (is_matrix(value)) return matrix(value);
      py::list out;
      for (const nlohmann::json& item : value) out.append(json_to_python(item));
      return out;
    }
    case nlohmann::json::value_t::string: return py::str(value.get<std::string>());
    case nlohmann::json::value_t::boolean: return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(value.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(value.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(value.get<double>());
    default: return py::none();
  }
}

void add_analyses(py::module_& m) {
  m.def("thrusters", &thrusters, py::arg("scenario"),
        "What the scenario's thruster sets can do, as `chaser thrusters SCENARIO --json F` writes it: a dict "
        "with NumPy arrays for the number arrays (configuration_matrix_columns: one row [Fx, Fy, Fz, Cx, Cy, Cz] "
        "per thruster).");
  m.def("fdi_design", &fdi_design, py::arg("scenario"), py::arg("model") = "position",
        "The residual generator design of one FDI scheme (Fonod 2015, IV.A), as `chaser fdi design SCENARIO "
        "--model M --out F` writes it: a dict with NumPy arrays for matrices (A_bar, L, Q, ...; complex "
        "eigenvalues as [re, im] rows). Raises ValueError where the command exits with 2.");
  m.def("fmea", &fmea, py::arg("scenario"), py::arg("overrides") = py::none(), py::arg("threads") = py::none(),
        py::arg("three_axis") = false, py::arg("optimize") = false, py::arg("history") = false,
        "The failure-mode and effects analysis of `chaser fmea` (Zhou 2018; docs/invsim.md) for an "
        "inverse-simulation scenario file: {'rows': fmea.csv as a structured array, 'layouts': {name: "
        "{description, class_I, class_II, class_III, propellant_kg}}, 'markdown': fmea.md's text}. overrides: "
        "as for load_scenario; threads: --threads (default every core); three_axis: --three-axis; optimize: "
        "--optimize, adds 'optimize' (optimize.csv as a structured array; ValueError without free choices); "
        "history: --history, adds 'histories': {(configuration, mode): {draws, draw_seed, samples: the history "
        "file's columns as a structured array, unrounded}}.");
}

}  // namespace chaser::python
