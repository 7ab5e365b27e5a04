// The design-time analyses of the command line, from Python: chaser.thrusters (`chaser thrusters
// --json`) and chaser.fdi_design (`chaser fdi design --out`). Each returns the JSON document the
// command writes, made by the same C++ function, as Python values with NumPy arrays for matrices.
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "flight/fdi/residual_design.hpp"
#include "flight/fdi/residual_design_json.hpp"
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
  const std::vector<py::ssize_t> shape =
      nested ? std::vector<py::ssize_t>{static_cast<py::ssize_t>(array.size()), static_cast<py::ssize_t>(array.front().size())}
             : std::vector<py::ssize_t>{static_cast<py::ssize_t>(array.size())};
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
  if (model != "position" && model != "attitude")
    throw py::value_error("model: position or attitude (got '" + model + "')");
  const Scenario scenario = scenario_argument(scenario_arg);
  nlohmann::json design;
  std::string problem;
  {
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
}

}  // namespace chaser::python
