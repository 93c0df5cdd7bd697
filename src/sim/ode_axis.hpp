#pragma once

// Internal to the rollout: one axis of an ODE hinge, slider or universal joint, read and
// driven in the URDF sign convention (positive = child rotates positively about, or moves
// along, the axis relative to the parent). ODE measures a hinge and a slider as body1
// relative to body2 and a universal joint's axes on body1 = parent; `sign` maps ODE's
// convention to ours.

#include <ode/ode.h>

#include "motoflex/model/robot_model.hpp"

namespace motoflex::detail {

struct OdeAxis {
  dJointID joint = nullptr;
  bool universal = false;
  bool slider = false;
  int axis = 1;
  double sign = 1.0;

  double angle_rad() const {  // m for a slider
    if (slider) return sign * dJointGetSliderPosition(joint);
    if (!universal) return sign * dJointGetHingeAngle(joint);
    return sign * (axis == 1 ? dJointGetUniversalAngle1(joint) : dJointGetUniversalAngle2(joint));
  }
  double rate_rad_s() const {  // m/s for a slider
    if (slider) return sign * dJointGetSliderPositionRate(joint);
    if (!universal) return sign * dJointGetHingeAngleRate(joint);
    return sign *
           (axis == 1 ? dJointGetUniversalAngle1Rate(joint) : dJointGetUniversalAngle2Rate(joint));
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
  return out;
}

}  // namespace motoflex::detail
