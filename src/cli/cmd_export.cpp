// motoflex export <best.json> --robot DIR --format json|urdf|sdf|mjcf --out FILE
//                 [--servo KIND] [--flex-sub-bodies N] [--dt S]
//                 [--check-mujoco LOG.csv [--hold-torso] [--settle S] [--duration S]]
//                 [--render PNG]
// Writes a fitted parameter set in another simulator's format, reads the file back with that
// format's own parser (urdfdom, sdformat, MuJoCo) and prints one JSON line. With
// --check-mujoco (mjcf only) it also replays LOG's commanded angles in motoflex (ODE) and in
// MuJoCo on the export and adds the angle RMS and both simulators' steps/s to that line. With
// --render (mjcf only) MuJoCo draws the export offscreen (OSMesa) into a PNG.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/export/exporter.hpp"
#include "motoflex/export/mujoco_check.hpp"
#include "motoflex/export/mujoco_render.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/motion/log_commands.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "option_checks.hpp"

namespace motoflex::cli {
namespace {

struct ExportArgs {
  std::string parameters;
  std::string robot;
  std::string format;
  std::string out;
  std::string servo;
  int flex_sub_bodies = 1;
  double dt_s = 0.001;
  std::string check_log;
  bool hold_torso = false;
  double settle_s = 0.0;
  double duration_s = 0.0;
  bool no_armature = false;
  std::string render_png;
};

// The log's commanded angles in model order, truncated to `duration_s` (0: all); its sidecar's
// per-log parameters are applied to `parameters`.
CommandTrajectory read_commands(const RobotModel& model, const std::string& path, double duration_s,
                                ParameterSet& parameters,
                                std::map<std::string, double>& log_parameters) {
  CommandTrajectory commands = read_log_commands(model, path, parameters, log_parameters);
  if (duration_s > 0.0) commands = truncate_trajectory(commands, duration_s);
  if (commands.frames() < 2) throw InputError(path, 0, "--duration", "leaves fewer than 2 frames");
  return commands;
}

nlohmann::ordered_json comparison_json(const MujocoComparison& c) {
  nlohmann::ordered_json per_joint = nlohmann::ordered_json::object();
  for (std::size_t j = 0; j < c.joints.size(); ++j) per_joint[c.joints[j]] = c.rms_deg_per_joint[j];
  return {{"rms_deg_per_joint", per_joint},
          {"rms_deg", c.rms_deg},
          {"max_abs_deg", c.max_abs_deg},
          {"steps", c.steps},
          {"mujoco_steps_per_s", c.mujoco_steps_per_s},
          {"motoflex_steps_per_s", c.motoflex_steps_per_s},
          {"motoflex_quick_steps_per_s", c.motoflex_quick_steps_per_s},
          {"rms_deg_quick", c.rms_deg_quick},
          {"motoflex_sparse_steps_per_s", c.motoflex_sparse_steps_per_s},
          {"rms_deg_sparse", c.rms_deg_sparse},
          {"rms_deg_sparse_vs_step", c.rms_deg_sparse_vs_step},
          {"motoflex_end", c.motoflex_end},
          {"geoms", c.geoms},
          {"visual_geoms", c.visual_geoms}};
}

const Exporter& check_arguments(const ExportArgs& args) {
  const Exporter* exporter = find_exporter(args.format);
  if (exporter == nullptr) {
    throw InputError("", 0, "--format", "expected one of " + exporter_formats());
  }
  if (!args.check_log.empty() && args.format != "mjcf") {
    throw InputError("", 0, "--check-mujoco", "needs --format mjcf");
  }
  if (!args.render_png.empty() && args.format != "mjcf") {
    throw InputError("", 0, "--render", "needs --format mjcf");
  }
  if (!(args.dt_s > 0.0 && args.dt_s <= 0.01)) {
    throw InputError("", 0, "--dt", "must be in (0, 0.01] s");
  }
  if (!(args.settle_s >= 0.0)) throw InputError("", 0, "--settle", "must be >= 0");
  if (!(args.duration_s >= 0.0)) throw InputError("", 0, "--duration", "must be >= 0");
  if (!std::filesystem::exists(std::filesystem::path(args.robot) / "robot.yaml")) {
    throw InputError(args.robot, 0, "--robot", "no robot.yaml in this folder");
  }
  return *exporter;
}

// Writes the file (atomically) with its meshes and returns what its parser complained about
// ("" = accepted).
// Torque terms found by the loop's discovery (joint.<J>.term_*) act only in motoflex's rollout:
// no exported format has a place for them but the JSON, so a file that drops them is said so.
void warn_dropped_discovered_terms(const ParameterSet& parameters, const std::string& format) {
  if (format == "json") return;
  const ParameterRegistry& registry = parameters.registry();
  for (std::size_t i = 0; i < registry.size(); ++i) {
    const std::string& name = registry.spec(i).name;
    if (name.find(".term_") == std::string::npos || parameters.get(i) == 0.0) continue;
    std::fprintf(stderr,
                 "motoflex: warning: %s = %g: a discovered torque term, which the %s export "
                 "drops (only the json export keeps it)\n",
                 name.c_str(), parameters.get(i), format.c_str());
  }
}

std::string write_checked_file(const Exporter& exporter, const ExportInput& input,
                               const ExportArgs& args, ExportedFile& file) {
  ExportOptions options;
  options.armature = !args.no_armature;
  file = exporter.write(input, options);
  const std::string complaint = exporter.read_back_errors(file);
  write_exported_file(file, args.out);
  return complaint;
}

int run(const ExportArgs& args) {
  const Exporter& exporter = check_arguments(args);
  StructureOptions structure;
  structure.flex_sub_bodies = args.flex_sub_bodies;
  const RobotModel model = load_robot(args.robot, structure);
  std::string servo = model.default_servo;
  if (!args.servo.empty()) {
    check_servo_parameters(model, args.servo, "", 0, "--servo");
    servo = args.servo;
  }
  ExportInput input{model, ParameterSet(model.parameters), servo, {}, args.dt_s};
  input.provenance = read_fitted_parameters(args.parameters, model.name, input.parameters);
  warn_dropped_discovered_terms(input.parameters, args.format);

  // The check's log may carry per-log conditions (a bench's mass or firmware gain): the export
  // is then made for those conditions, so that the file checked is the file written.
  std::map<std::string, double> log_parameters;
  CommandTrajectory commands;
  if (!args.check_log.empty()) {
    commands =
        read_commands(model, args.check_log, args.duration_s, input.parameters, log_parameters);
  }

  std::string parser_complaint;
  ExportedFile file;
  try {
    parser_complaint = write_checked_file(exporter, input, args, file);
  } catch (const ModelError& error) {
    std::fprintf(stderr, "motoflex: cannot export: %s\n", error.what());
    return 1;
  }
  if (!parser_complaint.empty()) {
    std::fprintf(stderr, "motoflex: %s rejects the %s export %s: %s\n",
                 exporter.reader_name().c_str(), args.format.c_str(), args.out.c_str(),
                 parser_complaint.c_str());
    return 1;
  }

  nlohmann::ordered_json summary;
  summary["format"] = args.format;
  summary["out"] = args.out;
  summary["robot"] = model.name;
  summary["servo"] = servo;
  summary["parameters"] = args.parameters;
  summary["read_back_by"] = exporter.reader_name();
  if (!log_parameters.empty()) summary["log_parameters"] = log_parameters;
  summary["meshes"] = file.assets.size();
  if (!args.render_png.empty()) {
    try {
      write_png(render_mjcf(file), args.render_png);
    } catch (const ModelError& error) {
      std::fprintf(stderr, "motoflex: cannot render the export: %s\n", error.what());
      return 1;
    }
    summary["render"] = args.render_png;
  }
  if (!args.check_log.empty()) {
    MujocoCheckOptions options;
    options.settle_s = args.settle_s;
    options.hold_torso = args.hold_torso;
    options.armature = !args.no_armature;
    options.flex_sub_bodies = args.flex_sub_bodies;
    MujocoComparison comparison;
    try {
      comparison = compare_with_mujoco(input, commands, options);
    } catch (const ModelError& error) {
      std::fprintf(stderr, "motoflex: MuJoCo check failed: %s\n", error.what());
      return 1;
    }
    summary["check_log"] = args.check_log;
    summary["hold_torso"] = args.hold_torso;
    const nlohmann::ordered_json check = comparison_json(comparison);
    for (const auto& [key, value] : check.items()) summary[key] = value;
  }
  std::printf("%s\n", summary.dump().c_str());
  return 0;
}

}  // namespace

CommandRunner add_export_command(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* sub = app.add_subcommand(
      "export", "write fitted parameters as JSON, URDF, SDF or MJCF, checked by their parsers");
  sub->add_option("parameters", args->parameters, "best.json of a fit, or a parameter JSON")
      ->required();
  sub->add_option("--robot", args->robot, "robot folder (robot.yaml + URDF)")->required();
  sub->add_option("--format", args->format, exporter_formats())->required();
  sub->add_option("--out", args->out, "output file")->required();
  sub->add_option("--servo", args->servo,
                  "servo law the parameters belong to (default: the robot's)");
  sub->add_option("--flex-sub-bodies", args->flex_sub_bodies,
                  "split flexible links into N sub-bodies (SDF/MJCF; default 1 = rigid)")
      ->check(CLI::Range(1, 64));
  sub->add_option("--dt", args->dt_s, "physics step in s (default 0.001)")
      ->check(positive_seconds());
  sub->add_option("--check-mujoco", args->check_log,
                  "mjcf: replay this log's commands in motoflex and MuJoCo and compare angles");
  sub->add_flag("--hold-torso", args->hold_torso,
                "check: hold the torso in the air (root welded in MuJoCo)");
  sub->add_option("--settle", args->settle_s, "check: hold the first pose this long first (s)")
      ->check(non_negative_seconds());
  sub->add_option("--duration", args->duration_s, "check: only the first S seconds of the log")
      ->check(positive_seconds());
  sub->add_option("--render", args->render_png,
                  "mjcf: draw the export with MuJoCo's offscreen renderer (OSMesa) into this PNG");
  sub->add_flag("--no-armature", args->no_armature,
                "mjcf: leave the armature out (motoflex's ODE joints have none)");
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
