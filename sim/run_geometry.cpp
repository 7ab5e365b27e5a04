#include "sim/run_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.hpp"
#include "model/thrusters.hpp"

namespace chaser::sim {

namespace {

nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

// The bus as the box the nozzles bound (the scenario gives no bus size; the thrusters sit on its
// corners and faces), at least 0.2 m across each way.
nlohmann::json bus_box(const model::ThrusterSetParams& set) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int i = 0; i < set.count; ++i) {
    lo = lo.cwiseMin(set.thrusters[static_cast<std::size_t>(i)].position_body_m);
    hi = hi.cwiseMax(set.thrusters[static_cast<std::size_t>(i)].position_body_m);
  }
  const Vec3 half = ((hi - lo) / 2.0).cwiseMax(0.1);
  return {{"centre_body_m", vec((hi + lo) / 2.0)}, {"half_extents_m", vec(half)}};
}

nlohmann::json thrusters(const model::ThrusterSetParams& set) {
  nlohmann::json list = nlohmann::json::array();
  for (int i = 0; i < set.count; ++i) {
    const model::ThrusterParams& t = set.thrusters[static_cast<std::size_t>(i)];
    const bool grouped = t.group != model::kNoGroup;
    list.push_back({{"name", model::thruster_name(i)},
                    {"position_body_m", vec(t.position_body_m)},
                    {"direction_body", vec(t.direction_body.normalized())},
                    {"max_thrust_N", t.max_thrust_N},
                    {"group", grouped ? nlohmann::json(set.groups[static_cast<std::size_t>(t.group)].name) : nullptr},
                    {"standby", grouped && set.groups[static_cast<std::size_t>(t.group)].standby}});
  }
  return list;
}

// The keep-out box whose surface lies nearest the point: the fixture sits on it.
const model::KeepOutBox* box_under(const std::vector<model::KeepOutBox>& boxes, const Vec3& p_target_m) {
  const model::KeepOutBox* best = nullptr;
  double best_d = std::numeric_limits<double>::infinity();
  for (const model::KeepOutBox& b : boxes) {
    const double d = std::abs(model::keep_out_distance_m({b}, p_target_m));
    if (d < best_d) best_d = d, best = &b;
  }
  return best;
}

// The grasp point's fixture: with capture.berthing a drogue; a grasp point off the centre of the
// face it sits on is on a ring's rim (ENVISAT's launcher adapter ring), the ring centred on the
// face; a point at a face's centre is a berthing fixture's. None without a body.
nlohmann::json fixture(const model::Scenario& s) {
  if (!s.target.body) return nullptr;
  const model::TargetBodyParams& body = *s.target.body;
  const Vec3 p = body.grasp_point_target_m;
  const model::KeepOutBox* box = box_under(body.keep_out, p);
  if (box == nullptr) return nullptr;
  // The face: the axis along which the point is farthest out of the box's centre, relative to size.
  const Vec3 rel = (p - box->centre_target_m).cwiseQuotient(box->half_extents_m);
  int axis = 0;
  rel.cwiseAbs().maxCoeff(&axis);
  Vec3 normal = Vec3::Zero();
  normal(axis) = rel(axis) >= 0.0 ? 1.0 : -1.0;
  Vec3 face_centre = box->centre_target_m;
  face_centre(axis) = p(axis);
  const double radius = (p - face_centre).norm();
  const bool berthing = s.capture && s.capture->berthing;
  const bool ring = !berthing && radius > 0.1;
  return {{"kind", ring ? "ring" : "drogue"},
          {"centre_target_m", vec(ring ? face_centre : p)},
          {"normal_target", vec(normal)},
          {"radius_m", ring ? radius : 0.12}};
}

nlohmann::json target(const model::Scenario& s) {
  if (!s.target.body) return {{"body", false}, {"keep_out", nlohmann::json::array()}, {"fixture", nullptr}};
  const model::TargetBodyParams& body = *s.target.body;
  nlohmann::json boxes = nlohmann::json::array();
  for (const model::KeepOutBox& b : body.keep_out)
    boxes.push_back({{"centre_target_m", vec(b.centre_target_m)}, {"half_extents_m", vec(b.half_extents_m)}});
  return {{"body", true},
          {"keep_out", boxes},
          {"grasp_point_target_m", vec(body.grasp_point_target_m)},
          {"capture_point_target_m", vec(body.capture_point_target_m)},
          {"fixture", fixture(s)}};
}

}  // namespace

nlohmann::json run_geometry(const model::Scenario& scenario) {
  const model::SpacecraftParams& chaser = scenario.chaser;
  return {{"scenario", scenario.name},
          {"control_period_s", scenario.control_period_s},
          {"lvlh", {{"mean_motion_radps", scenario.orbit.mean_motion_radps()}, {"exact", !scenario.orbit.earth.has_value()}}},
          {"chaser",
           {{"com_body_m", vec(chaser.com_body_m)},
            {"keep_out_radius_m", chaser.keep_out_radius_m},
            {"bus", bus_box(scenario.thrusters)},
            {"thrusters", thrusters(scenario.thrusters)},
            {"arm", chaser.arm ? nlohmann::json({{"mount_body_m", vec(chaser.arm->mount_body_m)}}) : nlohmann::json(nullptr)}}},
          {"target", target(scenario)},
          {"approach",
           {{"axis_lvlh", vec(scenario.guidance.approach_axis_lvlh)},
            {"corridor_half_angle_deg", scenario.guidance.corridor_half_angle_rad * 180.0 / kPi},
            {"capture_distance_m", scenario.guidance.capture_distance_m},
            // The mission monitor judges the cone beyond this range, and not with a synchronised approach.
            {"corridor_judged", !scenario.guidance.synchronised},
            {"corridor_min_distance_m", scenario.guidance.corridor_min_distance_m}}}};
}

}  // namespace chaser::sim
