#pragma once

// Internal to the exporters: what a viewer draws for each body of the simulated model.

#include <vector>

#include "exported_bodies.hpp"
#include "motoflex/model/robot_model.hpp"

namespace motoflex::detail {

// The visual shapes of one exported body, posed in the exported body's frame (its CoM, world
// orientation; for the bench arm the point mass's frame, see exported_bodies.hpp):
//  * each lumped URDF link draws its <visual> shapes; a link without any draws its collision
//    shapes instead (what URDF viewers do with collision-only robots such as the bundled Nao);
//  * a body with neither (a point mass on a rod, a small link between two hinges) draws a
//    sphere of water density at its CoM, radius (3m/(4π·1000 kg/m³))^(1/3) clamped to
//    [5, 50] mm, and a rod (capsule of 0.3 × that radius) from the CoM to each joint on it.
// Mesh visuals whose file was not found are left out (the loader already warned).
std::vector<VisualShape> exported_visuals(const RobotModel& model, const ExportedBody& body,
                                          const Eigen::Vector3d& offset_m);

// The pose of a model shape (X_BG, relative to the model body's CoM) in the exported body's
// frame: the same unless the exporter moved the body's CoM (the bench arm).
Eigen::Isometry3d exported_shape_pose(const ExportedBody& body, const Eigen::Isometry3d& X_BG,
                                      const Eigen::Vector3d& offset_m);

}  // namespace motoflex::detail
