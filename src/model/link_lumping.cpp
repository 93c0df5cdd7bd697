#include "link_lumping.hpp"

#include <algorithm>
#include <numeric>

#include "collision_meshes.hpp"
#include "kinematic_tree.hpp"

namespace motoflex::detail {
namespace {

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

std::string base_link_name(const std::string& name) {
  return name.substr(0, name.find('#'));
}

GroundContact contact_of(const std::string& link, const RobotYaml& spec) {
  const std::string base = base_link_name(link);
  for (const auto& foot : spec.feet) {
    if (foot == base) return GroundContact::kFoot;
  }
  for (const auto& other : spec.contact_links) {
    if (other == base) return GroundContact::kContact;
  }
  return GroundContact::kFall;
}

bool listed(const std::vector<std::string>& links, const std::string& link) {
  return std::find(links.begin(), links.end(), base_link_name(link)) != links.end();
}

// A body that nothing with mass belongs to cannot be simulated; say which joint moves it.
void report_massless(const UrdfTree& tree, const BodySpec& body, ErrorCollector& errors) {
  std::string links;
  for (const auto& name : body.links) links += (links.empty() ? "" : ", ") + name;
  const UrdfLink& first = tree.links[tree.link_index(body.links.front())];
  if (first.parent_joint < 0 || tree.links[tree.root_link].name == first.name) {
    errors.add(tree.path, first.line, first.name + ".inertial",
               "the base {" + links + "} has no mass (no <inertial>, or at most 1 µg)");
    return;
  }
  const UrdfJoint& joint = tree.joints[first.parent_joint];
  errors.add(tree.path, joint.line, joint.name,
             "joint '" + joint.name + "' moves {" + links +
                 "}, which have no mass (frame links: no <inertial>, or at most 1 µg); give one "
                 "an <inertial>, make the joint fixed, or hold it in robot.yaml");
}

}  // namespace

Lumping lump_links(const UrdfTree& tree, const RobotYaml& spec, bool merge_universal_pairs) {
  Lumping out;
  LinkGroups groups(tree.links.size());
  for (const UrdfJoint& joint : tree.joints) {
    if (joint.type == UrdfJointType::kFixed || spec.held.count(joint.name)) {
      groups.join(joint.parent_link, joint.child_link);
    }
  }
  if (merge_universal_pairs) {
    for (const auto& [first, second] : spec.universal_pairs) {
      const int a = tree.joint_index(first);
      const int b = tree.joint_index(second);
      // The link between the two axes is lumped into the child of the second axis.
      groups.join(tree.joints[b].child_link, tree.joints[b].parent_link);
      out.merged_second_joints.insert(b);
      out.universal_second[a] = b;
    }
  }
  out.order = links_breadth_first(tree, tree.root_link);
  out.body_of_link.assign(tree.links.size(), -1);
  std::map<int, int> body_of_group;
  for (const int link : out.order) {
    const auto [it, inserted] =
        body_of_group.try_emplace(groups.find(link), static_cast<int>(body_of_group.size()));
    out.body_of_link[link] = it->second;
  }
  return out;
}

std::vector<BodySpec> build_bodies(const UrdfTree& tree, const Lumping& lumping,
                                   const std::vector<Eigen::Isometry3d>& X_WL,
                                   const RobotYaml& spec, ErrorCollector& errors) {
  std::vector<BodySpec> bodies;
  for (const int link : lumping.order) {
    const auto b = static_cast<std::size_t>(lumping.body_of_link[link]);
    if (b == bodies.size()) {
      bodies.emplace_back();
      bodies.back().name = tree.links[link].name;
    } else if (tree.links[tree.link_index(bodies[b].name)].is_frame_link() &&
               !tree.links[link].is_frame_link()) {
      // Named after its first physical link, not a frame link lumped into it: a URDF's massless
      // `world` root welded to `base_link` is the body `base_link` (MJCF and SDF reserve "world").
      bodies[b].name = tree.links[link].name;
    }
    bodies[b].links.push_back(tree.links[link].name);
  }
  MeshLibrary meshes;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    BodySpec& body = bodies[b];
    double mass = 0.0;
    Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
    for (const auto& name : body.links) {
      const UrdfLink& link = tree.links[tree.link_index(name)];
      if (link.is_frame_link()) continue;
      mass += link.mass_kg;
      first_moment += link.mass_kg * (X_WL[tree.link_index(name)] * link.com_L_m);
    }
    body.is_static = spec.fixed_base && b == 0;
    if (!(mass > 0.0) && !body.is_static) report_massless(tree, body, errors);
    body.mass_kg = mass;
    body.com_W0_m = mass > 0.0
                        ? Eigen::Vector3d(first_moment / mass)
                        : Eigen::Vector3d(X_WL[tree.link_index(body.links.front())].translation());
    Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
    X_WB.translation() = body.com_W0_m;
    for (const auto& name : body.links) {
      const int l = tree.link_index(name);
      const UrdfLink& link = tree.links[l];
      if (!link.is_frame_link()) {
        const Eigen::Matrix3d R = X_WL[l].linear();
        body.inertia_kg_m2 += R * link.inertia_kg_m2 * R.transpose() +
                              parallel_axis(link.mass_kg, X_WL[l] * link.com_L_m - body.com_W0_m);
      }
      for (const UrdfCollision& collision : link.collisions) {
        CollisionShape shape;
        static_cast<ShapeGeometry&>(shape) = collision.shape;
        shape.link = name;
        shape.X_BG = X_WB.inverse() * X_WL[l] * collision.X_LG;
        shape.contact = contact_of(name, spec);
        shape.is_foot = shape.contact == GroundContact::kFoot;
        if (shape.kind == ShapeKind::kCylinder && listed(spec.capsule_links, name)) {
          shape.kind = ShapeKind::kCapsule;
        }
        if (shape.kind == ShapeKind::kMesh &&
            !meshes.attach(shape, listed(spec.trimesh_links, name), tree.path, link.line, errors)) {
          continue;
        }
        body.collisions.push_back(std::move(shape));
      }
      for (const UrdfVisual& visual : link.visuals) {
        VisualShape shape;
        static_cast<ShapeGeometry&>(shape) = visual.shape;
        shape.link = name;
        shape.X_BG = X_WB.inverse() * X_WL[l] * visual.X_LG;
        shape.material = visual.material;
        shape.rgba = visual.rgba;
        body.visuals.push_back(std::move(shape));
      }
    }
  }
  return bodies;
}

}  // namespace motoflex::detail
