#include "invsim/carried_opening.hpp"

#include <algorithm>

namespace chaser::invsim {

namespace {
double group_accel(const std::array<double, 2>& accel_mps2, int direction) { return accel_mps2[direction > 0 ? 0 : 1]; }
}  // namespace

double command_beyond_carried(const CarriedOpening& carried, const std::array<double, 2>& accel_mps2, double step_s,
                              double u_ls_mps2) {
  if (carried.direction == 0) return u_ls_mps2;
  return u_ls_mps2 - carried.direction * group_accel(accel_mps2, carried.direction) * carried.remaining_s / step_s;
}

Pulse open_for_step(CarriedOpening& carried, const Pulse& commanded, const std::array<double, 2>& accel_mps2,
                    double step_s) {
  const auto accel = [&](int direction) { return group_accel(accel_mps2, direction); };
  if (commanded.direction != 0) {
    if (carried.direction == 0 || carried.direction == commanded.direction) {
      carried.direction = commanded.direction;
      carried.remaining_s += commanded.on_time_s;
    } else {
      const double new_impulse = accel(commanded.direction) * commanded.on_time_s;  // [m/s]
      const double carried_impulse = accel(carried.direction) * carried.remaining_s;
      if (new_impulse <= carried_impulse) {
        carried.remaining_s -= new_impulse / accel(carried.direction);
      } else {
        carried.direction = commanded.direction;
        carried.remaining_s = (new_impulse - carried_impulse) / accel(commanded.direction);
      }
    }
  }
  if (carried.direction == 0 || !(carried.remaining_s > 0.0)) {
    carried = CarriedOpening{};
    return Pulse{0, 0.0};
  }
  const Pulse flown{carried.direction, std::min(carried.remaining_s, step_s)};
  carried.remaining_s -= flown.on_time_s;
  if (!(carried.remaining_s > 0.0)) carried = CarriedOpening{};
  return flown;
}

}  // namespace chaser::invsim
