#pragma once

// Joint torques outside the effect library, both sides of the loop's open-ended discovery:
//
// - the candidate terms the loop may discover (src/effects/term_discovery.cpp): a fixed library
//   of basis functions φ_k of a joint's state (position error, velocity, sign of velocity, the
//   gravity load, low powers and products, periodic functions of the angle). Each has one
//   coefficient per joint, `joint.<J>.term_<leaf>` (neutral 0), and the rollout adds
//   Σ_k c_k·φ_k(state) to the joint's torque. A discovered model is a sparse set of these.
// - truth-side torques no library effect and no single basis term models (cogging with a phase,
//   quadratic drag, a torque that saturates with the load), which only the hidden-effect truths
//   in scenarios/truth/hidden/ set; see truth_torque_nm.

#include <string>
#include <vector>

namespace motoflex {

// What a torque term sees of its joint each physics step (our sign convention).
struct TermState {
  double angle_rad = 0.0;
  double error_rad = 0.0;   // commanded − true angle
  double rate_rad_s = 0.0;  // true joint rate
  double load_nm = 0.0;     // gravity torque on everything the joint moves (ServoInput's)
};

struct TorqueTerm {
  std::string leaf;                         // parameter `joint.<J>.term_<leaf>`
  std::string formula;                      // φ in report notation, e.g. "ω·|ω|"
  double bound;                             // search bound of the coefficient: ±bound
  bool uses_load;                           // reads TermState::load_nm
  double (*value)(const TermState& state);  // nullptr for a periodic term
  int harmonic = 0;                         // k of sin(k·θ) / cos(k·θ); 0: `value`
  bool sine = false;
};

// φ(state) of `term`.
double term_value(const TorqueTerm& term, const TermState& state);

// The candidate library, in a fixed order.
const std::vector<TorqueTerm>& torque_terms();
// "joint.<joint>.term_<leaf>".
std::string term_parameter(const std::string& joint, const std::string& leaf);
// The term whose parameter name is `name` ("joint.<J>.term_<leaf>"), or nullptr.
const TorqueTerm* find_torque_term(const std::string& name);

// The truth-side torques of one joint (N·m); all zero = none.
struct TruthTorques {
  double cogging_nm = 0.0;  // A·sin(n·θ + φ)
  double cogging_periods = 6.0;
  double cogging_phase_rad = 0.0;
  double drag_nm_s2_per_rad2 = 0.0;  // −c·ω·|ω|
  double load_saturation_nm = 0.0;   // −S·tanh(τ_g / s): opposes the load, saturates at S
  double load_saturation_scale_nm = 0.2;
  bool active() const {
    return cogging_nm != 0.0 || drag_nm_s2_per_rad2 != 0.0 || load_saturation_nm != 0.0;
  }
};
double truth_torque_nm(const TruthTorques& truth, const TermState& state);
// The parameter leaves of TruthTorques: joint.<J>.<leaf>, in the struct's order.
const std::vector<std::string>& truth_torque_leaves();

}  // namespace motoflex
