// motoflex report <run-dir> [--out FILE]: one self-contained HTML page of a fit or loop run dir
// (report_page.hpp).

#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "motoflex/report/report_page.hpp"

namespace motoflex::cli {
namespace {

struct ReportArgs {
  std::string run_dir;
  std::string out;
  std::size_t max_points = 0;
};

int run_report_command(const ReportArgs& args) {
  report::ReportOptions options;
  if (args.max_points > 0) options.max_points_per_trace = args.max_points;
  const std::string path = report::write_report(args.run_dir, args.out, options);
  std::printf("report: %s\n", path.c_str());
  return 0;
}

}  // namespace

CommandRunner add_report_command(CLI::App& app) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* sub = app.add_subcommand(
      "report", "write one self-contained HTML report of a fit or loop run folder");
  sub->add_option("run_dir", args->run_dir, "run folder of `motoflex fit`, `resume` or `loop`")
      ->required();
  sub->add_option("--out", args->out, "HTML file to write (default: <run_dir>/report.html)");
  sub->add_option("--max-points", args->max_points,
                  "points per plotted trace at most; longer logs are thinned (default 2000)")
      ->check(CLI::Range(std::size_t{4}, std::size_t{1000000}));
  return [args] { return run_report_command(*args); };
}

}  // namespace motoflex::cli
