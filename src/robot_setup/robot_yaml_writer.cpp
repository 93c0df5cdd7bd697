#include "robot_yaml_writer.hpp"

#include <sstream>

#include "motoflex/core/number_text.hpp"

namespace motoflex::detail {
namespace {

// A name as a YAML scalar: plain when it is safe, double-quoted otherwise.
std::string scalar(const std::string& text) {
  bool plain = !text.empty();
  for (const char c : text) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '.' || c == '-' || c == '/';
    plain = plain && ok;
  }
  if (plain && text.front() != '-' && text != "true" && text != "false" && text != "null") {
    return text;
  }
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

std::string list(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + scalar(items[i]);
  return out + "]";
}

}  // namespace

std::string robot_yaml_text(const RobotFolderSpec& spec) {
  std::ostringstream out;
  std::istringstream header(spec.header);
  for (std::string line; std::getline(header, line);) out << "# " << line << "\n";
  out << "name: " << scalar(spec.name) << "\n";
  out << "urdf: " << scalar(spec.urdf) << "\n";
  out << "root_link: " << scalar(spec.base_link) << "\n";
  out << "fixed_base: " << (spec.fixed_base ? "true" : "false") << "\n";
  out << "torso_link: " << scalar(spec.base_link) << "\n";
  out << "ground: " << (spec.ground ? "true" : "false")
      << (spec.ground ? "\n" : "                  # mounted: no floor to touch or fall onto\n");
  out << "servo: " << scalar(spec.servo) << "\n";
  if (!spec.servos.empty()) out << "servos:                        # joints under another law\n";
  for (const auto& [joint, law] : spec.servos)
    out << "  " << scalar(joint) << ": " << scalar(law) << "\n";
  out << "actuated_joints:               # column order of the joint logs\n";
  for (const auto& joint : spec.actuated) {
    out << "  - {joint: " << scalar(joint) << ", group: " << scalar(joint) << "}\n";
  }
  out << "held_joints:" << (spec.held.empty() ? " {}" : "") << "\n";
  for (const auto& [joint, angle] : spec.held) {
    out << "  " << scalar(joint) << ": " << number_text(angle) << "\n";
  }
  out << "universal_joints:" << (spec.universal_pairs.empty() ? " []" : "") << "\n";
  for (const auto& [first, second] : spec.universal_pairs) {
    out << "  - [" << scalar(first) << ", " << scalar(second) << "]\n";
  }
  out << "flexible_links: []\n";
  out << "feet: " << list(spec.feet) << "\n";
  if (!spec.joint_limits.empty()) {
    out << "joint_limits:                  # replace the URDF's placeholder limits\n";
    for (const auto& [joint, range] : spec.joint_limits) {
      out << "  " << scalar(joint) << ": [" << number_text(range.first) << ", "
          << number_text(range.second) << "]\n";
    }
  }
  out << "stand_pose:" << (spec.stand_pose.empty() ? " {}" : "") << "\n";
  for (const auto& [joint, angle] : spec.stand_pose) {
    out << "  " << scalar(joint) << ": " << number_text(angle) << "\n";
  }
  out << "fall:\n  max_tilt_rad: 1.0\n  min_torso_height_m: 0.0\n";
  out << "initial_clearance_m: 0.001\n";
  out << "parameters:                    # name: [default, lower, upper]   # where from\n";
  for (const ParameterDefault& p : spec.parameters) {
    out << "  " << p.name << ": [" << number_text(p.value) << ", " << number_text(p.lower) << ", "
        << number_text(p.upper) << "]   # " << p.source << "\n";
  }
  return out.str();
}

}  // namespace motoflex::detail
