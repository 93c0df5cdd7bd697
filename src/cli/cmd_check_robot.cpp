// motoflex check-robot DIR
// Every problem of a robot folder at once, one line each (exit 2), or a short summary (exit 0).

#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "motoflex/robot_setup/robot_check.hpp"

namespace motoflex::cli {
namespace {

int run(const std::string& robot_dir) {
  const RobotCheckReport report = check_robot_folder(robot_dir);
  for (const InputError& problem : report.problems) {
    std::fprintf(stderr, "motoflex: %s\n", problem.what());
  }
  if (!report.problems.empty()) return 2;
  for (const std::string& line : report.summary) std::printf("%s\n", line.c_str());
  return 0;
}

}  // namespace

CommandRunner add_check_robot_command(CLI::App& app) {
  auto robot_dir = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand("check-robot", "report every problem of a robot folder");
  sub->add_option("robot", *robot_dir, "robot folder (robot.yaml)")->required();
  return [robot_dir] { return run(*robot_dir); };
}

}  // namespace motoflex::cli
