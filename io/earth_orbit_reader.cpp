// The COMRADE platform's sections: orbit.earth (a perturbed Earth orbit) and target.body
// (a rigid target tumbling by Euler's equations). Both are optional: a scenario without them is a
// circular-orbit run with a constant-rate target (Fonod 2015), and MSR files need no change.
#include <cstdio>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "io/scenario_sections.hpp"

namespace chaser::io {
namespace {

constexpr int kMinYear = 1900, kMaxYear = 2100;  // the Sun's and Moon's series (plant/earth) hold there
constexpr double kMaxDipoleAm2 = 1e4;            // [A m^2] residual dipoles of spacecraft are 0.1-100
constexpr double kMaxBallisticKgpm2 = 1e6;       // [kg/m^2]
constexpr double kMaxAreaToMassM2pkg = 100.0;    // [m^2/kg] (a solar sail is ~30)
constexpr double kMaxSpinRateDegps = 30.0;       // [deg/s] tumbling debris: 0-10 deg/s

bool leap_year(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }
int days_in_month(int y, int m) {
  constexpr int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && leap_year(y) ? 29 : days[m - 1];
}

// "YYYY-MM-DDThh:mm:ss[.s]" with every field in its calendar range.
void read_calendar_time(MapReader& r, std::string_view key, model::CalendarTime& out) {
  std::string text;
  if (!r.text(key, text)) return;
  model::CalendarTime t;
  char tail = 0;
  const int fields = std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%lf%c", &t.year, &t.month, &t.day, &t.hour,
                                 &t.minute, &t.second, &tail);
  const bool shaped = fields == 6 && text.size() >= 19 && text[4] == '-' && text[7] == '-' && text[10] == 'T';
  if (!shaped || t.year < kMinYear || t.year > kMaxYear || t.month < 1 || t.month > 12 || t.day < 1 ||
      t.day > days_in_month(t.year, t.month) || t.hour < 0 || t.hour > 23 || t.minute < 0 || t.minute > 59 ||
      !(t.second >= 0.0 && t.second < 60.0)) {
    r.diagnostics().add(r.path_of(key), fmt::format("must be a TT date and time 'YYYY-MM-DDThh:mm:ss' in years "
                                                    "[{}, {}] (got '{}')", kMinYear, kMaxYear, text));
    return;
  }
  out = t;
}

void read_surface(MapReader& r, model::OrbitBodySurface& out) {
  r.number("ballistic_coefficient_kgpm2", Range::left_open(0.0, kMaxBallisticKgpm2), out.ballistic_coefficient_kgpm2);
  r.number("area_to_mass_m2pkg", Range::closed(0.0, kMaxAreaToMassM2pkg), out.area_to_mass_m2pkg);
  r.number("reflectivity", Range::closed(1.0, 2.0), out.reflectivity);
  r.vec3("residual_dipole_body_Am2", Range::closed(-kMaxDipoleAm2, kMaxDipoleAm2), out.residual_dipole_body_Am2);
}

void read_earth_orbit(MapReader& r, model::EarthOrbitParams& out) {
  read_calendar_time(r, "epoch_tt", out.epoch_tt);
  r.angle_deg("inclination_deg", Range::closed(0.0, 180.0), out.inclination_rad);
  r.angle_deg("raan_deg", Range::right_open(0.0, 360.0), out.raan_rad);
  r.angle_deg("argument_of_latitude_deg", Range::right_open(0.0, 360.0), out.argument_of_latitude_rad);
  r.number("j2", Range::closed(0.0, 1e-2), out.j2);
  r.boolean("drag", out.drag);
  r.boolean("solar_pressure", out.solar_pressure);
  r.boolean("eclipses", out.eclipses);
  r.boolean("sun_gravity", out.sun_gravity);
  r.boolean("moon_gravity", out.moon_gravity);
  r.boolean("magnetic_torque", out.magnetic_torque);
  read_section(r, "target", [&](MapReader& m) { read_surface(m, out.target); });
  read_section(r, "chaser", [&](MapReader& m) { read_surface(m, out.chaser); });
}

void read_spin_case(MapReader& r, model::SpinCase& out) {
  r.choice("spin_case",
           {{"given", model::SpinCase::given}, {"S1", model::SpinCase::s1}, {"S2", model::SpinCase::s2},
            {"S3", model::SpinCase::s3}},
           out);
}

// target.body.keep_out (optional): 1 to 4 boxes {centre_target_m, half_extents_m}.
void read_keep_out(MapReader& r, std::vector<model::KeepOutBox>& out) {
  if (!r.has("keep_out")) return;
  const auto list = r.child("keep_out", fmt::format("a list of 1 to {} boxes", model::kMaxKeepOutBoxes));
  if (!list) return;
  if (!list->IsSequence() || list->size() < 1 || list->size() > static_cast<std::size_t>(model::kMaxKeepOutBoxes)) {
    r.diagnostics().add(r.path_of("keep_out"), fmt::format("must be a list of 1 to {} boxes (got {})",
                                                           model::kMaxKeepOutBoxes, describe_node(*list)));
    return;
  }
  out.assign(list->size(), model::KeepOutBox{});
  for (std::size_t i = 0; i < list->size(); ++i) {
    MapReader m((*list)[i], join_path(r.path_of("keep_out"), std::to_string(i)), r.diagnostics());
    m.vec3("centre_target_m", Range::closed(-kMaxLayoutExtentM, kMaxLayoutExtentM), out[i].centre_target_m);
    m.vec3("half_extents_m", Range::left_open(0.0, kMaxLayoutExtentM), out[i].half_extents_m);
    m.finish();
  }
}

void read_target_body(MapReader& r, model::TargetBodyParams& out) {
  r.number("mass_kg", Range::positive(), out.mass_kg);
  r.mat3("inertia_kgm2", out.inertia_kgm2);
  r.boolean("gravity_gradient", out.gravity_gradient);
  read_spin_case(r, out.spin_case);
  r.angle_deg("spin_rate_deg_s", Range::closed(0.0, kMaxSpinRateDegps), out.spin_rate_radps);
  r.vec3("grasp_point_target_m", Range::closed(-kMaxLayoutExtentM, kMaxLayoutExtentM), out.grasp_point_target_m);
  r.vec3("capture_point_target_m", Range::closed(-kMaxLayoutExtentM, kMaxLayoutExtentM), out.capture_point_target_m);
  // The fixture's lip (optional: model/arm.hpp's default), half extents in the grasp pose's axes.
  if (r.has("fixture")) read_section(r, "fixture", [&](MapReader& m) {
    m.vec3("half_extents_m", Range::left_open(0.0, 1.0), out.fixture.half_extents_m);
  });
  read_keep_out(r, out.keep_out);
}

}  // namespace

void read_optional_earth_orbit(MapReader& r, std::optional<model::EarthOrbitParams>& out) {
  if (!r.has("earth")) return;
  out.emplace();
  read_section(r, "earth", [&](MapReader& m) { read_earth_orbit(m, *out); });
}

void read_optional_target_body(MapReader& r, std::optional<model::TargetBodyParams>& out) {
  if (!r.has("body")) return;
  out.emplace();
  read_section(r, "body", [&](MapReader& m) { read_target_body(m, *out); });
}

}  // namespace chaser::io
