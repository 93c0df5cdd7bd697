#pragma once

// Internal to the rollout: one axis of an ODE hinge, slider or universal joint, read and
// driven in the URDF sign convention (positive = child rotates positively about, or moves
// along, the axis relative to the parent). ODE measures a hinge and a slider as body1
// relative to body2 and a universal joint's axes on body1 = parent; `sign` maps ODE's
// convention to ours.

#include <ode/ode.h>

#include <cmath>
#include <numbers>

#include "motoflex/model/robot_model.hpp"

namespace motoflex::detail {

struct OdeAxis {
  dJointID joint = nullptr;
  bool universal = false;
  bool slider = false;
  int axis = 1;
  double sign = 1.0;
  // A hinge without stops may turn any number of times, but ODE reports its angle in
  // (−π, π]: count the turns (read every step, so a jump of more than π is a wrap).
  bool count_turns = false;
  mutable double turns = 0.0;
  mutable double last_raw_rad = 0.0;

  double angle_rad() const {  // m for a slider
    if (slider) return sign * dJointGetSliderPosition(joint);
    if (!universal) {
      const double raw = sign * dJointGetHingeAngle(joint);
      if (!count_turns) return raw;
      if (raw - last_raw_rad > std::numbers::pi) turns -= 1.0;
      if (raw - last_raw_rad < -std::numbers::pi) turns += 1.0;
      last_raw_rad = raw;
      return raw + 2.0 * std::numbers::pi * turns;
    }
    return sign * (axis == 1 ? dJointGetUniversalAngle1(joint) : dJointGetUniversalAngle2(joint));
  }
  double rate_rad_s() const {  // m/s for a slider
    if (slider) return sign * dJointGetSliderPositionRate(joint);
    if (!universal) return sign * dJointGetHingeAngleRate(joint);
    return sign *
           (axis == 1 ? dJointGetUniversalAngle1Rate(joint) : dJointGetUniversalAngle2Rate(joint));
  }
  // Starts counting turns from the current pose, which is `angle` (rad).
  void sync_turns(double angle) const {
    if (!count_turns) return;
    last_raw_rad = sign * dJointGetHingeAngle(joint);
    turns = std::round((angle - last_raw_rad) / (2.0 * std::numbers::pi));
  }
  // Joint motor row: drive the rate toward velocity_rad_s with at most fmax_nm (N for a slider).
  void set_motor(double velocity_rad_s, double fmax_nm) const {
    if (slider) {
      dJointSetSliderParam(joint, dParamVel, sign * velocity_rad_s);
      dJointSetSliderParam(joint, dParamFMax, fmax_nm);
    } else if (!universal) {
      dJointSetHingeParam(joint, dParamVel, sign * velocity_rad_s);
      dJointSetHingeParam(joint, dParamFMax, fmax_nm);
    } else {
      dJointSetUniversalParam(joint, axis == 1 ? dParamVel : dParamVel2, sign * velocity_rad_s);
      dJointSetUniversalParam(joint, axis == 1 ? dParamFMax : dParamFMax2, fmax_nm);
    }
  }
};

// The axis `axis` (1 or 2) of model joint `spec` built as ODE joint `joint`.
inline OdeAxis ode_axis(dJointID joint, const JointSpec& spec, int axis) {
  OdeAxis out;
  out.joint = joint;
  out.slider = spec.kind == JointKind::kSlider;
  out.universal = spec.kind == JointKind::kUniversal || spec.kind == JointKind::kFlex;
  out.axis = axis;
  out.sign = out.universal ? -1.0 : 1.0;
  out.count_turns = spec.kind == JointKind::kHinge && !std::isfinite(spec.lower1_rad);
  return out;
}

}  // namespace motoflex::detail
