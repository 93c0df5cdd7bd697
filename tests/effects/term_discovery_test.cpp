// Open-ended discovery (term_discovery.hpp) on the bench logs whose truth has a torque no
// library effect models (scenarios/truth/hidden/{cogging,quadratic_drag,load_saturation}.yaml):
// at the truth with that torque switched off, the sparse regression on the linearised residual
// picks the terms that make it up, with their coefficients; on logs with nothing missing it
// picks nothing. And a discovered term is the same torque as the truth's where the two coincide.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "cli/cli_test_support.hpp"
#include "effect_test_support.hpp"
#include "fit/fit_test_support.hpp"
#include "motoflex/effects/term_discovery.hpp"
#include "motoflex/model/torque_terms.hpp"

namespace motoflex::testing {
namespace {

struct Discovered {
  FitConfig config;
  ParameterSet at;
  TermDiscovery discovery;
};

// A fit of `effect`'s logs whose only free parameter is the encoder offset (a constant, which
// no torque term mimics): the regression then has the terms' columns to itself. (With the M1
// parameters free at the truth, their linearised re-tune would mimic most of a torque; in the
// loop, discovery runs at a fitted optimum, where that re-tune has nothing left to give.)
std::string offset_only_fit(const std::filesystem::path& dir, const std::string& effect) {
  std::string text = read_text(write_hidden_bench_fit(dir, effect, "{}"));
  const auto from = text.find("free:\n");
  const auto to = text.find("fitness:");
  text.replace(from, to - from,
               "free:\n  joint.pendulum.encoder_offset_rad: {lower: -0.1, upper: 0.1}\n");
  const std::string path = (dir / "fit.yaml").string();
  std::ofstream(path) << text;
  return path;
}

// Discovery on `effect`'s training logs at its truth with the truth torque `off` set to 0.
Discovered discover_at_truth(const std::string& effect, const std::string& off,
                             std::size_t max_terms = 3) {
  const auto dir = fresh_dir("discover_" + effect);
  FitConfig config = load_fit_config(offset_only_fit(dir, effect));
  ParameterSet at = hidden_truth(effect, "train/chirp", config.space->base(), true);
  if (!off.empty()) at.set(off, 0.0);
  TermDiscovery discovery = discover_terms(config, at, 2, max_terms);
  return {std::move(config), std::move(at), std::move(discovery)};
}

double estimate_of(const TermDiscovery& d, const std::string& leaf) {
  for (const DiscoveredTerm& t : d.terms) {
    if (t.parameter == term_parameter("pendulum", leaf)) return t.estimate;
  }
  return 0.0;
}

TEST(TermDiscovery, FindsTheCoggingTorqueAsTheSixthHarmonicOfTheAngle) {
  // Truth: 0.04·sin(6θ + 0.7) = 0.0306·sin(6θ) + 0.0258·cos(6θ).
  const Discovered d = discover_at_truth("cogging", "joint.pendulum.cogging_nm");
  ASSERT_EQ(d.discovery.terms.size(), 2u) << discovered_formula(d.discovery.terms, d.at);
  EXPECT_NEAR(estimate_of(d.discovery, "sin6"), 0.04 * std::cos(0.7), 0.006);
  EXPECT_NEAR(estimate_of(d.discovery, "cos6"), 0.04 * std::sin(0.7), 0.006);
  EXPECT_GT(d.discovery.explained, 0.8);
  EXPECT_LT(d.discovery.delta_bic, 0.0);
}

// The training RMS at the truth with its torque switched off, and with the discovered terms
// added at their linearised estimates.
std::pair<double, double> rms_without_and_with(const Discovered& d) {
  ParameterSet with = d.at;
  for (const auto& [name, value] : d.discovery.estimate) with.set(name, value);
  const double without_deg = evaluate_in_detail(*d.config.train, d.at).rms_deg;
  const double with_deg = evaluate_in_detail(*d.config.train, with).rms_deg;
  std::printf("training RMS %.3f -> %.3f deg\n", without_deg, with_deg);
  return {without_deg, with_deg};
}

TEST(TermDiscovery, ExplainsTheQuadraticDrag) {
  // Truth: −0.003·ω·|ω|. Over the chirp's speeds the linearised regression prefers a viscous-
  // like combination (ω and sgn ω are nearly collinear with ω·|ω| there); what it must do is
  // remove most of the residual. Measured: 2.914 → 0.934 deg (−68 %).
  const Discovered d = discover_at_truth("quadratic_drag", "joint.pendulum.drag_nm_s2_per_rad2");
  ASSERT_FALSE(d.discovery.terms.empty());
  const auto [without, with] = rms_without_and_with(d);
  EXPECT_LT(with, 0.55 * without) << discovered_formula(d.discovery.terms, d.at);
}

TEST(TermDiscovery, ExplainsTheSaturatingLoadTorque) {
  // Truth: −0.06·tanh(τ_g / 0.1 N·m). On a pendulum τ_g ∝ sin θ, so a flattened odd function of
  // the load is as well a sum of odd harmonics of the angle; either way most of the residual
  // goes. Measured: 2.432 → 0.081 deg (−97 %).
  const Discovered d = discover_at_truth("load_saturation", "joint.pendulum.load_saturation_nm");
  ASSERT_FALSE(d.discovery.terms.empty());
  const auto [without, with] = rms_without_and_with(d);
  EXPECT_LT(with, 0.15 * without) << discovered_formula(d.discovery.terms, d.at);
}

TEST(TermDiscovery, FindsNothingWhenNothingIsMissing) {
  const Discovered d = discover_at_truth("none", "");
  EXPECT_TRUE(d.discovery.terms.empty()) << discovered_formula(d.discovery.terms, d.at);
  EXPECT_EQ(d.discovery.candidates, torque_terms().size());
}

TEST(TermDiscovery, KeepsTheFitsParametersInsideTheirBoundsAtABound) {
  // The fit's sensor delay at 0.5 ms on logs recorded without one, its bound at 0: the
  // linearised step proposes about 0 and the line search's 2× step of that would be −0.5 ms,
  // which the encoder rejects (this ended `motoflex loop` on the XL330 logs). Every proposal
  // must stay in the fit's bounds, and the cogging is still found.
  const auto dir = fresh_dir("discover_at_bound");
  std::string text = read_text(write_hidden_bench_fit(dir, "cogging", "{}"));
  const auto from = text.find("free:\n");
  text.replace(from, text.find("fitness:") - from,
               "free:\n  joint.pendulum.encoder_offset_rad: {lower: -0.1, upper: 0.1}\n"
               "  sensor.delay_s: {lower: 0.0, upper: 0.05}\n");
  std::ofstream(dir / "fit.yaml") << text;
  const FitConfig config = load_fit_config((dir / "fit.yaml").string());
  ParameterSet at = hidden_truth("cogging", "train/chirp", config.space->base(), true);
  ASSERT_EQ(at.get("sensor.delay_s"), 0.0);
  at.set("joint.pendulum.cogging_nm", 0.0);
  at.set("sensor.delay_s", 5e-4);
  TermDiscovery discovery;
  ASSERT_NO_THROW(discovery = discover_terms(config, at, 2, 3));
  for (const auto& [name, value] : discovery.fit_start) {
    if (name == "sensor.delay_s") {
      EXPECT_GE(value, 0.0);
    }
  }
  EXPECT_NEAR(estimate_of(discovery, "sin6"), 0.04 * std::cos(0.7), 0.006)
      << discovered_formula(discovery.terms, at);
  EXPECT_NEAR(estimate_of(discovery, "cos6"), 0.04 * std::sin(0.7), 0.006);
}

TEST(TermDiscovery, ADiscoveredTermIsTheSameTorqueAsTheTruths) {
  // −c·ω·|ω| as the truth's drag and as the candidate term ω·|ω| with coefficient −c: the same
  // rollout (the smooth sign is not involved), so the same fitness to rounding.
  const auto dir = fresh_dir("discover_same_torque");
  const FitConfig config = load_fit_config(write_hidden_bench_fit(dir, "quadratic_drag", "{}"));
  ParameterSet truth = hidden_truth("quadratic_drag", "train/chirp", config.space->base(), true);
  ParameterSet term = truth;
  term.set("joint.pendulum.drag_nm_s2_per_rad2", 0.0);
  term.set(term_parameter("pendulum", "w_absw"), -0.003);
  const double a = config.train->evaluate(truth).fitness;
  const double b = config.train->evaluate(term).fitness;
  EXPECT_NEAR(a, b, 1e-9 * std::abs(a) + 1e-15);
}

}  // namespace
}  // namespace motoflex::testing
