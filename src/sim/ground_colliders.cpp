#include "ground_colliders.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace motoflex::detail {
namespace {

constexpr int kMeshContactCandidates = 64;

void to_ode_rotation(const Eigen::Matrix3d& R, dMatrix3 out) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[r * 4 + c] = R(r, c);
    out[r * 4 + 3] = 0.0;
  }
}

// Of `n` candidate contacts, up to `max` that span the patch: the deepest first, then the
// farthest in each of eight horizontal directions. Keeps the candidates' order otherwise, so
// the choice is deterministic.
int choose_spread(const dContactGeom* candidates, int n, int max, dContactGeom* out) {
  if (n <= max) {
    std::copy(candidates, candidates + n, out);
    return n;
  }
  std::array<bool, kMeshContactCandidates> taken{};
  int count = 0;
  const auto take = [&](int k) {
    if (taken[k] || count >= max) return;
    taken[k] = true;
    out[count++] = candidates[k];
  };
  int deepest = 0;
  for (int k = 1; k < n; ++k) {
    if (candidates[k].depth > candidates[deepest].depth) deepest = k;
  }
  take(deepest);
  constexpr double kDiagonal = 0.70710678118654752;
  // The axes first: with fewer slots than directions the patch is still spanned both ways.
  const double directions[8][2] = {{1, 0},
                                   {-1, 0},
                                   {0, 1},
                                   {0, -1},
                                   {kDiagonal, kDiagonal},
                                   {-kDiagonal, -kDiagonal},
                                   {kDiagonal, -kDiagonal},
                                   {-kDiagonal, kDiagonal}};
  for (const auto& d : directions) {
    int best = 0;
    for (int k = 1; k < n; ++k) {
      const auto along = [&](int i) {
        return d[0] * candidates[i].pos[0] + d[1] * candidates[i].pos[1];
      };
      if (along(k) > along(best)) best = k;
    }
    take(best);
  }
  return count;
}

}  // namespace

int max_ground_contacts(const CollisionShape& shape) {
  switch (shape.kind) {
    case ShapeKind::kSphere:
      return 1;
    case ShapeKind::kCapsule:
      return 2;
    case ShapeKind::kMesh:
      return kMaxGroundContacts;
    default:
      return 4;
  }
}

GroundColliders::~GroundColliders() {
  for (const ShapeGeom& g : geoms_) dGeomDestroy(g.geom);
  for (dTriMeshDataID data : trimesh_data_) dGeomTriMeshDataDestroy(data);
}

ShapeGeom GroundColliders::add(const CollisionShape& shape, dBodyID body, std::size_t body_index,
                               const Eigen::Vector3d& offset_or_position) {
  ShapeGeom g;
  g.body = body;
  g.body_index = body_index;
  g.contact = shape.contact;
  g.max_contacts = max_ground_contacts(shape);
  switch (shape.kind) {
    case ShapeKind::kBox:
      g.geom = dCreateBox(nullptr, shape.size_m.x(), shape.size_m.y(), shape.size_m.z());
      break;
    case ShapeKind::kSphere:
      g.geom = dCreateSphere(nullptr, shape.radius_m);
      break;
    case ShapeKind::kCylinder:
      g.geom = dCreateCylinder(nullptr, shape.radius_m, shape.length_m);
      break;
    case ShapeKind::kCapsule:
      g.geom = dCreateCapsule(nullptr, shape.radius_m, shape.length_m);
      break;
    case ShapeKind::kMesh:
      g.mesh = true;
      if (shape.hull) {
        const ConvexHull& hull = *shape.hull;
        g.geom =
            dCreateConvex(nullptr, hull.planes.data(), static_cast<unsigned int>(hull.face_count()),
                          hull.points_m.data(), static_cast<unsigned int>(hull.vertex_count()),
                          hull.polygons.data());
      } else {
        const TriangleMesh& mesh = *shape.trimesh;
        dTriMeshDataID data = dGeomTriMeshDataCreate();
        trimesh_data_.push_back(data);
        dGeomTriMeshDataBuildDouble(
            data, mesh.vertices_m.data(), 3 * sizeof(double), static_cast<int>(mesh.vertex_count()),
            mesh.indices.data(), static_cast<int>(mesh.indices.size()), 3 * sizeof(std::uint32_t));
        g.geom = dCreateTriMesh(nullptr, data, nullptr, nullptr, nullptr);
      }
      break;
  }
  dMatrix3 R;
  to_ode_rotation(shape.X_BG.linear(), R);
  const Eigen::Vector3d& p = offset_or_position;
  if (body != nullptr) {
    dGeomSetBody(g.geom, body);
    dGeomSetOffsetPosition(g.geom, p.x(), p.y(), p.z());
    dGeomSetOffsetRotation(g.geom, R);
  } else {
    dGeomSetPosition(g.geom, p.x(), p.y(), p.z());
    dGeomSetRotation(g.geom, R);
  }
  geoms_.push_back(g);
  return g;
}

int GroundColliders::collide(const ShapeGeom& shape, dGeomID ground, dContactGeom* out) {
  if (!shape.mesh) {
    return dCollide(shape.geom, ground, shape.max_contacts, out, sizeof(dContactGeom));
  }
  std::array<dContactGeom, kMeshContactCandidates> candidates;
  const int n =
      dCollide(shape.geom, ground, kMeshContactCandidates, candidates.data(), sizeof(dContactGeom));
  return choose_spread(candidates.data(), n, shape.max_contacts, out);
}

}  // namespace motoflex::detail
