#pragma once

// Starting gains of a torque-controlled leg joint of a floating-base robot, derived from the
// robot's mass and leg geometry, so that a robot folder fresh from init-robot stands under its
// own weight (init-robot's default `pd_torque` law; README "Bring your own robot").

#include <cstddef>
#include <optional>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// The rule, for an actuated hinge with feet below it, on a robot of total mass M standing on n
// feet (g = 9.81 m/s², d = the largest distance from the joint's axis point to the origin of a
// foot's collision shape below it (a mesh foot: its link frame), in the stand pose):
//   hold torque  τ_h = (M·g/n)·d           the most the joint carries standing still
//   kp           = τ_h / θ_sag,  θ_sag = kStanceSag_rad: it yields at most θ_sag under τ_h
//   kd           = 2·ζ·√(kp·(M/n)·d²),  ζ = 1: critical for the weight share swinging at d
//   torque limit = kStanceTorqueMargin·τ_h: the weight on two legs, with as much again to move
// kp, kd and the limit are rounded to three significant digits (starting values, read by users).
// (kd acts through the law's implicit damping row, so a light shank swinging with it stays
// stable.) Null for a fixed base, a slider, a robot without feet, or a joint with no foot
// below it (an arm, a head): the law's other rules apply.
struct StanceGains {
  double lever_m = 0.0;         // d
  double hold_torque_nm = 0.0;  // τ_h
  double kp_nm_per_rad = 0.0;
  double kd_nm_s_per_rad = 0.0;
  double torque_max_nm = 0.0;
};

inline constexpr double kStanceSag_rad = 0.005;
inline constexpr double kStanceDampingRatio = 1.0;
inline constexpr double kStanceTorqueMargin = 4.0;

std::optional<StanceGains> stance_gains(const RobotModel& model, std::size_t actuator);

}  // namespace motoflex
