// motoflex import-motoflex FILE.csv --out LOG.csv [--robot NAME] [--clock original|plain]
// Turns a command file of the 2011 MoToFlex program (';'-separated joint angles, a header row of
// joint names, one row per 20 ms) into a joint log with <joint>.cmd columns and a sidecar. Signs
// and clock: include/motoflex/io/motoflex_command_file.hpp. `simulate --motion FILE.csv` reads
// such a file directly, with the original clock.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "commands.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/io/motoflex_command_file.hpp"

namespace motoflex::cli {
namespace {

struct ImportMotoflexArgs {
  std::string input;
  std::string out;
  std::string robot = "nao_motoflex_2011";
  std::string clock = "original";
};

int run(const ImportMotoflexArgs& args) {
  MotoflexCommandImportOptions options;
  options.robot = args.robot;
  if (args.robot.empty()) throw InputError("", 0, "--robot", "must not be empty");
  if (args.clock == "original") {
    options.clock = MotoflexCommandClock::kOriginal;
  } else if (args.clock == "plain") {
    options.clock = MotoflexCommandClock::kPlain;
  } else {
    throw InputError("", 0, "--clock", "expected 'original' or 'plain', got '" + args.clock + "'");
  }
  if (!std::filesystem::is_regular_file(args.input)) {
    throw InputError(args.input, 0, "", "no such file");
  }
  const JointLog log = import_motoflex_commands(args.input, options);
  const std::filesystem::path out_dir = std::filesystem::path(args.out).parent_path();
  if (!out_dir.empty()) std::filesystem::create_directories(out_dir);
  write_joint_log(args.out, log);
  std::printf("imported %s -> %s: %zu frames, t %.2f..%.2f s, robot %s, %s clock\n",
              args.input.c_str(), args.out.c_str(), log.frames(), log.time_s.front(),
              log.time_s.back(), log.meta.robot.c_str(), args.clock.c_str());
  return 0;
}

}  // namespace

CommandRunner add_import_motoflex_command(CLI::App& app) {
  auto args = std::make_shared<ImportMotoflexArgs>();
  CLI::App* sub = app.add_subcommand(
      "import-motoflex", "2011 MoToFlex command file (';'-separated angles) -> joint log");
  sub->add_option("file", args->input, "MoToFlex command file, e.g. UncompensatedTarget.csv")
      ->required();
  sub->add_option("--out", args->out, "output log CSV (a sidecar YAML is written beside it)")
      ->required();
  sub->add_option("--robot", args->robot, "robot named in the sidecar (default nao_motoflex_2011)");
  sub->add_option("--clock", args->clock,
                  "original: zero pose at t = 0, row k at 20k ms, row 0 unused (the 2011 "
                  "program's playback; default); plain: row k at 20k ms from row 0");
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
