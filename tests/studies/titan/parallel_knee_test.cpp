// Seed 000 eq. 1: the serial ↔ parallel-link knee conversion, checked against finite
// differences of the TITAN-VIII leg kinematics in both coordinate sets. The parallel-link
// coordinates come from an independent model of the four-bar (Fig. 2b): a crank at the thigh
// joint, turned by the knee actuator from the vertical, and a coupler as long as the thigh,
// closed by solving the loop for the shank — not from the substitution θ3p = θ2 + θ3 that the
// code under test implements.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/titan_leg_kinematics.hpp"
#include "motoflex/studies/titan/leg_jacobian_torque.hpp"
#include "motoflex/studies/titan/parallel_knee.hpp"

namespace motoflex {
namespace {

const TitanLegGeometry& fl_geometry() {
  static const RobotModel model = load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/titan8", StructureOptions{});
  static const TitanKinematics kinematics(model);
  return kinematics.geometry(TitanLeg::kFL);
}

// Ankle (J4, the paper's r_a) of the serial model for θ_s = (θ1, θ2, θ3).
Eigen::Vector3d ankle_serial(const Eigen::Vector3d& q) {
  return titan_leg_points(fl_geometry(), {q.x(), q.y(), q.z(), 0.0}).ankle_m;
}

// The four-bar (Fig. 2b): the knee actuator at the thigh joint T turns a crank of length r to
// the angle γ from the downward vertical, about the J2/J3 axis; a coupler as long as the thigh
// links the crank tip C to the point S on the shank, r below the knee K. Given γ,
// the loop |S(q3) − C(γ)| = |K − T| fixes the serial knee angle q3 (Newton's method on the
// branch that starts at the crank's own angle), and the ankle follows from the serial leg.
constexpr double kCrank_m = 0.04;

Eigen::Vector3d rotate_about(const Eigen::Vector3d& v, const Eigen::Vector3d& axis, double a) {
  return Eigen::AngleAxisd(a, axis.normalized()) * v;
}

double four_bar_knee_angle(const Eigen::Vector3d& p) {
  const TitanLegGeometry& g = fl_geometry();
  const auto points = [&](double q3) { return titan_leg_points(g, {p.x(), p.y(), q3, 0.0}); };
  const TitanLegPoints at_zero = points(0.0);
  const double heading = g.zero_heading_rad + p.x();
  const Eigen::Vector3d out(std::cos(heading), std::sin(heading), 0.0);
  const Eigen::Vector3d axis = out.cross(Eigen::Vector3d::UnitZ());  // J2, J3 axis
  const Eigen::Vector3d crank_tip =
      at_zero.thigh_m + kCrank_m * rotate_about(-Eigen::Vector3d::UnitZ(), axis, p.z());
  const double coupler_m = (at_zero.knee_m - at_zero.thigh_m).norm();
  // Closure residual: |S − C| − coupler, with S on the shank's extension above the knee.
  const auto residual = [&](double q3) {
    const TitanLegPoints leg = points(q3);
    const Eigen::Vector3d shank_down = (leg.ankle_m - leg.knee_m).normalized();
    return (leg.knee_m + kCrank_m * shank_down - crank_tip).norm() - coupler_m;
  };
  // Start where the shank hangs vertically (q3 = −q2) and let Newton find the closure.
  double q3 = -p.y();
  for (int k = 0; k < 50; ++k) {
    constexpr double h = 1e-7;
    const double f = residual(q3);
    const double slope = (residual(q3 + h) - residual(q3 - h)) / (2 * h);
    const double step = f / slope;
    q3 -= step;
    if (std::abs(step) < 1e-14) break;
  }
  return q3;
}

// The ankle in parallel-link coordinates θ_p = (θ1, θ2, γ), through the four-bar above.
Eigen::Vector3d ankle_parallel(const Eigen::Vector3d& p) {
  return titan_leg_points(fl_geometry(), {p.x(), p.y(), four_bar_knee_angle(p), 0.0}).ankle_m;
}

template <typename F>
Eigen::Matrix3d finite_difference_jacobian(F f, const Eigen::Vector3d& q) {
  constexpr double h = 1e-6;
  Eigen::Matrix3d J;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d a = q, b = q;
    a[i] += h;
    b[i] -= h;
    J.col(i) = (f(a) - f(b)) / (2 * h);
  }
  return J;
}

const Eigen::Vector3d kSerialAngles(-0.3398 + 0.2, -0.08, 0.25);  // a stance posture of FL
const Eigen::Vector3d kParallelAngles(kSerialAngles.x(), kSerialAngles.y(),
                                      kSerialAngles.y() + kSerialAngles.z());

TEST(ParallelKnee, AnalyticSerialJacobianMatchesFiniteDifferences) {
  const TitanLegPoints points = titan_leg_points(
      fl_geometry(), {kSerialAngles.x(), kSerialAngles.y(), kSerialAngles.z(), 0.0});
  const double heading = fl_geometry().zero_heading_rad + kSerialAngles.x();
  const Eigen::Vector3d out(std::cos(heading), std::sin(heading), 0.0);
  const Eigen::Vector3d across = out.cross(Eigen::Vector3d::UnitZ());  // J2, J3 axis
  const Eigen::Matrix3d analytic = serial_leg_jacobian(
      {JointAxisFrame{points.hip_m, Eigen::Vector3d::UnitZ()},
       JointAxisFrame{points.thigh_m, across}, JointAxisFrame{points.knee_m, across}},
      points.ankle_m);
  const Eigen::Matrix3d numeric = finite_difference_jacobian(ankle_serial, kSerialAngles);
  EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 1e-8) << analytic << "\n" << numeric;
}

TEST(ParallelKnee, TheFourBarKeepsTheShankParallelToTheCrank) {
  // An independent check of the coordinate map: the loop closure, solved numerically, gives
  // the serial knee angle γ − θ2 (the parallelogram keeps the shank parallel to the crank). The
  // Newton solve converges to ~1e-12 rad here.
  for (const double gamma : {-0.3, 0.0, 0.17, 0.4}) {
    const Eigen::Vector3d p(kSerialAngles.x(), kSerialAngles.y(), gamma);
    EXPECT_NEAR(four_bar_knee_angle(p), gamma - kSerialAngles.y(), 1e-9) << gamma;
  }
}

TEST(ParallelKnee, ParallelJacobianMatchesFiniteDifferencesOfTheFourBar) {
  const Eigen::Matrix3d Js = finite_difference_jacobian(ankle_serial, kSerialAngles);
  const Eigen::Matrix3d Jp = finite_difference_jacobian(ankle_parallel, kParallelAngles);
  EXPECT_LT((parallel_leg_jacobian(Js) - Jp).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT((serial_to_parallel_angle_map() * kSerialAngles - kParallelAngles).norm(), 1e-15);
}

TEST(ParallelKnee, EquationOneAgreesWithTheClosedFormAndKinematics) {
  const Eigen::Matrix3d Js = finite_difference_jacobian(ankle_serial, kSerialAngles);
  const Eigen::Matrix3d Jp = finite_difference_jacobian(ankle_parallel, kParallelAngles);
  const Eigen::Vector3d rates_s(0.3, -0.2, 0.5), torques_s(1.5, -12.0, 2.5);

  // Rates: the parallel angles of a short serial motion, differenced, are eq. 1's θ̇_p.
  constexpr double dt = 1e-6;
  const Eigen::Vector3d moved_p = serial_to_parallel_angle_map() * (kSerialAngles + rates_s * dt);
  const Eigen::Vector3d numeric_rates_p = (moved_p - kParallelAngles) / dt;
  const Eigen::Vector3d eq1_rates = parallel_rates_from_jacobians(Js, Jp, rates_s);
  EXPECT_LT((eq1_rates - numeric_rates_p).norm(), 1e-6);
  EXPECT_LT((eq1_rates - parallel_knee_rates(rates_s)).norm(), 1e-6);
  EXPECT_NEAR(eq1_rates.z(), rates_s.y() + rates_s.z(), 1e-6);

  // Torques: eq. 1 equals the closed form (τ1, τ2 − τ3, τ3) ...
  const Eigen::Vector3d eq1_torques = parallel_torques_from_jacobians(Js, Jp, torques_s);
  EXPECT_LT((eq1_torques - parallel_knee_torques(torques_s)).norm(), 1e-6);
  // ... both hold the same foot force (τ = Jᵀ F in each model) ...
  const Eigen::Vector3d force = Js.transpose().inverse() * torques_s;
  EXPECT_LT((Jp.transpose() * force - eq1_torques).norm(), 1e-6);
  // ... and the power is the same in both coordinates.
  EXPECT_NEAR(eq1_torques.dot(eq1_rates), torques_s.dot(rates_s), 1e-6);
}

TEST(ParallelKnee, SingularJacobianIsReported) {
  Eigen::Matrix3d singular = Eigen::Matrix3d::Identity();
  singular.col(2) = singular.col(1);
  EXPECT_THROW(parallel_torques_from_jacobians(singular, singular, Eigen::Vector3d::Ones()),
               std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
