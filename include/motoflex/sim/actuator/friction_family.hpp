#pragma once

// Joint friction as BAM's family of models M1–M6 (Duclusaud et al., ICRA 2025, §III;
// ../shared/reference/bam.md §2d), shared by every servo law that applies joint friction.
//
// Friction is a *budget* τ_f,max: the rollout applies it as the force limit of a zero-velocity
// ODE motor row, so the joint sticks while the other torques fit inside the budget and slips
// when they do not; ODE solves it implicitly, so it opposes the motion but never reverses it.
// BAM applies the same budget by clipping the stopping torque (bam.md §2b, Algorithm 1).
//
// With s(θ̇) = exp(−|θ̇/v_s|^α), τ_m the motor torque and τ_e the external torque:
//   M1 Coulomb–viscous   K_c + K_v|θ̇|
//   M2 Stribeck          M1 + s·K_cs
//   M3 load-dependent    M1 + K_l|τ_m − τ_e|
//   M4 Stribeck + load   M2 + K_l|τ_m − τ_e| + s·K_ls|τ_m − τ_e|
//   M5 directional       M2 + |K_m τ_m − K_e τ_e| + s·|K_ms τ_m − K_es τ_e|
//   M6 quadratic         M5 + s·Q,  Q = K_eq τ_e² if |τ_m| > |τ_e|, K_mq τ_m² if |τ_m| < |τ_e|,
//                        added only when τ_m and τ_e have opposite signs (BAM's code).
// Beyond BAM's family, the gear's back-driving loss (motoflex's own; not one of M1–M6):
//   + B·(K_b + s·K_bs)·|τ_e|,   B = 1 when the load drives the joint and the motor does not
// (τ_m·d ≤ 0, d the direction of motion, or of the net torque τ_m + τ_e at standstill).
// A high-ratio gear train loses more when the load turns the motor than when the motor turns the
// load (back-driving efficiency below forward efficiency; a lossy gear in power-flow form): an
// arm holds against gravity with little current yet still breaks away when the motor lifts it.
// M1–M6 cannot tell these apart, since both have τ_m and τ_e opposed. `friction_model` leaves
// this term alone; it is zero unless K_b or K_bs is set.
//
// M5 with K_m = K_e is M3's load term, and M6 with K_mq = K_eq = 0 is M5: each model is the most
// general one (M6) with some coefficients switched off or tied, so one set of parameter names
// serves all six (`joint.<J>.friction_model` picks the structure, see read_friction).
//
// τ_e is the torque of everything but the motor and the friction on the joint: the rollout
// passes the gravity torque of the bodies the joint moves, about its axis (BAM's bias torque
// τ_e = −m·g·l·sin θ on the pendulum bench; on a robot in contact it ignores the ground's share).

#include <string>
#include <vector>

#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {

enum class FrictionModel { kM1 = 1, kM2 = 2, kM3 = 3, kM4 = 4, kM5 = 5, kM6 = 6 };

struct FrictionParams {
  FrictionModel model = FrictionModel::kM6;
  double coulomb_nm = 0.0;               // K_c (BAM friction_base)
  double viscous_nm_s_per_rad = 0.0;     // K_v (friction_viscous)
  double stribeck_nm = 0.0;              // K_cs (friction_stribeck)
  double stribeck_velocity_rad_s = 0.1;  // v_s (dtheta_stribeck), > 0
  double stribeck_exponent = 2.0;        // α (alpha), > 0
  double load_motor = 0.0;               // K_m (M5, M6) or K_l (M3, M4): N·m per N·m
  double load_external = 0.0;            // K_e (M5, M6)
  double load_stribeck_motor = 0.0;      // K_ms (M5, M6) or K_ls (M4)
  double load_stribeck_external = 0.0;   // K_es (M5, M6)
  double quad_motor_per_nm = 0.0;        // K_mq (M6), 1/(N·m)
  double quad_external_per_nm = 0.0;     // K_eq (M6), 1/(N·m)
  double backdrive = 0.0;                // K_b: N·m per N·m of |τ_e| while the load drives
  double backdrive_static = 0.0;         // K_bs: the same, times the Stribeck shape s(θ̇)
};

// The friction budget (N·m, ≥ 0) at joint rate `velocity_rad_s` with motor torque
// `motor_torque_nm` and external torque `external_torque_nm` (both on the joint, N·m).
double friction_budget_nm(const FrictionParams& params, double velocity_rad_s,
                          double motor_torque_nm, double external_torque_nm);

// The budget as the zero-velocity motor row the rollout applies.
MotorCommand joint_friction(const FrictionParams& params, double velocity_rad_s,
                            double motor_torque_nm = 0.0, double external_torque_nm = 0.0);

// Whether the budget depends on the external torque (so the rollout must compute it).
bool friction_reads_external_torque(const FrictionParams& params);

// Which of the family's parameters a law reads.
enum class FrictionTerms {
  // K_c, K_v, K_cs, v_s, α: laws whose motor torque is not known before the step (velocity).
  kSpeedOnly,
  // K_c, K_v, K_cs, v_s and K_m on |τ_m| alone: the motoflex and bench laws as they always were
  // (M5 with K_e = K_ms = K_es = 0 and α = 2).
  kMotorLoad,
  // Every coefficient of M1–M6 and `friction_model`: the firmware and torque laws.
  kFamily,
};

// The parameter names of `joint` that read_friction reads for `terms`, in its order:
// joint.<J>.{friction_nm, viscous_nm_s_per_rad, stribeck_nm, stribeck_velocity_rad_s,
// stribeck_exponent, load_friction, load_friction_external, load_friction_stribeck,
// load_friction_external_stribeck, load_friction_quad_per_nm,
// load_friction_external_quad_per_nm, friction_model, backdrive_friction,
// backdrive_friction_static}.
std::vector<std::string> friction_parameter_names(const std::string& joint, FrictionTerms terms);

// Reads the friction of `joint`. For kFamily, joint.<J>.friction_model (1–6) selects the model;
// coefficients the model does not have are ignored, and M3/M4 tie K_e = K_m (K_es = K_ms). Throws
// ModelError for a negative coefficient, v_s or α not > 0, or a model that is not 1–6.
FrictionParams read_friction(const ParameterReader& get, const std::string& joint,
                             FrictionTerms terms);

// The same for an actuated joint: a prismatic joint's force-like names are in N and m
// (friction_n, viscous_n_s_per_m, stribeck_n, stribeck_velocity_m_s, *_quad_per_n), read into
// the same fields (N for N·m, m/s for rad/s).
std::vector<std::string> friction_parameter_names(const ActuatorSpec& joint, FrictionTerms terms);
FrictionParams read_friction(const ParameterReader& get, const ActuatorSpec& joint,
                             FrictionTerms terms);

}  // namespace motoflex
