// motoflex init-robot FILE.urdf --out DIR [--servo KIND] [--fixed-base|--floating-base]
// Writes a robot folder (robot.yaml beside a reference to the URDF) with every movable joint
// actuated and every parameter listed, prints the table of assumptions it made, and holds the
// stand pose to show the robot simulates (exit 0; exit 1 when it does not).

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "motoflex/robot_setup/robot_init.hpp"

namespace motoflex::cli {
namespace {

struct InitRobotArgs {
  std::string urdf;
  std::string out;
  std::string servo;
  bool fixed_base = false;
  bool floating_base = false;
};

int run(const InitRobotArgs& args) {
  RobotInitOptions options;
  options.urdf_path = args.urdf;
  options.out_dir = args.out;
  options.servo = args.servo;
  if (args.fixed_base) options.fixed_base = true;
  if (args.floating_base) options.fixed_base = false;
  const RobotInitResult result = init_robot(options);
  std::printf("%s", assumptions_table(result.assumptions).c_str());
  std::printf("wrote %s\n", result.robot_yaml.c_str());
  const RolloutResult& check = result.check;
  if (check.end != RolloutEnd::kCompleted) {
    std::fprintf(stderr, "motoflex: %s: simulation: stand pose held %.3g s: %s at %.3f s: %s\n",
                 result.robot_yaml.c_str(), check.time_s.empty() ? 0.0 : check.time_s.back(),
                 to_string(check.end), check.end_time_s, check.end_detail.c_str());
    return 1;
  }
  std::printf("simulates: stand pose held %.3g s with default parameters\n",
              check.time_s.empty() ? 0.0 : check.time_s.back());
  return 0;
}

}  // namespace

CommandRunner add_init_robot_command(CLI::App& app) {
  auto args = std::make_shared<InitRobotArgs>();
  CLI::App* sub = app.add_subcommand("init-robot", "write a robot folder from a URDF");
  sub->add_option("urdf", args->urdf, "the robot's URDF")->required();
  sub->add_option("--out", args->out, "robot folder to write (robot.yaml)")->required();
  sub->add_option("--servo", args->servo, "servo law of every joint (default pd_torque)");
  auto* fixed = sub->add_flag("--fixed-base", args->fixed_base, "the base is welded (an arm)");
  auto* floating =
      sub->add_flag("--floating-base", args->floating_base, "the base floats (a legged robot)");
  fixed->excludes(floating);
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
