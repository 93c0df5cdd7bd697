#include "inertia_check.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "motoflex/model/urdf_tree.hpp"

namespace motoflex::detail {

std::string implausible_inertia(double mass_kg, const Eigen::Matrix3d& inertia_kg_m2) {
  std::ostringstream out;
  if (!std::isfinite(mass_kg) || mass_kg < 0.0) {
    out << "mass " << mass_kg << " kg: must be finite and >= 0";
    return out.str();
  }
  if (mass_kg <= kFrameLinkMass_kg) return {};  // a frame link: no mass of its own
  if (mass_kg > kMaxLinkMass_kg) {
    out << "mass " << mass_kg << " kg is above 10 t: not a robot link (units?)";
    return out.str();
  }
  if (!inertia_kg_m2.allFinite()) return "inertia has a non-finite entry";
  const Eigen::Vector3d moments =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia_kg_m2).eigenvalues();
  if (!(moments.minCoeff() > 0.0)) {
    out << "inertia is not positive definite (principal moments " << moments(0) << ", "
        << moments(1) << ", " << moments(2) << " kg·m²)";
    return out.str();
  }
  if (moments(0) + moments(1) < moments(2) * (1.0 - kInertiaTriangleTolerance)) {
    out << "principal moments " << moments(0) << ", " << moments(1) << ", " << moments(2)
        << " kg·m² break the triangle inequality I1 + I2 >= I3: not a physical inertia tensor";
    return out.str();
  }
  return {};
}

}  // namespace motoflex::detail
