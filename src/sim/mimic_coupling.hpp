#pragma once

// Internal to the rollout: URDF <mimic> followers held at multiplier·q_leader + offset.
//
// ODE has no constraint between two joints, so the follower is driven by its own motor row
// with unbounded force toward the leader's rate plus a position correction, solved implicitly
// in the step (stable for any inertia ratio). The coupling drives the follower only: the
// follower's load reaches the parent body through its joint, not the leader's actuator (a
// linkage or a shared motor would make the leader feel it). A leader with a position servo
// tracks its command either way.

#include <vector>

#include "ode_axis.hpp"

namespace motoflex::detail {

// Share of the position error corrected per step (ODE's default ERP).
inline constexpr double kMimicErrorReduction = 0.2;

struct MimicCoupling {
  OdeAxis follower;
  OdeAxis leader;
  double multiplier = 1.0;
  double offset = 0.0;
  int leader_actuator = -1;  // the actuator driving the leader, or −1 (a passive leader)

  // Sets the follower's motor row for the next step of length dt_s.
  void drive(double dt_s) const {
    const double target = multiplier * leader.angle_rad() + offset;
    const double velocity = multiplier * leader.rate_rad_s() +
                            kMimicErrorReduction * (target - follower.angle_rad()) / dt_s;
    follower.set_motor(velocity, dInfinity);
  }
};

}  // namespace motoflex::detail
