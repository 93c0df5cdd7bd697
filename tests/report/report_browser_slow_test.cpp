// The report of a real short fit, opened in headless Chromium: the page's scripts run without
// a JavaScript error, plotly draws every figure, and the rendered page is a picture, not a
// blank. Skipped (with the reason printed) when Chromium is not installed
// (`apt-get install chromium`; scripts/setup installs it).

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>

#include "cli/cli_test_support.hpp"
#include "fit/fit_test_support.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

std::string find_chromium() {
  for (const char* candidate : {"/usr/bin/chromium", "/usr/bin/chromium-browser"}) {
    if (fs::exists(candidate)) return candidate;
  }
  return "";
}

struct Shell {
  int exit_code = -1;
  std::string output;
};

Shell run_shell(const std::string& command) {
  Shell result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// Chromium without anything that reaches the network or the user's profile; console messages
// (and uncaught exceptions) go to stderr. `mode` is --dump-dom or --screenshot=FILE.
std::string chromium_command(const std::string& chromium, const fs::path& profile,
                             const std::string& mode, const fs::path& page,
                             const fs::path& stderr_file) {
  return "timeout 180 " + chromium +
         " --headless --no-sandbox --disable-gpu --disable-background-networking"
         " --disable-component-update --disable-sync --no-first-run --disable-extensions"
         " --hide-scrollbars --user-data-dir=" +
         profile.string() +
         " --enable-logging=stderr --v=0 --virtual-time-budget=20000 --window-size=1400,3000 " +
         mode + " file://" + page.string() + " 2> " + stderr_file.string();
}

// Lines of Chromium's log that report the page's JavaScript: console output and uncaught
// exceptions ("CONSOLE" and "Uncaught" in Chromium's log format).
std::string javascript_messages(const std::string& log) {
  std::string out, line;
  std::istringstream in(log);
  while (std::getline(in, line)) {
    if (line.find("CONSOLE") != std::string::npos || line.find("Uncaught") != std::string::npos) {
      out += line + "\n";
    }
  }
  return out;
}

TEST(ReportBrowser, ARealFitsReportDrawsEveryFigureWithoutJavaScriptErrors) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    std::printf("chromium not installed: browser test skipped (apt-get install chromium)\n");
    GTEST_SKIP() << "chromium not installed (apt-get install chromium)";
  }
  const fs::path dir = fresh_dir("report_browser");
  record_pendulum_log(dir / "data", "swing");
  record_pendulum_log(dir / "validation", "swing_again", {}, 2);
  const std::string fit = write_pendulum_fit(
      dir, dir / "data", "{kind: mu_plus_lambda, mu: 2, lambda: 6, kappa: 3}", "{generations: 3}");
  const auto fitted = run_motoflex("fit " + fit + " --out " + (dir / "run").string() +
                                   " --validation " + (dir / "validation").string());
  ASSERT_EQ(fitted.exit_code, 0) << fitted.stderr_text;
  const fs::path page = dir / "run" / "report.html";
  ASSERT_TRUE(fs::exists(page));

  // (a) The DOM after the scripts ran: plotly's SVGs, no figure failed.
  const Shell dom = run_shell(
      chromium_command(chromium, dir / "profile_dom", "--dump-dom", page, dir / "dom.log"));
  ASSERT_EQ(dom.exit_code, 0) << read_text(dir / "dom.log");
  const std::string messages = javascript_messages(read_text(dir / "dom.log"));
  EXPECT_TRUE(messages.empty()) << messages;
  EXPECT_NE(dom.output.find("data-figures-failed=\"0\""), std::string::npos);
  // Convergence, the two logs (training and validation) and their joint's frequency response.
  EXPECT_NE(dom.output.find("data-figures-drawn=\"5\""), std::string::npos)
      << dom.output.substr(0, 2000);
  std::size_t svgs = 0;
  for (std::size_t at = dom.output.find("main-svg"); at != std::string::npos;
       at = dom.output.find("main-svg", at + 1)) {
    ++svgs;
  }
  EXPECT_GE(svgs, 5u);
  EXPECT_EQ(dom.output.find("class=\"plot-error\""), std::string::npos);

  // (b) A screenshot that is a picture: many colours, not one.
  const fs::path png = dir / "report.png";
  const Shell shot = run_shell(chromium_command(
      chromium, dir / "profile_shot", "--screenshot=" + png.string(), page, dir / "shot.log"));
  ASSERT_EQ(shot.exit_code, 0) << read_text(dir / "shot.log");
  ASSERT_TRUE(fs::exists(png));
  EXPECT_GT(fs::file_size(png), 10000u);
  const Shell colours = run_shell(
      "/usr/bin/python3 -c \"import sys, numpy, matplotlib.image as m; a = m.imread(sys.argv[1]); "
      "print(len(numpy.unique(a.reshape(-1, a.shape[2]), axis=0)))\" " +
      png.string());
  ASSERT_EQ(colours.exit_code, 0) << colours.output;
  EXPECT_GT(std::atoi(colours.output.c_str()), 100) << "distinct colours: " << colours.output;
}

}  // namespace
}  // namespace motoflex::testing
