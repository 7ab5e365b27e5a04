// The Python module `chaser` : scenarios and whole runs from Python, on the
// same C++ libraries as the `chaser` command. Nothing here computes: it converts between Python and
// the C++ types, and lets go of the GIL while C++ runs. docs/python.md is its reference.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "io/scenario_loader.hpp"
#include "python/module/module.hpp"
#include "sim/run.hpp"
#include "sim/run_directory.hpp"
#include "sim/run_geometry.hpp"
#include "sim/summary.hpp"
#include "sim/telemetry_channels.hpp"
#include "view/replay_page.hpp"
#include "view/run_files.hpp"

namespace chaser::python {

namespace {

PyObject* scenario_error_type = nullptr;  // chaser.ScenarioError, made once by the module's init

Scenario loaded_or_raise(io::LoadResult loaded) {
  if (!loaded.errors.empty()) raise_scenario_error(loaded.errors);
  return Scenario{std::move(*loaded.scenario), std::move(loaded.hash), std::move(loaded.canonical_yaml)};
}

// A value as one line of YAML flow style, as a user writes it after --set key=: python3-yaml
// quotes only what needs quotes, so the document and its hash are those of the same --set typed by
// hand (JSON's quoted keys would survive into the canonical document and change the hash).
std::string flow_yaml(const py::handle& value) {
  const py::object dump = py::module_::import("yaml").attr("safe_dump");
  std::string text = dump(value, py::arg("default_flow_style") = true, py::arg("sort_keys") = false,
                          py::arg("width") = std::numeric_limits<double>::infinity())
                         .cast<std::string>();
  for (const std::string_view end : {"\n...\n", "\n"})  // a scalar's document-end marker, the last newline
    if (text.ends_with(end)) text.resize(text.size() - end.size());
  return text;
}

Scenario load_file(const std::string& path, const py::object& overrides) {
  const std::vector<std::string> sets = override_strings(overrides);
  io::LoadResult loaded;
  {
    py::gil_scoped_release released;
    loaded = io::load_scenario_file(path, sets);
  }
  return loaded_or_raise(std::move(loaded));
}

Scenario load_text(const std::string& text, const py::object& overrides) {
  const std::vector<std::string> sets = override_strings(overrides);
  io::LoadResult loaded;
  {
    py::gil_scoped_release released;
    loaded = io::load_scenario_text(text, sets);
  }
  return loaded_or_raise(std::move(loaded));
}

// A dict as a scenario document: written as YAML by python3-yaml, then read by the C++ loader,
// which checks it as it checks a file.
Scenario from_dict(const py::dict& document, const py::object& overrides) {
  const py::object dump = py::module_::import("yaml").attr("safe_dump");
  return load_text(dump(document, py::arg("sort_keys") = false).cast<std::string>(), overrides);
}

// The rows' columns as NumPy arrays, in channel order.
py::dict telemetry_arrays(const sim::TelemetryRows& memory) {
  py::dict arrays;
  const std::size_t columns = memory.channels.size(), rows = memory.rows();
  for (std::size_t c = 0; c < columns; ++c) {
    py::array_t<double> column(static_cast<py::ssize_t>(rows));
    double* values = column.mutable_data();
    for (std::size_t r = 0; r < rows; ++r) values[r] = memory.values[r * columns + c];
    arrays[py::str(memory.channels[c])] = std::move(column);
  }
  return arrays;
}

// `chaser run`, from Python: the same run, summary and files (run_command in cli/run_command.cpp).
RunResult run(const Scenario& loaded, std::optional<std::uint64_t> seed, std::optional<std::string> out,
              const std::string& telemetry_format, const std::vector<std::string>& channels) {
  if (telemetry_format != "csv" && telemetry_format != "npy" && telemetry_format != "none")
    throw py::value_error("telemetry: csv, npy or none (got '" + telemetry_format + "')");
  model::Scenario scenario = loaded.scenario;
  if (seed) scenario.seed = *seed;
  check_channels(scenario, channels);

  sim::TelemetryRows memory;
  std::string summary_json, report, problem;
  {
    py::gil_scoped_release released;
    std::filesystem::path telemetry_path;
    if (out) {
      problem = sim::prepare_run_directory(*out);
      if (problem.empty()) telemetry_path = sim::run_telemetry_path(*out, telemetry_format);
    }
    if (problem.empty()) {
      const sim::RunResult result = sim::run_scenario(
          scenario, {.telemetry_path = telemetry_path.string(), .telemetry_channels = channels, .telemetry_rows = &memory});
      summary_json = sim::run_summary(scenario, loaded.hash, result).dump(2) + "\n";
      report = sim::summary_text(scenario, result);
      if (!result.telemetry_ok) problem = "cannot write " + telemetry_path.string();
      else if (out && !sim::write_whole_file(std::filesystem::path(*out) / "geometry.json",
                                             sim::run_geometry(scenario).dump(2) + "\n"))
        problem = "cannot write " + (std::filesystem::path(*out) / "geometry.json").string();
      // summary.json last: where it exists, the run and its telemetry are complete.
      else if (out && !sim::write_whole_file(std::filesystem::path(*out) / "summary.json", summary_json))
        problem = "cannot write " + (std::filesystem::path(*out) / "summary.json").string();
    }
  }
  if (!problem.empty()) {
    PyErr_SetString(PyExc_OSError, problem.c_str());
    throw py::error_already_set();
  }
  return run_result(summary_json, report, memory);
}

// `chaser view`, from Python: the page of a run folder (chaser.run(..., out=DIR)'s), written to
// `out` (default DIR/view.html); its path. ValueError, naming the file, for a folder it cannot draw.
std::string write_view(const std::string& run_dir, std::optional<std::string> out) {
  const std::filesystem::path path = out ? std::filesystem::path(*out) : std::filesystem::path(run_dir) / "view.html";
  std::string problem;
  {
    py::gil_scoped_release released;
    try {
      const view::ViewPage page = view::view_page(view::read_run_files(run_dir));
      if (!sim::write_whole_file(path, page.html)) problem = "cannot write " + path.string();
    } catch (const view::ViewInputError& e) {
      problem = e.what();
    } catch (const nlohmann::json::exception& e) {
      problem = run_dir + ": summary.json or geometry.json does not read (" + e.what() + ")";
    }
  }
  if (problem.rfind("cannot write", 0) == 0) {
    PyErr_SetString(PyExc_OSError, problem.c_str());
    throw py::error_already_set();
  }
  if (!problem.empty()) throw py::value_error(problem);
  return path.string();
}

}  // namespace

RunResult run_result(const std::string& summary_json, std::string report, const sim::TelemetryRows& rows) {
  return RunResult{py::module_::import("json").attr("loads")(summary_json), telemetry_arrays(rows), std::move(report)};
}

void check_channels(const model::Scenario& scenario, const std::vector<std::string>& patterns) {
  const std::vector<std::string> unmatched =
      sim::unmatched_patterns(sim::telemetry_channels(sim::telemetry_shape(scenario)), patterns);
  if (unmatched.empty()) return;
  std::string list;
  for (const std::string& p : unmatched) list += (list.empty() ? "" : ", ") + p;
  throw py::value_error("channels: " + list + " match no telemetry channel (names as in telemetry.csv's header)");
}

// --set strings from a list of "key.path=value", or from a dict {key.path: value} where a str value
// is YAML text as on the command line and any other value (numbers, booleans, None, lists, dicts)
// is written as YAML's flow style.
std::vector<std::string> override_strings(const py::object& overrides) {
  std::vector<std::string> out;
  if (overrides.is_none()) return out;
  if (py::isinstance<py::dict>(overrides)) {
    for (const auto& [key, value] : overrides.cast<py::dict>()) {
      const std::string text = py::isinstance<py::str>(value) ? value.cast<std::string>() : flow_yaml(value);
      out.push_back(py::str(key).cast<std::string>() + "=" + text);
    }
    return out;
  }
  if (py::isinstance<py::str>(overrides)) throw py::type_error("overrides: a dict or a list of 'key.path=value' strings");
  return overrides.cast<std::vector<std::string>>();
}

// Every problem at once, as the command line gives them: .errors the (key path, message) pairs,
// str() io::format_errors' lines.
[[noreturn]] void raise_scenario_error(const std::vector<io::ScenarioError>& errors) {
  py::list pairs;
  for (const io::ScenarioError& e : errors) pairs.append(py::make_tuple(e.key_path, e.message));
  py::object error = py::reinterpret_borrow<py::object>(scenario_error_type)(io::format_errors(errors));
  error.attr("errors") = pairs;
  PyErr_SetObject(scenario_error_type, error.ptr());
  throw py::error_already_set();
}

Scenario scenario_argument(const py::handle& value) {
  if (py::isinstance<Scenario>(value)) return value.cast<Scenario>();
  const py::object fspath = py::module_::import("os").attr("fspath");
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"))
    return load_file(py::str(fspath(value)).cast<std::string>(), py::none());
  throw py::type_error("scenario: a chaser.Scenario or a scenario file's path (got " +
                       py::str(py::type::of(value)).cast<std::string>() + ")");
}

Scenario with_overrides(const Scenario& loaded, const std::vector<std::string>& overrides) {
  io::LoadResult reloaded;
  {
    py::gil_scoped_release released;
    reloaded = io::load_scenario_text(loaded.canonical_yaml, overrides);
  }
  return loaded_or_raise(std::move(reloaded));
}

PYBIND11_MODULE(chaser, m) {
  m.doc() = "Chaser, a spacecraft GNC/FDIR simulator, from Python (docs/python.md).";
  m.attr("__version__") = sim::kChaserVersion;

  scenario_error_type = PyErr_NewExceptionWithDoc(
      "chaser.ScenarioError",
      "An invalid scenario: .errors lists every problem as (key path, message); str() is the command line's text.",
      PyExc_ValueError, nullptr);
  m.add_object("ScenarioError", py::handle(scenario_error_type));

  py::class_<Scenario>(m, "Scenario", "A loaded and validated scenario.")
      .def_static("from_dict", &from_dict, py::arg("document"), py::arg("overrides") = py::none(),
                  "A scenario from a dict with the keys of a scenario file (docs/scenario.md).")
      .def_property_readonly("name", [](const Scenario& s) { return s.scenario.name; })
      .def_property_readonly("seed", [](const Scenario& s) { return s.scenario.seed; })
      .def_property_readonly("hash", [](const Scenario& s) { return s.hash; },
                             "16 hex digits of the document after overrides, as in summary.json")
      .def_property_readonly("yaml", [](const Scenario& s) { return s.canonical_yaml; },
                             "The document after overrides, keys sorted")
      .def("__repr__", [](const Scenario& s) {
        return "<chaser.Scenario '" + s.scenario.name + "' hash " + s.hash + ">";
      });

  py::class_<RunResult>(m, "RunResult", "What one run gives: its summary and its telemetry.")
      .def_readonly("summary", &RunResult::summary, "summary.json's content, as a dict")
      .def_readonly("telemetry", &RunResult::telemetry, "channel name -> float64 array, one value per control period")
      .def_readonly("report", &RunResult::report, "the text `chaser run` prints")
      .def("__repr__", [](const RunResult& r) { return "<chaser.RunResult " + py::str(r.summary["scenario"]).cast<std::string>() + ">"; });

  m.def("load_scenario", &load_file, py::arg("path"), py::arg("overrides") = py::none(),
        "A scenario file, with overrides as `chaser run --set` takes them: a list of 'key.path=value' "
        "strings or a dict {key.path: value}. Raises ScenarioError with every problem.");
  m.def("load_scenario_text", &load_text, py::arg("text"), py::arg("overrides") = py::none(),
        "A scenario from YAML text; otherwise as load_scenario.");
  m.def("run", &run, py::arg("scenario"), py::arg("seed") = py::none(), py::arg("out") = py::none(),
        py::arg("telemetry") = "csv", py::arg("channels") = std::vector<std::string>{},
        "One closed-loop run, as `chaser run`: seed replaces the scenario's; with out=DIR it writes "
        "DIR/telemetry.<csv|npy> (telemetry='none': no file), DIR/geometry.json and DIR/summary.json as `chaser run --out DIR` "
        "does (chaser.view(DIR) then replays it); "
        "channels keeps the channels matching those patterns (and t_s), in memory and in the file.");
  m.def("view", &write_view, py::arg("run_dir"), py::arg("out") = py::none(),
        "The run in run_dir (chaser.run(..., out=run_dir)'s folder) replayed in 3D in one HTML page, as "
        "`chaser view run_dir --out out` writes it (docs/view.md); out defaults to run_dir/view.html. Returns "
        "the page's path; raises ValueError naming the file for a missing or truncated telemetry or summary.");
  add_campaign(m);
  add_analyses(m);
  add_simulation(m);
}

}  // namespace chaser::python
