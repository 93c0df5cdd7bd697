#pragma once

#include <string>

#include "motoflex/export/export_input.hpp"

namespace motoflex {

// XML namespace of the extension elements motoflex adds to URDF and SDF files.
inline constexpr const char* kMotoflexXmlNamespace = "urn:motoflex:export:1";

// The robot's own URDF (every link, joint, comment and number of the source file kept) with,
// on each actuated joint:
//   <dynamics damping friction>  viscous friction + reflected back-EMF (N·m·s/rad), Coulomb (N·m)
//   <limit effort velocity>      servo torque limit and no-load speed (actuator_export.hpp);
//                                a model without a speed limit keeps the URDF's velocity
//   <transmission>               ROS SimpleTransmission with mechanicalReduction = gear ratio
// and one <motoflex:model> element (namespace kMotoflexXmlNamespace) with what URDF cannot
// carry: every parameter by name, value and unit (motor R, L, K_t, backlash, gear spring and
// mass, PID, friction details, contact, sensors), the linearised servo gains and armature per
// joint, and the provenance. urdfdom, ROS and MuJoCo's URDF reader skip unknown elements.
// Lost for URDF consumers: armature, the servo law, backlash and gear compliance, flexible
// links, contact and world settings (all of them only inside <motoflex:model>).
// Throws InputError if the robot's URDF cannot be read.
std::string export_urdf(const ExportInput& input);

}  // namespace motoflex
