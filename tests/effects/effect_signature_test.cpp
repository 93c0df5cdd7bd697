// The effect signatures rank the effect that is really missing first: each hidden-effect log
// of reference_data/hidden/ scored at its own truth with that one effect switched off (no fit
// involved, so the residual is exactly the effect plus sensor noise).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cli/cli_test_support.hpp"
#include "effect_test_support.hpp"
#include "motoflex/effects/effect_signature.hpp"
#include "motoflex/model/effect_library.hpp"
#include "motoflex/model/parameters.hpp"

namespace motoflex::testing {
namespace {

struct HiddenCase {
  const char* effect;
  const char* parameter;  // the truth parameter that carries the effect
  double truth;
  double min_explained;  // about half the measured share of the residual the effect explains
};

// Measured (every parameter of the effect reset to the robot default): explained 0.963, 0.180,
// 0.700, 0.075, 0.071, 0.218; estimate/truth 1.000, 0.938, 0.758, 0.968, 0.918, 1.062.
const HiddenCase kCases[] = {
    {"encoder_offset", "joint.pendulum.encoder_offset_rad", 0.03, 0.5},
    {"sensor_delay", "sensor.delay_s", 0.015, 0.09},
    {"stribeck", "joint.pendulum.stribeck_nm", 0.08, 0.35},
    {"load_friction", "joint.pendulum.load_friction", 0.15, 0.035},
    {"resistance_drift", "motor.R_drift_per_s", 0.03, 0.035},
    {"torque_saturation", "motor.torque_saturation_per_a", 0.8, 0.1},
};

// The truth of `effect`'s recording with EVERY parameter of that effect (e.g. the Stribeck
// velocity as well as its magnitude) back at the robot's default, so the probe learns nothing
// from the truth's shape parameters. Returns how many parameters were reset.
std::size_t reset_effect_parameters(const std::string& effect, const ParameterSet& base,
                                    ParameterSet& current) {
  std::size_t reset = 0;
  if (effect == "none") return reset;
  const ParameterRegistry& registry = current.registry();
  for (const EffectParameter& p : find_effect(effect).parameters) {
    for (std::size_t i = 0; i < registry.size(); ++i) {
      const std::string& name = registry.spec(i).name;
      if (!parameter_pattern_matches(p.pattern, name)) continue;
      current.set(name, base.get(name));
      ++reset;
    }
  }
  return reset;
}

EffectRanking rank_at_truth_without(const std::string& effect, const char* parameter) {
  const auto dir = fresh_dir("signature_" + effect);
  const FitConfig config = load_fit_config(write_hidden_bench_fit(dir, effect, "{}"));
  ParameterSet current = hidden_truth(effect, "train/chirp", config.space->base(), true);
  const std::size_t reset = reset_effect_parameters(effect, config.space->base(), current);
  if (parameter != nullptr) {
    EXPECT_GE(reset, 1u) << effect << ": no parameter of the effect was reset";
    EXPECT_EQ(current.get(parameter), config.space->base().get(parameter)) << effect;
  }
  return rank_effects(config, current, {}, 2);
}

TEST(EffectSignature, TheMissingEffectRanksFirstWithItsMagnitude) {
  for (const HiddenCase& c : kCases) {
    const EffectRanking ranking = rank_at_truth_without(c.effect, c.parameter);
    ASSERT_FALSE(ranking.scores.empty());
    const EffectScore& top = ranking.scores.front();
    EXPECT_EQ(top.effect, c.effect);
    EXPECT_LT(top.delta_bic, 0.0) << c.effect;
    EXPECT_GT(top.explained, c.min_explained) << c.effect;
    // The linearised estimate of the effect's size points the refit the right way.
    double estimate = 0.0;
    for (const auto& [name, value] : top.estimate) {
      if (name == c.parameter) estimate = value;
    }
    std::printf("%s: explained %.3f, estimate/truth %.3f, delta BIC %.1f\n", c.effect,
                top.explained, estimate / c.truth, top.delta_bic);
    EXPECT_GT(estimate, 0.6 * c.truth) << c.effect;
    EXPECT_LT(estimate, 1.5 * c.truth) << c.effect;
    // The runner-up explains far less of what re-tuning the fit's own parameters cannot, unless
    // it contains the missing effect: BAM's load-dependent Stribeck friction (M4) has a Stribeck
    // term of its own and explains 40 % where Stribeck explains 72 %; a mounting offset shifts
    // the bench's reading by a fraction of itself (the P servo's droop under gravity), close to
    // a constant like the encoder offset's (90 % where the encoder offset explains 96 %); winding
    // heating probed with a 30 s time constant raises the resistance almost linearly over a log,
    // a current-weighted resistance drift (6 % where the drift explains 7 %). One pair only
    // resembles: a firmware D term (servo_derivative) damps the chirp's fastest swings, where the
    // current, and so the torque saturation, is largest (15 % where the saturation explains 22 %;
    // the refits, not the ranking, tell those two apart).
    // Every other effect must explain less than half.
    const EffectScore* runner_up = nullptr;
    for (std::size_t k = 1; k < ranking.scores.size() && runner_up == nullptr; ++k) {
      const std::string& next = ranking.scores[k].effect;
      const bool shares_signature =
          (c.effect == std::string("stribeck") && next == "load_stribeck_friction") ||
          (c.effect == std::string("encoder_offset") && next == "mounting_offset") ||
          (c.effect == std::string("resistance_drift") && next == "winding_heating") ||
          (c.effect == std::string("torque_saturation") && next == "servo_derivative");
      if (!shares_signature) runner_up = &ranking.scores[k];
    }
    ASSERT_NE(runner_up, nullptr);
    EXPECT_LT(runner_up->explained, 0.5 * top.explained)
        << c.effect << ": runner-up " << runner_up->effect;
    EXPECT_GT(runner_up->delta_bic, 0.5 * top.delta_bic) << c.effect;
  }
}

TEST(EffectSignature, NothingIsSupportedWhenNothingIsMissing) {
  const EffectRanking ranking = rank_at_truth_without("none", nullptr);
  for (const EffectScore& s : ranking.scores) {
    if (s.scored()) {
      EXPECT_GT(s.delta_bic, 0.0) << s.effect << " explains noise";
    }
  }
}

TEST(EffectSignature, EffectsTheFitAlreadyFreesOrTheRobotLacksAreNotCandidates) {
  const EffectRanking ranking = rank_at_truth_without("none", nullptr);
  for (const EffectScore& s : ranking.scores) {
    if (s.effect == "coulomb_friction" || s.effect == "viscous_friction") {
      EXPECT_EQ(s.status, "in model") << s.effect;
    }
    if (s.effect == "backlash" || s.effect == "link_flexibility" || s.effect == "foot_slip") {
      EXPECT_EQ(s.status, "not applicable");
    }
  }
}

// A config that holds every parameter of an effect at a value of its own (here a mounting offset
// measured elsewhere) leaves the loop nothing to free: the effect is not a candidate, so the
// loop does not refit it (a fit listing it with its parameters fixed is an error, which ended a
// loop on real XL330 logs before this).
TEST(EffectSignature, EffectsWhoseParametersTheConfigFixesAreNotCandidates) {
  const auto dir = fresh_dir("signature_held_fixed");
  const FitConfig config = load_fit_config(write_hidden_bench_fit(
      dir, "none", "{}", "fixed:\n  joint.pendulum.mounting_offset_rad: -0.03\n"));
  const ParameterSet current = hidden_truth("none", "train/chirp", config.space->base(), true);
  const EffectRanking ranking = rank_effects(config, current, {}, 2);
  bool seen = false;
  for (const EffectScore& s : ranking.scores) {
    if (s.effect == "mounting_offset") {
      seen = true;
      EXPECT_EQ(s.status, "held fixed");
      EXPECT_FALSE(s.scored());
    }
    if (s.effect == "encoder_offset") {
      EXPECT_TRUE(s.scored()) << s.status;
    }
  }
  EXPECT_TRUE(seen);
}

}  // namespace
}  // namespace motoflex::testing
