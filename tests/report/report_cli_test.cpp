// `motoflex report` and the report that `motoflex fit` writes at its end, as a user runs them.

#include <gtest/gtest.h>

#include <algorithm>

#include "cli/cli_test_support.hpp"
#include "fit/fit_test_support.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const char* kTinyEs = "{kind: mu_plus_lambda, mu: 2, lambda: 4, kappa: 3}";

TEST(ReportCli, AFitWritesItsReportAndInputsAtTheEnd) {
  const fs::path dir = fresh_dir("report_cli_fit");
  record_pendulum_log(dir / "data", "swing");
  const std::string fit = write_pendulum_fit(dir, dir / "data", kTinyEs, "{generations: 2}");
  const auto result = run_motoflex("fit " + fit + " --out " + (dir / "run").string());
  ASSERT_EQ(result.exit_code, 0) << result.stderr_text;
  EXPECT_NE(result.stdout_text.find("report: " + (dir / "run" / "report.html").string()),
            std::string::npos)
      << result.stdout_text;
  const std::string html = read_text(dir / "run" / "report.html");
  EXPECT_NE(html.find("<title>motoflex fit pendulum</title>"), std::string::npos);
  EXPECT_NE(html.find("id=\"log-0-plot\""), std::string::npos);  // the log, measured vs simulated
  EXPECT_NE(html.find("<code>bench.Kt_nm_per_a</code>"), std::string::npos);

  const nlohmann::json inputs = nlohmann::json::parse(read_text(dir / "run" / "inputs.json"));
  ASSERT_EQ(inputs["free"].size(), 4u);
  EXPECT_EQ(inputs["free"][0]["name"], "bench.Kt_nm_per_a");
  EXPECT_EQ(inputs["free"][0]["unit"], "N·m/A");
  EXPECT_EQ(inputs["free"][0]["lower"], 0.1);
  EXPECT_EQ(inputs["seed"], 7);
  const std::string log = inputs["train_logs"][0].get<std::string>();
  EXPECT_TRUE(fs::path(log).is_absolute()) << log;
  EXPECT_TRUE(fs::equivalent(log, dir / "data" / "swing.csv")) << log;

  // `resume` writes it too, with the generations it added.
  fs::remove(dir / "run" / "report.html");
  const auto resumed = run_motoflex("resume " + (dir / "run").string() + " --max-generations 3");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.stderr_text;
  EXPECT_NE(resumed.stdout_text.find("report: "), std::string::npos) << resumed.stdout_text;
  EXPECT_NE(read_text(dir / "run" / "report.html").find("<tr><td>generations</td><td>3</td>"),
            std::string::npos);
}

TEST(ReportCli, AReportThatCannotBeWrittenIsAWarningNotAFailedFit) {
  const fs::path dir = fresh_dir("report_cli_unwritable");
  record_pendulum_log(dir / "data", "swing");
  const std::string fit = write_pendulum_fit(dir, dir / "data", kTinyEs, "{generations: 1}");
  fs::create_directories(dir / "run" / "report.html");  // a folder where the file would go
  const auto result = run_motoflex("fit " + fit + " --out " + (dir / "run").string());
  EXPECT_EQ(result.exit_code, 0) << result.stderr_text;
  EXPECT_TRUE(fs::exists(dir / "run" / "best.json"));
  EXPECT_EQ(std::count(result.stderr_text.begin(), result.stderr_text.end(), '\n'), 1)
      << result.stderr_text;
  EXPECT_NE(result.stderr_text.find("motoflex: warning: no report for"), std::string::npos)
      << result.stderr_text;
}

TEST(ReportCli, ReportCommandWritesWhereToldAndRefusesAFolderThatIsNoRun) {
  const fs::path dir = fresh_dir("report_cli_command");
  const auto refused = run_motoflex("report " + dir.string());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.stderr_text, "motoflex: " + dir.string() +
                                     ": not a fit or loop run folder (no run.json, summary.json "
                                     "or loop.json)\n");
  write_text(dir / "summary.json", "{\"name\": \"bare\"}");
  const auto written =
      run_motoflex("report " + dir.string() + " --out " + (dir / "page.html").string());
  EXPECT_EQ(written.exit_code, 0) << written.stderr_text;
  EXPECT_EQ(written.stdout_text, "report: " + (dir / "page.html").string() + "\n");
  EXPECT_NE(read_text(dir / "page.html").find("motoflex fit bare"), std::string::npos);
  EXPECT_EQ(run_motoflex("report " + dir.string() + " --max-points 2").exit_code, 2);
}

}  // namespace
}  // namespace motoflex::testing
