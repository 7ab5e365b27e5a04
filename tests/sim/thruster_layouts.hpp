#pragma once
// Thruster sets other than MSR's two branches, as scenario overrides, for the closed-loop tests.
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/types.hpp"

namespace chaser::sim::testing {

// MSR branch A (scenarios/msr_terminal.yaml, T1..T8).
struct Nozzle {
  Vec3 position_m, direction;
};
inline const Nozzle kBranchA[8] = {
    {{1.0, 0.8, 0.8}, {0.36, 0.36, -1.0}},   {{-1.0, 0.8, -0.8}, {0.36, 1.0, 0.36}},
    {{-1.0, 0.8, 0.8}, {-1.0, 0.36, -0.36}}, {{-1.0, -0.8, 0.8}, {0.36, -1.0, -0.36}},
    {{-1.0, -0.8, -0.8}, {-0.36, -0.36, 1.0}}, {{1.0, -0.8, 0.8}, {-0.36, -1.0, -0.36}},
    {{1.0, -0.8, -0.8}, {1.0, -0.36, 0.36}},  {{1.0, 0.8, -0.8}, {-0.36, 1.0, 0.36}}};

// A flow-style YAML list of `count` thrusters: copy c = i / 8 of branch A, mounted at (1 - 0.05 c)
// of the radius with its directions turned by 15 c deg about body z, so the copies differ. No
// groups: every thruster flies from the start.
inline std::string thruster_list(int count, double thrust_N = 22.0) {
  std::string out = "thrusters.list=[";
  for (int i = 0; i < count; ++i) {
    const int copy = i / 8;
    const Nozzle& n = kBranchA[i % 8];
    const double a = copy * 15.0 * kPi / 180.0;
    const Vec3 p = (1.0 - 0.05 * copy) * n.position_m;
    const Vec3 d(std::cos(a) * n.direction.x() - std::sin(a) * n.direction.y(),
                 std::sin(a) * n.direction.x() + std::cos(a) * n.direction.y(), n.direction.z());
    out += fmt::format("{}{{name: T{}, position_body_m: [{}, {}, {}], direction_body: [{}, {}, {}], max_thrust_N: {}}}",
                       i ? ", " : "", i + 1, p.x(), p.y(), p.z(), d.x(), d.y(), d.z(), thrust_N);
  }
  return out + "]";
}

// The overrides that fly a set without standby groups: no recovery, and the eight-lane FDI off.
inline std::vector<std::string> one_set_overrides(int count) {
  return {thruster_list(count),           "thrusters.standby_groups=[]",  "fdi.recovery=none",
          "fdi.position.enabled=false",   "fdi.attitude.enabled=false",   "fdi.deficit.detection=false",
          "fdi.active_check.enabled=false"};
}

}  // namespace chaser::sim::testing
