// URDF → UrdfTree with urdfdom, every problem of a link or joint collected (urdfdom itself
// stops at the first and has no line numbers; the XML scan supplies them).

#include <console_bridge/console.h>

#include <urdf_parser/urdf_parser.h>
#include <cmath>
#include <map>
#include <memory>

#include "inertia_check.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/model/urdf_tree.hpp"
#include "urdf_geometry.hpp"
#include "urdf_xml_scan.hpp"

namespace motoflex {
namespace {

using detail::to_isometry;

// Collects urdfdom's messages (it reports through console_bridge and returns null).
class CapturingHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN && first_problem.empty()) {
      first_problem = text;
    }
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors.push_back(text);
  }
  std::string first_problem;
  std::vector<std::string> errors;
};

// A quoted name inside an urdfdom message ("joint 'x'", "link [x]"), if any.
std::string quoted_name(const std::string& text) {
  for (const char* quotes : {"''", "[]", "\"\""}) {
    const auto open = text.find(quotes[0]);
    if (open == std::string::npos) continue;
    const auto close = text.find(quotes[1], open + 1);
    if (close != std::string::npos) return text.substr(open + 1, close - open - 1);
  }
  return {};
}

struct Reader {
  const std::string& path;
  const detail::UrdfXmlScan& scan;
  ErrorCollector& errors;

  int line_of(const std::string& name) const {
    if (const auto it = scan.link_lines.find(name); it != scan.link_lines.end()) return it->second;
    if (const auto it = scan.joint_lines.find(name); it != scan.joint_lines.end()) {
      return it->second;
    }
    return 0;
  }

  UrdfLink read_link(const urdf::Link& link) const;
  UrdfJoint read_joint(const urdf::Joint& joint) const;
};

UrdfLink Reader::read_link(const urdf::Link& link) const {
  UrdfLink out;
  out.name = link.name;
  out.line = line_of(link.name);
  if (link.inertial) {
    const auto& in = *link.inertial;
    const Eigen::Isometry3d X = to_isometry(in.origin);
    Eigen::Matrix3d inertia;
    inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    out.has_inertial = true;
    out.mass_kg = in.mass;
    out.com_L_m = X.translation();
    out.inertia_kg_m2 = X.linear() * inertia * X.linear().transpose();
    const std::string problem = detail::implausible_inertia(in.mass, out.inertia_kg_m2);
    if (!problem.empty()) errors.add(path, out.line, link.name + ".inertial", problem);
  }
  for (std::size_t i = 0; i < link.collision_array.size(); ++i) {
    const auto& collision = link.collision_array[i];
    if (!collision || !collision->geometry) continue;
    const bool capsule = scan.capsule_collisions.count({link.name, static_cast<int>(i)}) > 0;
    std::string problem;
    UrdfCollision shape{detail::shape_from_urdf(*collision->geometry, capsule, path, problem),
                        to_isometry(collision->origin), capsule};
    if (!problem.empty()) {
      errors.add(path, out.line, link.name + ".collision[" + std::to_string(i) + "]", problem);
      continue;
    }
    out.collisions.push_back(std::move(shape));
  }
  for (std::size_t i = 0; i < link.visual_array.size(); ++i) {
    const auto& visual = link.visual_array[i];
    if (!visual || !visual->geometry) continue;
    const bool capsule = scan.capsule_visuals.count({link.name, static_cast<int>(i)}) > 0;
    // A visual that cannot be drawn is the exporters' business, not a simulation problem: a
    // mesh that is not found keeps its URI with an empty path.
    std::string problem;
    UrdfVisual shape{detail::shape_from_urdf(*visual->geometry, capsule, path, problem),
                     to_isometry(visual->origin), visual->material_name, std::nullopt};
    if (visual->material) {
      const auto& c = visual->material->color;
      shape.rgba = Eigen::Vector4d(c.r, c.g, c.b, c.a);
    }
    out.visuals.push_back(std::move(shape));
  }
  return out;
}

UrdfJoint Reader::read_joint(const urdf::Joint& joint) const {
  UrdfJoint out;
  out.name = joint.name;
  out.line = line_of(joint.name);
  switch (joint.type) {
    case urdf::Joint::REVOLUTE:
    case urdf::Joint::CONTINUOUS:
      out.type = UrdfJointType::kRevolute;
      out.continuous = joint.type == urdf::Joint::CONTINUOUS;
      break;
    case urdf::Joint::PRISMATIC:
      out.type = UrdfJointType::kPrismatic;
      break;
    case urdf::Joint::FLOATING:
      out.type = UrdfJointType::kFloating;
      break;
    case urdf::Joint::PLANAR:
      out.type = UrdfJointType::kFixed;  // read on as fixed so the rest can be checked
      errors.add(path, out.line, joint.name + ".type",
                 "planar joints are not supported (model the plane as two prismatic joints and "
                 "a revolute one with massless links between them)");
      break;
    default:
      out.type = UrdfJointType::kFixed;
      break;
  }
  out.X_PJ = to_isometry(joint.parent_to_joint_origin_transform);
  if (out.movable()) {
    const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    if (!(axis.norm() > 1e-9)) {
      errors.add(path, out.line, joint.name + ".axis", "zero axis");
    } else {
      out.axis_J = axis.normalized();
    }
  }
  if (joint.limits) {
    if (out.movable() && !out.continuous) {
      out.limited = true;
      out.lower_rad = joint.limits->lower;
      out.upper_rad = joint.limits->upper;
      if (!(out.lower_rad <= out.upper_rad)) {
        errors.add(path, out.line, joint.name + ".limit", "lower must not exceed upper");
      }
    }
    // urdfdom reads an absent effort or velocity as 0, which no real joint has.
    if (joint.limits->effort > 0.0) out.effort = joint.limits->effort;
    if (joint.limits->velocity > 0.0) out.velocity = joint.limits->velocity;
  }
  if (joint.dynamics) {
    out.damping = joint.dynamics->damping;
    out.friction = joint.dynamics->friction;
  }
  if (joint.mimic && !joint.mimic->joint_name.empty()) {
    out.mimic = UrdfMimic{joint.mimic->joint_name, joint.mimic->multiplier, joint.mimic->offset};
  }
  return out;
}

// A massless root whose only joint is floating is the world frame of a free-floating robot:
// the child is the base. Any other floating joint is an error (one free base per robot).
void choose_root(UrdfTree& tree, ErrorCollector& errors) {
  const UrdfLink& root = tree.links[tree.root_link];
  for (const int j : root.child_joints) {
    const UrdfJoint& joint = tree.joints[j];
    if (joint.type != UrdfJointType::kFloating) continue;
    if (root.child_joints.size() == 1 && root.is_frame_link() && root.collisions.empty()) {
      tree.root_link = joint.child_link;
      return;
    }
  }
  for (UrdfJoint& joint : tree.joints) {
    if (joint.type != UrdfJointType::kFloating) continue;
    errors.add(tree.path, joint.line, joint.name + ".type",
               "a floating joint is only accepted between a massless root link and the robot's "
               "base (motoflex simulates one free base)");
    joint.type = UrdfJointType::kFixed;
  }
}

}  // namespace

UrdfTree read_urdf_tree(const std::string& urdf_path, ErrorCollector& errors) {
  const detail::UrdfXmlScan scan = detail::scan_urdf_xml(urdf_path);
  CapturingHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(scan.text);
  console_bridge::restorePreviousOutputHandler();
  const Reader reader{urdf_path, scan, errors};
  if (!model) {
    const std::string reason =
        handler.first_problem.empty() ? "invalid URDF" : handler.first_problem;
    const std::string name = quoted_name(reason);
    throw InputError(urdf_path, reader.line_of(name), name, reason);
  }
  // urdfdom drops an element it cannot read (a <collision> with a bad shape, ...) with an error
  // message and goes on: each is a problem of the file.
  for (const std::string& message : handler.errors) {
    const std::string name = quoted_name(message);
    errors.add(urdf_path, reader.line_of(name), name, message);
  }

  UrdfTree tree;
  tree.path = urdf_path;
  tree.robot_name = model->getName();
  tree.joint_document_order = scan.joint_order;
  std::map<std::string, int> link_ids;
  for (const auto& [name, link] : model->links_) {
    link_ids[name] = static_cast<int>(tree.links.size());
    tree.links.push_back(reader.read_link(*link));
  }
  for (const auto& [name, joint] : model->joints_) {
    UrdfJoint out = reader.read_joint(*joint);
    out.parent_link = link_ids.at(joint->parent_link_name);
    out.child_link = link_ids.at(joint->child_link_name);
    tree.joints.push_back(std::move(out));
  }
  for (std::size_t j = 0; j < tree.joints.size(); ++j) {
    tree.links[tree.joints[j].parent_link].child_joints.push_back(static_cast<int>(j));
    tree.links[tree.joints[j].child_link].parent_joint = static_cast<int>(j);
  }
  tree.root_link = link_ids.at(model->getRoot()->name);
  choose_root(tree, errors);
  return tree;
}

}  // namespace motoflex
