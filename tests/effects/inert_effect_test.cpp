// An effect is inert at a refit's optimum when switching it back to the current model's value
// does not worsen the training fitness (inert_effect.hpp). On logs recorded with a Stribeck
// term (reference_data/hidden/stribeck), at the recording's truth: the Stribeck term is needed
// (switched off, the fitness rises), a Stribeck term of 0 N·m is inert, and so is a current
// limit of 100 A, far above any current the bench draws (7.4 V over 2.6 Ω: 2.8 A at most).

#include "motoflex/effects/inert_effect.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"
#include "effect_test_support.hpp"
#include "fit/fit_test_support.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/refit_config.hpp"
#include "motoflex/model/effect_library.hpp"

namespace motoflex::testing {
namespace {

// The refit of the hidden-Stribeck bench fit with `effect`, and the truth as its best point.
struct Case {
  FitConfig base;
  ParameterSet truth;
  FitConfig refit;
};

Case refit_case(const std::string& name, const std::string& effect) {
  const auto dir = fresh_dir("inert_effect_" + name);
  FitConfig base = load_fit_config(write_hidden_bench_fit(dir, "stribeck", "{}"));
  ParameterSet truth = hidden_truth("stribeck", "train/chirp", base.space->base(), false);
  nlohmann::json fitted = nlohmann::json::object();
  for (const FreeParameter& p : base.free_parameters) fitted[p.name] = truth.get(p.name);
  FitConfig refit = load_fit_config(
      write_refit_config(base, fitted, find_effect(effect), {}, (dir / "refit").string()));
  return Case{std::move(base), std::move(truth), std::move(refit)};
}

TEST(InertEffect, ANeededEffectIsNotInertAndAnEffectAtItsNeutralValueIs) {
  const Case c = refit_case("stribeck", "stribeck");
  ASSERT_GT(c.truth.get("joint.pendulum.stribeck_nm"), 0.0);
  // The current model: the truth without the Stribeck term (its neutral 0 N·m).
  ParameterSet current = c.truth;
  current.set("joint.pendulum.stribeck_nm", 0.0);
  const std::size_t own = c.base.free_parameters.size();
  EXPECT_FALSE(effect_is_inert(*c.refit.train, *c.refit.space, own, c.truth, current));
  EXPECT_TRUE(effect_is_inert(*c.refit.train, *c.refit.space, own, current, current));
  // Without effect parameters there is nothing to be inert.
  EXPECT_FALSE(effect_is_inert(*c.base.train, *c.base.space, own, c.truth, current));
}

TEST(InertEffect, ACurrentLimitAboveEveryCurrentIsInert) {
  const Case c = refit_case("current_limit", "current_limit");
  const std::size_t own = c.base.free_parameters.size();
  ParameterSet above = c.truth;  // the current model's limit is the neutral 1000 A
  above.set("motor.current_limit_a", 100.0);
  EXPECT_TRUE(effect_is_inert(*c.refit.train, *c.refit.space, own, above, c.truth));
  // One that binds changes the motion: then the truth without it is a different model.
  ParameterSet binding = c.truth;
  binding.set("motor.current_limit_a", 0.3);
  EXPECT_NE(c.refit.train->evaluate(binding).fitness, c.refit.train->evaluate(c.truth).fitness);
}

}  // namespace
}  // namespace motoflex::testing
