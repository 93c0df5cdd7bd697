#pragma once

// Internal to the servo export rules: the velocity gain of a stiff position actuator standing
// in for an ODE velocity constraint (ideal and velocity servos), kv·dt = 5·I_subtree (the
// derivation is in actuator_export.hpp).

#include "motoflex/export/actuator_export.hpp"

namespace motoflex::detail {

inline double stiff_servo_kv_nm_s_per_rad(const ExportInput& input, std::size_t actuator,
                                          double armature) {
  constexpr double kStiffServoInertiaSteps = 5.0;
  // On a slider both terms are masses (kg), and kv is in N·s/m.
  return kStiffServoInertiaSteps * (subtree_inertia_kg_m2(input.model, actuator) + armature) /
         input.dt_s;
}

}  // namespace motoflex::detail
