#pragma once

#include <string>
#include <vector>

#include "motoflex/export/export_input.hpp"

namespace motoflex {

// What the fitted servo and joint model of one actuated joint become in a simulator that has
// only joint-level dynamics (viscous damping, Coulomb friction, armature) and a linear position
// servo with a force limit (URDF, SDF, MJCF). All values are joint side.
//
// Linearised servos (derivations; σ gear ratio, S stiffness factor, K_t torque constant, R
// armature resistance, U_bat supply voltage):
//  * motoflex (seed 001, Algorithm 1 with the RL lag L/R ≈ 50 µs ≪ 1 ms neglected): the joint
//    torque is σ·S·K_t/R·U with U = clamp(kp·e + ki·∫e + kd·ė, ±U_bat), so with g = σ·S·K_t/R
//    (N·m per V):  kp_joint = g·kp_v,  kv_joint = g·kd_v (the derivative of e = θ_d − θ is −θ̇
//    for a constant command),  effort = g·U_bat. The integral term has no counterpart in a
//    linear position actuator and is dropped. The back-EMF/viscous term B·ω_m reaches the joint
//    as B·σ²·θ̇ (ω_m = σ·θ̇, τ = σ·T_M) and becomes joint damping, together with the joint's own
//    viscous friction: damping = joint.viscous + B·σ². motoflex integrates B·σ² implicitly as a
//    linear damper (an unbounded zero-velocity motor row with CFM = 1/(B·σ²), rollout.cpp), as
//    MuJoCo integrates joint damping; the held-Nao comparison in
//    tests/export/mujoco_check_test.cpp shows what the rest of the export drops.
//  * bench (BAM eq. 12–13): τ = K_t/R·U_s·clip(g_e·kp·e, ±d_max) − K_t²/R·θ̇, so
//    kp_joint = K_t/R·U_s·g_e·kp, kv_joint = 0, effort = K_t/R·U_s·d_max, and the back-EMF
//    term K_t²/R is joint damping (outside the force limit, as in BAM).
//  * ideal and velocity servos are velocity constraints in ODE (a motor row that reaches the
//    velocity (θ_next − θ)/dt, resp. −k_d·(θ − θ_d), within one step with at most τ_max). A
//    position actuator reproduces that when its velocity gain dominates the joint's inertia
//    under implicit integration: with kv·dt = 5·I_subtree (the inertia of everything the joint
//    moves, about its axis, in the build pose) and kp = kv/dt, one step closes 5/6 of the error
//    (v_next = (I·v + kv·e)/(I + kv·dt) ≈ e/dt; the command is the angle at the END of the
//    step); the velocity servo gets kp = kv·k_d. effort = τ_max. Why not stiffer: MuJoCo clamps
//    the force kp·e − kv·θ̇ of the state at the START of the step, before the implicit velocity
//    update removes kv·Δθ̇ from it, so the clamp sees about (1 + kv·dt/I) times the inertial
//    torque the joint really receives; at 50·I/dt the 20 N·m limit of the Nao's ideal servo was
//    reached spuriously and a held hip drifted by 30°, at 5·I/dt the held Nao tracks motoflex's
//    ideal servo to 0.001° (tests/export/mujoco_check_test.cpp).
//
// Armature (reflected rotor inertia J_rotor·σ²): the Nao's model has no rotor inertia; the
// gear's small mass m_g (`gear.<G>.mass_kg_m2`) is already a joint-side inertia and is exported
// as the armature of the motoflex servo. In motoflex m_g sits in the torque path (Algorithm 2),
// not on the joint, so this adds inertia that the ODE rollout does not see (the servo is heavily
// overdamped, so its effect on tracking is small; measured in tests/export/). The bench's
// `bench.armature_kg_m2` is its rotor inertia already reflected through the gear (BAM). Every
// other law adds the joint's own `joint.<J>.armature_kg_m2` (`armature_kg` on a slider; the
// rollout's joint-space inertia row, which is MuJoCo's armature exactly); the stiff ideal/velocity
// PD counts it in the inertia it moves. pd_torque and the firmware laws (dynamixel, feetech) are
// linearised in their rule files (src/export/servo/).
//
// Not representable and dropped: the PID integral, the motor inductance, the gear's backlash,
// spring and damped small mass, Stribeck and load-dependent friction, sensor effects, and the
// motor effects (R drift, supply sag). Coulomb friction and viscous damping are applied by
// motoflex as one clipped budget (F_c + c·|θ̇|) of a zero-velocity ODE motor; other simulators
// apply them separately (a dry-friction constraint plus linear damping).
struct ActuatorExport {
  std::string joint;  // URDF joint name
  std::string group;  // gear group from robot.yaml
  double lower_rad = 0.0;
  double upper_rad = 0.0;
  bool limited = false;
  double damping_nm_s_per_rad = 0.0;  // viscous friction + reflected back-EMF
  double friction_nm = 0.0;           // Coulomb friction
  double effort_nm = 0.0;             // torque limit of the servo
  double velocity_rad_s = 0.0;        // no-load speed effort/damping; 0 when the model has no limit
  double reduction = 1.0;             // gear ratio σ (1 for the joint-side bench and ideal models)
  double armature = 0.0;              // reflected rotor inertia: kg·m² on a hinge, kg on a slider
  bool prismatic = false;             // a slider: lengths in m, efforts in N, the armature a mass
  double kp_nm_per_rad = 0.0;         // linearised servo stiffness
  double kv_nm_s_per_rad = 0.0;       // linearised servo damping (on the joint rate)
  bool command_is_next_angle = false;  // ideal servo: the target is the angle at step end
  // The encoder reads the joint angle plus this (the effect mounting_offset): the servo's and
  // the log's zero, off the build pose's. MJCF's joint `ref`; URDF and SDF have no such field.
  double mounting_offset_rad = 0.0;
};

// Joint-level values of the flexible-link joints (seed 001 eq. 1), when the model has any.
struct FlexExport {
  double spring_nm_per_rad = 0.0;
  double damping_nm_s_per_rad = 0.0;
  double friction_nm = 0.0;
};

// One entry per actuator, in model (log column) order. Throws ModelError when the servo needs a
// parameter the robot does not declare, or the values make no sense (e.g. R <= 0).
std::vector<ActuatorExport> export_actuators(const ExportInput& input);
FlexExport export_flex(const ExportInput& input);

// Inertia about the joint axis of everything `actuator` moves, in the build pose (kg·m²); for a
// slider the mass it moves (kg).
double subtree_inertia_kg_m2(const RobotModel& model, std::size_t actuator);

}  // namespace motoflex
