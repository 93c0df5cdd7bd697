#pragma once

// Internal to the URDF reader: urdfdom's shapes as motoflex's ShapeGeometry.

#include <urdf_model/link.h>

#include <Eigen/Geometry>
#include <string>

#include "motoflex/model/geometry.hpp"

namespace motoflex::detail {

Eigen::Isometry3d to_isometry(const urdf::Pose& pose);

// The shape of a <collision> or <visual>: `capsule` when the URDF wrote <capsule> (the scan
// renamed it <cylinder>). Mesh files are resolved against `urdf_path` (resolve_mesh_path).
// Returns what is wrong with the shape in `problem` (a non-positive size, a mesh file that
// cannot be found: mesh.path stays empty) and the shape as far as it could be read.
ShapeGeometry shape_from_urdf(const urdf::Geometry& geometry, bool capsule,
                              const std::string& urdf_path, std::string& problem);

}  // namespace motoflex::detail
