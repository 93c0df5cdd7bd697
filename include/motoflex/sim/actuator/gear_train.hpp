#pragma once

namespace motoflex {

// Gear with flexibility and tolerance (seed 001 §3.2, Algorithm 2, Table 1). All quantities
// are on the joint side, in the rotational reading of the paper's linear model (radius 1).
struct GearParams {
  double ratio = 1.0;  // σ: joint torque per motor torque (also motor speed per joint speed)
  double backlash_rad = 0.0;          // l_h: hull length; no torque passes while the mass is inside
  double spring_nm_per_rad = 1.0e6;   // D_g: gear elasticity, acting once the mass touches the hull
  double mass_kg_m2 = 1.0e-3;         // m_g: small inertia of the gears next to the motor
  double viscous_nm_s_per_rad = 0.0;  // B_g: viscous friction on the small mass
};

// Algorithm 2, sub-stepped `substeps` times per physics step dt_s (Δt_g = dt_s/substeps):
//   p_h = p_m − l_h if p_m > l_h;  p_h = p_m if p_m < 0;  else 0       (lines 3–9)
//   in contact (p_h ≠ 0):  ṗ_m ← (ṗ_m + (σ·T_M − D_g·p_h)/m_g·Δt_g) / (1 + B_g·Δt_g/m_g +
//   D_g·Δt_g²/m_g) inside the hull:       ṗ_m ← (ṗ_m + σ·T_M/m_g·Δt_g) / (1 + B_g·Δt_g/m_g) p_m ←
//   p_m + ṗ_m·Δt_g T_j += D_g·p_h(p_m)/substeps                                         (line 13)
// The paper lists forward Euler, which gains energy on the spring at any step size. Symplectic
// Euler is stable only for sqrt(D_g/m_g)·Δt_g < 2 and, with a backlash, a contact that lasts
// only a few substeps gains or loses energy at each impact: with MoToFlex's values (ω = 1.28e5
// rad/s) and 100 substeps the mass rattled between the hull walls forever (±3 N·m at the joint,
// a numerical artefact). Here the spring force in contact is implicit (evaluated at the new
// position) and the viscous term too: unconditionally stable, dissipative at impacts when a
// contact is resolved by few substeps (real gear-tooth impacts are inelastic too), and
// converging to the exact solution as the substep count grows. Static equilibrium is exact
// (settle_at). As in the paper, the hull and spring act on the torque path: the joint's motion
// reaches the motor through the PID and the back-EMF, not through the gear.
// One instance per joint, per rollout.
class GearTrain {
 public:
  // Throws std::invalid_argument for non-positive dt, substeps or mass, or negative
  // backlash/spring/viscous values.
  GearTrain(const GearParams& params, double dt_s, int substeps);

  // Runs `substeps` sub-steps with a constant motor-side torque (N·m) and returns the mean
  // joint torque over the physics step (N·m).
  double update(double motor_torque_nm);

  // Places the mass where the spring holds `joint_torque_nm` statically, at rest (p = l_h + T/D
  // for T > 0, T/D for T < 0, l_h/2 for T = 0).
  void settle_at(double joint_torque_nm);

  double mass_position_rad() const { return position_rad_; }
  double mass_velocity_rad_s() const { return velocity_rad_s_; }
  void set_state(double position_rad, double velocity_rad_s);
  const GearParams& params() const { return params_; }
  int substeps() const { return substeps_; }

 private:
  GearParams params_;
  int substeps_;
  double substep_s_;
  // Per-substep constants of the loop, computed once in the constructor (hot path). The loop
  // carries the position increment s = ṗ_m·Δt_g instead of the velocity, which shortens the
  // dependency chain per substep (same maths, see update()).
  double free_factor_ = 1.0;       // 1/(1 + B_g·Δt_g/m_g): inside the hull
  double contact_factor_ = 1.0;    // 1/(1 + B_g·Δt_g/m_g + D_g·Δt_g²/m_g): touching the hull
  double drive_step_gain_ = 0.0;   // σ·Δt_g²/m_g: increment per N·m of motor torque
  double spring_step_gain_ = 0.0;  // D_g·Δt_g²/m_g: increment per rad of compression
  double mean_torque_gain_ = 0.0;  // D_g/substeps: mean spring torque per rad of summed compression
  double position_rad_ = 0.0;
  double velocity_rad_s_ = 0.0;
};

}  // namespace motoflex
