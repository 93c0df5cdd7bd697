#include "motoflex/motion/nao_kick.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "motoflex/motion/nao_stance.hpp"

namespace motoflex {
namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c);
  return buffer;
}

double smooth(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

// The quasi-static state a phase ends in: CoM and kicking-sole positions in the world frame
// (origin on the ground midway between the ankles).
struct KickPose {
  double duration_s = 0.0;  // of the phase that ends in this pose
  const char* phase = "";
  Eigen::Vector3d com_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d kick_sole_m = Eigen::Vector3d::Zero();
};

}  // namespace

double NaoKickParams::duration_s() const {
  return 2.0 * rest_s + shift_s + lift_s + backswing_s + kick_s + return_s + put_down_s +
         shift_back_s;
}

std::string NaoKickParams::validate() const {
  for (const auto& [name, value] :
       {std::pair{"com_height_m", com_height_m}, std::pair{"foot_spacing_m", foot_spacing_m},
        std::pair{"lift_height_m", lift_height_m}, std::pair{"shift_s", shift_s},
        std::pair{"lift_s", lift_s}, std::pair{"backswing_s", backswing_s},
        std::pair{"kick_s", kick_s}, std::pair{"return_s", return_s},
        std::pair{"put_down_s", put_down_s}, std::pair{"shift_back_s", shift_back_s},
        std::pair{"rate_hz", rate_hz}}) {
    if (!(std::isfinite(value) && value > 0.0)) {
      return std::string(name) + format(" = %g: must be positive", value);
    }
  }
  if (!(std::isfinite(rest_s) && rest_s >= 0.0)) {
    return format("rest_s = %g: must be >= 0", rest_s);
  }
  if (foot_spacing_m < 0.0776) {
    return format("foot_spacing_m = %g: the soles overlap below 0.0776 m", foot_spacing_m);
  }
  // Sole outline around the ankle: x from −0.05 to +0.10, y 0.03877 inward, 0.05002 outward.
  if (!(support_com_x_m > -0.05 && support_com_x_m < 0.10)) {
    return format("support_com_x_m = %g: must lie over the sole, (-0.05, 0.10) m from the ankle",
                  support_com_x_m);
  }
  if (!(support_com_y_m > -0.05002 && support_com_y_m < 0.03877)) {
    return format(
        "support_com_y_m = %g: must lie over the sole, (-0.05002, 0.03877) m inward "
        "of the ankle",
        support_com_y_m);
  }
  // The soles' inner edges are 0.03877 m from the ankles: the swinging foot must stay clear.
  if (!(std::isfinite(swing_inward_m) && swing_inward_m >= 0.0 &&
        swing_inward_m <= foot_spacing_m - 2.0 * 0.03877)) {
    return format("swing_inward_m = %g: must be within [0, foot_spacing_m - 0.0775 = %g] m",
                  swing_inward_m, foot_spacing_m - 2.0 * 0.03877);
  }
  if (!(std::isfinite(backswing_m) && std::isfinite(reach_m) && reach_m > -backswing_m)) {
    return format("reach_m = %g: must be ahead of the backswing position (-%g m)", reach_m,
                  backswing_m);
  }
  if (rate_hz > 1000.0) return format("rate_hz = %g: must be <= 1000", rate_hz);
  return {};
}

CommandTrajectory nao_kick_trajectory(const RobotModel& model, const NaoKickParams& p) {
  if (const std::string error = p.validate(); !error.empty()) throw std::invalid_argument(error);
  const NaoStance stance(model);
  const double half = 0.5 * p.foot_spacing_m;
  const double support_y = p.kick_left ? -half : half;
  const double kick_y = -support_y;
  const double inward = p.kick_left ? 1.0 : -1.0;  // toward the kicking leg, seen from support
  const Eigen::Vector3d centre(p.support_com_x_m, 0.0, p.com_height_m);
  const Eigen::Vector3d over_support(p.support_com_x_m, support_y + inward * p.support_com_y_m,
                                     p.com_height_m);
  const Eigen::Vector3d down(0.0, kick_y, 0.0);
  // Lifted, the kicking foot moves under its hip (the torso leans over the support foot), which
  // keeps the kicking leg's hip and ankle roll small.
  const double swing_y = kick_y + inward * -p.swing_inward_m;
  const Eigen::Vector3d up(0.0, swing_y, p.lift_height_m);
  const Eigen::Vector3d back(-p.backswing_m, swing_y, p.lift_height_m);
  const Eigen::Vector3d front(p.reach_m, swing_y, p.lift_height_m);
  const std::vector<KickPose> poses = {
      {0.0, "start", centre, down},
      {p.rest_s, "rest", centre, down},
      {p.shift_s, "shift", over_support, down},
      {p.lift_s, "lift", over_support, up},
      {p.backswing_s, "backswing", over_support, back},
      {p.kick_s, "kick", over_support, front},
      {p.return_s, "return", over_support, up},
      {p.put_down_s, "put_down", over_support, down},
      {p.shift_back_s, "shift_back", centre, down},
      {p.rest_s, "rest", centre, down},
  };

  const std::size_t joints = model.actuators.size();
  const double dt = 1.0 / p.rate_hz;
  const auto frames = static_cast<std::size_t>(std::floor(p.duration_s() * p.rate_hz + 1e-9)) + 1;
  std::vector<double> times(frames), angles(frames * joints);
  NaoStance::Solution previous;
  std::size_t phase = 1;
  double phase_start = 0.0;
  for (std::size_t f = 0; f < frames; ++f) {
    const double t = f * dt;
    while (phase + 1 < poses.size() && t > phase_start + poses[phase].duration_s + 1e-12) {
      phase_start += poses[phase].duration_s;
      ++phase;
    }
    const KickPose& from = poses[phase - 1];
    const KickPose& to = poses[phase];
    const double w = to.duration_s > 0.0 ? smooth((t - phase_start) / to.duration_s) : 1.0;
    NaoFootPose support_sole, kick_sole;
    support_sole.position_m = {0.0, support_y, 0.0};
    kick_sole.position_m = from.kick_sole_m + w * (to.kick_sole_m - from.kick_sole_m);
    const Eigen::Vector3d com = from.com_m + w * (to.com_m - from.com_m);
    try {
      previous = stance.solve(com, p.kick_left ? kick_sole : support_sole,
                              p.kick_left ? support_sole : kick_sole, f == 0 ? nullptr : &previous);
    } catch (const NaoLegUnreachable& error) {
      throw std::invalid_argument(std::string("kick phase '") + to.phase +
                                  format("' at t = %.2f s: ", t) + error.what() +
                                  " (check lift_height_m, backswing_m, reach_m, com_height_m)");
    }
    times[f] = t;
    stance.write_actuator_angles(previous.legs, &angles[f * joints]);
  }
  return CommandTrajectory(std::move(times), std::move(angles), joints);
}

}  // namespace motoflex
