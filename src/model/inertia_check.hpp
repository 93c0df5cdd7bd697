#pragma once

// Internal to the URDF reader: is a link's <inertial> a physical rigid body?

#include <Eigen/Core>
#include <string>

namespace motoflex::detail {

// Empty when `mass_kg` and `inertia_kg_m2` (about the CoM) can belong to a rigid body: a mass
// in (kFrameLinkMass_kg, kMaxLinkMass_kg], a symmetric positive-definite inertia whose
// principal moments obey I1 + I2 >= I3 within kInertiaTriangleTolerance; otherwise what is
// wrong, with the numbers. Frame links (mass <= kFrameLinkMass_kg) are not judged.
std::string implausible_inertia(double mass_kg, const Eigen::Matrix3d& inertia_kg_m2);

}  // namespace motoflex::detail
