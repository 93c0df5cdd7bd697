#include "exported_visuals.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace motoflex::detail {
namespace {

constexpr double kWaterDensity_kg_m3 = 1000.0;
constexpr double kMinMarkerRadius_m = 0.005;
constexpr double kMaxMarkerRadius_m = 0.05;
constexpr double kRodToMarkerRadius = 0.3;

VisualShape visual_of(const CollisionShape& shape) {
  VisualShape visual;
  static_cast<ShapeGeometry&>(visual) = shape;
  visual.link = shape.link;
  visual.X_BG = shape.X_BG;
  return visual;
}

bool drawable(const ShapeGeometry& shape) {
  return shape.kind != ShapeKind::kMesh || !shape.mesh.path.empty();
}

// A sphere at the CoM and a rod to each joint of the body (positions in the body frame).
std::vector<VisualShape> stick_figure(const RobotModel& model, const ExportedBody& body,
                                      const Eigen::Vector3d& offset_m, std::size_t body_index) {
  const double radius_m =
      std::clamp(std::cbrt(3.0 * body.mass_kg / (4.0 * M_PI * kWaterDensity_kg_m3)),
                 kMinMarkerRadius_m, kMaxMarkerRadius_m);
  std::vector<VisualShape> out;
  VisualShape sphere;
  sphere.kind = ShapeKind::kSphere;
  sphere.radius_m = radius_m;
  sphere.link = body.spec->name;
  out.push_back(sphere);
  for (const JointSpec& joint : model.joints) {
    const bool own =
        body.spec->parent_joint >= 0 && &model.joints[body.spec->parent_joint] == &joint;
    if (!own && joint.parent_body != static_cast<int>(body_index)) continue;
    const Eigen::Vector3d to_joint = joint.anchor_W0_m + offset_m - body.com_m;
    const double length_m = to_joint.norm();
    if (length_m < 1e-6) continue;
    VisualShape rod;
    rod.kind = ShapeKind::kCapsule;
    rod.radius_m = kRodToMarkerRadius * radius_m;
    rod.length_m = length_m;
    rod.link = body.spec->name;
    // The capsule's z axis along the rod, centred halfway.
    rod.X_BG.linear() =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), to_joint).toRotationMatrix();
    rod.X_BG.translation() = 0.5 * to_joint;
    out.push_back(rod);
  }
  return out;
}

}  // namespace

Eigen::Isometry3d exported_shape_pose(const ExportedBody& body, const Eigen::Isometry3d& X_BG,
                                      const Eigen::Vector3d& offset_m) {
  Eigen::Isometry3d pose = X_BG;
  pose.translation() += body.spec->com_W0_m + offset_m - body.com_m;
  return pose;
}

std::vector<VisualShape> exported_visuals(const RobotModel& model, const ExportedBody& body,
                                          const Eigen::Vector3d& offset_m) {
  const BodySpec& spec = *body.spec;
  std::set<std::string> drawn_links;
  std::vector<VisualShape> out;
  for (const VisualShape& visual : spec.visuals) {
    if (!drawable(visual)) continue;
    drawn_links.insert(visual.link);
    out.push_back(visual);
  }
  for (const CollisionShape& shape : spec.collisions) {
    if (drawn_links.count(shape.link) == 0) out.push_back(visual_of(shape));
  }
  for (VisualShape& visual : out) visual.X_BG = exported_shape_pose(body, visual.X_BG, offset_m);
  if (!out.empty()) return out;
  const std::size_t index = static_cast<std::size_t>(body.spec - model.bodies.data());
  return stick_figure(model, body, offset_m, index);
}

}  // namespace motoflex::detail
