#pragma once

// Internal to the model loader: the meshes of collision shapes, each file read once per load.

#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "motoflex/core/error_collector.hpp"
#include "motoflex/model/geometry.hpp"

namespace motoflex::detail {

class MeshLibrary {
 public:
  // Gives a mesh shape its convex hull (or, `as_trimesh`, its triangles). A file that cannot
  // be read or hulled is reported at `urdf_path`:`link_line` (the shape's link); returns false
  // then.
  bool attach(CollisionShape& shape, bool as_trimesh, const std::string& urdf_path, int link_line,
              ErrorCollector& errors);

 private:
  using Key = std::tuple<std::string, double, double, double>;  // path and scale
  std::shared_ptr<const TriangleMesh> triangles(const CollisionShape& shape);
  std::map<Key, std::shared_ptr<const TriangleMesh>> triangles_;
  std::map<Key, std::shared_ptr<const ConvexHull>> hulls_;
};

}  // namespace motoflex::detail
