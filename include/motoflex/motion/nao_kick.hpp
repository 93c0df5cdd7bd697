#pragma once

#include <string>

#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"

namespace motoflex {

// A forward kick of a Nao-class robot standing on one leg, like the kicking robot of the
// MoToFlex paper's fitness. Quasi-static: the whole-body CoM (from the model's bodies) is moved
// over the support foot and stays there while the kicking foot lifts, swings back, kicks
// forward, returns and is put down; then the weight goes back to the middle. Each phase blends
// the CoM and the kicking foot between their poses with a quintic smoothstep (zero velocity and
// acceleration at the phase ends); leg inverse kinematics at every command frame.
struct NaoKickParams {
  bool kick_left = false;        // kicking leg (the other one supports)
  double com_height_m = 0.24;    // whole-body CoM above the ground (constant)
  double foot_spacing_m = 0.10;  // lateral distance between the two ankles while standing
  // Where the CoM goes over the support foot, relative to its ankle (x forward, y inward).
  double support_com_x_m = 0.02;
  double support_com_y_m = 0.015;
  double lift_height_m = 0.03;   // kicking foot above the ground while it swings
  double swing_inward_m = 0.02;  // lifted kicking foot moved toward the support foot
  double backswing_m = 0.04;     // kicking foot behind the support ankle before the kick
  double reach_m = 0.09;         // kicking foot in front of the support ankle at the kick's end
  // Phase durations, in order.
  double rest_s = 0.5;   // standing still at the start and at the end
  double shift_s = 1.0;  // weight onto the support leg
  double lift_s = 0.6;
  double backswing_s = 0.5;
  double kick_s = 0.3;    // the kick itself
  double return_s = 0.6;  // foot back below the hip
  double put_down_s = 0.6;
  double shift_back_s = 1.0;  // weight back to the middle
  double rate_hz = 100.0;

  double duration_s() const;
  // Empty when usable; otherwise one line naming the parameter, its value and the limit.
  std::string validate() const;
};

// The kick as commanded angles at rate_hz in model actuator order (non-leg actuators at the
// stand pose). Throws std::invalid_argument naming the parameter and the limit for invalid or
// unreachable parameters.
CommandTrajectory nao_kick_trajectory(const RobotModel& model, const NaoKickParams& params);

}  // namespace motoflex
