#pragma once

// How each servo law becomes a linear position actuator with joint-level dynamics in a
// simulator that has nothing else (URDF, SDF, MJCF): one rule per law, in
// src/export/servo/<law>_servo_export.cpp, listed in servo_export_registry.cpp. The derivations
// are in actuator_export.hpp.

#include <cstddef>
#include <string>

#include "motoflex/export/actuator_export.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {

struct ServoExportRule {
  std::string law;          // the servo law's registry name
  std::string description;  // one line for the exported files' comments
  // Fills the servo and joint dynamics fields of `out` (kp, kv, effort, damping, friction,
  // reduction, armature) for one actuator. Throws ModelError for values that make no sense.
  void (*fill)(const ExportInput& input, std::size_t actuator, const ParameterReader& get,
               ActuatorExport& out);
  bool command_is_next_angle = false;  // the target is the angle at the END of the step
};

// The rule of `law`; throws ModelError when the law has none (it cannot be exported).
const ServoExportRule& servo_export_rule(const std::string& law);

}  // namespace motoflex
