#pragma once

// Shapes of a robot's links as the model keeps them: collision shapes the simulator gives to
// ODE, and visual shapes kept for the exporters. Every size is in metres; every pose is the
// shape frame in its body frame (X_BG) or link frame (X_LG).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace motoflex {

enum class ShapeKind {
  kBox,       // size_m: full edge lengths
  kSphere,    // radius_m
  kCylinder,  // radius_m, length_m along the shape's z axis (URDF and ODE agree)
  kCapsule,   // radius_m, length_m of the cylindrical part along z; hemispherical caps beyond
  kMesh,      // a mesh file (STL, DAE, OBJ), scaled by mesh_scale
};
const char* to_string(ShapeKind kind);

// A mesh file as the URDF names it.
struct MeshSource {
  std::string uri;   // as written (`package://pkg/meshes/foot.stl`, `meshes/foot.stl`, ...)
  std::string path;  // the file it resolved to (absolute); empty when no file was found
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};

// The geometry of one shape, without its pose.
struct ShapeGeometry {
  ShapeKind kind = ShapeKind::kBox;
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();  // box
  double radius_m = 0.0;                             // sphere, cylinder, capsule
  double length_m = 0.0;                             // cylinder, capsule (see ShapeKind)
  MeshSource mesh;                                   // mesh
};

// A convex hull in ODE's dCreateConvex layout, in the shape frame (scale applied). Immutable
// once loaded and shared read-only by every rollout.
struct ConvexHull {
  std::vector<double> points_m;        // x, y, z per vertex
  std::vector<double> planes;          // per face: outward unit normal n, then d = n·p on it
  std::vector<unsigned int> polygons;  // per face: vertex count, then vertex indices
                                       // (counter-clockwise seen from outside)
  std::size_t vertex_count() const { return points_m.size() / 3; }
  std::size_t face_count() const { return planes.size() / 4; }
};

// A triangle mesh in the shape frame (scale applied), for ODE trimesh geoms.
struct TriangleMesh {
  std::vector<double> vertices_m;      // x, y, z per vertex
  std::vector<std::uint32_t> indices;  // three vertex indices per triangle
  std::size_t vertex_count() const { return vertices_m.size() / 3; }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

// How a link's shapes meet the ground.
enum class GroundContact {
  kFoot,     // collides with the ground; a foot force sensor; never a fall (robot.yaml feet)
  kContact,  // collides with the ground without ending the rollout (robot.yaml contact_links)
  kFall,     // touching the ground ends the rollout as a fall (every other link)
};

// One collision shape of a body.
struct CollisionShape : ShapeGeometry {
  std::string link;                                        // URDF link it came from
  Eigen::Isometry3d X_BG = Eigen::Isometry3d::Identity();  // shape pose in its body frame
  GroundContact contact = GroundContact::kFall;
  bool is_foot = false;  // contact == kFoot (kept as a flag for the many readers of feet)
  // Meshes: exactly one of these is set. The hull is the default (decimated to at most
  // kMaxHullVertices vertices); a trimesh when robot.yaml lists the link in `trimesh_links`.
  std::shared_ptr<const ConvexHull> hull;
  std::shared_ptr<const TriangleMesh> trimesh;
};

// One visual shape of a body (not simulated; for the exporters).
struct VisualShape : ShapeGeometry {
  std::string link;
  Eigen::Isometry3d X_BG = Eigen::Isometry3d::Identity();
  std::string material;                 // URDF material name, may be empty
  std::optional<Eigen::Vector4d> rgba;  // the material's colour when the URDF gives one
};

// The most vertices a collision hull keeps (ODE's convex collider is linear in them).
inline constexpr std::size_t kMaxHullVertices = 64;

}  // namespace motoflex
