// `motoflex fit --start-from BEST.json`: a fit chained on an earlier run starts at that run's
// best point and keeps it as its incumbent, so with the same logs and model it can only end at
// that fitness or below; a parameter the earlier run held comes from its "parameters"; a file
// without a value for a free parameter is an error naming the file and the parameter.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fit_test_support.hpp"
#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;
using testing::first_pendulum_fit;
using testing::read_text;
using testing::record_pendulum_log;
using testing::write_pendulum_fit;

FitSummary run_fit(const std::string& fit_yaml, const fs::path& out,
                   const std::string& start_from = "") {
  FitOverrides overrides;
  overrides.out = out.string();
  if (!start_from.empty()) overrides.start_from = start_from;
  return FitSession(load_fit_config(fit_yaml, overrides), false).run();
}

TEST(FitStartFromTest, AChainedFitStartsAtTheEarlierBestAndNeverEndsWorse) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_start_from");
  fs::remove_all(dir);
  first_pendulum_fit(dir, 40);
  const nlohmann::json first =
      nlohmann::json::parse(read_text(dir / "first" / "run" / "best.json"));
  const double first_fitness = first["fitness"].get<double>();

  // One evaluation: only the incumbent, which must reproduce the earlier best exactly.
  fs::create_directories(dir / "second");
  const std::string second_yaml = write_pendulum_fit(
      dir / "second", dir / "data", "{kind: cma_es, sigma: 0.3, restarts: 0}", "{evaluations: 1}");
  const std::string best = (dir / "first" / "run" / "best.json").string();
  run_fit(second_yaml, dir / "second" / "run", best);
  const nlohmann::json second =
      nlohmann::json::parse(read_text(dir / "second" / "run" / "best.json"));
  EXPECT_EQ(second["fitness"].get<double>(), first_fitness);
  for (const auto& [name, value] : first["free"].items()) {
    EXPECT_EQ(second["free"][name].get<double>(), value.get<double>()) << name;
  }
  // The search itself starts there too, and run.json keeps the file for `resume`.
  FitOverrides overrides;
  overrides.out = (dir / "unused").string();
  overrides.start_from = best;
  const FitConfig config = load_fit_config(second_yaml, overrides);
  const std::vector<double> start = config.space->start();
  const std::vector<double> incumbent = config.incumbent_x;
  ASSERT_EQ(start.size(), 4u);
  EXPECT_EQ(start, incumbent);
  const nlohmann::json run = nlohmann::json::parse(read_text(dir / "second" / "run" / "run.json"));
  EXPECT_NE(run.dump().find("best.json"), std::string::npos);

  // A longer chained search ends at or below the earlier best.
  fs::create_directories(dir / "third");
  const std::string third_yaml = write_pendulum_fit(
      dir / "third", dir / "data", "{kind: cma_es, sigma: 0.05, restarts: 0}", "{evaluations: 30}");
  run_fit(third_yaml, dir / "third" / "run", best);
  const nlohmann::json third =
      nlohmann::json::parse(read_text(dir / "third" / "run" / "best.json"));
  EXPECT_LE(third["fitness"].get<double>(), first_fitness);
  fs::remove_all(dir);
}

TEST(FitStartFromTest, HeldParametersComeFromParametersAndMissingOnesAreNamed) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_start_from_files");
  fs::remove_all(dir);
  record_pendulum_log(dir / "data", "clean");
  const std::string yaml =
      write_pendulum_fit(dir, dir / "data", "{kind: cma_es, sigma: 0.3}", "{evaluations: 10}");
  FitOverrides overrides;
  overrides.out = (dir / "run").string();

  // K_t only in "parameters" (an earlier run that held it), the armature beyond its bound.
  const fs::path held = dir / "held.json";
  std::ofstream(held) << R"({"free": {"joint.pendulum.friction_nm": 0.02,
      "joint.pendulum.viscous_nm_s_per_rad": 0.03, "bench.armature_kg_m2": 0.5},
      "parameters": {"bench.Kt_nm_per_a": 0.42}})";
  overrides.start_from = held.string();
  const FitConfig config = load_fit_config(yaml, overrides);
  std::map<std::string, double> starts;
  for (const FreeParameter& p : config.space->free_parameters()) starts[p.name] = p.start;
  EXPECT_DOUBLE_EQ(starts.at("bench.Kt_nm_per_a"), 0.42);
  EXPECT_DOUBLE_EQ(starts.at("joint.pendulum.friction_nm"), 0.02);
  EXPECT_DOUBLE_EQ(starts.at("bench.armature_kg_m2"), 0.05);  // clamped to the upper bound

  const fs::path lacking = dir / "lacking.json";
  std::ofstream(lacking) << R"({"free": {"joint.pendulum.friction_nm": 0.02}})";
  overrides.start_from = lacking.string();
  try {
    load_fit_config(yaml, overrides);
    ADD_FAILURE() << "a best.json without K_t was accepted";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("lacking.json"), std::string::npos) << what;
    EXPECT_NE(what.find("bench.Kt_nm_per_a"), std::string::npos) << what;
  }
  overrides.start_from = (dir / "absent.json").string();
  EXPECT_THROW(load_fit_config(yaml, overrides), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motoflex
