// Domain-randomisation ranges from several fits: between-run spread, each fit's standard error,
// log-scale parameters, clipping at the bounds, and runs that do not match.

#include "motoflex/report/parameter_spread.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "report_test_support.hpp"

namespace motoflex::report {
namespace {

namespace fs = std::filesystem;
using motoflex::testing::write_text;

// A fit run dir with two free parameters: kp (linear, bounds 0–10) and a log-scale armature
// (bounds 1e-4–1e-2); `se_kp` < 0: no confidence intervals in summary.json.
std::string write_run(const fs::path& dir, double kp, double armature, double se_kp = -1.0,
                      bool with_armature = true) {
  fs::create_directories(dir);
  write_text(dir / "run.json", R"({"kind": "fit"})");
  write_text(dir / "inputs.json",
             R"({"name": "unit", "robot": "arm", "free": [
                 {"name": "bench.kp", "unit": "1", "start": 3, "lower": 0, "upper": 10, "log": false},
                 {"name": "bench.armature_kg_m2", "unit": "kg·m²", "start": 0.001,
                  "lower": 0.0001, "upper": 0.01, "log": true}]})");
  nlohmann::json best;
  best["free"]["bench.kp"] = kp;
  if (with_armature) best["free"]["bench.armature_kg_m2"] = armature;
  write_text(dir / "best.json", best.dump());
  nlohmann::json summary = {{"best_fitness", 1e-4}};
  if (se_kp >= 0.0) {
    summary["confidence_intervals"]["bench.kp"] = {
        {"standard_error", se_kp}, {"lower", kp - 1.96 * se_kp}, {"upper", kp + 1.96 * se_kp}};
  }
  write_text(dir / "summary.json", summary.dump());
  return dir.string();
}

TEST(ParameterSpread, ThreeUnitsGiveTheirMeanAndASpreadOfTwoStandardDeviations) {
  const fs::path dir = motoflex::testing::scratch_dir("spread_units");
  const SpreadReport r =
      parameter_spread({write_run(dir / "a", 4.0, 1e-3), write_run(dir / "b", 5.0, 4e-3),
                        write_run(dir / "c", 6.0, 2e-3)},
                       2.0);
  ASSERT_EQ(r.parameters.size(), 2u);
  const ParameterSpread& kp = r.parameters[0];
  EXPECT_EQ(kp.name, "bench.kp");
  EXPECT_DOUBLE_EQ(kp.mean, 5.0);
  EXPECT_DOUBLE_EQ(kp.between_runs, 1.0);  // sample standard deviation of 4, 5, 6
  EXPECT_TRUE(std::isnan(kp.within_run));
  EXPECT_DOUBLE_EQ(kp.lower, 3.0);
  EXPECT_DOUBLE_EQ(kp.upper, 7.0);
  EXPECT_FALSE(kp.clipped);
  // The armature is log-scale: geometric mean 2e-3, ln values ±ln 2 and 0 around it (a spread
  // by a factor of 2), and a range of 2 such factors each side.
  const ParameterSpread& armature = r.parameters[1];
  EXPECT_TRUE(armature.log_scale);
  EXPECT_NEAR(armature.mean, 2e-3, 1e-15);
  EXPECT_NEAR(armature.between_runs, 2.0, 1e-12);
  EXPECT_NEAR(armature.lower, 5e-4, 1e-15);
  EXPECT_NEAR(armature.upper, 8e-3, 1e-15);
  EXPECT_FALSE(armature.clipped);
}

TEST(ParameterSpread, ARangeBeyondTheBoundsIsCutThere) {
  const fs::path dir = motoflex::testing::scratch_dir("spread_bounds");
  const SpreadReport r =
      parameter_spread({write_run(dir / "a", 1.0, 1e-4), write_run(dir / "b", 9.0, 1e-2)}, 2.0);
  EXPECT_DOUBLE_EQ(r.parameters[0].lower, 0.0);  // 5 ± 2·5.66, bounds 0–10
  EXPECT_DOUBLE_EQ(r.parameters[0].upper, 10.0);
  EXPECT_TRUE(r.parameters[0].clipped);
  EXPECT_DOUBLE_EQ(r.parameters[1].lower, 1e-4);
  EXPECT_DOUBLE_EQ(r.parameters[1].upper, 1e-2);
  EXPECT_NE(spread_markdown(r).find("(at a bound)"), std::string::npos);
}

TEST(ParameterSpread, OneFitWithAStandardErrorGivesKErrorsEachSide) {
  const fs::path dir = motoflex::testing::scratch_dir("spread_one");
  const SpreadReport r = parameter_spread({write_run(dir / "a", 4.0, 1e-3, 0.25)}, 2.0);
  const ParameterSpread& kp = r.parameters[0];
  EXPECT_TRUE(std::isnan(kp.between_runs));
  EXPECT_DOUBLE_EQ(kp.within_run, 0.25);
  EXPECT_DOUBLE_EQ(kp.lower, 3.5);
  EXPECT_DOUBLE_EQ(kp.upper, 4.5);
  // No standard error for the armature and one run: no spread, the range is the value.
  EXPECT_DOUBLE_EQ(r.parameters[1].lower, 1e-3);
  EXPECT_DOUBLE_EQ(r.parameters[1].upper, 1e-3);
  const nlohmann::json json = spread_json(r);
  EXPECT_TRUE(json["parameters"][1]["between_runs"].is_null());
  EXPECT_EQ(json["parameters"][0]["bounds"][1], 10.0);
  EXPECT_NE(spread_markdown(r).find("| bench.kp | 1 | 1 | 4 |"), std::string::npos)
      << spread_markdown(r);
  EXPECT_NE(spread_markdown(r).find("| bench.armature_kg_m2 | kg·m² | 1 | 0.001 | – | – |"),
            std::string::npos)
      << spread_markdown(r);
}

TEST(ParameterSpread, TheRangeCoversEachRunsOwnErrorAndTheSpreadBetweenRuns) {
  // Two runs 0.2 apart, one with a large standard error: its ±2 se reaches further than the
  // between-run spread.
  const fs::path dir = motoflex::testing::scratch_dir("spread_mixed");
  const SpreadReport r = parameter_spread(
      {write_run(dir / "a", 5.0, 1e-3, 1.0), write_run(dir / "b", 5.2, 1e-3, 0.01)}, 2.0);
  const ParameterSpread& kp = r.parameters[0];
  EXPECT_DOUBLE_EQ(kp.lower, 3.0);
  EXPECT_DOUBLE_EQ(kp.upper, 7.0);
  EXPECT_NEAR(kp.within_run, std::sqrt((1.0 + 1e-4) / 2.0), 1e-12);
}

TEST(ParameterSpread, RunsThatDoNotMatchAreNamed) {
  const fs::path dir = motoflex::testing::scratch_dir("spread_bad");
  const std::string good = write_run(dir / "a", 4.0, 1e-3);
  const std::string missing = write_run(dir / "b", 4.0, 1e-3, -1.0, false);
  try {
    parameter_spread({good, missing}, 2.0);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (fs::path(missing) / "best.json").string());
    EXPECT_EQ(e.field(), "free.bench.armature_kg_m2");
  }
  EXPECT_THROW(parameter_spread({}, 2.0), InputError);
  EXPECT_THROW(parameter_spread({good}, 0.0), InputError);
  EXPECT_THROW(parameter_spread({(dir / "nothing").string()}, 2.0), InputError);
}

TEST(ParameterSpread, TheCommandPrintsTheTableAndWritesTheRanges) {
  const fs::path dir = motoflex::testing::scratch_dir("spread_cli");
  const std::string a = write_run(dir / "a", 4.0, 1e-3), b = write_run(dir / "b", 6.0, 1e-3);
  const auto run = motoflex::testing::run_motoflex("spread " + a + " " + b + " --k 1 --out " +
                                                   (dir / "ranges.json").string());
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  EXPECT_NE(run.stdout_text.find("| bench.kp | 1 | 2 | 5 |"), std::string::npos) << run.stdout_text;
  const nlohmann::json ranges =
      nlohmann::json::parse(motoflex::testing::read_file_text(dir / "ranges.json"));
  EXPECT_DOUBLE_EQ(ranges["k"], 1.0);
  EXPECT_NEAR(ranges["parameters"][0]["lower"].get<double>(), 5.0 - std::sqrt(2.0), 1e-12);
  // A folder that is no run: exit code 2 and one line naming it.
  const auto bad = motoflex::testing::run_motoflex("spread " + (dir / "nothing").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.stderr_text.find("nothing"), std::string::npos) << bad.stderr_text;
  EXPECT_EQ(bad.stderr_text.find('\n'), bad.stderr_text.size() - 1) << bad.stderr_text;
}

}  // namespace
}  // namespace motoflex::report
