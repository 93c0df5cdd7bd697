#include "collision_meshes.hpp"

#include <stdexcept>

#include "motoflex/core/error.hpp"
#include "motoflex/model/mesh_geometry.hpp"

namespace motoflex::detail {
namespace {

std::tuple<std::string, double, double, double> key_of(const CollisionShape& shape) {
  const Eigen::Vector3d& s = shape.mesh.scale;
  return {shape.mesh.path, s.x(), s.y(), s.z()};
}

}  // namespace

std::shared_ptr<const TriangleMesh> MeshLibrary::triangles(const CollisionShape& shape) {
  auto& slot = triangles_[key_of(shape)];
  if (!slot) {
    slot = std::make_shared<const TriangleMesh>(load_mesh_file(shape.mesh.path, shape.mesh.scale));
  }
  return slot;
}

bool MeshLibrary::attach(CollisionShape& shape, bool as_trimesh, const std::string& urdf_path,
                         int link_line, ErrorCollector& errors) {
  return errors.check([&] {
    try {
      if (as_trimesh) {
        shape.trimesh = triangles(shape);
        return;
      }
      auto& hull = hulls_[key_of(shape)];
      if (!hull)
        hull = std::make_shared<const ConvexHull>(convex_hull(triangles(shape)->vertices_m));
      shape.hull = hull;
    } catch (const InputError& error) {
      throw InputError(urdf_path, link_line, shape.link + ".collision",
                       "mesh " + shape.mesh.path + ": " + error.message());
    } catch (const std::invalid_argument& error) {
      throw InputError(urdf_path, link_line, shape.link + ".collision",
                       "mesh " + shape.mesh.path + ": " + error.what() +
                           " (or list the link in robot.yaml trimesh_links)");
    }
  });
}

}  // namespace motoflex::detail
