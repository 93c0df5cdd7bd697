#include "motoflex/model/torque_terms.hpp"

#include <cmath>

namespace motoflex {
namespace {

// Smooth sign: a torque with a hard sign chatters in an explicit step; 0.05 rad/s is well
// below the speeds the benches log.
constexpr double kSignVelocity_rad_s = 0.05;

double sgn(double rate_rad_s) {
  return std::tanh(rate_rad_s / kSignVelocity_rad_s);
}

// The periodic candidates of the angle. k = 1 is left out: on a pendulum sin θ is the load.
TorqueTerm periodic(int k, bool sine) {
  const std::string n = std::to_string(k);
  return {(sine ? "sin" : "cos") + n,
          (sine ? "sin(" : "cos(") + n + "·θ)",
          0.5,
          false,
          nullptr,
          k,
          sine};
}

std::vector<TorqueTerm> build_terms() {
  std::vector<TorqueTerm> terms = {
      {"e", "e", 20.0, false, [](const TermState& s) { return s.error_rad; }},
      {"w", "ω", 0.5, false, [](const TermState& s) { return s.rate_rad_s; }},
      {"sgnw", "sgn(ω)", 0.5, false, [](const TermState& s) { return sgn(s.rate_rad_s); }},
      {"load", "τ_g", 1.0, true, [](const TermState& s) { return s.load_nm; }},
      {"w_absw", "ω·|ω|", 0.1, false,
       [](const TermState& s) { return s.rate_rad_s * std::abs(s.rate_rad_s); }},
      {"w3", "ω³", 0.02, false,
       [](const TermState& s) { return s.rate_rad_s * s.rate_rad_s * s.rate_rad_s; }},
      {"load_sgnw", "τ_g·sgn(ω)", 1.0, true,
       [](const TermState& s) { return s.load_nm * sgn(s.rate_rad_s); }},
      {"absload_sgnw", "|τ_g|·sgn(ω)", 1.0, true,
       [](const TermState& s) { return std::abs(s.load_nm) * sgn(s.rate_rad_s); }},
      {"load_absload", "τ_g·|τ_g|", 2.0, true,
       [](const TermState& s) { return s.load_nm * std::abs(s.load_nm); }},
      {"load3", "τ_g³", 4.0, true,
       [](const TermState& s) { return s.load_nm * s.load_nm * s.load_nm; }},
      {"e3", "e³", 2000.0, false,
       [](const TermState& s) { return s.error_rad * s.error_rad * s.error_rad; }},
      {"e_absw", "e·|ω|", 5.0, false,
       [](const TermState& s) { return s.error_rad * std::abs(s.rate_rad_s); }},
      {"e_sgnw", "e·sgn(ω)", 20.0, false,
       [](const TermState& s) { return s.error_rad * sgn(s.rate_rad_s); }},
  };
  for (const int k : {2, 3, 4, 6, 8}) {
    terms.push_back(periodic(k, true));
    terms.push_back(periodic(k, false));
  }
  return terms;
}

}  // namespace

const std::vector<TorqueTerm>& torque_terms() {
  static const std::vector<TorqueTerm> terms = build_terms();
  return terms;
}

std::string term_parameter(const std::string& joint, const std::string& leaf) {
  return "joint." + joint + ".term_" + leaf;
}

const TorqueTerm* find_torque_term(const std::string& name) {
  const auto at = name.rfind(".term_");
  if (name.rfind("joint.", 0) != 0 || at == std::string::npos) return nullptr;
  const std::string leaf = name.substr(at + 6);
  for (const TorqueTerm& term : torque_terms()) {
    if (term.leaf == leaf) return &term;
  }
  return nullptr;
}

double term_value(const TorqueTerm& term, const TermState& state) {
  if (term.harmonic == 0) return term.value(state);
  const double phase = term.harmonic * state.angle_rad;
  return term.sine ? std::sin(phase) : std::cos(phase);
}

double truth_torque_nm(const TruthTorques& truth, const TermState& state) {
  double torque_nm = truth.cogging_nm *
                     std::sin(truth.cogging_periods * state.angle_rad + truth.cogging_phase_rad);
  torque_nm -= truth.drag_nm_s2_per_rad2 * state.rate_rad_s * std::abs(state.rate_rad_s);
  if (truth.load_saturation_nm != 0.0) {
    torque_nm -=
        truth.load_saturation_nm * std::tanh(state.load_nm / truth.load_saturation_scale_nm);
  }
  return torque_nm;
}

const std::vector<std::string>& truth_torque_leaves() {
  static const std::vector<std::string> leaves = {"cogging_nm",         "cogging_periods",
                                                  "cogging_phase_rad",  "drag_nm_s2_per_rad2",
                                                  "load_saturation_nm", "load_saturation_scale_nm"};
  return leaves;
}

}  // namespace motoflex
