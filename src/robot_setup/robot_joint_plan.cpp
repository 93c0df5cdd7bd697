#include "robot_joint_plan.hpp"

#include <cmath>

#include "motoflex/core/number_text.hpp"

namespace motoflex::detail {
namespace {

// Mass of `link` and everything welded to it by fixed joints (frame links weigh nothing).
double welded_mass_kg(const UrdfTree& tree, int link) {
  double mass = tree.links[link].is_frame_link() ? 0.0 : tree.links[link].mass_kg;
  for (const int j : tree.links[link].child_joints) {
    if (tree.joints[j].type == UrdfJointType::kFixed)
      mass += welded_mass_kg(tree, tree.joints[j].child_link);
  }
  return mass;
}

double subtree_mass_kg(const UrdfTree& tree, int link) {
  double mass = tree.links[link].is_frame_link() ? 0.0 : tree.links[link].mass_kg;
  for (const int j : tree.links[link].child_joints)
    mass += subtree_mass_kg(tree, tree.joints[j].child_link);
  return mass;
}

// The joint after `joint` that can share a universal joint with it: the only movable joint of
// its child, revolute like it, at the same point, with an orthogonal axis.
int universal_partner(const UrdfTree& tree, int joint) {
  const UrdfJoint& first = tree.joints[joint];
  if (first.type != UrdfJointType::kRevolute) return -1;
  int partner = -1;
  for (const int j : tree.links[first.child_link].child_joints) {
    if (!tree.joints[j].movable()) continue;
    if (partner >= 0) return -1;
    partner = j;
  }
  if (partner < 0) return -1;
  const UrdfJoint& second = tree.joints[partner];
  const Eigen::Vector3d axis = second.X_PJ.linear() * second.axis_J;
  const bool crossing = second.type == UrdfJointType::kRevolute && !second.mimic &&
                        second.X_PJ.translation().norm() <= 1e-9 &&
                        std::abs(first.axis_J.dot(axis)) <= 1e-6;
  return crossing ? partner : -1;
}

double midpoint_if_zero_outside(const UrdfJoint& joint, const std::pair<double, double>& limits) {
  if (!joint.limited || (limits.first <= 0.0 && 0.0 <= limits.second)) return 0.0;
  return 0.5 * (limits.first + limits.second);
}

}  // namespace

JointPlan plan_joints(const UrdfTree& tree, std::vector<Assumption>& assumptions) {
  JointPlan plan;
  std::vector<std::string> frame_links;
  for (const UrdfLink& link : tree.links) {
    const bool welded =
        link.parent_joint >= 0
            ? tree.joints[link.parent_joint].type == UrdfJointType::kFixed
            : !link.child_joints.empty() &&
                  tree.joints[link.child_joints.front()].type == UrdfJointType::kFixed;
    if (link.is_frame_link() && welded) {
      frame_links.push_back(link.name);
    }
  }
  if (!frame_links.empty()) {
    std::string names;
    for (std::size_t i = 0; i < frame_links.size() && i < 6; ++i)
      names += (i ? ", " : "") + frame_links[i];
    if (frame_links.size() > 6) names += ", ... (" + std::to_string(frame_links.size()) + ")";
    assumptions.push_back(
        {"frame links", "lumped into their parents", names + ": no mass of their own"});
  }
  for (const std::string& name : tree.joint_document_order) {
    const int j = tree.joint_index(name);
    if (j < 0 || !tree.joints[j].movable()) continue;
    const UrdfJoint& joint = tree.joints[j];
    if (joint.mimic) {
      assumptions.push_back(
          {name, "not actuated", "follows '" + joint.mimic->joint + "' (URDF <mimic>)"});
      continue;
    }
    const ScreenedJoint screened = screen_urdf_joint(joint);
    assumptions.insert(assumptions.end(), screened.assumptions.begin(), screened.assumptions.end());
    std::pair<double, double> limits{joint.lower_rad, joint.upper_rad};
    if (screened.limits) {
      limits = *screened.limits;
      plan.joint_limits.emplace_back(name, limits);
    }
    const double start = midpoint_if_zero_outside(joint, limits);
    if (welded_mass_kg(tree, joint.child_link) <= 0.0) {
      if (subtree_mass_kg(tree, joint.child_link) <= 0.0) {
        plan.held.emplace_back(name, start);
        assumptions.push_back(
            {name, "held at " + short_number_text(start), "moves only massless links"});
        continue;
      }
      const int partner = universal_partner(tree, j);
      if (partner >= 0) {
        plan.universal_pairs.emplace_back(name, tree.joints[partner].name);
        assumptions.push_back({name, "universal with " + tree.joints[partner].name,
                               "its child link is massless; the axes cross at right angles"});
      }
    }
    plan.actuated.push_back(name);
    plan.hints[name] = screened.hints;
    if (start != 0.0) {
      plan.stand_pose.emplace_back(name, start);
      assumptions.push_back(
          {name + " stand pose", short_number_text(start), "0 is outside its limits: mid-range"});
    }
  }
  return plan;
}

}  // namespace motoflex::detail
