#include "urdf_geometry.hpp"

#include <cmath>
#include <memory>

#include "motoflex/model/urdf_tree.hpp"

namespace motoflex::detail {

Eigen::Isometry3d to_isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return X;
}

namespace {

bool positive(double value) {
  return std::isfinite(value) && value > 0.0;
}

}  // namespace

ShapeGeometry shape_from_urdf(const urdf::Geometry& geometry, bool capsule,
                              const std::string& urdf_path, std::string& problem) {
  ShapeGeometry shape;
  problem.clear();
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      shape.kind = ShapeKind::kBox;
      shape.size_m = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
      if (!positive(box.dim.x) || !positive(box.dim.y) || !positive(box.dim.z)) {
        problem = "box size must be positive";
      }
      break;
    }
    case urdf::Geometry::SPHERE:
      shape.kind = ShapeKind::kSphere;
      shape.radius_m = static_cast<const urdf::Sphere&>(geometry).radius;
      if (!positive(shape.radius_m)) problem = "sphere radius must be positive";
      break;
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      shape.kind = capsule ? ShapeKind::kCapsule : ShapeKind::kCylinder;
      shape.radius_m = cylinder.radius;
      shape.length_m = cylinder.length;
      // A capsule of zero length is a sphere; a cylinder needs a length.
      if (!positive(shape.radius_m) || !std::isfinite(shape.length_m) || shape.length_m < 0.0 ||
          (!capsule && shape.length_m == 0.0)) {
        problem =
            std::string(capsule ? "capsule" : "cylinder") + " radius and length must be positive";
      }
      break;
    }
    case urdf::Geometry::MESH: {
      const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
      shape.kind = ShapeKind::kMesh;
      shape.mesh.uri = mesh.filename;
      shape.mesh.scale = Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z);
      shape.mesh.path = resolve_mesh_path(mesh.filename, urdf_path);
      if (!shape.mesh.scale.allFinite() || shape.mesh.scale.cwiseAbs().minCoeff() == 0.0) {
        problem = "mesh scale must be finite and non-zero";
      } else if (shape.mesh.path.empty()) {
        problem = "mesh file '" + mesh.filename +
                  "' not found (package:// is looked up in the URDF's folder and its parents)";
      }
      break;
    }
  }
  return shape;
}

}  // namespace motoflex::detail
