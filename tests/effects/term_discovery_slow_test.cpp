// motoflex loop with open-ended discovery, end to end, on logs whose truth has a torque no
// library effect models (reference_data/hidden/cogging: 0.04·sin(6θ + 0.7) N·m):
// the loop adds the discovered torque terms, prints them as a formula with the fitted
// coefficients, and the validation RMS falls by at least half.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"
#include "effect_test_support.hpp"
#include "fit/fit_test_support.hpp"
#include "motoflex/effects/effect_loop.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

TEST(DiscoveryLoop, FindsAndFixesATorqueOutsideTheLibrary) {
  const fs::path dir = fresh_dir("loop_discovery");
  const std::string fit = write_hidden_bench_fit(
      dir, "cogging",
      "{candidates: 1, max_iterations: 1, min_gain: 0.05, discover_terms: 2, discover_always: "
      "true, refit: {strategy: {kind: cma_es, sigma: 0.1, restarts: 0}, budget: {evaluations: "
      "300}}}");
  const LoopResult result = run_loop(fit, {}, true);
  ASSERT_EQ(result.iterations.size(), 1u);
  const LoopIteration& it = result.iterations.front();
  EXPECT_EQ(it.added_effect, "discovered_torque");
  EXPECT_NE(it.discovered_formula.find("τ_pendulum = "), std::string::npos)
      << it.discovered_formula;
  EXPECT_LE(it.val_rms_after_deg, 0.5 * it.val_rms_before_deg)
      << it.val_rms_before_deg << " -> " << it.val_rms_after_deg << " deg";
  const nlohmann::json loop = nlohmann::json::parse(read_text(dir / "run" / "loop.json"));
  EXPECT_EQ(loop["iterations"][0]["discovered_formula"], it.discovered_formula);
  EXPECT_NE(read_text(dir / "run" / "report.md").find(it.discovered_formula), std::string::npos);
}

}  // namespace
}  // namespace motoflex::testing
