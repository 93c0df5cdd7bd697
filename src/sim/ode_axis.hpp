#pragma once

// Internal to the rollout: one actuated axis of an ODE hinge or universal joint, read and
// driven in the URDF sign convention (positive = child rotates positively about the axis
// relative to the parent). ODE measures a hinge as body1 relative to body2 and a universal
// joint's axes on body1 = parent; `sign` maps ODE's convention to ours.

#include <ode/ode.h>

#include "motoflex/model/robot_model.hpp"

namespace motoflex::detail {

struct OdeAxis {
  dJointID joint = nullptr;
  bool universal = false;
  int axis = 1;
  double sign = 1.0;

  double angle_rad() const {
    if (!universal) return sign * dJointGetHingeAngle(joint);
    return sign * (axis == 1 ? dJointGetUniversalAngle1(joint) : dJointGetUniversalAngle2(joint));
  }
  double rate_rad_s() const {
    if (!universal) return sign * dJointGetHingeAngleRate(joint);
    return sign *
           (axis == 1 ? dJointGetUniversalAngle1Rate(joint) : dJointGetUniversalAngle2Rate(joint));
  }
  // Joint motor row: drive the rate toward velocity_rad_s with at most fmax_nm.
  void set_motor(double velocity_rad_s, double fmax_nm) const {
    if (!universal) {
      dJointSetHingeParam(joint, dParamVel, sign * velocity_rad_s);
      dJointSetHingeParam(joint, dParamFMax, fmax_nm);
    } else {
      dJointSetUniversalParam(joint, axis == 1 ? dParamVel : dParamVel2, sign * velocity_rad_s);
      dJointSetUniversalParam(joint, axis == 1 ? dParamFMax : dParamFMax2, fmax_nm);
    }
  }
};

}  // namespace motoflex::detail
