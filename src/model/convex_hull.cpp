// Convex hulls with qhull (reentrant libqhull_r), decimated to a bounded vertex count.

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

#include "motoflex/model/mesh_geometry.hpp"

namespace motoflex {
namespace {

// One qhull run; frees qhull's memory however it ends.
class Qhull {
 public:
  explicit Qhull(std::vector<double> points) : points_(std::move(points)) {
    errors_ = open_memstream(&error_text_, &error_size_);
    qh_zero(&qh_, errors_);
    char command[] = "qhull Qt";  // triangulated facets; qhull merges coplanar ones first
    exit_code_ = qh_new_qhull(&qh_, 3, static_cast<int>(points_.size() / 3), points_.data(), False,
                              command, nullptr, errors_);
  }
  ~Qhull() {
    int long_bytes = 0, total_bytes = 0;
    qh_freeqhull(&qh_, !qh_ALL);
    qh_memfreeshort(&qh_, &long_bytes, &total_bytes);
    if (errors_ != nullptr) std::fclose(errors_);
    std::free(error_text_);
  }
  Qhull(const Qhull&) = delete;
  Qhull& operator=(const Qhull&) = delete;

  bool ok() const { return exit_code_ == 0; }
  std::string error() {
    if (errors_ != nullptr) std::fflush(errors_);
    std::string text = error_text_ == nullptr ? "" : std::string(error_text_, error_size_);
    const auto end = text.find('\n');  // qhull's first line says what went wrong
    return text.substr(0, end);
  }
  qhT& qh() { return qh_; }
  const std::vector<double>& points() const { return points_; }

 private:
  std::vector<double> points_;  // qhull keeps a pointer to them
  qhT qh_{};
  FILE* errors_ = nullptr;
  char* error_text_ = nullptr;
  std::size_t error_size_ = 0;
  int exit_code_ = 0;
};

ConvexHull hull_of(std::vector<double> points) {
  Qhull run(std::move(points));
  if (!run.ok()) {
    throw std::invalid_argument("no convex hull (the mesh is flat or degenerate): " + run.error());
  }
  qhT* qh = &run.qh();
  ConvexHull hull;
  std::map<int, unsigned int> index_of;  // qhull point id → hull vertex
  for (facetT* facet = qh->facet_list; facet != nullptr && facet->next != nullptr;
       facet = facet->next) {
    setT* vertices = facet->vertices;
    if (qh_setsize(qh, vertices) != 3) continue;  // 'Qt' makes every facet a triangle
    unsigned int corner[3];
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) {
      const auto* vertex = static_cast<vertexT*>(vertices->e[k].p);
      const int id = qh_pointid(qh, vertex->point);
      const auto [it, inserted] =
          index_of.try_emplace(id, static_cast<unsigned int>(hull.vertex_count()));
      if (inserted) hull.points_m.insert(hull.points_m.end(), vertex->point, vertex->point + 3);
      corner[k] = it->second;
      p[k] = Eigen::Vector3d(vertex->point[0], vertex->point[1], vertex->point[2]);
    }
    const Eigen::Vector3d normal(facet->normal[0], facet->normal[1], facet->normal[2]);
    // ODE wants each face counter-clockwise seen from outside.
    if ((p[1] - p[0]).cross(p[2] - p[0]).dot(normal) < 0.0) std::swap(corner[1], corner[2]);
    hull.planes.insert(hull.planes.end(),
                       {normal.x(), normal.y(), normal.z(), -static_cast<double>(facet->offset)});
    hull.polygons.insert(hull.polygons.end(), {3u, corner[0], corner[1], corner[2]});
  }
  return hull;
}

// `count` unit directions: ±x, ±y, ±z, the eight diagonals, then a Fibonacci sphere.
std::vector<Eigen::Vector3d> sample_directions(std::size_t count) {
  std::vector<Eigen::Vector3d> directions;
  for (int axis = 0; axis < 3; ++axis) {
    directions.push_back(Eigen::Vector3d::Unit(axis));
    directions.push_back(-Eigen::Vector3d::Unit(axis));
  }
  for (int corner = 0; corner < 8; ++corner) {
    directions.push_back(
        Eigen::Vector3d((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1)
            .normalized());
  }
  const std::size_t rest = count > directions.size() ? count - directions.size() : 0;
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < rest; ++i) {
    const double z = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(rest);
    const double r = std::sqrt(1.0 - z * z);
    const double phi = golden_angle * static_cast<double>(i);
    directions.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  directions.resize(std::min(directions.size(), count));
  return directions;
}

}  // namespace

ConvexHull convex_hull(const std::vector<double>& points_m, std::size_t max_vertices) {
  if (max_vertices < 8) throw std::invalid_argument("convex_hull: max_vertices must be >= 8");
  if (points_m.size() < 12 || points_m.size() % 3 != 0) {
    throw std::invalid_argument("no convex hull: fewer than four points");
  }
  ConvexHull hull = hull_of(points_m);
  if (hull.vertex_count() <= max_vertices) return hull;
  // Keep the support point of each sampled direction (the first on ties), then hull those.
  std::vector<bool> kept(hull.vertex_count(), false);
  std::vector<double> support;
  for (const Eigen::Vector3d& d : sample_directions(max_vertices)) {
    std::size_t best = 0;
    double best_dot = -std::numeric_limits<double>::infinity();
    for (std::size_t v = 0; v < hull.vertex_count(); ++v) {
      const double dot = d.dot(Eigen::Vector3d(hull.points_m[3 * v], hull.points_m[3 * v + 1],
                                               hull.points_m[3 * v + 2]));
      if (dot > best_dot) {
        best_dot = dot;
        best = v;
      }
    }
    if (kept[best]) continue;
    kept[best] = true;
    support.insert(support.end(), hull.points_m.begin() + 3 * best,
                   hull.points_m.begin() + 3 * best + 3);
  }
  return hull_of(std::move(support));
}

}  // namespace motoflex
