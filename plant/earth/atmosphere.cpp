#include "plant/earth/atmosphere.hpp"

#include <array>
#include <cmath>

namespace chaser::plant::earth {

namespace {

struct Band {
  double base_km;         // h_0
  double density_kgpm3;   // rho_0 at h_0
  double scale_height_km; // H
};

// Vallado 2013, Table 8-4 (exponential atmosphere model).
constexpr std::array<Band, 28> kBands{{
    {0, 1.225, 7.249},         {25, 3.899e-2, 6.349},     {30, 1.774e-2, 6.682},
    {40, 3.972e-3, 7.554},     {50, 1.057e-3, 8.382},     {60, 3.206e-4, 7.714},
    {70, 8.770e-5, 6.549},     {80, 1.905e-5, 5.799},     {90, 3.396e-6, 5.382},
    {100, 5.297e-7, 5.877},    {110, 9.661e-8, 7.263},    {120, 2.438e-8, 9.473},
    {130, 8.484e-9, 12.636},   {140, 3.845e-9, 16.149},   {150, 2.070e-9, 22.523},
    {180, 5.464e-10, 29.740},  {200, 2.789e-10, 37.105},  {250, 7.248e-11, 45.546},
    {300, 2.418e-11, 53.628},  {350, 9.518e-12, 53.298},  {400, 3.725e-12, 58.515},
    {450, 1.585e-12, 60.828},  {500, 6.967e-13, 63.822},  {600, 1.454e-13, 71.835},
    {700, 3.614e-14, 88.667},  {800, 1.170e-14, 124.64},  {900, 5.245e-15, 181.05},
    {1000, 3.019e-15, 268.00},
}};

}  // namespace

double exponential_density_kgpm3(double altitude_m) {
  const double h_km = altitude_m / 1000.0;
  if (h_km <= 0.0) return kBands.front().density_kgpm3;
  std::size_t i = kBands.size() - 1;
  while (i > 0 && h_km < kBands[i].base_km) --i;
  const Band& b = kBands[i];
  return b.density_kgpm3 * std::exp(-(h_km - b.base_km) / b.scale_height_km);
}

Vec3 drag_acceleration_eci(const DragParams& p, const Vec3& r_eci_m, const Vec3& v_eci_mps) {
  const Vec3 v_rel = p.corotating_atmosphere ? Vec3(v_eci_mps - Vec3(0, 0, kEarthRotationRadps).cross(r_eci_m))
                                             : v_eci_mps;
  const double rho = exponential_density_kgpm3(r_eci_m.norm() - p.equatorial_radius_m);
  return -rho * v_rel.norm() / (2.0 * p.ballistic_coefficient_kgpm2) * v_rel;
}

double circular_decay_rate_mps(double mu_m3ps2, double semi_major_axis_m, double density_kgpm3,
                               double ballistic_coefficient_kgpm2) {
  return -density_kgpm3 * std::sqrt(mu_m3ps2 * semi_major_axis_m) / ballistic_coefficient_kgpm2;
}

}  // namespace chaser::plant::earth
