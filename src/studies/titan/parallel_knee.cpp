#include "motoflex/studies/titan/parallel_knee.hpp"

#include <Eigen/LU>
#include <stdexcept>

namespace motoflex {
namespace {

Eigen::Matrix3d checked_inverse(const Eigen::Matrix3d& matrix, const char* what) {
  Eigen::Matrix3d inverse;
  bool invertible = false;
  matrix.computeInverseWithCheck(inverse, invertible, 1e-12);
  if (!invertible) throw std::invalid_argument(std::string(what) + " is singular");
  return inverse;
}

}  // namespace

Eigen::Matrix3d serial_to_parallel_angle_map() {
  Eigen::Matrix3d M;
  M << 1.0, 0.0, 0.0,  //
      0.0, 1.0, 0.0,   //
      0.0, 1.0, 1.0;
  return M;
}

Eigen::Matrix3d parallel_leg_jacobian(const Eigen::Matrix3d& serial_jacobian) {
  return serial_jacobian * serial_to_parallel_angle_map().inverse();
}

Eigen::Vector3d parallel_rates_from_jacobians(const Eigen::Matrix3d& serial_jacobian,
                                              const Eigen::Matrix3d& parallel_jacobian,
                                              const Eigen::Vector3d& serial_rates_rad_s) {
  // Seed 000 eq. 1, first line.
  return checked_inverse(parallel_jacobian, "parallel-link Jacobian") * serial_jacobian *
         serial_rates_rad_s;
}

Eigen::Vector3d parallel_torques_from_jacobians(const Eigen::Matrix3d& serial_jacobian,
                                                const Eigen::Matrix3d& parallel_jacobian,
                                                const Eigen::Vector3d& serial_torques_nm) {
  // Seed 000 eq. 1, second line.
  return parallel_jacobian.transpose() *
         checked_inverse(serial_jacobian.transpose(), "serial-link Jacobian") * serial_torques_nm;
}

Eigen::Vector3d parallel_knee_rates(const Eigen::Vector3d& serial_rates_rad_s) {
  return {serial_rates_rad_s.x(), serial_rates_rad_s.y(),
          serial_rates_rad_s.y() + serial_rates_rad_s.z()};
}

Eigen::Vector3d parallel_knee_torques(const Eigen::Vector3d& serial_torques_nm) {
  return {serial_torques_nm.x(), serial_torques_nm.y() - serial_torques_nm.z(),
          serial_torques_nm.z()};
}

}  // namespace motoflex
