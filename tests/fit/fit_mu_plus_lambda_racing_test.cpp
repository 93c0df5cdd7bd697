// `strategy: {kind: mu_plus_lambda}` races within each generation: an offspring is stopped once
// its partial error passes the μ-th best of the parents and of the offspring evaluated before
// it. A pendulum fit gives the same generations and best.json with racing, with the parents'
// threshold alone (`racing: false`) and with no early termination at all, bit for bit (all but
// the batch median, a censored statistic), racing spares more frames than the parents'
// threshold, and 1 and 2 threads race alike, median and frame counts included; a chunk of 5
// (`race_chunk`) changes the work only.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_session.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

nlohmann::json run_fit(const fs::path& dir, const fs::path& data, bool early_termination,
                       bool racing, int threads = 2, int race_chunk = 0) {
  const std::string fitness = std::string("fitness: {m: 2, early_termination: ") +
                              (early_termination ? "true" : "false") +
                              "}\nthreads: " + std::to_string(threads) + "\n";
  const std::string strategy =
      std::string(
          "{kind: mu_plus_lambda, mu: 3, lambda: 12, kappa: 3, "
          "initial_step: 0.2, racing: ") +
      (racing ? "true" : "false") +
      (race_chunk > 0 ? ", race_chunk: " + std::to_string(race_chunk) : "") + "}";
  fs::create_directories(dir);
  FitOverrides overrides;
  overrides.out = (dir / "run").string();
  FitSession(load_fit_config(write_pendulum_fit(dir, data, strategy, "{evaluations: 111}", fitness),
                             overrides),
             false)
      .run();
  return nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
}

// generations.csv without the seconds and the batch median (columns 6 and 4).
std::string generations_without_median(const fs::path& run) {
  std::string out;
  std::istringstream lines(generations_without_seconds(run));
  for (std::string line; std::getline(lines, line);) {
    const std::size_t third = line.find(',', line.find(',', line.find(',') + 1) + 1);
    const std::size_t fourth = line.find(',', third + 1);
    out += line.substr(0, third) + line.substr(fourth) + "\n";
  }
  return out;
}

nlohmann::json best_of(const fs::path& run) {
  const nlohmann::json b = nlohmann::json::parse(read_text(run / "best.json"));
  return nlohmann::json{{"fitness", b["fitness"]}, {"free", b["free"]}};
}

TEST(FitMuPlusLambdaRacing, RacingWithinTheGenerationChangesNothingButTheWork) {
  const fs::path dir = fresh_dir("fit_mu_plus_lambda_racing");
  record_pendulum_log(dir / "data", "sin_sin");
  const nlohmann::json full = run_fit(dir / "full", dir / "data", false, true);
  const nlohmann::json parents = run_fit(dir / "parents", dir / "data", true, false);
  const nlohmann::json raced = run_fit(dir / "raced", dir / "data", true, true);
  const nlohmann::json one = run_fit(dir / "one", dir / "data", true, true, 1);
  EXPECT_EQ(generations_without_seconds(dir / "one" / "run"),
            generations_without_seconds(dir / "raced" / "run"));
  EXPECT_EQ(one["early_termination"], raced["early_termination"]);
  run_fit(dir / "chunk5", dir / "data", true, true, 2, 5);
  for (const char* which : {"parents", "raced", "chunk5"}) {
    EXPECT_EQ(generations_without_median(dir / which / "run"),
              generations_without_median(dir / "full" / "run"))
        << which;
    EXPECT_EQ(best_of(dir / which / "run"), best_of(dir / "full" / "run")) << which;
  }
  const auto frames = [](const nlohmann::json& summary, const char* key) {
    return summary["early_termination"][key].get<std::uint64_t>();
  };
  EXPECT_EQ(frames(full, "frames_saved"), 0u);
  for (const nlohmann::json* summary : {&parents, &raced}) {
    EXPECT_EQ(frames(*summary, "frames_saved") + frames(*summary, "frames_simulated"),
              frames(full, "frames_simulated"));
  }
  // Nine generations of 12 after the 3 initial individuals: every offspring after the first 3
  // of a generation also races against its predecessors.
  EXPECT_GT(frames(raced, "frames_saved"), frames(parents, "frames_saved"));
}

}  // namespace
}  // namespace motoflex::testing
