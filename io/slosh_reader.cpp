// chaser.slosh: the chaser's propellant tanks whose first lateral slosh mode the
// Earth-orbit plant models. Optional; the checks that need other keys (orbit.earth, the chaser's
// mass and inertia, the liquid fitting its tank) are in scenario_validation.cpp.
#include <fmt/format.h>

#include "io/scenario_sections.hpp"
#include "model/slosh.hpp"

namespace chaser::io {
namespace {

constexpr int kMaxTanks = model::kMaxSloshTanks;
constexpr double kMaxTankSizeM = 10.0;       // [m] radius and height
constexpr double kMaxDensityKgpm3 = 3000.0;  // [kg/m^3] liquids: hydrazine 1004, MON 1440, water 1000
constexpr double kMaxGEffMps2 = 10.0;        // [m/s^2] a settling acceleration, not a launch load
constexpr double kMaxSurfaceTensionNpm = 1.0;  // [N/m] liquids: hydrazine 0.066, MON 0.027, water 0.072, mercury 0.49

void read_tank(const YAML::Node& node, const std::string& path, model::SloshTankSpec& out, Diagnostics& diag) {
  MapReader m(node, path, diag);
  m.vec3("bottom_centre_body_m", Range::closed(-kMaxLayoutExtentM, kMaxLayoutExtentM), out.bottom_centre_body_m);
  m.direction("axis_body", out.axis_body);
  m.number("radius_m", Range::left_open(0.0, kMaxTankSizeM), out.radius_m);
  m.number("height_m", Range::left_open(0.0, kMaxTankSizeM), out.height_m);
  m.number("liquid_mass_kg", Range::positive(), out.liquid_mass_kg);
  m.number("density_kgpm3", Range::left_open(0.0, kMaxDensityKgpm3), out.density_kgpm3);
  m.number("damping_ratio", Range::right_open(0.0, 1.0), out.damping_ratio);
  if (m.has("surface_tension_Npm"))
    m.number("surface_tension_Npm", Range::closed(0.0, kMaxSurfaceTensionNpm), out.surface_tension_Npm);
  m.finish();
}

void read_slosh(MapReader& r, model::SloshParams& out) {
  if (r.has("model"))
    r.choice("model", {{"spring_mass", model::SloshModel::spring_mass}, {"pendulum", model::SloshModel::pendulum}},
             out.model);
  r.number("g_eff_mps2", Range::left_open(0.0, kMaxGEffMps2), out.g_eff_mps2);
  const auto list = r.child("tanks", fmt::format("a list of 1 to {} tanks", kMaxTanks));
  if (!list) return;
  if (!list->IsSequence() || list->size() < 1 || list->size() > static_cast<std::size_t>(kMaxTanks)) {
    r.diagnostics().add(r.path_of("tanks"), fmt::format("must be a list of 1 to {} tanks (got {})", kMaxTanks,
                                                        describe_node(*list)));
    return;
  }
  out.tanks.assign(list->size(), model::SloshTankSpec{});
  for (std::size_t i = 0; i < list->size(); ++i)
    read_tank((*list)[i], join_path(r.path_of("tanks"), std::to_string(i)), out.tanks[i], r.diagnostics());
}

}  // namespace

void read_optional_slosh(MapReader& r, std::optional<model::SloshParams>& out) {
  if (!r.has("slosh")) return;
  out.emplace();
  read_section(r, "slosh", [&](MapReader& m) { read_slosh(m, *out); });
}

}  // namespace chaser::io
