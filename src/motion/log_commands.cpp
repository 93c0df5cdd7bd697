#include "motoflex/motion/log_commands.hpp"

#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/io/motoflex_command_file.hpp"

namespace motoflex {

CommandTrajectory read_log_commands(const RobotModel& model, const std::string& path,
                                    ParameterSet& parameters,
                                    std::map<std::string, double>& log_parameters,
                                    std::string* description) {
  JointLog log;
  if (is_motoflex_command_file(path)) {
    // The 2011 program's own command files replay directly, with its playback clock (the
    // importer's default; `motoflex import-motoflex` writes the same log to disk).
    log = import_motoflex_commands(path);
    for (const std::string& joint : model.actuator_names()) {
      if (!log.joint_index(joint)) {
        throw InputError(
            path, 1, joint,
            "not in this MoToFlex command file (robot " + model.name + " actuates it)");
      }
    }
  } else {
    JointLogRequirements requirements;
    requirements.need_commanded = true;
    requirements.joints = model.actuator_names();
    log = read_joint_log(path, requirements);
  }
  if (!log.meta.robot.empty() && log.meta.robot != model.name) {
    throw InputError(joint_log_sidecar_path(path), 0, "robot",
                     "log is of robot '" + log.meta.robot + "', the model is '" + model.name + "'");
  }
  for (const auto& [name, value] : log.meta.parameters) {
    if (!parameters.registry().contains(name)) {
      throw InputError(joint_log_sidecar_path(path), 0, "parameters." + name,
                       "unknown parameter for robot " + model.name);
    }
    parameters.set(name, value);
    log_parameters[name] = value;
  }
  const std::size_t n = model.actuators.size();
  std::vector<double> angles(log.frames() * n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t column = *log.joint_index(model.actuators[j].name);
    for (std::size_t f = 0; f < log.frames(); ++f) angles[f * n + j] = log.commanded(f, column);
  }
  if (description != nullptr) {
    *description = log.meta.motion.empty() ? "replay of " + path : log.meta.motion;
  }
  CommandTrajectory trajectory(log.time_s, std::move(angles), n);
  if (!log.supply_v.empty()) trajectory.set_supply_v(log.supply_v);
  return trajectory;
}

CommandTrajectory truncate_trajectory(const CommandTrajectory& in, double duration_s) {
  std::vector<double> times, angles;
  for (std::size_t f = 0; f < in.frames(); ++f) {
    if (in.time_s(f) - in.start_s() > duration_s + 1e-9) break;
    times.push_back(in.time_s(f));
    for (std::size_t j = 0; j < in.joints(); ++j) angles.push_back(in.angle_rad(f, j));
  }
  const std::size_t kept = times.size();
  CommandTrajectory out(std::move(times), std::move(angles), in.joints());
  if (in.has_supply()) {
    // Already smoothed over the whole log: keep those values rather than re-average the cut.
    out.set_smoothed_supply_v(std::vector<double>(
        in.supply_v().begin(), in.supply_v().begin() + static_cast<std::ptrdiff_t>(kept)));
  }
  return out;
}

}  // namespace motoflex
