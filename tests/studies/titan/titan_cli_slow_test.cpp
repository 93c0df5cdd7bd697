// A whole `motoflex titan` run, shortened (static 2 s, one crawl period per posture, a 1 s
// timing run): what the command writes carries the study's physics, not just files.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "cli/cli_test_support.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

std::string short_study() {
  std::ifstream in(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/titan/paper.yaml");
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const auto replace = [&](const std::string& pattern, const std::string& with) {
    const std::string before = text;
    text = std::regex_replace(text, std::regex(pattern), with);
    EXPECT_NE(text, before) << "the paper file no longer has " << pattern;
  };
  replace("robot: \\.\\./robots/titan8",
          "robot: " + std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/titan8");
  replace("duration_s: 5\\.0", "duration_s: 2.0");
  replace("periods: 3 ", "periods: 1 ");
  replace("crawl_s: 10\\.0", "crawl_s: 1.0");
  replace("repeats: 3 ", "repeats: 1 ");
  return text;
}

TEST(TitanCli, AShortWholeStudyReproducesThePapersFindings) {
  const fs::path dir = fresh_dir("titan_cli");
  write_text(dir / "study.yaml", short_study());
  const CommandResult run = run_motoflex("titan " + (dir / "study.yaml").string() + " --out " +
                                         (dir / "out").string() + " --threads 2");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  std::ifstream in(dir / "out" / "titan.json");
  const nlohmann::json study = nlohmann::json::parse(in);

  // §III static standing: the knee carries a quarter of the weight (paper 49.1 N; measured
  // 49.05 N), the other knee loads vanish (measured 0.54 at most), and the Jacobian torque
  // settles faster than the joint-feedback torque (measured 0.29 s vs 0.75 s).
  EXPECT_NEAR(study["static"]["knee_fz_n"].get<double>(), 49.1, 0.5);
  EXPECT_LT(study["static"]["knee_other_max"].get<double>(), 1.5);
  EXPECT_LT(study["static"]["jacobian_converge_s"].get<double>(),
            study["static"]["feedback_converge_s"].get<double>());
  // §VI up-and-down: the joint work over the rise is the potential-energy gain (measured to
  // 0.0003 %) and over a whole period vanishes (measured 0.0008 % of the rise).
  EXPECT_LT(study["updown"]["rise_error_percent"].get<double>(), 0.01);
  EXPECT_LT(study["updown"]["period_integral_percent_of_rise"].get<double>(), 0.01);
  // §V crawl: posture A needs the least averaged power (measured A 0.71 W; B 2.28, C 1.64,
  // D 1.18 W).
  const nlohmann::json& crawl = study["crawl"];
  const double a = crawl["A"]["avg_abs_power_w"].get<double>();
  for (const char* posture : {"B", "C", "D"}) {
    EXPECT_LT(a, crawl[posture]["avg_abs_power_w"].get<double>()) << posture;
  }
  // The timing run simulated what it was asked to (1 s at 1 ms steps).
  EXPECT_EQ(study["timing"]["steps"].get<int>(), 1000);
  // And the report and the per-figure series are written.
  for (const char* file : {"report.md", "static_knee.csv", "updown.csv", "crawl_A_FL_cycle.csv"}) {
    EXPECT_TRUE(fs::exists(dir / "out" / file)) << file;
  }
  // The figures (scripts/plot_titan.py; matplotlib is a set-up dependency): drawn, no warning.
  EXPECT_EQ(run.stderr_text.find("no plot"), std::string::npos) << run.stderr_text;
  for (const char* png : {"fig5_static_knee.png", "updown.png", "fig10_power.png"}) {
    EXPECT_GT(fs::exists(dir / "out" / png) ? fs::file_size(dir / "out" / png) : 0u, 1000u) << png;
  }
}

}  // namespace
}  // namespace motoflex::testing
