// The logs of a fit: folders and files listed, BAM JSON folders imported, logs read into fit
// cases for the scenario's robot.

#include <algorithm>
#include <filesystem>

#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/io/bam_import.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/io/yaml_reader.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

bool has_extension(const fs::path& folder, const char* extension) {
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) return true;
  }
  return false;
}

// A folder without *.csv logs is searched for BAM JSON logs, in it and in its subfolders (BAM
// keeps a session in raw/ and processed/), and they are imported into `import_dir`; anything
// else is listed as it is.
std::vector<std::string> logs_of_one(const std::string& folder_or_file, const std::string& field,
                                     const fs::path& import_dir) {
  if (fs::is_directory(folder_or_file) && !has_extension(folder_or_file, ".csv")) {
    const std::vector<BamDirectoryItem> items = import_bam_directory(folder_or_file);
    if (std::none_of(items.begin(), items.end(),
                     [](const BamDirectoryItem& item) { return item.import.has_value(); })) {
      throw InputError(folder_or_file, 0, field,
                       "no *.csv logs in this folder, and no BAM trajectory log in it or below "
                       "it (motoflex import-bam lists what it skipped)");
    }
    std::error_code error;
    fs::create_directories(import_dir, error);
    if (error) {
      throw InputError(import_dir.string(), 0, field, "cannot create: " + error.message());
    }
    for (const BamDirectoryItem& item : items) {
      if (!item.import) continue;
      const fs::path csv = import_dir / (item.output_stem + ".csv");
      write_joint_log(csv.string(), item.import->log);
    }
    return list_logs(import_dir.string(), field);
  }
  return list_logs(folder_or_file, field);
}

}  // namespace

std::vector<std::string> logs_of(const std::vector<LogSource>& sources,
                                 const std::string& import_dir) {
  std::vector<std::string> out;
  for (const LogSource& source : sources) {
    for (auto& log : logs_of_one(source.path, source.where.field, import_dir)) {
      out.push_back(std::move(log));
    }
  }
  return out;
}

std::vector<std::string> list_logs(const std::string& folder_or_file, const std::string& field) {
  std::vector<std::string> logs;
  if (fs::is_regular_file(folder_or_file)) return {fs::absolute(folder_or_file).lexically_normal()};
  if (!fs::is_directory(folder_or_file)) {
    throw InputError(folder_or_file, 0, field, "no such log folder or file");
  }
  for (const auto& entry : fs::directory_iterator(folder_or_file)) {
    if (entry.is_regular_file() && entry.path().extension() == ".csv") {
      logs.push_back(fs::absolute(entry.path()).lexically_normal());
    }
  }
  std::sort(logs.begin(), logs.end());
  if (logs.empty()) throw InputError(folder_or_file, 0, field, "no *.csv logs in this folder");
  return logs;
}

namespace {

// The frames within the first window_s seconds of a log (all of them for window_s = 0).
std::size_t frames_in_window(const JointLog& log, double window_s, const std::string& path) {
  if (!(window_s > 0.0)) return log.frames();
  std::size_t frames = 0;
  while (frames < log.frames() && log.time_s[frames] - log.time_s[0] <= window_s + 1e-9) {
    ++frames;
  }
  if (frames < 2) {
    throw InputError(path, 0, "fitness.window_s",
                     "window of " + std::to_string(window_s) + " s keeps fewer than 2 frames");
  }
  return frames;
}

}  // namespace

std::vector<FitCase> load_fit_cases(const Scenario& scenario,
                                    const std::vector<std::string>& log_paths,
                                    const FitnessOptions& fitness) {
  const bool need_imu = fitness.imu_weight > 0.0;
  const double window_s = fitness.window_s;
  const RobotModel& model = *scenario.model;
  const std::size_t n = model.actuators.size();
  std::vector<FitCase> cases;
  for (const auto& path : log_paths) {
    // A log of another robot is named as such before its columns are checked.
    const std::string sidecar = joint_log_sidecar_path(path);
    if (fs::exists(sidecar)) {
      const YamlValue meta = YamlValue::load_file(sidecar);
      const std::string robot = meta.is_map() ? meta.get_string("robot", "") : "";
      if (!robot.empty() && robot != model.name) {
        throw InputError(
            sidecar, meta.at("robot").line(), "robot",
            "log of robot '" + robot + "', but the fit's scenario simulates '" + model.name + "'");
      }
    }
    JointLogRequirements requirements;
    requirements.need_commanded = true;
    requirements.need_measured = true;
    requirements.joints = model.actuator_names();
    const JointLog log = read_joint_log(path, requirements);
    if (!log.meta.robot.empty() && log.meta.robot != model.name) {
      throw InputError(joint_log_sidecar_path(path), 0, "robot",
                       "log of robot '" + log.meta.robot + "', but the fit's scenario simulates '" +
                           model.name + "'");
    }
    FitCase fit_case;
    fit_case.name = fs::path(path).stem().string();
    const std::size_t frames = frames_in_window(log, window_s, path);
    std::vector<double> time_s(log.time_s.begin(),
                               log.time_s.begin() + static_cast<std::ptrdiff_t>(frames));
    std::vector<double> commanded(frames * n), measured(frames * n);
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t column = *log.joint_index(model.actuators[j].name);
      for (std::size_t f = 0; f < frames; ++f) {
        commanded[f * n + j] = log.commanded(f, column);
        measured[f * n + j] = log.measured(f, column);
      }
    }
    fit_case.commands = CommandTrajectory(std::move(time_s), std::move(commanded), n);
    if (!log.supply_v.empty()) {
      // Smoothed over the whole log, then cut to the window like the angles.
      std::vector<double> supply = CommandTrajectory::smoothed_supply_v(log.time_s, log.supply_v);
      supply.resize(frames);
      fit_case.commands.set_smoothed_supply_v(std::move(supply));
    }
    fit_case.measured_rad = std::move(measured);
    if (!log.imu_roll_rad.empty() && !log.imu_pitch_rad.empty()) {
      fit_case.measured_imu_rad.resize(2 * frames);
      for (std::size_t f = 0; f < frames; ++f) {
        fit_case.measured_imu_rad[2 * f] = log.imu_roll_rad[f];
        fit_case.measured_imu_rad[2 * f + 1] = log.imu_pitch_rad[f];
      }
    } else if (need_imu) {
      throw InputError(path, 1, log.imu_roll_rad.empty() ? "imu.roll" : "imu.pitch",
                       "missing column: the fit scores the IMU (fitness.imu_weight > 0)");
    }
    fit_case.options = scenario.rollout;
    for (const auto& [name, value] : log.meta.parameters) {
      const auto index = model.parameters.find(name);
      if (!index) {
        throw InputError(joint_log_sidecar_path(path), 0, "parameters." + name,
                         "unknown parameter for robot " + model.name);
      }
      fit_case.parameter_overrides.emplace_back(*index, value);
    }
    cases.push_back(std::move(fit_case));
  }
  return cases;
}

}  // namespace motoflex
