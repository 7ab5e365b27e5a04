#include "flight/sync_approach.hpp"

#include <algorithm>
#include <cmath>

#include "core/rotation.hpp"

namespace chaser::flight {

namespace {

constexpr double kDifferenceStep_s = 0.05;  // h of the central differences (header: error budget)

struct Pose {
  Vec3 r_lvlh_m = Vec3::Zero();
  Quat q_inertial_from_body = Quat::Identity();
};

struct StepTimes {
  double fly_around_start_s, axis_start_s, rotation_start_s, rotation_end_s;
};

StepTimes step_times(const SyncApproachPlan& plan) {
  const model::SyncApproachParams& a = plan.approach;
  const double axis_start = a.fly_around_start_s + a.fly_around_duration_s;
  const double rotation_start = axis_start + a.axis_approach_duration_s;
  return {a.fly_around_start_s, axis_start, rotation_start, rotation_start + a.rotation_sync_duration_s};
}

double progress(double t_s, double start_s, double duration_s) {
  return rest_to_rest_quintic((t_s - start_s) / duration_s)[0];
}

// The target's attitude carried from its estimate to t_s: phi = omega dt + omega' dt^2 / 2 (the
// rate's own turning adds only third-order terms).
Quat target_attitude_at(const TargetEstimate& target, double t_s) {
  const double dt = t_s - target.t_s;
  return (target.q_inertial_from_target *
          quat_from_rotation_vector(target.omega_target_radps * dt + target.omega_dot_target_radps2 * (0.5 * dt * dt)))
      .normalized();
}

class PoseModel {
 public:
  PoseModel(const SyncApproachPlan& plan, const Vec3& axis_inertial, const TargetEstimate* target,
            const Vec3& start_target_m, const Quat& sync_offset, const model::TargetOrbit& orbit)
      : plan_(plan),
        times_(step_times(plan)),
        axis_inertial_(axis_inertial),
        target_(target),
        start_target_m_(start_target_m),
        sync_offset_(sync_offset),
        orbit_(orbit),
        u0_(plan.line.approach_axis_lvlh.normalized()),
        q_line_lvlh_from_body_(target_pointing_q_lvlh_from_body(u0_)) {}

  Pose at(double t_s) const {
    const Quat q_inertial_from_lvlh = orbit_.q_inertial_from_lvlh(t_s);
    const Vec3 a = q_inertial_from_lvlh.conjugate() * axis_inertial_;  // the axis in LVLH at t
    const double radius = plan_.line.capture_distance_m, d = plan_.approach.axis_distance_m;
    if (t_s < times_.axis_start_s) {  // the line's end, then the great circle to the axis
      const double s = progress(t_s, times_.fly_around_start_s, plan_.approach.fly_around_duration_s);
      return pointing(q_inertial_from_lvlh, radius * (rotation_towards(u0_, a, s) * u0_));
    }
    const double s_axis = progress(t_s, times_.axis_start_s, plan_.approach.axis_approach_duration_s);
    const Pose on_axis = pointing(q_inertial_from_lvlh, (radius + (d - radius) * s_axis) * a);
    if (t_s < times_.rotation_start_s || target_ == nullptr) return on_axis;
    const double duration = plan_.approach.rotation_sync_duration_s;
    const double tau = std::clamp((t_s - times_.rotation_start_s) / duration, 0.0, 1.0);
    const double s = rest_to_rest_quintic(tau)[0];
    const Quat q_inertial_from_target = target_attitude_at(*target_, t_s);
    const Vec3 fixed_point_lvlh = q_inertial_from_lvlh.conjugate() * (q_inertial_from_target * start_target_m_);
    // The spin-up: a virtual target that lags the real one by L (target's rate times L, turned back),
    // L = D (tau - S(tau)) - s(tau) D / 2 with S = int_0^tau s: L = 0 and L' = 1 at the start (the
    // virtual target at rest, as the pointing chaser), L = 0 and L' = 0 at the end (the real one).
    // The chaser is the virtual target's, offset by the pointing attitude in its frame at the start,
    // slerped to q_target_from_body: neither end moves in that frame, so the slerp never wraps (a
    // slerp of the inertial attitudes would, the target turning 500 deg in 200 s at 2.5 deg/s).
    const double tau4 = tau * tau * tau * tau;
    const double lag_s = duration * (tau - tau4 * (2.5 - 3.0 * tau + tau * tau)) - 0.5 * duration * s;
    const Vec3 omega_target = target_->omega_target_radps + target_->omega_dot_target_radps2 * (t_s - target_->t_s);
    const Quat virtual_target = q_inertial_from_target * quat_from_rotation_vector(-lag_s * omega_target);
    // The pointing attitude's own turn since the start (with LVLH, n at most: 0.2 rad in 200 s),
    // faded out by the power 1 - s, so that the start's rate is the pointing's, not zero.
    const Quat pointing_turn = on_axis_attitude(times_.rotation_start_s).conjugate() * on_axis.q_inertial_from_body;
    const Quat fading_turn = quat_from_rotation_vector((1.0 - s) * rotation_vector_from_quat(pointing_turn));
    const Vec3 r_lvlh = (1.0 - s) * on_axis.r_lvlh_m + s * fixed_point_lvlh;
    const Quat spun = (virtual_target * sync_offset_.slerp(s, transfer_start_attitude()) * fading_turn).normalized();
    // The boresight held on the target's CoM: the virtual target turns about the estimated spin axis,
    // not about the line of sight (a tumble's axis wanders in the body: 21 deg off the LIDAR's
    // boresight half-way through S1's spin-up without this), so the least turn that puts body +x
    // back on the line of sight follows. It is nil at both ends, where the two attitudes point.
    const Vec3 boresight = spun * Vec3::UnitX();
    const Vec3 line_of_sight = q_inertial_from_lvlh * (-r_lvlh).normalized();
    return {r_lvlh, (rotation_towards(boresight, line_of_sight, 1.0) * spun).normalized()};
  }

  // The transfer's first attitude in the target's frame (flight/sync_guidance.hpp): boresight on the
  // target, as sync_offset_'s, so that the slerp between them is a roll about the line of sight and
  // the target stays in view.
  Quat transfer_start_attitude() const {
    return transfer_attitude(plan_.transfer.q_target_from_body, start_target_m_, 0.0);
  }

  // The pointing attitude on the axis at its end (the rotation's synchronisation starts from it).
  Quat on_axis_attitude(double t_s) const {
    const Quat q_inertial_from_lvlh = orbit_.q_inertial_from_lvlh(t_s);
    const Vec3 a = q_inertial_from_lvlh.conjugate() * axis_inertial_;
    return pointing(q_inertial_from_lvlh, plan_.approach.axis_distance_m * a).q_inertial_from_body;
  }

 private:
  // Body +x on the target: the line's attitude turned by the least rotation from -u0 to -r.
  Pose pointing(const Quat& q_inertial_from_lvlh, const Vec3& r_lvlh_m) const {
    const Quat turn = rotation_towards(-u0_, -r_lvlh_m.normalized(), 1.0);
    return {r_lvlh_m, (q_inertial_from_lvlh * turn * q_line_lvlh_from_body_).normalized()};
  }

  const SyncApproachPlan& plan_;
  StepTimes times_;
  Vec3 axis_inertial_;
  const TargetEstimate* target_;
  Vec3 start_target_m_;
  Quat sync_offset_;  // the pointing attitude in the target's frame when the synchronisation starts
  const model::TargetOrbit& orbit_;
  Vec3 u0_;
  Quat q_line_lvlh_from_body_;
};

// Velocity, acceleration and body rate by central differences (header).
GuidanceRef differentiate(const PoseModel& model, double t_s) {
  const double h = kDifferenceStep_s;
  const Pose before = model.at(t_s - h), now = model.at(t_s), after = model.at(t_s + h);
  GuidanceRef ref;
  ref.r_lvlh_m = now.r_lvlh_m;
  ref.v_lvlh_mps = (after.r_lvlh_m - before.r_lvlh_m) / (2.0 * h);
  ref.a_lvlh_mps2 = (after.r_lvlh_m - 2.0 * now.r_lvlh_m + before.r_lvlh_m) / (h * h);
  ref.q_inertial_from_body = now.q_inertial_from_body;
  ref.omega_body_radps =
      rotation_vector_from_quat(before.q_inertial_from_body.conjugate() * after.q_inertial_from_body) / (2.0 * h);
  return ref;
}

}  // namespace

std::optional<Vec3> angular_momentum_axis(const TargetEstimate& target, const Mat3& inertia_kgm2) {
  if (target.omega_target_radps.norm() < 1e-6) return std::nullopt;
  return (target.q_inertial_from_target * (inertia_kgm2 * target.omega_target_radps)).normalized();
}

SyncStep sync_step(const SyncApproachPlan& plan, double t_s) {
  const StepTimes times = step_times(plan);
  if (t_s < times.fly_around_start_s) return SyncStep::kLine;
  if (t_s < times.axis_start_s) return SyncStep::kFlyAround;
  if (t_s < times.rotation_start_s) return SyncStep::kAxisApproach;
  if (t_s < times.rotation_end_s) return SyncStep::kRotationSync;
  return SyncStep::kTransfer;
}

GuidanceRef sync_approach_reference(const SyncApproachPlan& plan, SyncApproachLatch& latch,
                                    const std::optional<TargetEstimate>& target, const model::TargetOrbit& orbit,
                                    double t_s) {
  const StepTimes times = step_times(plan);
  if (!latch.axis_inertial && t_s >= times.fly_around_start_s && target)
    latch.axis_inertial = angular_momentum_axis(*target, plan.target_inertia_kgm2);
  if (!latch.axis_inertial) return guidance_reference(plan.line, t_s, orbit.lvlh_at(t_s));

  const Vec3 axis_point_inertial = plan.approach.axis_distance_m * *latch.axis_inertial;
  const PoseModel pointing_only(plan, *latch.axis_inertial, nullptr, Vec3::Zero(), Quat::Identity(), orbit);
  // p_start and the attitude offset, fixed when the rotation's synchronisation starts; near its start
  // (t + h) they are needed before: the same from the estimate of now. Earlier nothing reads them.
  std::optional<Vec3> start_target_m = latch.start_target_m;
  std::optional<Quat> sync_offset = latch.sync_offset;
  if (!start_target_m && target && t_s + kDifferenceStep_s >= times.rotation_start_s) {
    const Quat q_target_from_inertial = target->q_inertial_from_target.conjugate();
    start_target_m = q_target_from_inertial * axis_point_inertial;
    sync_offset = (q_target_from_inertial * pointing_only.on_axis_attitude(std::max(t_s, times.rotation_start_s)))
                      .normalized();
    if (t_s >= times.rotation_start_s) latch.start_target_m = start_target_m, latch.sync_offset = sync_offset;
  }
  if (t_s >= times.rotation_end_s && target && latch.start_target_m) {
    SyncTransferParams transfer = plan.transfer;
    transfer.start_target_m = *latch.start_target_m;
    return sync_reference(transfer, *target, orbit.lvlh_at(t_s), t_s);
  }
  const PoseModel model(plan, *latch.axis_inertial, target ? &*target : nullptr, start_target_m.value_or(Vec3::Zero()),
                    sync_offset.value_or(Quat::Identity()), orbit);
  return differentiate(model, t_s);
}

}  // namespace chaser::flight
