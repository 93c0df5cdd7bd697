#pragma once

// Internal to the model loader: robot.yaml's sections as plain values, each read on its own
// so a file with several problems reports all of them (the format: scenarios/robots/README.md).

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "motoflex/core/error_collector.hpp"
#include "motoflex/io/yaml_reader.hpp"

namespace motoflex::detail {

struct RobotYaml {
  std::string name;
  std::string urdf_path;  // resolved; empty when robot.yaml does not name a URDF
  std::string root_link;  // empty: the URDF's base
  std::string torso_link;
  bool fixed_base = false;
  std::string servo = "ideal";
  int servo_line = 0;
  struct Actuated {
    std::string joint;
    std::string group;
    YamlValue where;
  };
  std::vector<Actuated> actuated;
  struct ServoEntry {
    std::string key;  // an actuated joint or a group
    std::string law;
    YamlValue where;
  };
  std::vector<ServoEntry> servos;
  std::map<std::string, double> held;
  std::vector<std::pair<std::string, std::string>> universal_pairs;
  std::vector<std::string> flexible_links;
  bool flexible_split_box = false;  // `flexible_split: box` (default `span`)
  std::vector<std::string> feet;
  std::vector<std::string> contact_links;
  std::vector<std::string> trimesh_links;
  std::vector<std::string> capsule_links;
  bool joint_stops = true;
  bool ground = true;
  struct Limits {
    std::string joint;
    double lower = 0.0;
    double upper = 0.0;
    YamlValue where;
  };
  std::vector<Limits> joint_limits;  // replace the URDF's (rad or m)
  double max_tilt_rad = 1.0;
  double min_torso_height_m = 0.0;
  double initial_clearance_m = 0.001;
  std::map<std::string, double> stand_pose;
};

// Reads every section of robot.yaml's root mapping; each problem goes to `errors` and leaves
// that section at its default.
RobotYaml read_robot_yaml(const YamlValue& root, ErrorCollector& errors);

}  // namespace motoflex::detail
