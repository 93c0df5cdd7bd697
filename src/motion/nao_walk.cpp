#include "motoflex/motion/nao_walk.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "motoflex/motion/nao_stance.hpp"
#include "motoflex/motion/zmp_preview.hpp"
#include "nao_footsteps.hpp"

namespace motoflex {
namespace {

using detail::NaoFootsteps;

using detail::kSoleBack_m;
using detail::kSoleFront_m;
using detail::kSoleInner_m;
using detail::kSoleOuter_m;
constexpr double kMaxStepHeight_m = 0.10;
// Sanity bounds of the foot pitch at toe-off and heel strike (57° and 46°): beyond them the
// rigid sole would stand almost on end; the leg IK checks the joint limits on top of that.
constexpr double kMaxToeOff_rad = 1.0;
constexpr double kMaxHeelStrike_rad = 0.8;

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[320];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c, d);
  return buffer;
}

NaoFootPose flat(const Eigen::Vector3d& position) {
  NaoFootPose pose;
  pose.position_m = position;
  return pose;
}

// The sole point of a foot pitched about an edge, with the yaw the leg gave it.
Eigen::Vector3d sole_point(const NaoEdgeFoot& foot, double yaw_rad) {
  if (foot.pitch_rad == 0.0) return foot.edge_m - Eigen::Vector3d(foot.edge_x_m, 0.0, 0.0);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).matrix() *
                            Eigen::AngleAxisd(foot.pitch_rad, Eigen::Vector3d::UnitY()).matrix();
  return foot.edge_m - R * Eigen::Vector3d(foot.edge_x_m, 0.0, 0.0);
}

bool stance_reachable(const NaoStance& stance, double com_height_m, double half_step_m,
                      double half_spacing_m) {
  try {
    stance.solve({0.0, 0.0, com_height_m}, flat({half_step_m, half_spacing_m, 0.0}),
                 flat({-half_step_m, -half_spacing_m, 0.0}));
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

// The CoM heights at which the robot can stand with this foot spacing, by bisection from the
// best standing height found on a coarse scan; {0, 0} if none.
std::pair<double, double> reachable_com_heights(const NaoStance& stance, double spacing_m) {
  const double half_spacing = 0.5 * spacing_m;
  double best = -1.0;
  for (double h = 0.40; h > 0.05; h -= 0.01) {
    if (stance_reachable(stance, h, 0.0, half_spacing)) {
      best = h;
      break;
    }
  }
  if (best < 0.0) return {0.0, 0.0};
  double lo = best, hi = best + 0.01;
  while (hi - lo > 1e-4) {
    const double mid = 0.5 * (lo + hi);
    (stance_reachable(stance, mid, 0.0, half_spacing) ? lo : hi) = mid;
  }
  const double top = lo;
  double low_ok = best, low_bad = 0.0;
  while (low_ok - low_bad > 1e-4) {
    const double mid = 0.5 * (low_ok + low_bad);
    (stance_reachable(stance, mid, 0.0, half_spacing) ? low_ok : low_bad) = mid;
  }
  return {low_ok, top};
}

}  // namespace

std::vector<std::pair<const char*, double*>> NaoWalkParams::numeric_fields() {
  return {{"speed_mm_s", &speed_mm_s},
          {"step_duration_s", &step_duration_s},
          {"step_height_m", &step_height_m},
          {"double_support_ratio", &double_support_ratio},
          {"com_height_m", &com_height_m},
          {"foot_spacing_m", &foot_spacing_m},
          {"start_s", &start_s},
          {"stop_s", &stop_s},
          {"duration_s", &duration_s},
          {"rate_hz", &rate_hz},
          {"zmp_offset_x_m", &zmp_offset_x_m},
          {"zmp_offset_y_m", &zmp_offset_y_m},
          {"zmp_travel_x_m", &zmp_travel_x_m},
          {"zmp_transfer_smoothing", &zmp_transfer_smoothing},
          {"toe_off_rad", &toe_off_rad},
          {"heel_strike_rad", &heel_strike_rad},
          {"torso_offset_x_m", &torso_offset_x_m},
          {"preview_s", &preview_s}};
}

std::optional<double> NaoWalkParams::numeric(std::string_view key) const {
  NaoWalkParams copy = *this;
  for (const auto& [name, value] : copy.numeric_fields()) {
    if (key == name) return *value;
  }
  return std::nullopt;
}

std::string NaoWalkParams::validate() const {
  const auto positive = [](const char* name, double value) -> std::string {
    if (std::isfinite(value) && value > 0.0) return {};
    return std::string(name) + format(" = %g: must be positive", value);
  };
  for (const auto& [name, value] :
       {std::pair{"step_duration_s", step_duration_s}, std::pair{"com_height_m", com_height_m},
        std::pair{"start_s", start_s}, std::pair{"stop_s", stop_s},
        std::pair{"duration_s", duration_s}, std::pair{"rate_hz", rate_hz},
        std::pair{"preview_s", preview_s}, std::pair{"foot_spacing_m", foot_spacing_m}}) {
    if (auto error = positive(name, value); !error.empty()) return error;
  }
  if (!std::isfinite(speed_mm_s) || speed_mm_s < 0.0) {
    return format("speed_mm_s = %g: must be >= 0 (the walk goes straight forward)", speed_mm_s);
  }
  if (!(step_height_m >= 0.0 && step_height_m <= kMaxStepHeight_m)) {
    return format("step_height_m = %g: must be within [0, %g] m", step_height_m, kMaxStepHeight_m);
  }
  if (!(double_support_ratio >= 0.0 && double_support_ratio <= 0.9)) {
    return format("double_support_ratio = %g: must be within [0, 0.9]", double_support_ratio);
  }
  if (foot_spacing_m < 2.0 * kSoleInner_m) {
    return format(
        "foot_spacing_m = %g: the soles overlap below %g m (inner edge %g m from the "
        "ankle)",
        foot_spacing_m, 2.0 * kSoleInner_m, kSoleInner_m);
  }
  if (rate_hz > 1000.0) return format("rate_hz = %g: must be <= 1000", rate_hz);
  if (!(zmp_offset_x_m > -kSoleBack_m && zmp_offset_x_m < kSoleFront_m)) {
    return format("zmp_offset_x_m = %g: must lie inside the sole, (-%g, %g) m from the ankle",
                  zmp_offset_x_m, kSoleBack_m, kSoleFront_m);
  }
  if (!(zmp_travel_x_m >= 0.0 && zmp_offset_x_m - 0.5 * zmp_travel_x_m > -kSoleBack_m &&
        zmp_offset_x_m + 0.5 * zmp_travel_x_m < kSoleFront_m)) {
    return format(
        "zmp_travel_x_m = %g: must be >= 0 and keep zmp_offset_x_m +- half of it inside "
        "the sole, (-%g, %g) m from the ankle",
        zmp_travel_x_m, kSoleBack_m, kSoleFront_m);
  }
  if (!(zmp_offset_y_m > -kSoleOuter_m && zmp_offset_y_m < kSoleInner_m)) {
    return format(
        "zmp_offset_y_m = %g: must lie inside the sole, (-%g, %g) m inward of the "
        "ankle",
        zmp_offset_y_m, kSoleOuter_m, kSoleInner_m);
  }
  if (!(zmp_transfer_smoothing >= 0.0 && zmp_transfer_smoothing <= 1.0)) {
    return format("zmp_transfer_smoothing = %g: must be within [0, 1]", zmp_transfer_smoothing);
  }
  if (!(toe_off_rad >= 0.0 && toe_off_rad <= kMaxToeOff_rad)) {
    return format("toe_off_rad = %g: must be within [0, %g] rad", toe_off_rad, kMaxToeOff_rad);
  }
  if (!(heel_strike_rad >= 0.0 && heel_strike_rad <= kMaxHeelStrike_rad)) {
    return format("heel_strike_rad = %g: must be within [0, %g] rad", heel_strike_rad,
                  kMaxHeelStrike_rad);
  }
  if (!std::isfinite(torso_offset_x_m) || std::abs(torso_offset_x_m) > 0.05) {
    return format("torso_offset_x_m = %g: must be within [-0.05, 0.05] m", torso_offset_x_m);
  }
  const double needed = start_s + stop_s + step_duration_s;
  if (duration_s < needed - 1e-9) {
    return format(
        "duration_s = %g: start_s + stop_s + two steps (one step_duration_s) need at "
        "least %g s",
        duration_s, needed);
  }
  return {};
}

namespace {

// Plans the walk into `plan`. Returns an empty string, or where and why a leg could not follow
// ("at t = 1.90 s: left leg: ...").
std::string try_plan(const RobotModel& model, const NaoStance& stance, const NaoWalkParams& p,
                     NaoWalkPlan& plan) {
  plan = {};
  plan.params = p;
  plan.mass_kg = stance.mass_kg();
  plan.step_length_m = 1e-3 * p.speed_mm_s * p.step_duration_s / 2.0;
  const NaoFootsteps footsteps(p, plan.step_length_m);
  plan.steps = static_cast<int>(footsteps.steps().size());
  plan.walk_start_s = p.start_s;
  plan.walk_end_s = footsteps.walk_end_s();
  plan.steady_start_s = plan.walk_start_s + 2.0 * footsteps.step_s();
  plan.steady_end_s = footsteps.steady_end_s();

  // Reference ZMP at the command frames, then the CoM by preview control (one controller per
  // axis; the cart-table axes are independent).
  const double dt = 1.0 / p.rate_hz;
  const auto frames = static_cast<std::size_t>(std::floor(p.duration_s * p.rate_hz + 1e-9)) + 1;
  std::vector<double> ref_x(frames), ref_y(frames);
  for (std::size_t f = 0; f < frames; ++f) {
    const Eigen::Vector2d zmp = footsteps.zmp_ref(f * dt);
    ref_x[f] = zmp.x();
    ref_y[f] = zmp.y();
  }
  ZmpPreviewOptions options;
  options.dt_s = dt;
  options.com_height_m = p.com_height_m;
  options.preview_s = p.preview_s;
  // Kajita's weights (Q_e = 1, Q_x = 0) with R = 1e-7 instead of 1e-6: at our 10 ms period
  // (Kajita: 5 ms) this keeps the table ZMP within 4 mm of the reference at 200 mm/s.
  options.jerk_weight = 1e-7;
  const ZmpPreviewController controller(options);
  const ZmpPreviewController::Track track_x = controller.track(ref_x);
  const ZmpPreviewController::Track track_y = controller.track(ref_y);

  const std::size_t joints = model.actuators.size();
  std::vector<double> times(frames), angles(frames * joints);
  plan.samples.resize(frames);
  NaoStance::Solution previous;
  for (std::size_t f = 0; f < frames; ++f) {
    NaoWalkSample& s = plan.samples[f];
    s.time_s = f * dt;
    s.zmp_ref_m = {ref_x[f], ref_y[f]};
    s.zmp_m = {track_x.zmp_m[f], track_y.zmp_m[f]};
    s.com_m = {track_x.com_m[f], track_y.com_m[f]};
    s.com_accel_m_s2 = {track_x.accel_m_s2[f], track_y.accel_m_s2[f]};
    NaoEdgeFoot left, right;
    footsteps.feet(s.time_s, p.step_height_m, left, right, s.support);
    const Eigen::Vector3d com(s.com_m.x() + p.torso_offset_x_m, s.com_m.y(), p.com_height_m);
    NaoStance::EdgeSolution solution;
    try {
      solution = stance.solve(com, left, right, f == 0 ? nullptr : &previous);
    } catch (const NaoLegUnreachable& error) {
      return format("at t = %.2f s: ", s.time_s) + error.what();
    }
    previous = solution;
    s.left_foot = left;
    s.right_foot = right;
    s.left_yaw_rad = solution.left_yaw_rad;
    s.right_yaw_rad = solution.right_yaw_rad;
    s.left_sole_m = sole_point(left, solution.left_yaw_rad);
    s.right_sole_m = sole_point(right, solution.right_yaw_rad);
    s.torso_m = previous.torso_W_m;
    times[f] = s.time_s;
    stance.write_actuator_angles(previous.legs, &angles[f * joints]);
  }
  plan.commands = CommandTrajectory(std::move(times), std::move(angles), joints);
  return {};
}

// Largest speed in [low, high] mm/s (1 mm/s resolution) that can be planned, by bisection;
// `low` must be plannable.
double max_speed_mm_s(const RobotModel& model, const NaoStance& stance, NaoWalkParams p, double low,
                      double high) {
  NaoWalkPlan scratch;
  while (high - low > 1.0) {
    p.speed_mm_s = 0.5 * (low + high);
    (try_plan(model, stance, p, scratch).empty() ? low : high) = p.speed_mm_s;
  }
  return std::floor(low);
}

// Throws unless standing at the CoM height with the foot spacing is reachable.
void check_standing(const NaoStance& stance, const NaoWalkParams& p) {
  if (stance_reachable(stance, p.com_height_m, 0.0, 0.5 * p.foot_spacing_m)) return;
  const auto [low, high] = reachable_com_heights(stance, p.foot_spacing_m);
  if (high <= 0.0) {
    throw std::invalid_argument(
        format("foot_spacing_m = %g: the legs cannot stand with this "
               "spacing at any CoM height",
               p.foot_spacing_m));
  }
  throw std::invalid_argument(
      format("com_height_m = %g: out of reach; standing with "
             "foot_spacing_m %g the legs reach CoM heights %.3f to "
             "%.3f m",
             p.com_height_m, p.foot_spacing_m, low, high));
}

}  // namespace

NaoWalkPlan plan_nao_walk(const RobotModel& model, const NaoWalkParams& p) {
  if (const std::string error = p.validate(); !error.empty()) throw std::invalid_argument(error);
  const NaoStance stance(model, p.joint_limits);
  check_standing(stance, p);
  NaoWalkPlan plan;
  const std::string failure = try_plan(model, stance, p, plan);
  if (failure.empty()) return plan;

  // Name the limit: the fastest walk with the other parameters unchanged, or, if not even
  // stepping in place works, the posture parameters.
  NaoWalkParams in_place = p;
  in_place.speed_mm_s = 0.0;
  NaoWalkPlan scratch;
  if (p.speed_mm_s > 0.0 && try_plan(model, stance, in_place, scratch).empty()) {
    const double fastest = max_speed_mm_s(model, stance, p, 0.0, p.speed_mm_s);
    throw std::invalid_argument(
        format("speed_mm_s = %g: step length %.3f m (speed * step_duration_s / 2) exceeds the "
               "reachable %.3f m ",
               p.speed_mm_s, plan.step_length_m, 1e-3 * fastest * p.step_duration_s / 2.0) +
        format("(speed_mm_s <= %g) at com_height_m %g, ", fastest, p.com_height_m) +
        format("step_duration_s %g; ", p.step_duration_s) + failure +
        (p.toe_off_rad > 0.0 || p.heel_strike_rad > 0.0
             ? std::string()
             : std::string("; the feet stay flat: toe_off_rad and heel_strike_rad let them roll "
                           "over their toe and heel edges for longer steps")));
  }
  throw std::invalid_argument(
      format("com_height_m = %g: even stepping in place is out of reach with foot_spacing_m %g, ",
             p.com_height_m, p.foot_spacing_m) +
      format("step_height_m %g, zmp_offset_y_m %g ", p.step_height_m, p.zmp_offset_y_m) + failure);
}

double nao_max_walk_speed_mm_s(const RobotModel& model, const NaoWalkParams& params) {
  if (const std::string error = params.validate(); !error.empty()) {
    throw std::invalid_argument(error);
  }
  const NaoStance stance(model, params.joint_limits);
  check_standing(stance, params);
  NaoWalkParams p = params;
  p.speed_mm_s = 0.0;
  NaoWalkPlan scratch;
  if (!try_plan(model, stance, p, scratch).empty()) return 0.0;
  return max_speed_mm_s(model, stance, p, 0.0, 1000.0);
}

CommandTrajectory nao_walk_trajectory(const RobotModel& model, const NaoWalkParams& params) {
  return plan_nao_walk(model, params).commands;
}

}  // namespace motoflex
