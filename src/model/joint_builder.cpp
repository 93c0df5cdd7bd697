#include "joint_builder.hpp"

#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace motoflex::detail {
namespace {

using AxisOf = std::map<std::string, std::pair<int, int>>;  // URDF joint → (model joint, axis)

void set_limits(const UrdfJoint& tj, bool stops, double& lower, double& upper) {
  if (tj.limited && stops) {
    lower = tj.lower_rad;
    upper = tj.upper_rad;
  }
}

ActuatorSpec make_actuator(const RobotYaml::Actuated& a, const UrdfJoint& tj, int joint, int axis) {
  ActuatorSpec actuator;
  actuator.name = a.joint;
  actuator.group = a.group;
  actuator.servo_scope = a.group;
  actuator.joint = joint;
  actuator.axis = axis;
  actuator.prismatic = tj.type == UrdfJointType::kPrismatic;
  if (tj.limited) {
    actuator.lower_rad = tj.lower_rad;
    actuator.upper_rad = tj.upper_rad;
  }
  actuator.urdf_effort = tj.effort;
  actuator.urdf_velocity = tj.velocity;
  actuator.urdf_damping = tj.damping;
  actuator.urdf_friction = tj.friction;
  return actuator;
}

// robot.yaml `servos:`: a joint's own entry wins over its group's.
void assign_servos(RobotModel& model, const RobotYaml& spec) {
  for (const bool joints_pass : {false, true}) {
    for (const auto& entry : spec.servos) {
      for (ActuatorSpec& actuator : model.actuators) {
        const bool named = joints_pass
                               ? actuator.name == entry.key
                               : actuator.group == entry.key && !model.actuator_index(entry.key);
        if (!named) continue;
        actuator.servo = entry.law;
        actuator.servo_scope = entry.key;
      }
    }
  }
  for (const auto& entry : spec.servos) model.source.servos_lines[entry.key] = entry.where.line();
}

// Couples each <mimic> follower to its first leader that is no follower itself.
void attach_mimics(RobotModel& model, const UrdfTree& tree, const AxisOf& axis_of,
                   ErrorCollector& errors) {
  for (JointSpec& joint : model.joints) {
    const int j = tree.joint_index(joint.name);
    if (j < 0 || !tree.joints[j].mimic) continue;
    MimicSpec mimic;
    const UrdfJoint* follower = &tree.joints[j];
    for (std::size_t hops = 0; follower->mimic; ++hops) {
      const UrdfMimic& m = *follower->mimic;
      const int leader = tree.joint_index(m.joint);
      if (leader < 0 || !tree.joints[leader].movable() || hops > tree.joints.size()) {
        errors.add(tree.path, tree.joints[j].line, joint.name + ".mimic",
                   leader < 0 ? "mimics '" + m.joint + "', which is not in the URDF"
                   : hops > tree.joints.size() ? "mimic couplings form a cycle"
                                               : "mimics '" + m.joint + "', which cannot move");
        mimic.leader_joint = -1;
        break;
      }
      // q = M·q_this + O and q_this = m·q_leader + o give q = M·m·q_leader + M·o + O.
      mimic.offset += mimic.multiplier * m.offset;
      mimic.multiplier *= m.multiplier;
      follower = &tree.joints[leader];
      const auto it = axis_of.find(follower->name);
      if (it != axis_of.end()) std::tie(mimic.leader_joint, mimic.leader_axis) = it->second;
    }
    if (mimic.leader_joint < 0) continue;
    joint.mimic = mimic;
    // The coupling sets where a follower is; its own stops could only fight it (and ODE's
    // powered stop pushes with the motor's unbounded force).
    joint.lower1_rad = -std::numeric_limits<double>::infinity();
    joint.upper1_rad = std::numeric_limits<double>::infinity();
  }
}

}  // namespace

void build_joints(RobotModel& model, const UrdfTree& tree, const Lumping& lumping,
                  const std::vector<Eigen::Isometry3d>& X_WL, const RobotYaml& spec,
                  ErrorCollector& errors) {
  std::set<std::string> actuated;
  for (const auto& a : spec.actuated) actuated.insert(a.joint);
  AxisOf axis_of;
  for (const int link : lumping.order) {
    for (const int j : tree.links[link].child_joints) {
      const UrdfJoint& tj = tree.joints[j];
      if (tj.type == UrdfJointType::kFixed || tj.type == UrdfJointType::kFloating ||
          spec.held.count(tj.name) || lumping.merged_second_joints.count(j)) {
        continue;
      }
      JointSpec joint;
      joint.name = tj.name;
      joint.parent_body = lumping.body_of_link[tj.parent_link];
      joint.child_body = lumping.body_of_link[tj.child_link];
      const Eigen::Isometry3d X_WJ = X_WL[tj.parent_link] * tj.X_PJ;
      joint.anchor_W0_m = X_WJ.translation();
      joint.axis1_W0 = (X_WJ.linear() * tj.axis_J).normalized();
      // Flex joints are springs, never stopped.
      set_limits(tj, spec.joint_stops, joint.lower1_rad, joint.upper1_rad);
      const int index = static_cast<int>(model.joints.size());
      if (tj.type == UrdfJointType::kFlex) {
        joint.kind = JointKind::kFlex;
        joint.axis2_W0 = (X_WJ.linear() * tj.axis2_J).normalized();
      } else if (tj.type == UrdfJointType::kPrismatic) {
        joint.kind = JointKind::kSlider;
      } else if (const auto it = lumping.universal_second.find(j);
                 it != lumping.universal_second.end()) {
        const UrdfJoint& second = tree.joints[it->second];
        joint.kind = JointKind::kUniversal;
        joint.name = tj.name + "+" + second.name;
        joint.child_body = lumping.body_of_link[second.child_link];
        const Eigen::Isometry3d X_WJ2 = X_WL[second.parent_link] * second.X_PJ;
        joint.axis2_W0 = (X_WJ2.linear() * second.axis_J).normalized();
        set_limits(second, spec.joint_stops, joint.lower2_rad, joint.upper2_rad);
        axis_of[second.name] = {index, 2};
      }
      if (tj.type != UrdfJointType::kFlex) axis_of[tj.name] = {index, 1};
      model.bodies[joint.child_body].parent_joint = index;
      model.joints.push_back(joint);
    }
  }
  for (const auto& a : spec.actuated) {
    const auto it = axis_of.find(a.joint);
    if (it == axis_of.end()) continue;  // reported by the robot.yaml check
    const auto [joint, axis] = it->second;
    const int index = static_cast<int>(model.actuators.size());
    (axis == 1 ? model.joints[joint].actuator1 : model.joints[joint].actuator2) = index;
    model.actuators.push_back(
        make_actuator(a, tree.joints[tree.joint_index(a.joint)], joint, axis));
  }
  assign_servos(model, spec);
  attach_mimics(model, tree, axis_of, errors);
}

}  // namespace motoflex::detail
