#include "motoflex/robot_setup/robot_folder_tools.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "motoflex/core/number_text.hpp"
#include "motoflex/model/body_kinematics.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {
namespace {

constexpr double kFootTolerance_m = 0.005;
constexpr double kFootToleranceShare = 0.02;

std::string base_link_name(const std::string& name) {
  return name.substr(0, name.find('#'));
}

// Links that have collision geometry somewhere below them (themselves excluded).
std::set<int> links_with_shapes_below(const UrdfTree& tree) {
  std::set<int> out;
  for (std::size_t l = 0; l < tree.links.size(); ++l) {
    if (tree.links[l].collisions.empty()) continue;
    for (int joint = tree.links[l].parent_joint; joint >= 0;
         joint = tree.links[tree.joints[joint].parent_link].parent_joint) {
      out.insert(tree.joints[joint].parent_link);
    }
  }
  return out;
}

std::string counts_text(const std::map<std::string, int>& counts) {
  std::string out;
  for (const auto& [what, n] : counts)
    out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  return out.empty() ? "none" : out;
}

}  // namespace

std::vector<LinkHeight> leaf_link_heights(const UrdfTree& tree, const RobotModel& model,
                                          const std::vector<double>& pose) {
  const std::vector<Eigen::Isometry3d> poses = body_poses(model, pose);
  std::map<std::string, double> lowest;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    for (const CollisionShape& shape : model.bodies[b].collisions) {
      const std::string link = base_link_name(shape.link);
      const double z = lowest_point_z(shape, poses[b]);
      const auto [it, inserted] = lowest.try_emplace(link, z);
      if (!inserted) it->second = std::min(it->second, z);
    }
  }
  const std::set<int> inner = links_with_shapes_below(tree);
  std::vector<LinkHeight> out;
  for (const auto& [link, z] : lowest) {
    const int index = tree.link_index(link);
    if (index >= 0 && !inner.count(index) && std::isfinite(z)) out.push_back({link, z});
  }
  return out;
}

std::vector<std::string> lowest_leaf_links(const UrdfTree& tree, const RobotModel& model,
                                           const std::vector<double>& pose, bool at_robot_bottom) {
  const std::vector<LinkHeight> leaves = leaf_link_heights(tree, model, pose);
  if (leaves.empty()) return {};
  const std::vector<Eigen::Isometry3d> poses = body_poses(model, pose);
  double top = -std::numeric_limits<double>::infinity();
  for (const auto& X : poses) top = std::max(top, X.translation().z());
  double bottom = std::numeric_limits<double>::infinity();
  for (const LinkHeight& leaf : leaves) bottom = std::min(bottom, leaf.lowest_z_m);
  const double tolerance = std::max(kFootTolerance_m, kFootToleranceShare * (top - bottom));
  if (at_robot_bottom && bottom > lowest_shape_point_z(model, poses) + tolerance) return {};
  std::vector<std::string> feet;
  for (const LinkHeight& leaf : leaves) {
    if (leaf.lowest_z_m <= bottom + tolerance) feet.push_back(leaf.link);
  }
  return feet;
}

RolloutResult hold_stand_pose(const RobotModel& model, double duration_s) {
  const ParameterSet parameters(model.parameters);
  const std::vector<double> pose = model.stand_pose_vector();
  std::vector<double> angles = pose;
  angles.insert(angles.end(), pose.begin(), pose.end());
  const CommandTrajectory commands({0.0, duration_s}, angles, pose.size());
  RolloutOptions options;
  options.servo.clear();  // each joint's own law
  options.hold_torso = !model.fixed_base;
  return run_rollout(model, parameters, commands, options);
}

std::vector<std::string> describe_robot(const RobotModel& model) {
  double mass_kg = 0.0;
  std::map<std::string, int> shapes, joints, laws;
  std::set<std::string> feet;
  int missing_visuals = 0;
  for (const BodySpec& body : model.bodies) {
    mass_kg += body.mass_kg;
    for (const CollisionShape& shape : body.collisions) {
      std::string kind = to_string(shape.kind);
      if (shape.kind == ShapeKind::kMesh) {
        kind = shape.hull
                   ? "convex hull (" + std::to_string(shape.hull->vertex_count()) + " vertices)"
                   : "trimesh";
      }
      ++shapes[kind];
      if (shape.is_foot) feet.insert(base_link_name(shape.link));
    }
    for (const VisualShape& visual : body.visuals) {
      missing_visuals += visual.kind == ShapeKind::kMesh && visual.mesh.path.empty();
    }
  }
  const char* names[] = {"hinge", "universal", "flex", "slider"};
  for (const JointSpec& joint : model.joints) {
    ++joints[std::string(names[static_cast<int>(joint.kind)]) + (joint.mimic ? " (mimic)" : "")];
  }
  for (std::size_t a = 0; a < model.actuators.size(); ++a)
    ++laws[actuator_servo_name(model, "", a)];
  std::string feet_text;
  for (const auto& foot : feet) feet_text += (feet_text.empty() ? "" : ", ") + foot;
  return {
      "robot " + model.name + " (" + (model.fixed_base ? "fixed base" : "floating base") +
          (model.ground ? "" : ", no ground") + ")",
      "bodies: " + std::to_string(model.bodies.size()) + ", total mass " +
          short_number_text(mass_kg) + " kg",
      "joints: " + counts_text(joints),
      "actuators: " + std::to_string(model.actuators.size()) + " (" + counts_text(laws) + ")",
      "collision shapes: " + counts_text(shapes),
      "feet: " + (feet_text.empty() ? std::string("none") : feet_text),
      "visual meshes not found: " + std::to_string(missing_visuals),
  };
}

}  // namespace motoflex
