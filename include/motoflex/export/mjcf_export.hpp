#pragma once

#include <string>
#include <vector>

#include "motoflex/export/export_input.hpp"

namespace motoflex {

// How the MJCF places the robot. Defaults: the exported file as a user gets it.
struct MjcfOptions {
  // Free-floating robots get a free joint on the root body; true welds the root to the world
  // instead (motoflex's held torso, RolloutOptions::hold_torso).
  bool weld_root = false;
  // Actuated joint angles (model order) the robot is placed in; empty: all zero.
  std::vector<double> placement_pose_rad;
  // Gap between the lowest foot point and the ground in that pose; negative: the robot's
  // initial_clearance_m (a held torso uses 0.1 m).
  double clearance_m = -1.0;
  // false leaves the armature out (motoflex's ODE joints carry none for the motoflex servo).
  bool armature = true;
};

// A MuJoCo model (MJCF as accepted by MuJoCo 2.2.2, Debian 12) of the simulated robot:
//  * bodies: the same rigid bodies motoflex builds in ODE (links welded by fixed or held joints
//    are one body; hinge pairs declared universal are two hinges at one point in one body;
//    flexible sub-links are joined by two hinges with stiffness/damping/frictionloss from the
//    flex.* parameters), with their masses and inertias; the bench servo's arm is a point mass
//    bench.mass_kg at bench.length_m with bench.armature_kg_m2 as joint armature;
//  * base: free joint (free-floating robots) or welded (fixed base, or options.weld_root);
//  * joints: range from the URDF, damping (viscous + reflected back-EMF), frictionloss
//    (Coulomb), armature (actuator_export.hpp: m_g for the motoflex servo);
//  * one <general> position actuator per actuated joint, in log column order: force =
//    kp·(ctrl − q) − kv·q̇ clamped to ±effort (in 2.2.2 a PD servo must be written as
//    gainprm="kp" biastype="affine" biasprm="0 -kp -kv"; <position kv> came in 3.1.0). ctrl is
//    the commanded angle; for the ideal servo it is the angle to reach at the end of the step;
//  * <option timestep = dt integrator="implicit">: the stiff servo damping, joint damping and
//    reflected back-EMF are integrated implicitly (motoflex's ODE rows are implicit too);
//  * contact (robots with feet): a ground plane; only the feet collide with it and nothing else
//    collides (motoflex: any other body touching the ground is a fall). Friction contact.mu;
//    the ODE soft contact (soft_erp, soft_cfm at step h) is the spring-damper
//    k = erp/(h·cfm), c = (1 − erp)/cfm; per contact point with the mass m = robot mass / foot
//    contact points this is MuJoCo's solref (timeconst 2m/c, dampratio c/(2·√(k·m))), with the
//    time constant raised to 2·dt where it is shorter (MuJoCo's own safety limit);
//  * geometry: the collision shapes motoflex simulates (group 3, hidden in MuJoCo's viewer;
//    mesh hulls inline) and visual geoms (group 1, contype = conaffinity = 0, mass 0) for what
//    a viewer shows (exported_visuals.hpp: URDF visuals, else collision shapes, else a CoM
//    sphere with rods to the joints); a mesh visual names its file relative to the MJCF file,
//    "<robot>_meshes/<file>", which mesh_assets (exported_file.hpp) provides;
//  * <custom>: every parameter as numeric "motoflex:<name>", and the provenance as text.
// MuJoCo has no backlash: the gear's dead zone (gear.<G>.backlash_rad), its spring and small
// mass are left out, so the exported joint is stiff where motoflex's has a play of l_h. MuJoCo's
// documented workaround (a second hinge with range ±l_h/2 and armature) was not used: it adds a
// DOF and a constraint row per joint, and MoToFlex's l_h ≈ 1e-5 rad (6e-4°) is far below the
// scale at which the export is compared with motoflex (tests/export/). Also lost: PID
// integral, motor inductance, Stribeck and load friction, contact slip, sensor effects, motor
// effects. The JSON export keeps all of them.
std::string export_mjcf(const ExportInput& input, const MjcfOptions& options = {});

}  // namespace motoflex
