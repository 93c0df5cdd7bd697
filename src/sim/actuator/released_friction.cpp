#include "motoflex/sim/actuator/released_friction.hpp"

#include <algorithm>

#include "motoflex/model/joint_units.hpp"

namespace motoflex {

std::vector<std::string> released_friction_parameter_names(const ActuatorSpec& joint) {
  const JointUnits units = joint_units(joint);
  return {joint_parameter(joint, "released_friction_delta", units.effort),
          joint_parameter(joint, "released_viscous_delta", units.damping)};
}

ReleasedFrictionChange read_released_friction(const ParameterReader& get,
                                              const ActuatorSpec& joint) {
  const std::vector<std::string> names = released_friction_parameter_names(joint);
  return {get(names[0]), get(names[1])};
}

FrictionParams released_friction(const FrictionParams& powered,
                                 const ReleasedFrictionChange& change) {
  // read_friction keeps K_c, K_v >= 0, so a change of 0 returns them exactly.
  FrictionParams released = powered;
  released.coulomb_nm = std::max(0.0, powered.coulomb_nm + change.coulomb_delta_nm);
  released.viscous_nm_s_per_rad =
      std::max(0.0, powered.viscous_nm_s_per_rad + change.viscous_delta_nm_s_per_rad);
  return released;
}

}  // namespace motoflex
