// motoflex spread RUN... [--k K] [--out FILE]: domain-randomisation ranges from several fits of
// the same parameters (units, sessions, seeds): mean, spread between runs, each fit's own
// standard error and the range to sample (parameter_spread.hpp).

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/report/parameter_spread.hpp"

namespace motoflex::cli {
namespace {

struct SpreadArgs {
  std::vector<std::string> run_dirs;
  double k = 2.0;
  std::string out;
};

int run_spread_command(const SpreadArgs& args) {
  const report::SpreadReport spread = report::parameter_spread(args.run_dirs, args.k);
  std::fputs(report::spread_markdown(spread).c_str(), stdout);
  if (!args.out.empty()) {
    write_file_atomically(args.out, report::spread_json(spread).dump(2) + "\n");
    std::printf("ranges: %s\n", args.out.c_str());
  }
  return 0;
}

}  // namespace

CommandRunner add_spread_command(CLI::App& app) {
  auto args = std::make_shared<SpreadArgs>();
  CLI::App* sub = app.add_subcommand(
      "spread",
      "domain-randomisation ranges from several fits of the same parameters (units, sessions, "
      "seeds): mean, spread between runs, each fit's standard error, the range to sample");
  sub->add_option("runs", args->run_dirs, "run folders of `motoflex fit` or `loop`")->required();
  sub->add_option("--k", args->k,
                  "standard deviations (between runs) or errors (within a run) on each side "
                  "(default 2)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--out", args->out, "JSON file of the ranges to write");
  return [args] { return run_spread_command(*args); };
}

}  // namespace motoflex::cli
