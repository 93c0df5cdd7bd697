#pragma once

// Joule heating of a DC motor's winding, and the resistance it brings.
//
// The winding (heat capacity C) takes the Joule heat I²·R and loses heat to the motor housing
// through a thermal resistance R_th, so its rise ΔT above the housing follows
//   C·dΔT/dt = I²·R − ΔT/R_th,   time constant τ = R_th·C,
// and copper's resistance rises with it: R(ΔT) = R₀·(1 + α·ΔT), α = 0.00393/K. A stalled servo
// draws its largest current exactly when it heats fastest, so its torque per volt falls within
// seconds: an arm driven against gravity at full duty creeps to a stall and holds lower than a
// cold motor would, while a servo that spends the same time tracking at low current stays
// cold. Each rollout starts with the winding at the housing's temperature (ΔT = 0).
//
// Over a step of dt the heating power is held, so the rise relaxes exactly towards P·R_th:
//   ΔT ← P·R_th + (ΔT − P·R_th)·exp(−dt/τ).
// R_th = 0 is no heating: ΔT stays 0 and the resistance factor is exactly 1.

namespace motoflex {

// Copper's temperature coefficient of resistance near room temperature (1/K).
constexpr double kCopperResistancePerK = 0.00393;
// The temperature at which a resistance that is scaled by temperature is given (°C).
constexpr double kResistanceReferenceC = 25.0;

struct WindingHeatingParams {
  double thermal_resistance_k_per_w = 0.0;  // R_th, winding to housing; 0 = no heating
  double heat_capacity_j_per_k = 0.5;       // C of the winding, > 0
};

class WindingTemperature {
 public:
  // Throws ModelError for a negative R_th or a C that is not > 0, or dt_s not > 0.
  WindingTemperature(const WindingHeatingParams& params, double dt_s);

  bool heats() const { return thermal_resistance_k_per_w_ > 0.0; }
  double rise_k() const { return rise_k_; }
  // R(ΔT)/R₀ = 1 + α·ΔT.
  double resistance_factor() const { return 1.0 + kCopperResistancePerK * rise_k_; }
  // One step with `current_a` through a winding of `resistance_ohm` (the heated one).
  void advance(double current_a, double resistance_ohm);

 private:
  double thermal_resistance_k_per_w_;
  double decay_;  // exp(−dt/τ)
  double rise_k_ = 0.0;
};

}  // namespace motoflex
