#pragma once

// The friction of a released joint (its H-bridge off, BAM's torque_enable false), which need
// not be the powered joint's. A servo that drives or holds loads its gear mesh with the motor's
// torque, and the fits' Coulomb level carries part of that; released, the arm swings on the
// bearings and an unloaded mesh. On the XL330 bench the released arm's half swings give a
// Coulomb friction of 0.004–0.010 N·m and a viscous 0.008–0.010 N·m·s/rad (README, the
// released arm), where fits of the powered logs put the Coulomb level at 0.03–0.04 N·m.
//
// The released joint's Coulomb and viscous coefficients are the powered ones plus a change:
//   K_c,released = max(0, K_c + ΔK_c),   K_v,released = max(0, K_v + ΔK_v),
// joint.<J>.released_friction_delta_nm and joint.<J>.released_viscous_delta_nm_s_per_rad
// (a slider's in N and N·s/m). Every other term of the friction family is the same in both
// states (its motor-torque terms vanish with the motor torque). ΔK_c = ΔK_v = 0, the neutral,
// is the powered friction, bit for bit.

#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"
#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {

struct ReleasedFrictionChange {
  double coulomb_delta_nm = 0.0;            // ΔK_c
  double viscous_delta_nm_s_per_rad = 0.0;  // ΔK_v
};

// joint.<J>.released_friction_delta_<nm|n>, joint.<J>.released_viscous_delta_<nm_s_per_rad|...>.
std::vector<std::string> released_friction_parameter_names(const ActuatorSpec& joint);

ReleasedFrictionChange read_released_friction(const ParameterReader& get,
                                              const ActuatorSpec& joint);

// The released joint's friction: `powered` with the changed Coulomb and viscous coefficients.
FrictionParams released_friction(const FrictionParams& powered,
                                 const ReleasedFrictionChange& change);

}  // namespace motoflex
