#pragma once

// The unit suffixes of an actuated joint's own parameters: a revolute joint's are in rad and
// N·m (`joint.knee.friction_nm`), a prismatic joint's in m and N (`joint.slide.friction_n`).

#include <string>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

struct JointUnits {
  const char* position;   // "rad" | "m"
  const char* effort;     // "nm" | "n"
  const char* velocity;   // "rad_s" | "m_s"
  const char* damping;    // "nm_s_per_rad" | "n_s_per_m"
  const char* stiffness;  // "nm_per_rad" | "n_per_m"
  const char* inertia;    // "kg_m2" | "kg" (armature: reflected inertia or mass)
};

inline JointUnits joint_units(const ActuatorSpec& actuator) {
  if (actuator.prismatic) return {"m", "n", "m_s", "n_s_per_m", "n_per_m", "kg"};
  return {"rad", "nm", "rad_s", "nm_s_per_rad", "nm_per_rad", "kg_m2"};
}

// "joint.<name>.<leaf>_<unit>", e.g. joint_parameter(a, "friction", joint_units(a).effort).
inline std::string joint_parameter(const ActuatorSpec& actuator, const std::string& leaf,
                                   const char* unit) {
  return "joint." + actuator.name + "." + leaf + "_" + unit;
}

}  // namespace motoflex
