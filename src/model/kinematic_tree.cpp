#include "kinematic_tree.hpp"

#include <console_bridge/console.h>

#include <urdf_parser/urdf_parser.h>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "motoflex/core/error.hpp"

namespace motoflex::detail {
namespace {

// Collects urdfdom's error messages (it reports through console_bridge and returns null).
class CapturingHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN && first_error.empty()) first_error = text;
  }
  std::string first_error;
};

// The 1-based line of the first `name="<name>"` in the file, or 0 (urdfdom has no line numbers).
int line_of_name(const std::string& path, const std::string& name) {
  if (name.empty()) return 0;
  std::ifstream in(path);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.find("name=\"" + name + "\"") != std::string::npos) return number;
  }
  return 0;
}

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

Eigen::Isometry3d to_isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return X;
}

// An orthonormal pair perpendicular to `along`, preferring the link's own x and y axes.
std::pair<Eigen::Vector3d, Eigen::Vector3d> bending_axes(const Eigen::Vector3d& along) {
  const Eigen::Vector3d s = along.normalized();
  Eigen::Vector3d first = Eigen::Vector3d::UnitX() - s * s.x();
  if (first.norm() < 0.5) first = Eigen::Vector3d::UnitY() - s * s.y();
  first.normalize();
  return {first, s.cross(first).normalized()};
}

// Replaces link `link_id` by `parts` (part 0 keeps its id and name), part k's frame at
// `origins[k]` in the link frame (link axes), joined in a chain by kFlex joints (joint k at
// `steps[k]` in part k−1's frame) that bend about the axes orthogonal to `span`; the link's
// child joint moves to the last part.
void wire_pieces(KinematicTree& tree, int link_id, int child_joint, std::vector<TreeLink>& parts,
                 const std::vector<Eigen::Vector3d>& origins,
                 const std::vector<Eigen::Vector3d>& steps, const Eigen::Vector3d& span) {
  const int pieces = static_cast<int>(parts.size());
  const std::string link_name = tree.links[link_id].name;
  const int parent_joint = tree.links[link_id].parent_joint;
  const auto [bend1, bend2] = bending_axes(span);
  std::vector<int> ids(pieces);
  ids[0] = link_id;
  for (int k = 1; k < pieces; ++k) {
    ids[k] = static_cast<int>(tree.links.size());
    tree.links.emplace_back();
  }
  for (int k = 0; k < pieces; ++k) {
    parts[k].name = k == 0 ? link_name : link_name + "#" + std::to_string(k);
    parts[k].parent_joint = k == 0 ? parent_joint : -1;
    parts[k].child_joints.clear();
    tree.links[ids[k]] = parts[k];
  }
  for (int k = 1; k < pieces; ++k) {
    TreeJoint flex;
    flex.name = link_name + "#flex" + std::to_string(k);
    flex.type = TreeJointType::kFlex;
    flex.parent_link = ids[k - 1];
    flex.child_link = ids[k];
    flex.X_PJ = Eigen::Isometry3d::Identity();
    flex.X_PJ.translation() = steps[k];
    flex.axis_J = bend1;
    flex.axis2_J = bend2;
    const int flex_id = static_cast<int>(tree.joints.size());
    tree.joints.push_back(flex);
    tree.links[ids[k - 1]].child_joints.push_back(flex_id);
    tree.links[ids[k]].parent_joint = flex_id;
  }
  TreeJoint& original_child = tree.joints[child_joint];
  original_child.parent_link = ids[pieces - 1];
  original_child.X_PJ.translation() -= origins[pieces - 1];
  tree.links[ids[pieces - 1]].child_joints.push_back(child_joint);
}

}  // namespace

int KinematicTree::link_index(const std::string& name) const {
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (links[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int KinematicTree::joint_index(const std::string& name) const {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

Eigen::Matrix3d parallel_axis(double mass_kg, const Eigen::Vector3d& d_m) {
  return mass_kg * (d_m.squaredNorm() * Eigen::Matrix3d::Identity() - d_m * d_m.transpose());
}

KinematicTree load_urdf_tree(const std::string& urdf_path) {
  std::ifstream file(urdf_path);
  if (!file) throw InputError(urdf_path, 0, "", "cannot open URDF file");
  std::stringstream text;
  text << file.rdbuf();

  CapturingHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text.str());
  console_bridge::restorePreviousOutputHandler();
  if (!model) {
    const std::string reason = handler.first_error.empty() ? "invalid URDF" : handler.first_error;
    const std::string name = quoted_name(reason);
    throw InputError(urdf_path, line_of_name(urdf_path, name), name, reason);
  }

  KinematicTree tree;
  std::map<std::string, int> link_ids;
  for (const auto& [name, link] : model->links_) {
    TreeLink out;
    out.name = name;
    if (link->inertial) {
      const auto& in = *link->inertial;
      const Eigen::Isometry3d X = to_isometry(in.origin);
      Eigen::Matrix3d inertia;
      inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
      out.mass_kg = in.mass;
      out.com_L_m = X.translation();
      out.inertia_kg_m2 = X.linear() * inertia * X.linear().transpose();
      const int line = line_of_name(urdf_path, name);
      if (!(in.mass >= 0.0) || !std::isfinite(in.mass)) {
        throw InputError(urdf_path, line, name + ".inertial.mass", "must be >= 0");
      }
      if (in.mass > 0.0) {
        const Eigen::Vector3d eig =
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(out.inertia_kg_m2).eigenvalues();
        if (!(eig.minCoeff() > 0.0) || eig(0) + eig(1) < eig(2) * (1.0 - 1e-6)) {
          throw InputError(urdf_path, line, name + ".inertial.inertia",
                           "not a physical inertia tensor (must be positive definite and obey "
                           "the triangle inequality)");
        }
      }
    }
    for (const auto& collision : link->collision_array) {
      if (!collision || !collision->geometry) continue;
      if (collision->geometry->type != urdf::Geometry::BOX) {
        throw InputError(urdf_path, line_of_name(urdf_path, name), name + ".collision",
                         "only <box> collision geometry is supported");
      }
      const auto box = std::dynamic_pointer_cast<urdf::Box>(collision->geometry);
      out.boxes.push_back(
          {Eigen::Vector3d(box->dim.x, box->dim.y, box->dim.z), to_isometry(collision->origin)});
    }
    link_ids[name] = static_cast<int>(tree.links.size());
    tree.links.push_back(std::move(out));
  }

  for (const auto& [name, joint] : model->joints_) {
    TreeJoint out;
    out.name = name;
    const int line = line_of_name(urdf_path, name);
    switch (joint->type) {
      case urdf::Joint::REVOLUTE:
      case urdf::Joint::CONTINUOUS:
        out.type = TreeJointType::kRevolute;
        break;
      case urdf::Joint::FIXED:
        out.type = TreeJointType::kFixed;
        break;
      default:
        throw InputError(urdf_path, line, name + ".type",
                         "only revolute, continuous and fixed joints are supported");
    }
    out.parent_link = link_ids.at(joint->parent_link_name);
    out.child_link = link_ids.at(joint->child_link_name);
    out.X_PJ = to_isometry(joint->parent_to_joint_origin_transform);
    if (out.type == TreeJointType::kRevolute) {
      const Eigen::Vector3d axis(joint->axis.x, joint->axis.y, joint->axis.z);
      if (!(axis.norm() > 1e-9)) throw InputError(urdf_path, line, name + ".axis", "zero axis");
      out.axis_J = axis.normalized();
      if (joint->type == urdf::Joint::REVOLUTE && joint->limits) {
        out.limited = true;
        out.lower_rad = joint->limits->lower;
        out.upper_rad = joint->limits->upper;
        if (!(out.lower_rad <= out.upper_rad)) {
          throw InputError(urdf_path, line, name + ".limit", "lower must not exceed upper");
        }
      }
    }
    tree.joints.push_back(std::move(out));
  }
  for (std::size_t j = 0; j < tree.joints.size(); ++j) {
    tree.links[tree.joints[j].parent_link].child_joints.push_back(static_cast<int>(j));
    tree.links[tree.joints[j].child_link].parent_joint = static_cast<int>(j);
  }
  tree.root_link = link_ids.at(model->getRoot()->name);
  return tree;
}

void split_flexible_link(KinematicTree& tree, const std::string& link_name, int pieces) {
  if (pieces <= 1) return;
  const int link_id = tree.link_index(link_name);
  if (link_id < 0) throw std::invalid_argument("flexible link '" + link_name + "' not in URDF");
  if (tree.links[link_id].child_joints.size() != 1) {
    throw std::invalid_argument("flexible link '" + link_name +
                                "' must have exactly one child joint to be split");
  }
  const TreeLink whole = tree.links[link_id];
  const int child_joint = whole.child_joints.front();
  const Eigen::Vector3d span = tree.joints[child_joint].X_PJ.translation();
  if (span.norm() < 1e-6) {
    throw std::invalid_argument("flexible link '" + link_name + "' has zero length");
  }
  const double piece_mass = whole.mass_kg / pieces;

  // Piece k spans [k/N, (k+1)/N] of the link; its frame is the link frame shifted by k/N·span.
  std::vector<Eigen::Vector3d> com(pieces);
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (int k = 0; k < pieces; ++k) {
    const double offset = (k + 0.5) / pieces - 0.5;
    com[k] = whole.com_L_m + offset * span;
    spread += parallel_axis(piece_mass, com[k] - whole.com_L_m);
  }
  // Equal share of what the spread of the pieces does not already account for; keeps the total
  // inertia about the CoM exact when that remainder is positive definite.
  Eigen::Matrix3d piece_inertia = (whole.inertia_kg_m2 - spread) / pieces;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(piece_inertia);
  Eigen::Vector3d eig = solver.eigenvalues();
  const double floor = 1e-3 * std::max(whole.inertia_kg_m2.trace() / 3.0 / pieces, 1e-12);
  if (eig.minCoeff() < floor) {
    eig = eig.cwiseMax(floor);
    piece_inertia = solver.eigenvectors() * eig.asDiagonal() * solver.eigenvectors().transpose();
  }

  std::vector<TreeLink> parts(pieces);
  std::vector<Eigen::Vector3d> origins(pieces);
  for (int k = 0; k < pieces; ++k) {
    origins[k] = (static_cast<double>(k) / pieces) * span;
    parts[k].mass_kg = piece_mass;
    parts[k].com_L_m = com[k] - origins[k];
    parts[k].inertia_kg_m2 = piece_inertia;
  }
  // Each collision box goes to the piece that contains its centre along the span.
  for (const TreeBox& box : whole.boxes) {
    const double along = box.X_LG.translation().dot(span) / span.squaredNorm();
    const int k = std::clamp(static_cast<int>(std::floor(along * pieces)), 0, pieces - 1);
    TreeBox moved = box;
    moved.X_LG.translation() -= origins[k];
    parts[k].boxes.push_back(moved);
  }
  const std::vector<Eigen::Vector3d> steps(pieces, span / pieces);
  wire_pieces(tree, link_id, child_joint, parts, origins, steps, span);
}

void split_flexible_box(KinematicTree& tree, const std::string& link_name, int pieces) {
  if (pieces <= 1) return;
  const int link_id = tree.link_index(link_name);
  if (link_id < 0) throw std::invalid_argument("flexible link '" + link_name + "' not in URDF");
  const TreeLink whole = tree.links[link_id];
  if (whole.child_joints.size() != 1 || whole.boxes.size() != 1) {
    throw std::invalid_argument("flexible link '" + link_name +
                                "' must have exactly one child joint and one box to be split");
  }
  const Eigen::Vector3d span = tree.joints[whole.child_joints.front()].X_PJ.translation();
  if (span.norm() < 1e-6) {
    throw std::invalid_argument("flexible link '" + link_name + "' has zero length");
  }
  // The box's own axis closest to the span is the stacking direction.
  const TreeBox& box = whole.boxes.front();
  int stack_axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(box.X_LG.linear().col(i).dot(span)) >
        std::abs(box.X_LG.linear().col(stack_axis).dot(span))) {
      stack_axis = i;
    }
  }
  Eigen::Vector3d direction = box.X_LG.linear().col(stack_axis);
  if (direction.dot(span) < 0.0) direction = -direction;
  const double height_m = box.size_m[stack_axis];
  Eigen::Vector3d piece_size = box.size_m;
  piece_size[stack_axis] = height_m / pieces;
  const double piece_mass = whole.mass_kg / pieces;
  // A homogeneous box's inertia about its centre, in the link axes.
  const Eigen::Vector3d s2 = piece_size.cwiseProduct(piece_size);
  const Eigen::Matrix3d local =
      Eigen::Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y()).asDiagonal() *
      (piece_mass / 12.0);
  const Eigen::Matrix3d piece_inertia = box.X_LG.linear() * local * box.X_LG.linear().transpose();

  std::vector<TreeLink> parts(pieces);
  std::vector<Eigen::Vector3d> origins(pieces, Eigen::Vector3d::Zero());
  const Eigen::Vector3d near_face = box.X_LG.translation() - 0.5 * height_m * direction;
  for (int k = 0; k < pieces; ++k) {
    // Piece k's frame sits on its face toward the link origin (the link frame for piece 0): the bending joint
    // between two pieces is where their faces meet.
    if (k > 0) origins[k] = near_face + (static_cast<double>(k) / pieces) * height_m * direction;
    const Eigen::Vector3d centre = near_face + ((k + 0.5) / pieces) * height_m * direction;
    parts[k].mass_kg = piece_mass;
    parts[k].com_L_m = centre - origins[k];
    parts[k].inertia_kg_m2 = piece_inertia;
    TreeBox piece_box = box;
    piece_box.size_m = piece_size;
    piece_box.X_LG.translation() = centre - origins[k];
    parts[k].boxes.push_back(piece_box);
  }
  std::vector<Eigen::Vector3d> steps(pieces, Eigen::Vector3d::Zero());
  for (int k = 1; k < pieces; ++k) steps[k] = origins[k] - origins[k - 1];
  wire_pieces(tree, link_id, whole.child_joints.front(), parts, origins, steps, span);
}

std::vector<Eigen::Isometry3d> link_poses(const KinematicTree& tree,
                                          const std::vector<double>& joint_angles_rad) {
  std::vector<Eigen::Isometry3d> poses(tree.links.size(), Eigen::Isometry3d::Identity());
  std::vector<int> stack{tree.root_link};
  while (!stack.empty()) {
    const int link = stack.back();
    stack.pop_back();
    for (const int j : tree.links[link].child_joints) {
      const TreeJoint& joint = tree.joints[j];
      Eigen::Isometry3d X = poses[link] * joint.X_PJ;
      if (joint.type == TreeJointType::kRevolute) {
        X.rotate(Eigen::AngleAxisd(joint_angles_rad.at(j), joint.axis_J));
      }
      poses[joint.child_link] = X;
      stack.push_back(joint.child_link);
    }
  }
  return poses;
}

}  // namespace motoflex::detail
