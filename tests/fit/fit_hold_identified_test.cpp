// `hold_identified: true` with `--start-from RUN/best.json`: the free parameters RUN's
// summary.json marks identified (confidence_intervals.<name>.identified) leave the search and are
// held at RUN's values; the others stay free. Holding them at exactly those values reproduces
// RUN's fitness bit for bit; the held values are `fixed` entries, so they are part of the fit's
// identity; a run without intervals, a config without --start-from and a run that identified
// everything are errors that name the file.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fit_test_support.hpp"
#include "io/input_error_support.hpp"
#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;
using testing::expect_input_error;
using testing::first_pendulum_fit;
using testing::read_text;
using testing::write_pendulum_fit;

void write_intervals(const fs::path& summary, const std::map<std::string, bool>& identified) {
  nlohmann::json intervals = nlohmann::json::object();
  for (const auto& [name, yes] : identified) intervals[name] = {{"identified", yes}};
  std::ofstream(summary) << nlohmann::json{{"confidence_intervals", intervals}}.dump();
}

TEST(FitHoldIdentifiedTest, HoldsWhatTheEarlierRunIdentifiedAtItsValues) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_hold_identified");
  fs::remove_all(dir);
  const fs::path best = first_pendulum_fit(dir, 40);
  const nlohmann::json first = nlohmann::json::parse(read_text(best));
  fs::create_directories(dir / "second");
  const std::string yaml =
      write_pendulum_fit(dir / "second", dir / "data", "{kind: cma_es, sigma: 0.3, restarts: 0}",
                         "{evaluations: 1}", "hold_identified: true\n");
  FitOverrides overrides;
  overrides.out = (dir / "second" / "run").string();
  overrides.start_from = best.string();

  // The first run had no polish: no intervals to go by.
  const std::string summary = (best.parent_path() / "summary.json").string();
  std::string what = expect_input_error([&] { load_fit_config(yaml, overrides); }, summary, 0,
                                        "confidence_intervals");
  EXPECT_NE(what.find("covariance: true"), std::string::npos) << what;

  // K_t and the friction identified, the viscous coefficient not, the armature not listed.
  write_intervals(best.parent_path() / "summary.json",
                  {{"bench.Kt_nm_per_a", true},
                   {"joint.pendulum.friction_nm", true},
                   {"joint.pendulum.viscous_nm_s_per_rad", false}});
  const FitConfig config = load_fit_config(yaml, overrides);
  std::vector<std::string> free;
  for (const FreeParameter& p : config.space->free_parameters()) free.push_back(p.name);
  EXPECT_EQ(free, (std::vector<std::string>{"joint.pendulum.viscous_nm_s_per_rad",
                                            "bench.armature_kg_m2"}));
  for (const char* held : {"bench.Kt_nm_per_a", "joint.pendulum.friction_nm"}) {
    const double value = first["free"][held].get<double>();
    EXPECT_EQ(config.space->base().get(held), value) << held;
    bool in_fixed = false;
    for (const auto& [name, fixed] : config.fixed) in_fixed |= name == held && fixed == value;
    EXPECT_TRUE(in_fixed) << held;
  }
  ASSERT_EQ(config.incumbent_x.size(), 2u);

  // Held at the earlier values, the one evaluation (the incumbent) is the earlier best exactly.
  FitSession(load_fit_config(yaml, overrides), false).run();
  const nlohmann::json second =
      nlohmann::json::parse(read_text(dir / "second" / "run" / "best.json"));
  EXPECT_EQ(second["fitness"].get<double>(), first["fitness"].get<double>());
  EXPECT_EQ(second["parameters"]["bench.Kt_nm_per_a"].get<double>(),
            first["free"]["bench.Kt_nm_per_a"].get<double>());

  // A third stage chained on the second (which has no intervals of its own) holds the same
  // parameters: the second's summary lists what it held.
  const nlohmann::json second_summary =
      nlohmann::json::parse(read_text(dir / "second" / "run" / "summary.json"));
  EXPECT_EQ(second_summary["held_identified"],
            (nlohmann::json{"bench.Kt_nm_per_a", "joint.pendulum.friction_nm"}));
  FitOverrides third = overrides;
  third.out = (dir / "third_stage").string();
  third.start_from = (dir / "second" / "run" / "best.json").string();
  const FitConfig chained = load_fit_config(yaml, third);
  std::vector<std::string> chained_free;
  for (const FreeParameter& p : chained.space->free_parameters()) chained_free.push_back(p.name);
  EXPECT_EQ(chained_free, free);
  EXPECT_EQ(chained.space->base().get("bench.Kt_nm_per_a"),
            first["free"]["bench.Kt_nm_per_a"].get<double>());

  // Other held values are another fit: resume must not mix them.
  write_intervals(best.parent_path() / "summary.json", {{"bench.Kt_nm_per_a", true}});
  overrides.out = (dir / "third").string();
  EXPECT_NE(load_fit_config(yaml, overrides).hash, config.hash);
  fs::remove_all(dir);
}

TEST(FitHoldIdentifiedTest, NeedsAStartAndSomethingLeftToSearch) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_hold_identified_errors");
  fs::remove_all(dir);
  fs::create_directories(dir / "earlier");
  const std::string yaml = write_pendulum_fit(dir, dir / "data", "{kind: cma_es}",
                                              "{evaluations: 1}", "hold_identified: true\n");
  testing::record_pendulum_log(dir / "data", "clean");
  FitOverrides overrides;
  overrides.out = (dir / "run").string();
  std::string what =
      expect_input_error([&] { load_fit_config(yaml, overrides); }, yaml, 12, "hold_identified");
  EXPECT_NE(what.find("--start-from"), std::string::npos) << what;

  const fs::path best = dir / "earlier" / "best.json";
  std::ofstream(best) << R"({"free": {"bench.Kt_nm_per_a": 0.4, "joint.pendulum.friction_nm": 0.05,
      "joint.pendulum.viscous_nm_s_per_rad": 0.02, "bench.armature_kg_m2": 0.003}})";
  write_intervals(dir / "earlier" / "summary.json", {{"bench.Kt_nm_per_a", true},
                                                     {"joint.pendulum.friction_nm", true},
                                                     {"joint.pendulum.viscous_nm_s_per_rad", true},
                                                     {"bench.armature_kg_m2", true}});
  overrides.start_from = best.string();
  what = expect_input_error([&] { load_fit_config(yaml, overrides); },
                            (dir / "earlier" / "summary.json").string(), 0, "hold_identified");
  EXPECT_NE(what.find("nothing is left"), std::string::npos) << what;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motoflex
