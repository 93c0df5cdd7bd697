#pragma once

// Internal to the rollout: the ODE geoms of a robot's collision shapes and their contacts with
// the ground plane. Only the ground collides (the robot's own links never do).

#include <ode/ode.h>

#include <cstddef>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex::detail {

// Contacts one shape may make with the ground in a step: boxes and cylinders four, a capsule
// two, a sphere one, a mesh eight (chosen to span its contact patch, see
// GroundColliders::collide).
int max_ground_contacts(const CollisionShape& shape);
inline constexpr int kMaxGroundContacts = 8;

struct ShapeGeom {
  dGeomID geom = nullptr;
  dBodyID body = nullptr;  // nullptr: the welded base (never collides, never falls)
  std::size_t body_index = 0;
  GroundContact contact = GroundContact::kFall;
  int max_contacts = 1;
  bool mesh = false;  // convex hull or trimesh: contacts are chosen among many candidates
};

// Owns the geoms of one rollout (and the trimesh data they read; the vertex arrays stay in the
// shared model).
class GroundColliders {
 public:
  GroundColliders() = default;
  ~GroundColliders();
  GroundColliders(const GroundColliders&) = delete;
  GroundColliders& operator=(const GroundColliders&) = delete;

  // The geom of `shape` on `body` at `offset_B` (shape position relative to the ODE body's
  // position) with the shape's orientation; on a static body the pose is in the world.
  ShapeGeom add(const CollisionShape& shape, dBodyID body, std::size_t body_index,
                const Eigen::Vector3d& offset_or_position);

  // The ground contacts of `shape` (at most shape.max_contacts, into `out`): every one ODE
  // finds for primitives; for meshes, of up to 64 candidates the deepest and the extremes in
  // eight horizontal directions, so a flat face resting on the ground is held at its corners.
  static int collide(const ShapeGeom& shape, dGeomID ground, dContactGeom* out);

 private:
  std::vector<ShapeGeom> geoms_;
  std::vector<dTriMeshDataID> trimesh_data_;
};

}  // namespace motoflex::detail
