#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/number_text.hpp"
#include "motoflex/io/joint_log.hpp"

namespace motoflex {
namespace {

// Shortest text that parses back to exactly `value` (std::to_chars guarantees the round trip),
// or `digits` significant digits when digits > 0.
void append_number(std::string& out, double value, int digits = 0) {
  char buffer[40];
  const auto result = digits > 0 ? std::to_chars(buffer, buffer + sizeof(buffer), value,
                                                 std::chars_format::general, digits)
                                 : std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

[[noreturn]] void reject(const std::string& csv_path, const std::string& reason) {
  throw std::invalid_argument("write_joint_log(" + csv_path + "): " + reason);
}

bool is_valid_joint_name(const std::string& name) {
  if (name.empty() || name.find_first_of(",\r\n") != std::string::npos) return false;
  const auto is_blank = [](char c) { return c == ' ' || c == '\t'; };
  return !is_blank(name.front()) && !is_blank(name.back());
}

void check_finite(const std::string& csv_path, const std::vector<double>& values,
                  const std::string& what) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i]))
      reject(csv_path, what + "[" + std::to_string(i) + "] is not finite");
  }
}

// Everything read_joint_log would reject is rejected here, so a written log always reads back.
void check_log(const std::string& csv_path, const JointLog& log) {
  if (joint_log_sidecar_path(csv_path) == csv_path) {
    reject(csv_path, "the CSV path must not end in .yaml (the sidecar would overwrite it)");
  }
  const std::size_t frames = log.frames();
  const std::size_t joints = log.joints();
  if (frames < 2) reject(csv_path, "a joint log needs at least 2 frames");
  const auto check_size = [&](const std::vector<double>& values, std::size_t expected,
                              const char* name) {
    if (!values.empty() && values.size() != expected) {
      reject(csv_path, std::string(name) + " has " + std::to_string(values.size()) +
                           " values, expected 0 or " + std::to_string(expected));
    }
  };
  check_size(log.commanded_rad, frames * joints, "commanded_rad");
  check_size(log.measured_rad, frames * joints, "measured_rad");
  check_size(log.imu_roll_rad, frames, "imu_roll_rad");
  check_size(log.imu_pitch_rad, frames, "imu_pitch_rad");
  check_size(log.supply_v, frames, "supply_v");
  if (joints > 0 && !log.has_commanded() && !log.has_measured()) {
    reject(csv_path, "joints are named but there are no commanded or measured angles");
  }
  std::set<std::string> names;
  for (const std::string& name : log.joint_names) {
    if (!is_valid_joint_name(name)) reject(csv_path, "invalid joint name '" + name + "'");
    if (!names.insert(name).second) reject(csv_path, "duplicate joint name '" + name + "'");
  }
  check_finite(csv_path, log.time_s, "time_s");
  for (std::size_t i = 1; i < frames; ++i) {
    if (!(log.time_s[i] > log.time_s[i - 1])) {
      reject(csv_path, "time_s must strictly increase (frame " + std::to_string(i) + ")");
    }
  }
  check_finite(csv_path, log.commanded_rad, "commanded_rad");
  check_finite(csv_path, log.measured_rad, "measured_rad");
  check_finite(csv_path, log.imu_roll_rad, "imu_roll_rad");
  check_finite(csv_path, log.imu_pitch_rad, "imu_pitch_rad");
  check_finite(csv_path, log.supply_v, "supply_v");

  const JointLogMeta& meta = log.meta;
  if (meta.robot.empty()) reject(csv_path, "meta.robot is empty");
  if (!std::isfinite(meta.rate_hz) || meta.rate_hz <= 0.0) {
    reject(csv_path, "meta.rate_hz must be positive and finite");
  }
  if (meta.units != "rad") reject(csv_path, "meta.units must be \"rad\"");
  for (const auto& [name, value] : meta.parameters) {
    if (name.empty()) reject(csv_path, "meta.parameters has an empty name");
    if (!std::isfinite(value)) reject(csv_path, "meta.parameters." + name + " is not finite");
  }
}

std::string format_csv(const JointLog& log, int digits) {
  const std::size_t joints = log.joints();
  std::string out;
  out.reserve(32 + log.frames() * (1 + 2 * joints + 2) * 24);
  out += "time_s";
  for (const std::string& name : log.joint_names) {
    if (log.has_commanded()) out += "," + name + ".cmd";
    if (log.has_measured()) out += "," + name + ".meas";
  }
  if (!log.imu_roll_rad.empty()) out += ",imu.roll";
  if (!log.imu_pitch_rad.empty()) out += ",imu.pitch";
  if (!log.supply_v.empty()) out += ",supply_v";
  out += '\n';
  for (std::size_t frame = 0; frame < log.frames(); ++frame) {
    append_number(out, log.time_s[frame]);
    for (std::size_t joint = 0; joint < joints; ++joint) {
      if (log.has_commanded()) {
        out += ',';
        append_number(out, log.commanded(frame, joint), digits);
      }
      if (log.has_measured()) {
        out += ',';
        append_number(out, log.measured(frame, joint), digits);
      }
    }
    if (!log.imu_roll_rad.empty()) {
      out += ',';
      append_number(out, log.imu_roll_rad[frame], digits);
    }
    if (!log.imu_pitch_rad.empty()) {
      out += ',';
      append_number(out, log.imu_pitch_rad[frame], digits);
    }
    if (!log.supply_v.empty()) {
      out += ',';
      append_number(out, log.supply_v[frame], digits);
    }
    out += '\n';
  }
  return out;
}

// Numbers go through number_text so they round-trip exactly and come out as plain scalars;
// strings go through the emitter, which quotes them when YAML needs it.
std::string format_sidecar(const JointLogMeta& meta) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "robot" << YAML::Value << meta.robot;
  out << YAML::Key << "rate_hz" << YAML::Value << number_text(meta.rate_hz);
  if (!meta.motion.empty()) out << YAML::Key << "motion" << YAML::Value << meta.motion;
  out << YAML::Key << "units" << YAML::Value << meta.units;
  if (!meta.origin.empty()) out << YAML::Key << "origin" << YAML::Value << meta.origin;
  if (!meta.parameters.empty()) {
    out << YAML::Key << "parameters" << YAML::Value << YAML::BeginMap;
    for (const auto& [name, value] : meta.parameters) {
      out << YAML::Key << name << YAML::Value << number_text(value);
    }
    out << YAML::EndMap;
  }
  if (!meta.notes.empty()) out << YAML::Key << "notes" << YAML::Value << meta.notes;
  out << YAML::EndMap;
  if (!out.good()) throw std::logic_error("joint log sidecar: YAML emitter: " + out.GetLastError());
  return std::string(out.c_str(), out.size()) + "\n";
}

}  // namespace

void write_joint_log(const std::string& csv_path, const JointLog& log, int significant_digits) {
  check_log(csv_path, log);
  const std::string csv = format_csv(log, significant_digits);
  const std::string sidecar = format_sidecar(log.meta);
  write_file_atomically(csv_path, csv);
  // Last, so a sidecar on disk means its CSV is complete.
  write_file_atomically(joint_log_sidecar_path(csv_path), sidecar);
}

}  // namespace motoflex
