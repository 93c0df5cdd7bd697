#pragma once

// Internal to the exporters: the rigid bodies of the simulated model as SDF and MJCF write
// them. Body frames are at the CoM with world orientation in the build pose (actuated joints at
// 0, held joints at their angle), exactly as motoflex builds its ODE bodies, so every pose is a
// translation.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "motoflex/export/export_input.hpp"

namespace motoflex::detail {

struct ExportedBody {
  const BodySpec* spec = nullptr;
  double mass_kg = 0.0;
  Eigen::Vector3d com_m = Eigen::Vector3d::Zero();          // build pose, robot placed (see below)
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Zero();  // about the CoM
};

// The bodies in model order. The bench servo's arm carries the bench load as the rollout does:
// a point mass bench.mass_kg at bench.length_m from the axis along the URDF arm, with an
// inertia of `bench_arm_inertia_kg_m2` about its CoM (SDF: the armature, as in ODE; MJCF: a
// negligible value, the armature goes onto the joint). All positions are shifted by
// `offset_m` (see placement_offset_m).
std::vector<ExportedBody> exported_bodies(const ExportInput& input, const Eigen::Vector3d& offset_m,
                                          bool armature_in_bench_arm);

// Where the exported robot stands: zero for a fixed base; for a free-floating robot the shift
// that puts the lowest foot point initial_clearance_m above the ground z = 0 in the pose
// `actuator_angles_rad` (the rollout's placement).
Eigen::Vector3d placement_offset_m(const RobotModel& model,
                                   const std::vector<double>& actuator_angles_rad,
                                   double clearance_m);

// "a: b" for the XML comments that say what an export drops.
std::string servo_description(const ExportInput& input);

// The first words of an export's header comment: "Exported by motoflex <version><target> from
// <fit or 'defaults'>; servo <description>" (`target` e.g. " for MuJoCo 2.2.2+", or empty).
std::string export_header(const ExportInput& input, const std::string& target);

}  // namespace motoflex::detail
