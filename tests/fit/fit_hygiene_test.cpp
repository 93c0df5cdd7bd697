// Fit hygiene (issue 18, item 7): a fitted parameter the data cannot move the fitness with is
// named in summary.json and the report, the others get their sensitivity; the excitation check
// names the joints a log leaves still; residuals refuses an unconverged fit unless --force.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex/fit/excitation_check.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// A pendulum fit of friction and viscous friction plus a coefficient nothing reads on this bench
// (the ground's friction: the arm never touches the ground), stopped by its budget after a few
// generations.
fs::path small_unconverged_fit(const std::string& name) {
  const fs::path dir = fresh_dir(name);
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit =
      write_pendulum_fit(dir, dir / "data", "{kind: mu_plus_lambda, mu: 2, lambda: 6, kappa: 3}",
                         "{generations: 2}", "");
  // Replace the free section's last entry by the ignored coefficient.
  std::string text = read_text(fit);
  text.replace(text.find("  bench.armature_kg_m2"),
               text.find("strategy:") - text.find("  bench.armature_kg_m2"),
               "  contact.mu: {lower: 0.5, upper: 1.5}\n");
  write_text(fit, text);
  const CommandResult run = run_motoflex("fit " + fit + " --out " + (dir / "run").string());
  EXPECT_EQ(run.exit_code, 0) << run.stderr_text;
  return dir / "run";
}

TEST(FitHygiene, SensitivityNamesTheParameterTheDataCannotDetermine) {
  const fs::path run = small_unconverged_fit("fit_sensitivity");
  const nlohmann::json summary = read_json(run / "summary.json");
  EXPECT_FALSE(summary["converged"].get<bool>());
  const nlohmann::json& s = summary["sensitivity"]["parameters"];
  // Nothing touches the ground: moving it changes nothing, exactly.
  EXPECT_EQ(s["contact.mu"]["relative_fitness_change_per_bound_width"].get<double>(), 0.0);
  EXPECT_FALSE(s["contact.mu"]["determined"].get<bool>());
  ASSERT_EQ(summary["sensitivity"]["undetermined"].size(), 1u);
  EXPECT_EQ(summary["sensitivity"]["undetermined"][0], "contact.mu");
  // The others move the fitness strongly (measured: K_t 25.9, friction 8.7, viscous 3.7 per
  // bound-width, log scale, two generations from the start): far above the 0.1 threshold.
  for (const char* name :
       {"joint.pendulum.friction_nm", "joint.pendulum.viscous_nm_s_per_rad", "bench.Kt_nm_per_a"}) {
    EXPECT_GT(s[name]["relative_fitness_change_per_bound_width"].get<double>(), 1.0) << name;
    EXPECT_TRUE(s[name]["determined"].get<bool>()) << name;
  }
}

TEST(FitHygiene, ResidualsRefusesAnUnconvergedFitUnlessForced) {
  const fs::path run = small_unconverged_fit("residuals_guard");
  const CommandResult refused =
      run_motoflex("residuals " + run.string() + " --effects sensor_delay");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.stderr_text.find("did not converge"), std::string::npos) << refused.stderr_text;
  EXPECT_NE(refused.stderr_text.find("--force"), std::string::npos) << refused.stderr_text;
  EXPECT_FALSE(fs::exists(run / "residuals" / "residuals.json"));

  const CommandResult forced =
      run_motoflex("residuals " + run.string() + " --effects sensor_delay --force");
  ASSERT_EQ(forced.exit_code, 0) << forced.stderr_text;
  EXPECT_NE(forced.stdout_text.find("UNRELIABLE"), std::string::npos) << forced.stdout_text;
  const nlohmann::json analysis = read_json(run / "residuals" / "residuals.json");
  EXPECT_FALSE(analysis["ranking_reliable"].get<bool>());
  EXPECT_NE(analysis["ranking_unreliable_because"].get<std::string>().find("budget"),
            std::string::npos);
  EXPECT_NE(read_text(run / "residuals" / "residuals.md").find("UNRELIABLE ranking"),
            std::string::npos);
}

TEST(FitHygiene, ExcitationCheckNamesTheJointsALogLeavesStill) {
  RobotModel model;
  model.actuators.resize(3);
  model.actuators[0].name = "moving";
  model.actuators[1].name = "still";
  model.actuators[2].name = "slide";
  model.actuators[2].prismatic = true;
  FitCase a, b;
  // Frame-major, model order. "still" moves 0.004 rad over both logs together, "slide" 0.8 mm.
  a.measured_rad = {0.0, 0.100, 0.0000, 0.5, 0.102, 0.0008};
  b.measured_rad = {-0.3, 0.098, 0.0002, 0.2, 0.101, 0.0004};
  const std::vector<StillJoint> still = still_joints(model, {a, b});
  ASSERT_EQ(still.size(), 2u);
  EXPECT_EQ(still[0].joint, "still");
  EXPECT_NEAR(still[0].range, 0.004, 1e-15);
  EXPECT_EQ(still[1].joint, "slide");
  EXPECT_NEAR(still[1].range, 0.0008, 1e-15);
  const auto warnings = excitation_warnings(model, {a, b});
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("'still' moves only 0.004 rad"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("0.0008 m"), std::string::npos) << warnings[1];
}

}  // namespace
}  // namespace motoflex::testing
