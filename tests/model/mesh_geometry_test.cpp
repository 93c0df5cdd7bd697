// Mesh files through assimp and their convex hulls through qhull: sizes in metres whatever the
// format and unit, hulls with outward faces, decimation that keeps the extremes.

#include "motoflex/model/mesh_geometry.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <stdexcept>
#include <string>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

std::string mesh(const std::string& file) {
  return std::string(MOTOFLEX_SOURCE_DIR) + "/tests/data/meshes/" + file;
}

struct Box3 {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(1e9), max = Eigen::Vector3d::Constant(-1e9);
};

Box3 bounds(const std::vector<double>& xyz) {
  Box3 b;
  for (std::size_t i = 0; i < xyz.size(); i += 3) {
    const Eigen::Vector3d p(xyz[i], xyz[i + 1], xyz[i + 2]);
    b.min = b.min.cwiseMin(p);
    b.max = b.max.cwiseMax(p);
  }
  return b;
}

// assimp keeps float32 vertices: 0.05 comes back as 0.0500000007.
constexpr double kFloat = 1e-8;

TEST(MeshGeometryTest, EveryFormatReadsTheSameCubeInMetres) {
  for (const auto& [file, scale] : {std::pair<std::string, double>{"cube_100mm.stl", 1.0},
                                    {"cube_100mm.obj", 1.0},
                                    {"cube_100mm_in_mm.dae", 1.0},
                                    {"cube_mm_ascii.stl", 0.001}}) {
    SCOPED_TRACE(file);
    const TriangleMesh cube = load_mesh_file(mesh(file), Eigen::Vector3d::Constant(scale));
    EXPECT_EQ(cube.triangle_count(), 12u);
    EXPECT_EQ(cube.vertex_count(), 8u);  // shared corners joined
    const Box3 b = bounds(cube.vertices_m);
    EXPECT_LT((b.min - Eigen::Vector3d::Constant(-0.05)).cwiseAbs().maxCoeff(), kFloat);
    EXPECT_LT((b.max - Eigen::Vector3d::Constant(0.05)).cwiseAbs().maxCoeff(), kFloat);
  }
}

TEST(MeshGeometryTest, ColladaUnitIsAppliedButNotItsUpAxis) {
  const TriangleMesh cone = load_mesh_file(mesh("cone_in_mm.dae"), Eigen::Vector3d::Ones());
  const Box3 b = bounds(cone.vertices_m);
  EXPECT_NEAR(b.max.z(), 0.08, kFloat);  // the apex stays up +z, in metres
  EXPECT_NEAR(b.min.z(), 0.0, kFloat);
  EXPECT_NEAR(b.max.x(), 0.05, kFloat);
}

TEST(MeshGeometryTest, MirroringScaleKeepsTrianglesFacingOut) {
  const TriangleMesh plain = load_mesh_file(mesh("cube_100mm.stl"), Eigen::Vector3d::Ones());
  const TriangleMesh mirrored =
      load_mesh_file(mesh("cube_100mm.stl"), Eigen::Vector3d(-1.0, 1.0, 1.0));
  const auto outward = [](const TriangleMesh& m) {
    int out = 0;
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
      Eigen::Vector3d p[3];
      for (int k = 0; k < 3; ++k) {
        const std::size_t v = m.indices[3 * t + k];
        p[k] =
            Eigen::Vector3d(m.vertices_m[3 * v], m.vertices_m[3 * v + 1], m.vertices_m[3 * v + 2]);
      }
      const Eigen::Vector3d centre = (p[0] + p[1] + p[2]) / 3.0;  // cube centred at 0
      out += (p[1] - p[0]).cross(p[2] - p[0]).dot(centre) > 0.0;
    }
    return out;
  };
  EXPECT_EQ(outward(plain), 12);
  EXPECT_EQ(outward(mirrored), 12);
}

TEST(MeshGeometryTest, CubeHullHasEightCornersAndOutwardFaces) {
  const TriangleMesh cube = load_mesh_file(mesh("cube_100mm.stl"), Eigen::Vector3d::Ones());
  const ConvexHull hull = convex_hull(cube.vertices_m);
  EXPECT_EQ(hull.vertex_count(), 8u);
  EXPECT_EQ(hull.face_count(), 12u);  // two triangles per side
  for (std::size_t f = 0; f < hull.face_count(); ++f) {
    const Eigen::Vector3d n(hull.planes[4 * f], hull.planes[4 * f + 1], hull.planes[4 * f + 2]);
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_NEAR(n.cwiseAbs().maxCoeff(), 1.0, 1e-7);    // axis-aligned
    EXPECT_NEAR(hull.planes[4 * f + 3], 0.05, kFloat);  // n·p = d on the face, 5 cm out
    ASSERT_EQ(hull.polygons[4 * f], 3u);
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) {
      const unsigned v = hull.polygons[4 * f + 1 + k];
      p[k] =
          Eigen::Vector3d(hull.points_m[3 * v], hull.points_m[3 * v + 1], hull.points_m[3 * v + 2]);
      EXPECT_NEAR(n.dot(p[k]), hull.planes[4 * f + 3], kFloat);
    }
    EXPECT_GT((p[1] - p[0]).cross(p[2] - p[0]).dot(n), 0.0);  // counter-clockwise from outside
  }
}

TEST(MeshGeometryTest, ConcaveMeshHullFillsTheHollow) {
  const TriangleMesh u = load_mesh_file(mesh("u_block.stl"), Eigen::Vector3d::Ones());
  EXPECT_GT(u.vertex_count(), 8u);
  EXPECT_EQ(convex_hull(u.vertices_m).vertex_count(), 8u);  // the U's bounding box
}

TEST(MeshGeometryTest, DecimatedHullKeepsTheExtremes) {
  const TriangleMesh sphere = load_mesh_file(mesh("icosphere_642.stl"), Eigen::Vector3d::Ones());
  EXPECT_EQ(sphere.vertex_count(), 642u);
  const ConvexHull full = convex_hull(sphere.vertices_m, 1000);
  EXPECT_EQ(full.vertex_count(), 642u);
  const ConvexHull hull = convex_hull(sphere.vertices_m);
  EXPECT_LE(hull.vertex_count(), kMaxHullVertices);
  EXPECT_GE(hull.vertex_count(), kMaxHullVertices - 8);  // few directions share a vertex
  const Box3 a = bounds(sphere.vertices_m), b = bounds(hull.points_m);
  EXPECT_EQ(a.min, b.min);  // the support points of ±x, ±y, ±z are kept exactly
  EXPECT_EQ(a.max, b.max);
}

TEST(MeshGeometryTest, FlatMeshesAndMissingFilesAreReported) {
  const TriangleMesh flat = load_mesh_file(mesh("flat_square.obj"), Eigen::Vector3d::Ones());
  EXPECT_THROW(convex_hull(flat.vertices_m), std::invalid_argument);
  EXPECT_THROW(load_mesh_file(mesh("no_such_file.stl"), Eigen::Vector3d::Ones()), InputError);
}

}  // namespace
}  // namespace motoflex
