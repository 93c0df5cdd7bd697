#pragma once

// A DC motor driven by an H-bridge at a PWM duty cycle (BAM eq. 12–13, bam.md §2c):
//   U = supply_v·duty,  I = (U − K_t·N·θ̇)/R,  τ_joint = N·K_t·I
// with K_t and R on the motor side and a gear ratio N (N = 1: K_t is joint side, BAM's form
// τ = K_t·U/R − K_t²·θ̇/R). The inductance is neglected (L/R ≈ 50 µs ≪ 1 ms). The firmware's
// optional current limit I_max restricts the duty to the window where |I| ≤ I_max:
//   duty ∈ [(K_t·N·θ̇ − R·I_max)/U_s, (K_t·N·θ̇ + R·I_max)/U_s]   (BAM HEAD's max_current).
// With a torque saturation k > 0 the torque is N·K_t·tanh(k·I)/k (torque_saturation.hpp); the
// output's current stays the winding's I.

namespace motoflex {

struct HBridgeMotorParams {
  double supply_v = 7.4;
  double torque_constant_nm_per_a = 0.6;  // K_t, motor side (joint side when gear_ratio = 1)
  double resistance_ohm = 2.6;            // R
  double gear_ratio = 1.0;                // N: motor turns per joint turn
  double current_limit_a = 0.0;           // I_max; 0 = no limit
  double saturation_per_a = 0.0;          // k = 1/I_s of torque_saturation.hpp; 0 = linear
};

struct HBridgeMotorOutput {
  double torque_nm = 0.0;  // on the joint
  double current_a = 0.0;  // through the windings (before any torque saturation)
};

// Throws nothing; R must be > 0 (the laws check it when they read it).
HBridgeMotorOutput h_bridge_motor(const HBridgeMotorParams& params, double duty,
                                  double joint_rate_rad_s);

}  // namespace motoflex
