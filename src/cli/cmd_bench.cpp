// motoflex bench --robot <name|dir> [--solver step|sparse|quick] [--seconds S] [--servo KIND]
//                [--flex N] [--substeps N] [--no-universal] [--rollouts R] [--threads T]
// Times rollouts of a robot holding its stand pose and prints one JSON line.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "motoflex/core/build_info.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/parallel_rollouts.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "option_checks.hpp"

namespace motoflex::cli {
namespace {

struct BenchArgs {
  std::string robot = "nao";
  std::string solver = "step";
  std::string servo;
  double seconds = 10.0;
  int flex = 1;
  int substeps = 100;
  bool no_universal = false;
  int rollouts = 1;
  int threads = 1;
};

std::string robot_directory(const std::string& robot) {
  namespace fs = std::filesystem;
  for (const fs::path& candidate : {fs::path(robot), fs::path("scenarios/robots") / robot,
                                    fs::path(data_directory()) / "scenarios/robots" / robot}) {
    if (fs::exists(candidate / "robot.yaml")) return candidate.string();
  }
  throw InputError("", 0, "--robot", "no robot '" + robot + "' (looked for <dir>/robot.yaml)");
}

int run(const BenchArgs& args) {
  if (!(args.seconds > 0.0)) throw InputError("", 0, "--seconds", "must be positive");
  if (args.rollouts < 1 || args.threads < 1) {
    throw InputError("", 0, "--rollouts/--threads", "must be >= 1");
  }
  const auto solver = parse_step_solver(args.solver);
  if (!solver) throw InputError("", 0, "--solver", kStepSolverChoices);
  StructureOptions structure;
  structure.flex_sub_bodies = args.flex;
  structure.universal_joints = !args.no_universal;
  const RobotModel model = load_robot(robot_directory(args.robot), structure);
  RolloutOptions options;
  options.solver = *solver;
  options.gear_substeps = args.substeps;
  options.servo = model.default_servo;
  if (!args.servo.empty()) {
    check_servo_parameters(model, args.servo, "", 0, "--servo");
    options.servo = args.servo;
  }
  const ParameterSet parameters(model.parameters);
  const std::vector<double> pose = model.stand_pose_vector();
  const CommandTrajectory commands =
      keyframe_trajectory({{0.0, pose}, {args.seconds, pose}}, 100.0);

  std::vector<RolloutJob> jobs(args.rollouts, RolloutJob{&model, &parameters, &commands, options});
  const auto start = std::chrono::steady_clock::now();
  const std::vector<RolloutResult> results = run_rollouts(jobs, args.threads);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::size_t steps = 0;
  for (const auto& r : results) steps += r.physics_steps;
  nlohmann::ordered_json out;
  out["robot"] = model.name;
  out["solver"] = args.solver;
  out["servo"] = options.servo;
  out["flex_sub_bodies"] = args.flex;
  out["gear_substeps"] = args.substeps;
  out["universal_joints"] = !args.no_universal;
  out["bodies"] = model.bodies.size();
  out["joints"] = model.joints.size();
  out["rollouts"] = args.rollouts;
  out["threads"] = args.threads;
  out["sim_seconds_each"] = args.seconds;
  out["physics_steps"] = steps;
  out["wall_s"] = wall_s;
  out["steps_per_s"] = steps / wall_s;
  out["realtime_factor"] = steps * options.dt_s / wall_s;
  out["end"] = to_string(results.front().end);
  if (results.front().end != RolloutEnd::kCompleted) out["end_detail"] = results.front().end_detail;
  std::printf("%s\n", out.dump().c_str());
  return 0;
}

}  // namespace

CommandRunner add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* sub = app.add_subcommand("bench", "time rollouts of a robot; prints one JSON line");
  sub->add_option("--robot", args->robot, "robot name (scenarios/robots/<name>) or folder");
  sub->add_option("--solver", args->solver,
                  "step (exact, reproducible), sparse (the same LCP, faster solver) or quick");
  sub->add_option("--seconds", args->seconds, "simulated seconds per rollout")
      ->check(positive_seconds());
  sub->add_option("--servo", args->servo, "servo model (default: the robot's)");
  sub->add_option("--flex", args->flex, "sub-bodies per flexible link (1 = rigid)")
      ->check(CLI::Range(1, 64));
  sub->add_option("--substeps", args->substeps, "gear sub-steps per physics step")
      ->check(CLI::Range(1, 10000));
  sub->add_flag("--no-universal", args->no_universal, "keep hinge pairs as two hinges");
  sub->add_option("--rollouts", args->rollouts, "number of rollouts")->check(CLI::Range(1, 100000));
  sub->add_option("--threads", args->threads, "OpenMP threads")->check(thread_count());
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
