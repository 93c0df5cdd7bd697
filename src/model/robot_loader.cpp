#include "motoflex/model/robot_loader.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>
#include <set>

#include "kinematic_tree.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "parameter_catalog.hpp"

namespace motoflex {
namespace {

using detail::KinematicTree;
using detail::TreeJointType;

// Disjoint sets over links; links welded together end up in one body.
class LinkGroups {
 public:
  explicit LinkGroups(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(int a, int b) { parent_[find(b)] = find(a); }

 private:
  std::vector<int> parent_;
};

struct RobotYaml {
  std::string name;
  std::string urdf_path;
  std::string root_link;
  std::string torso_link;
  bool fixed_base = false;
  bool joint_stops = true;
  std::string servo;
  int servo_line = 0;
  struct Actuated {
    std::string joint;
    std::string group;
    YamlValue where;
  };
  std::vector<Actuated> actuated;
  std::map<std::string, double> held;
  std::vector<std::pair<std::string, std::string>> universal_pairs;
  std::vector<std::string> flexible_links;
  bool flexible_split_box = false;  // `flexible_split: box` (default `span`)
  std::vector<std::string> feet;
  double max_tilt_rad = 1.0;
  double min_torso_height_m = 0.0;
  double initial_clearance_m = 0.001;
  std::map<std::string, double> stand_pose;
};

RobotYaml read_robot_yaml(const YamlValue& root) {
  root.require_keys_within({"name", "urdf", "root_link", "fixed_base", "torso_link", "servo",
                            "joint_stops", "actuated_joints", "held_joints", "universal_joints",
                            "flexible_links", "flexible_split", "feet", "fall",
                            "initial_clearance_m", "stand_pose", "parameters"});
  RobotYaml out;
  out.name = root.at("name").as_string();
  out.urdf_path = root.resolve_path(root.at("urdf").as_string());
  out.root_link = root.at("root_link").as_string();
  out.torso_link = root.get_string("torso_link", out.root_link);
  out.fixed_base = root.get_bool("fixed_base", false);
  out.joint_stops = root.get_bool("joint_stops", true);
  const YamlValue servo = root.at("servo");
  out.servo = servo.as_string();
  out.servo_line = servo.line();
  for (const YamlValue& item : root.at("actuated_joints").items()) {
    item.require_keys_within({"joint", "group"});
    out.actuated.push_back({item.at("joint").as_string(), item.at("group").as_string(), item});
  }
  if (out.actuated.empty()) root.at("actuated_joints").fail("at least one actuated joint needed");
  if (const auto held = root.find("held_joints")) {
    for (const auto& [joint, angle] : held->entries()) out.held[joint] = angle.as_double();
  }
  if (const auto pairs = root.find("universal_joints")) {
    for (const YamlValue& pair : pairs->items()) {
      const auto names = pair.as_string_list();
      if (names.size() != 2) pair.fail("expected a pair [first_joint, second_joint]");
      out.universal_pairs.emplace_back(names[0], names[1]);
    }
  }
  if (const auto links = root.find("flexible_links")) out.flexible_links = links->as_string_list();
  if (const auto split = root.find("flexible_split")) {
    const std::string how = split->as_string();
    if (how != "span" && how != "box") split->fail("expected 'span' or 'box'");
    out.flexible_split_box = how == "box";
  }
  if (const auto feet = root.find("feet")) out.feet = feet->as_string_list();
  if (const auto fall = root.find("fall")) {
    fall->require_keys_within({"max_tilt_rad", "min_torso_height_m"});
    out.max_tilt_rad = fall->get_double("max_tilt_rad", out.max_tilt_rad);
    out.min_torso_height_m = fall->get_double("min_torso_height_m", out.min_torso_height_m);
  }
  out.initial_clearance_m = root.get_double("initial_clearance_m", out.initial_clearance_m);
  if (const auto pose = root.find("stand_pose")) {
    for (const auto& [joint, angle] : pose->entries()) out.stand_pose[joint] = angle.as_double();
  }
  return out;
}

void check_link(const KinematicTree& tree, const YamlValue& where, const std::string& link) {
  if (tree.link_index(link) < 0) where.fail("link '" + link + "' is not in the URDF");
}

int require_revolute(const KinematicTree& tree, const YamlValue& where, const std::string& joint) {
  const int j = tree.joint_index(joint);
  if (j < 0) where.fail("joint '" + joint + "' is not in the URDF");
  if (tree.joints[j].type != TreeJointType::kRevolute) {
    where.fail("joint '" + joint + "' is not revolute");
  }
  return j;
}

}  // namespace

RobotModel load_robot_model(const std::string& robot_dir, const StructureOptions& structure) {
  if (structure.flex_sub_bodies < 1 || structure.flex_sub_bodies > 16) {
    throw InputError("", 0, "physics.flex_sub_bodies", "must be between 1 and 16");
  }
  const std::string yaml_path = (std::filesystem::path(robot_dir) / "robot.yaml").string();
  const YamlValue root = YamlValue::load_file(yaml_path);
  const RobotYaml spec = read_robot_yaml(root);
  KinematicTree tree = detail::load_urdf_tree(spec.urdf_path);

  // --- validate names against the URDF -------------------------------------------------------
  if (tree.links[tree.root_link].name != spec.root_link) {
    root.at("root_link").fail("the URDF's root link is '" + tree.links[tree.root_link].name + "'");
  }
  check_link(tree, root.find("torso_link") ? root.at("torso_link") : root.at("root_link"),
             spec.torso_link);
  std::set<std::string> actuated_names;
  for (const auto& a : spec.actuated) {
    require_revolute(tree, a.where.at("joint"), a.joint);
    if (!actuated_names.insert(a.joint).second) a.where.fail("joint listed twice");
  }
  for (const auto& [joint, angle] : spec.held) {
    const YamlValue where = root.at("held_joints").at(joint);
    const int j = require_revolute(tree, where, joint);
    if (actuated_names.count(joint)) where.fail("a joint cannot be both actuated and held");
    const auto& tj = tree.joints[j];
    if (tj.limited && (angle < tj.lower_rad - 1e-9 || angle > tj.upper_rad + 1e-9)) {
      where.fail("hold angle outside the URDF limits");
    }
  }
  for (const auto& [joint, angle] : spec.stand_pose) {
    if (!actuated_names.count(joint)) {
      root.at("stand_pose").at(joint).fail("'" + joint + "' is not an actuated joint");
    }
  }
  for (const auto& link : spec.flexible_links) check_link(tree, root.at("flexible_links"), link);
  for (const auto& link : spec.feet) check_link(tree, root.at("feet"), link);
  for (const auto& [first, second] : spec.universal_pairs) {
    const YamlValue where = root.at("universal_joints");
    const int a = require_revolute(tree, where, first);
    const int b = require_revolute(tree, where, second);
    if (!actuated_names.count(first) || !actuated_names.count(second)) {
      where.fail("universal pair [" + first + ", " + second + "] must be actuated joints");
    }
    if (tree.joints[b].parent_link != tree.joints[a].child_link) {
      where.fail("'" + second + "' must be the child joint of '" + first + "''s link");
    }
    if (tree.joints[b].X_PJ.translation().norm() > 1e-9) {
      where.fail("the axes of [" + first + ", " + second + "] do not intersect");
    }
    const Eigen::Vector3d axis_b = tree.joints[b].X_PJ.linear() * tree.joints[b].axis_J;
    if (std::abs(tree.joints[a].axis_J.dot(axis_b)) > 1e-6) {
      where.fail("the axes of [" + first + ", " + second + "] are not orthogonal");
    }
  }

  // --- structure edits -------------------------------------------------------------------------
  for (const auto& link : spec.flexible_links) {
    try {
      if (spec.flexible_split_box) {
        detail::split_flexible_box(tree, link, structure.flex_sub_bodies);
      } else {
        detail::split_flexible_link(tree, link, structure.flex_sub_bodies);
      }
    } catch (const std::invalid_argument& error) {
      root.at("flexible_links").fail(error.what());
    }
  }

  // Build configuration: held joints at their angle, everything else at zero.
  std::vector<double> build_angles(tree.joints.size(), 0.0);
  for (const auto& [joint, angle] : spec.held) build_angles[tree.joint_index(joint)] = angle;
  const auto X_WL = detail::link_poses(tree, build_angles);

  LinkGroups groups(tree.links.size());
  std::set<int> merged_second_joints;   // second joint of each universal pair (if merged)
  std::map<int, int> universal_second;  // first joint → second joint
  for (std::size_t j = 0; j < tree.joints.size(); ++j) {
    const auto& joint = tree.joints[j];
    if (joint.type == TreeJointType::kFixed || spec.held.count(joint.name)) {
      groups.join(joint.parent_link, joint.child_link);
    }
  }
  if (structure.universal_joints) {
    for (const auto& [first, second] : spec.universal_pairs) {
      const int a = tree.joint_index(first);
      const int b = tree.joint_index(second);
      // The link between the two axes is lumped into the child of the second axis.
      groups.join(tree.joints[b].child_link, tree.joints[b].parent_link);
      merged_second_joints.insert(b);
      universal_second[a] = b;
    }
  }

  RobotModel model;
  model.name = spec.name;
  model.directory = robot_dir;
  model.urdf_path = spec.urdf_path;
  model.default_servo = spec.servo;
  model.source.yaml_path = yaml_path;
  model.source.servo_line = spec.servo_line;
  model.structure = structure;
  model.fixed_base = spec.fixed_base;
  model.joint_stops = spec.joint_stops;
  model.max_tilt_rad = spec.max_tilt_rad;
  model.min_torso_height_m = spec.min_torso_height_m;
  model.initial_clearance_m = spec.initial_clearance_m;
  model.stand_pose_rad = spec.stand_pose;

  // Bodies in breadth-first order from the root, so every parent precedes its children.
  std::map<int, int> body_of_group;
  std::vector<int> order{tree.root_link};
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (const int j : tree.links[order[i]].child_joints)
      order.push_back(tree.joints[j].child_link);
  }
  const std::set<std::string> feet(spec.feet.begin(), spec.feet.end());
  for (const int link : order) {
    const int group = groups.find(link);
    auto [it, inserted] = body_of_group.try_emplace(group, static_cast<int>(model.bodies.size()));
    if (inserted) {
      BodySpec body;
      body.name = tree.links[link].name;
      model.bodies.push_back(body);
    }
    model.bodies[it->second].links.push_back(tree.links[link].name);
  }
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    BodySpec& body = model.bodies[b];
    double mass = 0.0;
    Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
    for (const auto& name : body.links) {
      const int l = tree.link_index(name);
      mass += tree.links[l].mass_kg;
      first_moment += tree.links[l].mass_kg * (X_WL[l] * tree.links[l].com_L_m);
    }
    const bool is_static = spec.fixed_base && b == 0;
    if (!(mass > 0.0) && !is_static) {
      throw InputError(spec.urdf_path, 0, body.name,
                       "body made of links {" + body.links.front() + ", ...} has no mass");
    }
    body.is_static = is_static;
    body.mass_kg = mass;
    body.com_W0_m = mass > 0.0
                        ? Eigen::Vector3d(first_moment / mass)
                        : Eigen::Vector3d(X_WL[tree.link_index(body.links.front())].translation());
    for (const auto& name : body.links) {
      const int l = tree.link_index(name);
      const auto& link = tree.links[l];
      const Eigen::Matrix3d R = X_WL[l].linear();
      body.inertia_kg_m2 +=
          R * link.inertia_kg_m2 * R.transpose() +
          detail::parallel_axis(link.mass_kg, X_WL[l] * link.com_L_m - body.com_W0_m);
      const std::string base_name = name.substr(0, name.find('#'));
      for (const auto& box : link.boxes) {
        Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
        X_WB.translation() = body.com_W0_m;
        body.boxes.push_back(
            {name, box.size_m, X_WB.inverse() * X_WL[l] * box.X_LG, feet.count(base_name) > 0});
      }
    }
  }
  model.root_body = 0;
  {
    const int torso_link = tree.link_index(spec.torso_link);
    model.torso_body = body_of_group.at(groups.find(torso_link));
    model.R_torsoBody_torsoLink = X_WL[torso_link].linear();
  }

  // Joints between bodies, in the same breadth-first order.
  std::map<std::string, std::pair<int, int>> actuated_axis;  // joint name → (model joint, axis)
  for (const int link : order) {
    for (const int j : tree.links[link].child_joints) {
      const auto& tj = tree.joints[j];
      if (tj.type == TreeJointType::kFixed || spec.held.count(tj.name) ||
          merged_second_joints.count(j)) {
        continue;
      }
      JointSpec joint;
      joint.name = tj.name;
      joint.parent_body = body_of_group.at(groups.find(tj.parent_link));
      joint.child_body = body_of_group.at(groups.find(tj.child_link));
      const Eigen::Isometry3d X_WJ = X_WL[tj.parent_link] * tj.X_PJ;
      joint.anchor_W0_m = X_WJ.translation();
      joint.axis1_W0 = (X_WJ.linear() * tj.axis_J).normalized();
      // Without joint stops the URDF limits stay on the actuators (planners, exporters) but
      // never become ODE stops.
      if (tj.limited && spec.joint_stops) {
        joint.lower1_rad = tj.lower_rad;
        joint.upper1_rad = tj.upper_rad;
      }
      const int index = static_cast<int>(model.joints.size());
      if (tj.type == TreeJointType::kFlex) {
        joint.kind = JointKind::kFlex;
        joint.axis2_W0 = (X_WJ.linear() * tj.axis2_J).normalized();
      } else if (const auto it = universal_second.find(j); it != universal_second.end()) {
        const auto& second = tree.joints[it->second];
        joint.kind = JointKind::kUniversal;
        joint.name = tj.name + "+" + second.name;
        joint.child_body = body_of_group.at(groups.find(second.child_link));
        const Eigen::Isometry3d X_WJ2 = X_WL[second.parent_link] * second.X_PJ;
        joint.axis2_W0 = (X_WJ2.linear() * second.axis_J).normalized();
        if (second.limited && spec.joint_stops) {
          joint.lower2_rad = second.lower_rad;
          joint.upper2_rad = second.upper_rad;
        }
        actuated_axis[second.name] = {index, 2};
      }
      if (actuated_names.count(tj.name)) actuated_axis[tj.name] = {index, 1};
      model.bodies[joint.child_body].parent_joint = index;
      model.joints.push_back(joint);
    }
  }
  for (const auto& a : spec.actuated) {
    const auto [joint, axis] = actuated_axis.at(a.joint);
    ActuatorSpec actuator;
    actuator.name = a.joint;
    actuator.group = a.group;
    actuator.servo_scope = a.group;
    actuator.joint = joint;
    actuator.axis = axis;
    const auto& tj = tree.joints[tree.joint_index(a.joint)];
    if (tj.limited) {
      actuator.lower_rad = tj.lower_rad;
      actuator.upper_rad = tj.upper_rad;
    }
    const int index = static_cast<int>(model.actuators.size());
    (axis == 1 ? model.joints[joint].actuator1 : model.joints[joint].actuator2) = index;
    model.actuators.push_back(actuator);
  }

  // --- parameters (their names are checked against the servo laws in the sim layer) ---------
  const YamlValue parameters = root.at("parameters");
  model.source.parameters_line = parameters.line();
  for (const auto& [name, value] : parameters.entries()) {
    const auto triple = value.as_double_list();
    if (triple.size() != 3) value.fail("expected [default, lower, upper]");
    if (!(triple[1] < triple[2])) value.fail("lower bound must be below the upper bound");
    if (triple[0] < triple[1] || triple[0] > triple[2]) {
      value.fail("default must lie within [lower, upper]");
    }
    model.parameters.add({name, unit_from_parameter_name(name), triple[0], triple[1], triple[2]});
    model.source.parameter_lines[name] = value.line();
  }
  for (const auto& spec : detail::effect_parameter_specs(model)) {
    if (!model.parameters.contains(spec.name)) model.parameters.add(spec);
  }
  return model;
}

}  // namespace motoflex
