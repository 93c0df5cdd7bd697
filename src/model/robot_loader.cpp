// robot.yaml + URDF → RobotModel, in passes that each report every problem they find: the
// sections of robot.yaml, the URDF's links and joints, robot.yaml's names against the URDF,
// bodies (lumping, shapes), joints and actuators, parameters.

#include "motoflex/model/robot_loader.hpp"

#include <filesystem>

#include "joint_builder.hpp"
#include "kinematic_tree.hpp"
#include "link_lumping.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/urdf_tree.hpp"
#include "robot_parameters.hpp"
#include "robot_yaml.hpp"
#include "robot_yaml_check.hpp"

namespace motoflex {
namespace {

RobotModel model_header(const detail::RobotYaml& spec, const std::string& robot_dir,
                        const std::string& yaml_path, const StructureOptions& structure) {
  RobotModel model;
  model.name = spec.name;
  model.directory = robot_dir;
  model.urdf_path = spec.urdf_path;
  model.default_servo = spec.servo;
  model.source.yaml_path = yaml_path;
  model.source.servo_line = spec.servo_line;
  model.structure = structure;
  model.fixed_base = spec.fixed_base;
  model.max_tilt_rad = spec.max_tilt_rad;
  model.min_torso_height_m = spec.min_torso_height_m;
  model.initial_clearance_m = spec.initial_clearance_m;
  model.joint_stops = spec.joint_stops;
  model.ground = spec.ground;
  model.stand_pose_rad = spec.stand_pose;
  return model;
}

void split_flexible_links(UrdfTree& tree, const detail::RobotYaml& spec, const YamlValue& root,
                          int pieces, ErrorCollector& errors) {
  for (const auto& link : spec.flexible_links) {
    try {
      if (spec.flexible_split_box) {
        detail::split_flexible_box(tree, link, pieces);
      } else {
        detail::split_flexible_link(tree, link, pieces);
      }
    } catch (const std::invalid_argument& error) {
      errors.check([&] { root.at("flexible_links").fail(error.what()); });
    }
  }
}

}  // namespace

std::optional<RobotModel> load_robot_model(const std::string& robot_dir,
                                           const StructureOptions& structure,
                                           ErrorCollector& errors) {
  if (structure.flex_sub_bodies < 1 || structure.flex_sub_bodies > 16) {
    errors.add("", 0, "physics.flex_sub_bodies", "must be between 1 and 16");
    return std::nullopt;
  }
  const std::string yaml_path = (std::filesystem::path(robot_dir) / "robot.yaml").string();
  std::optional<YamlValue> root;
  if (!errors.check([&] { root = YamlValue::load_file(yaml_path); })) return std::nullopt;
  detail::RobotYaml spec = detail::read_robot_yaml(*root, errors);
  if (spec.urdf_path.empty()) return std::nullopt;
  std::optional<UrdfTree> tree;
  if (!errors.check([&] { tree = read_urdf_tree(spec.urdf_path, errors); })) return std::nullopt;
  detail::check_robot_yaml(spec, *tree, *root, errors);
  for (const auto& limits : spec.joint_limits) {
    UrdfJoint& joint = tree->joints[tree->joint_index(limits.joint)];
    joint.limited = true;
    joint.lower_rad = limits.lower;
    joint.upper_rad = limits.upper;
  }
  split_flexible_links(*tree, spec, *root, structure.flex_sub_bodies, errors);

  // Build configuration: held joints at their position, everything else at zero.
  std::vector<double> build_positions(tree->joints.size(), 0.0);
  for (const auto& [joint, position] : spec.held) {
    build_positions[tree->joint_index(joint)] = position;
  }
  const auto X_WL = detail::link_poses(*tree, build_positions);
  const detail::Lumping lumping = detail::lump_links(*tree, spec, structure.universal_joints);

  RobotModel model = model_header(spec, robot_dir, yaml_path, structure);
  model.bodies = detail::build_bodies(*tree, lumping, X_WL, spec, errors);
  model.root_body = 0;
  int torso_link = tree->link_index(spec.torso_link);
  if (lumping.body_of_link[torso_link] < 0) {
    errors.check(
        [&] { root->at("torso_link").fail("'" + spec.torso_link + "' is not below the base"); });
    torso_link = tree->root_link;
  }
  model.torso_body = lumping.body_of_link[torso_link];
  model.R_torsoBody_torsoLink = X_WL[torso_link].linear();
  detail::build_joints(model, *tree, lumping, X_WL, spec, errors);
  detail::read_robot_parameters(*root, model, errors);
  return model;
}

RobotModel load_robot_model(const std::string& robot_dir, const StructureOptions& structure) {
  ErrorCollector errors;
  std::optional<RobotModel> model = load_robot_model(robot_dir, structure, errors);
  errors.throw_if_any();
  return std::move(*model);
}

}  // namespace motoflex
