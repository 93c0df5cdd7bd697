#pragma once

#include <string>

#include "motoflex/export/export_input.hpp"

namespace motoflex {

// An SDFormat 1.9 world with the simulated robot (as accepted by libsdformat 12):
//  * <physics type="ode">: step = input.dt_s, solver "world" (dWorldStep, what motoflex uses),
//    the fitted world.erp / world.cfm as ODE constraint ERP/CFM, gravity −9.81;
//  * a ground plane (robots with feet) whose surfaces and the feet carry contact.mu (mu, mu2),
//    contact.slip (slip1, slip2), contact.soft_erp / soft_cfm;
//  * the model: the same rigid bodies motoflex builds (links welded by fixed or held joints are
//    one link, named after its first URDF link; declared hinge pairs are `universal` joints;
//    flexible links are split into sub-links joined by universal joints); a fixed base is a
//    `fixed` joint to the world;
//  * per actuated axis: <dynamics damping friction spring_stiffness=0> and
//    <limit lower upper effort velocity> from actuator_export.hpp; flexible-link axes carry
//    flex.spring_nm_per_rad as spring_stiffness (spring_reference 0), flex damping and friction,
//    integrated implicitly (<physics><ode><implicit_spring_damper>) as motoflex does;
//  * per link its <collision> shapes and <visual> shapes as the MJCF export draws them, meshes
//    by a URI relative to the SDF file ("<robot>_meshes/<file>", see mesh_assets);
//  * <motoflex:servo> per actuated joint (ignored by SDF consumers): the linearised servo
//    gains, armature and gear ratio.
// Lost: armature (SDF has no element; only in <motoflex:servo>), the servo law itself, backlash
// and gear compliance (the gear spring is in series with the motor, not a joint spring, so
// spring_stiffness stays 0 on actuated joints), Stribeck/load friction, sensor effects.
std::string export_sdf(const ExportInput& input);

}  // namespace motoflex
