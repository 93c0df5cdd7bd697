// The whole page from synthetic run dirs: every section, "not available" where the run dir has
// nothing to show, data the page's script can parse, and nothing loaded from the network.

#include "motoflex/report/report_page.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <regex>

#include "motoflex/core/error.hpp"
#include "report_test_support.hpp"

namespace motoflex::report {
namespace {

namespace fs = std::filesystem;
using motoflex::testing::fresh_dir;
using motoflex::testing::read_file_text;
using motoflex::testing::write_text;

// The page's JSON data, parsed.
nlohmann::json page_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"motoflex-data\">";
  const std::size_t begin = html.find(open);
  EXPECT_NE(begin, std::string::npos);
  const std::size_t end = html.find("</script>", begin);
  return nlohmann::json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

// The page without the text of its script elements (the tags stay): the markup a browser loads
// resources for. (libstdc++'s std::regex recurses per character: the 1.5 MB bundle would
// overflow the stack.)
std::string markup_only(const std::string& html) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = html.find("<script", at);
    if (open == std::string::npos) break;
    const std::size_t tag_end = html.find('>', open);
    out += html.substr(at, tag_end + 1 - at);
    at = html.find("</script>", tag_end);
    if (at == std::string::npos) return out;
  }
  return out + html.substr(at);
}

void expect_nothing_from_the_network(const std::string& page) {
  const std::string html = markup_only(page);
  EXPECT_LT(html.size(), 200000u);
  EXPECT_NE(html.find("<script type=\"application/json\" id=\"motoflex-data\">"),
            std::string::npos);
  // Every script and style is inline: no element loads a URL.
  EXPECT_FALSE(std::regex_search(html, std::regex("<script[^>]*\\ssrc\\s*=", std::regex::icase)));
  EXPECT_FALSE(std::regex_search(html, std::regex("<link[^>]*href", std::regex::icase)));
  EXPECT_FALSE(std::regex_search(
      html, std::regex("(src|href)\\s*=\\s*[\"']?\\s*(https?:)?//", std::regex::icase)));
  EXPECT_FALSE(std::regex_search(html, std::regex("@import", std::regex::icase)));
}

TEST(RenderReport, AFullFitRunDirHasEverySection) {
  const fs::path dir = fresh_dir("report_page_full");
  motoflex::testing::write_fit_run_dir(dir);
  const std::string html = render_report(read_run_dir(dir.string()));
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  for (const char* id : {"id=\"summary\"", "id=\"convergence\"", "id=\"log-0-plot\"",
                         "id=\"log-0-channel\"", "id=\"parameters\"", "id=\"residuals\""}) {
    EXPECT_NE(html.find(id), std::string::npos) << id;
  }
  EXPECT_NE(html.find("<title>motoflex fit toy_fit</title>"), std::string::npos);
  EXPECT_NE(html.find("max_generations"), std::string::npos);  // stop reason
  EXPECT_NE(html.find("openmp(2 threads)"), std::string::npos);
  EXPECT_NE(html.find("<code>pid.kp_v_per_rad</code>"), std::string::npos);
  // The knee is the channel with the larger residual: the log opens on it.
  EXPECT_NE(html.find("<option value=\"1\" selected>knee"), std::string::npos);
  // No uncertainty, no correlation, no residual analysis in this run dir.
  EXPECT_NE(html.find("Standard errors and confidence intervals: not available"),
            std::string::npos);
  EXPECT_EQ(html.find("id=\"correlation\""), std::string::npos);
  EXPECT_NE(html.find("Not available: run <code>motoflex residuals"), std::string::npos);
  expect_nothing_from_the_network(html);

  const nlohmann::json data = page_data(html);
  EXPECT_EQ(data["convergence"]["best"].size(), 3u);
  EXPECT_TRUE(data["convergence"]["median"][0].is_null());  // inf in generations.csv
  ASSERT_EQ(data["logs"].size(), 1u);
  EXPECT_NEAR(data["logs"][0]["channels"][1]["rms_deg"].get<double>(),
              0.01 * 180.0 / std::numbers::pi, 1e-4);
  EXPECT_TRUE(data["correlation"].is_null());
}

TEST(RenderReport, ALogOpensOnTheWorstJointEvenWhenTheImuIsWorse) {
  const fs::path dir = fresh_dir("report_page_imu");
  motoflex::testing::write_fit_run_dir(dir);
  JointLog measured = motoflex::testing::two_joint_log(300);
  JointLog simulated = motoflex::testing::two_joint_log(300, -0.01);
  measured.imu_roll_rad.assign(300, 0.1);  // 5.7 deg off, ten times the knee's error
  measured.imu_pitch_rad.assign(300, 0.0);
  simulated.imu_roll_rad.assign(300, 0.0);
  simulated.imu_pitch_rad.assign(300, 0.0);
  write_joint_log((dir / "data" / "walk.csv").string(), measured);
  write_joint_log((dir / "best" / "walk.csv").string(), simulated);
  const std::string html = render_report(read_run_dir(dir.string()));
  EXPECT_NE(html.find("<option value=\"1\" selected>knee"), std::string::npos);
  EXPECT_NE(html.find("<option value=\"2\">imu.roll (RMS 5.73 deg)"), std::string::npos);
}

TEST(RenderReport, UncertaintyResidualsAndThinningWhenTheRunDirHasThem) {
  const fs::path dir = fresh_dir("report_page_extras");
  motoflex::testing::write_fit_run_dir(dir, true, 5000);
  write_text(dir / "summary.json", R"({"name": "toy_fit", "free": {"pid.kp_v_per_rad": 321.5},
    "confidence_intervals": {"pid.kp_v_per_rad": {"standard_error": 12.5, "lower": 297,
                                                  "upper": 346}},
    "covariance": {"names": ["pid.kp_v_per_rad"], "matrix": [[156.25]]}})");
  fs::create_directories(dir / "residuals");
  write_text(dir / "residuals" / "residuals.md",
             "# Residuals of toy_fit\n\n| joint | RMS |\n"
             "|---|---|\n| knee | 0.57 |\n");
  const std::string html = render_report(read_run_dir(dir.string()), {1000});
  EXPECT_NE(html.find("[297, 346]"), std::string::npos);
  EXPECT_NE(html.find("id=\"correlation\""), std::string::npos);
  EXPECT_NE(html.find("<td>knee</td><td>0.57</td>"), std::string::npos);
  EXPECT_NE(html.find("thinned to at most 1000 points per trace"), std::string::npos);
  const nlohmann::json data = page_data(html);
  EXPECT_LE(data["logs"][0]["channels"][0]["measured"].size(), 1000u);
  EXPECT_EQ(data["correlation"]["matrix"][0][0], 1.0);
}

TEST(RenderReport, ARunDirWithoutOptionalFilesStillMakesAPage) {
  const fs::path dir = fresh_dir("report_page_sparse");
  motoflex::testing::write_fit_run_dir(dir, false);
  const std::string html = render_report(read_run_dir(dir.string()));
  EXPECT_NE(html.find("Not available (no generations.csv rows)"), std::string::npos);
  EXPECT_NE(html.find("Not available (no log with both a measured and a simulated file"),
            std::string::npos);
  EXPECT_NE(html.find("no inputs.json"), std::string::npos);  // in the notes
  EXPECT_TRUE(page_data(html)["logs"].empty());
}

TEST(RenderReport, UncertaintyKeysOfAnotherShapeAreANoteNotALostReport) {
  const fs::path dir = fresh_dir("report_page_bad_uncertainty");
  motoflex::testing::write_fit_run_dir(dir);
  write_text(dir / "summary.json", R"({"name": "toy_fit", "correlation": [[1, 0.5], [0.5, 1]]})");
  const std::string html = render_report(read_run_dir(dir.string()));
  EXPECT_NE(html.find("parameter uncertainty not shown: " + (dir / "summary.json").string() +
                      ": correlation: not an object"),
            std::string::npos);
  EXPECT_NE(html.find("id=\"log-0-plot\""), std::string::npos);
}

TEST(RenderReport, AMeasuredLogThatMovedIsANoteAndTheRestIsShown) {
  const fs::path dir = fresh_dir("report_page_moved_log");
  motoflex::testing::write_fit_run_dir(dir);
  fs::remove(dir / "data" / "walk.csv");
  const std::string html = render_report(read_run_dir(dir.string()));
  EXPECT_NE(html.find("training log walk: the measured log"), std::string::npos);
  EXPECT_NE(html.find("id=\"convergence\""), std::string::npos);
}

TEST(RenderReport, ALoopDirShowsBeforeAndAfter) {
  const fs::path dir = fresh_dir("report_page_loop");
  motoflex::testing::write_fit_run_dir(dir / "01_stribeck");
  write_text(dir / "loop.json", R"({"fit": "/x/bench_hidden.yaml",
    "iterations": [{"added_effect": "stribeck",
    "train_rms_before": 0.2, "train_rms_after": 0.1, "val_rms_before": 0.1553,
    "val_rms_after": 0.0605}, {"added_effect": null, "reoptimised": true,
    "reoptimised_from": "control",
    "train_rms_before": 0.1, "train_rms_after": 0.09, "val_rms_before": 0.0605,
    "val_rms_after": 0.0550}], "final_run_dir": ")" +
                                    (dir / "01_stribeck").string() + R"("})");
  write_text(dir / "report.md", "# Closing the loop: toy\n\nFinal model adds: stribeck.\n");
  const std::string html = render_report(read_run_dir(dir.string()));
  EXPECT_NE(html.find("<title>motoflex loop bench_hidden</title>"), std::string::npos);
  EXPECT_NE(html.find("id=\"loop\""), std::string::npos);
  EXPECT_NE(html.find("0.1553 → 0.0605"), std::string::npos);
  EXPECT_NE(html.find("-61 %"), std::string::npos);
  // The second iteration added nothing but went on from the control refit.
  EXPECT_NE(html.find("<td>2</td><td>– (re-optimised: control)</td>"), std::string::npos);
  EXPECT_NE(html.find("Final model adds: stribeck."), std::string::npos);
  EXPECT_NE(html.find("the loop&#39;s final model"), std::string::npos);
}

TEST(WriteReport, DefaultsToReportHtmlInTheRunDirAndTakesAnOutPath) {
  const fs::path dir = fresh_dir("report_page_write");
  motoflex::testing::write_fit_run_dir(dir);
  EXPECT_EQ(write_report(dir.string()), (dir / "report.html").string());
  EXPECT_NE(read_file_text(dir / "report.html").find("</html>"), std::string::npos);
  const fs::path other = dir / "elsewhere.html";
  EXPECT_EQ(write_report(dir.string(), other.string()), other.string());
  EXPECT_TRUE(fs::exists(other));
  EXPECT_THROW(write_report(dir.string(), (dir / "no" / "such" / "dir.html").string()), InputError);
}

}  // namespace
}  // namespace motoflex::report
