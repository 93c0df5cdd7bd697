// `strategy: {kind: cma_es, negative_weights: pooled}`: the active CMA-ES whose worse ranks share
// one negative weight races them. A pendulum fit with early termination gives the same
// generations and best.json as one without, bit for bit, and stops rollouts early; a bad value
// names the field.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_session.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

nlohmann::json run_fit(const fs::path& dir, const fs::path& data, bool early_termination) {
  const std::string fitness = std::string("fitness: {m: 2, early_termination: ") +
                              (early_termination ? "true" : "false") + "}\nthreads: 2\n";
  fs::create_directories(dir);
  FitOverrides overrides;
  overrides.out = (dir / "run").string();
  FitSession(load_fit_config(
                 write_pendulum_fit(
                     dir, data, "{kind: cma_es, sigma: 0.3, restarts: 0, negative_weights: pooled}",
                     "{evaluations: 160}", fitness),
                 overrides),
             false)
      .run();
  return nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
}

TEST(FitCmaRacing, PooledActiveCmaEsRacesAndChangesNothingButTheWork) {
  const fs::path dir = fresh_dir("fit_cma_racing");
  record_pendulum_log(dir / "data", "sin_sin");
  const nlohmann::json full = run_fit(dir / "full", dir / "data", false);
  const nlohmann::json raced = run_fit(dir / "raced", dir / "data", true);
  EXPECT_EQ(generations_without_seconds(dir / "raced" / "run"),
            generations_without_seconds(dir / "full" / "run"));
  const auto best = [&](const char* which) {
    nlohmann::json b = nlohmann::json::parse(read_text(dir / which / "run" / "best.json"));
    return nlohmann::json{{"fitness", b["fitness"]}, {"free", b["free"]}};
  };
  EXPECT_EQ(best("raced"), best("full"));
  const auto& early = raced["early_termination"];
  EXPECT_EQ(full["early_termination"]["frames_saved"].get<std::uint64_t>(), 0u);
  // Of each generation of 8, the 3 samples after rank max(μ, λ/2 + 1) = 5 may stop.
  EXPECT_GT(early["individuals_stopped_early"].get<std::uint64_t>(), 10u);
  EXPECT_GT(early["frames_saved"].get<std::uint64_t>(), 0u);
  EXPECT_EQ(
      early["frames_saved"].get<std::uint64_t>() + early["frames_simulated"].get<std::uint64_t>(),
      full["early_termination"]["frames_simulated"].get<std::uint64_t>());
}

TEST(FitCmaRacing, UnknownNegativeWeightsNamesTheField) {
  const fs::path dir = fresh_dir("fit_cma_racing_bad");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string path = write_pendulum_fit(
      dir, dir / "data", "{kind: cma_es, negative_weights: sorted}", "{evaluations: 10}");
  try {
    load_fit_config(path);
    FAIL() << "negative_weights: sorted was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("negative_weights"), std::string::npos) << what;
    EXPECT_NE(what.find("ranked or pooled"), std::string::npos) << what;
    EXPECT_NE(what.find("fit.yaml"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace motoflex::testing
