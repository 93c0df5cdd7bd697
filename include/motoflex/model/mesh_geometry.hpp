#pragma once

// Meshes for collisions: files read through assimp, convex hulls through qhull.

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "motoflex/model/geometry.hpp"

namespace motoflex {

// Every triangle of a mesh file (STL, OBJ, DAE and the other formats assimp reads), in metres
// after multiplying each vertex by `scale` component-wise. Node transforms and a COLLADA
// <unit meter> are applied; a COLLADA <up_axis> is not (a URDF mesh is in its link's frame,
// as ROS tools read it). Throws InputError naming the file when it cannot be read or holds
// no triangle.
TriangleMesh load_mesh_file(const std::string& path, const Eigen::Vector3d& scale);

// The convex hull of `points_m` (x, y, z per point) with at most `max_vertices` vertices
// (>= 8). A hull with more vertices is replaced by the hull of its support points in
// `max_vertices` fixed directions (the six axis directions, the eight diagonals, then a
// Fibonacci sphere): a slightly smaller convex shape that touches the true hull in each of
// those directions, so the lowest point of an upright shape is kept exactly. Faces are
// triangles. Throws std::invalid_argument when the points span no volume (flat or fewer than
// four points), with qhull's reason.
ConvexHull convex_hull(const std::vector<double>& points_m,
                       std::size_t max_vertices = kMaxHullVertices);

}  // namespace motoflex
