#include "robot_yaml_check.hpp"

#include <cmath>
#include <set>

namespace motoflex::detail {
namespace {

// Runs `check` for each item; the items it reports a problem for are dropped.
template <typename Item, typename Check>
void keep_valid(std::vector<Item>& items, ErrorCollector& errors, Check check) {
  std::vector<Item> kept;
  for (Item& item : items) {
    if (errors.check([&] { check(item); })) kept.push_back(std::move(item));
  }
  items = std::move(kept);
}

struct Checker {
  RobotYaml& spec;
  const UrdfTree& tree;
  const YamlValue& root;
  ErrorCollector& errors;
  std::set<std::string> actuated;

  YamlValue where(const char* key) const { return root.find(key) ? root.at(key) : root; }

  int movable_joint(const YamlValue& at, const std::string& name) const {
    const int j = tree.joint_index(name);
    if (j < 0) at.fail("joint '" + name + "' is not in the URDF");
    if (!tree.joints[j].movable()) {
      at.fail("joint '" + name + "' is not revolute, continuous or prismatic");
    }
    return j;
  }

  void check_links(const char* key, std::vector<std::string>& links) const {
    keep_valid(links, errors, [&](const std::string& link) {
      if (tree.link_index(link) < 0) where(key).fail("link '" + link + "' is not in the URDF");
    });
  }

  void check_base();
  void check_actuated();
  void check_held();
  void check_universal_pairs();
  void check_servos();
  void check_stand_pose();
};

void Checker::check_base() {
  const std::string base = tree.links[tree.root_link].name;
  errors.check([&] {
    if (!spec.root_link.empty() && spec.root_link != base) {
      root.at("root_link").fail("the URDF's base link is '" + base + "'");
    }
  });
  spec.root_link = base;
  if (spec.torso_link.empty()) spec.torso_link = base;
  errors.check([&] {
    if (tree.link_index(spec.torso_link) < 0) {
      where(root.find("torso_link") ? "torso_link" : "root_link")
          .fail("link '" + spec.torso_link + "' is not in the URDF");
    }
  });
  if (tree.link_index(spec.torso_link) < 0) spec.torso_link = base;
}

void Checker::check_actuated() {
  keep_valid(spec.actuated, errors, [&](const RobotYaml::Actuated& a) {
    const int j = movable_joint(a.where.at("joint"), a.joint);
    if (const auto& mimic = tree.joints[j].mimic) {
      a.where.at("joint").fail("joint '" + a.joint + "' follows '" + mimic->joint +
                               "' (URDF <mimic>): it is driven through its leader and cannot "
                               "have an actuator of its own");
    }
    if (!actuated.insert(a.joint).second) a.where.fail("joint listed twice");
  });
}

void Checker::check_held() {
  for (auto it = spec.held.begin(); it != spec.held.end();) {
    const auto& [joint, angle] = *it;
    const bool ok = errors.check([&, &joint = joint, angle = angle] {
      const YamlValue at = root.at("held_joints").at(joint);
      const UrdfJoint& tj = tree.joints[movable_joint(at, joint)];
      if (actuated.count(joint)) at.fail("a joint cannot be both actuated and held");
      if (tj.limited && (angle < tj.lower_rad - 1e-9 || angle > tj.upper_rad + 1e-9)) {
        at.fail("hold angle outside the URDF limits");
      }
      if (tj.mimic && !spec.held.count(tj.mimic->joint)) {
        at.fail("joint '" + joint + "' follows '" + tj.mimic->joint +
                "' (URDF <mimic>): hold its leader, not the follower");
      }
    });
    it = ok ? std::next(it) : spec.held.erase(it);
  }
  // A follower of a held leader is held where the coupling puts it.
  for (const UrdfJoint& joint : tree.joints) {
    if (!joint.mimic || spec.held.count(joint.name)) continue;
    const auto leader = spec.held.find(joint.mimic->joint);
    if (leader == spec.held.end()) continue;
    spec.held[joint.name] = joint.mimic->multiplier * leader->second + joint.mimic->offset;
  }
}

void Checker::check_universal_pairs() {
  keep_valid(spec.universal_pairs, errors, [&](const std::pair<std::string, std::string>& pair) {
    const auto& [first, second] = pair;
    const YamlValue at = root.at("universal_joints");
    const int a = movable_joint(at, first);
    const int b = movable_joint(at, second);
    if (tree.joints[a].type != UrdfJointType::kRevolute ||
        tree.joints[b].type != UrdfJointType::kRevolute) {
      at.fail("universal pair [" + first + ", " + second + "] must be revolute joints");
    }
    if (!actuated.count(first) || !actuated.count(second)) {
      at.fail("universal pair [" + first + ", " + second + "] must be actuated joints");
    }
    if (tree.joints[b].parent_link != tree.joints[a].child_link) {
      at.fail("'" + second + "' must be the child joint of '" + first + "''s link");
    }
    if (tree.joints[b].X_PJ.translation().norm() > 1e-9) {
      at.fail("the axes of [" + first + ", " + second + "] do not intersect");
    }
    const Eigen::Vector3d axis_b = tree.joints[b].X_PJ.linear() * tree.joints[b].axis_J;
    if (std::abs(tree.joints[a].axis_J.dot(axis_b)) > 1e-6) {
      at.fail("the axes of [" + first + ", " + second + "] are not orthogonal");
    }
  });
}

void Checker::check_servos() {
  std::set<std::string> groups;
  for (const auto& a : spec.actuated) groups.insert(a.group);
  keep_valid(spec.servos, errors, [&](const RobotYaml::ServoEntry& entry) {
    if (!actuated.count(entry.key) && !groups.count(entry.key)) {
      entry.where.fail("'" + entry.key + "' is neither an actuated joint nor a group");
    }
  });
}

void Checker::check_stand_pose() {
  for (auto it = spec.stand_pose.begin(); it != spec.stand_pose.end();) {
    const std::string& joint = it->first;
    const bool ok = errors.check([&] {
      if (!actuated.count(joint)) {
        root.at("stand_pose").at(joint).fail("'" + joint + "' is not an actuated joint");
      }
    });
    it = ok ? std::next(it) : spec.stand_pose.erase(it);
  }
}

}  // namespace

void check_robot_yaml(RobotYaml& spec, const UrdfTree& tree, const YamlValue& root,
                      ErrorCollector& errors) {
  Checker checker{spec, tree, root, errors, {}};
  checker.check_base();
  checker.check_actuated();
  checker.check_held();
  checker.check_stand_pose();
  checker.check_links("flexible_links", spec.flexible_links);
  checker.check_links("feet", spec.feet);
  checker.check_links("contact_links", spec.contact_links);
  checker.check_links("trimesh_links", spec.trimesh_links);
  checker.check_links("capsule_links", spec.capsule_links);
  keep_valid(spec.joint_limits, errors, [&](const RobotYaml::Limits& limits) {
    checker.movable_joint(limits.where, limits.joint);
  });
  checker.check_universal_pairs();
  checker.check_servos();
}

}  // namespace motoflex::detail
