#pragma once

#include <Eigen/Core>
#include <array>

#include "motoflex/studies/titan/joint_wrench.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/titan_leg_kinematics.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {

// One TITAN-VIII leg at the end of one physics step. Joint order J1 … J4; torques are what the
// joint applies to its distal (child) body about the joint axis in the model's positive
// direction, i.e. the actuator torque, in the serial-link coordinates of the model.
struct TitanLegSample {
  std::array<double, 4> angle_rad{};
  std::array<double, 4> rate_rad_s{};
  // Seed 000 eq. 4–5: the 6-axis joint feedback moved to the joint point, projected on the axis.
  std::array<double, 4> feedback_torque_nm{};
  // Seed 000 eq. 7 with r_a and F at J4: F is the force J4 transmits to the foot.
  std::array<double, 3> jacobian_torque_nm{};
  Eigen::Vector3d ankle_force_n = Eigen::Vector3d::Zero();  // F of eq. 7, world frame
  // Knee (J3) load in the paper's sign (left side of eq. 4, inverted): the force and the moment
  // about the knee point that the shank exerts on the knee, world frame. Standing, its z
  // component is the weight carried above the knee.
  JointWrench knee_load;
  double knee_third_law_residual_n = 0.0;  // |f1 + f2| of the knee (eq. 4, first line)
};

// Reads joint torques of a TITAN-VIII rollout from ODE's joint feedback. It turns feedback on
// for the 16 leg joints of `rollout` (Rollout::enable_joint_feedback); it must not outlive the
// rollout. Call before_step() right
// before and after_step() right after every Rollout::step(): the feedback of a step was
// computed with the joint anchors and body CoMs at the *start* of the step, which before_step
// records, so eq. 4 is evaluated on the exact lever arms ODE used (ode_and_titan8.md §2.1).
// Needs hinge joints with body 1 = child (Rollout's convention) and the leg layout that
// TitanKinematics checks.
class TitanTorqueProbe {
 public:
  TitanTorqueProbe(const RobotModel& model, const TitanKinematics& kinematics, Rollout& rollout);
  TitanTorqueProbe(const TitanTorqueProbe&) = delete;
  TitanTorqueProbe& operator=(const TitanTorqueProbe&) = delete;

  void before_step();
  void after_step();

  const TitanLegSample& leg(TitanLeg leg) const { return samples_[index(leg)]; }
  const Rollout& rollout() const { return rollout_; }

  // Lowest point of the leg's foot contact boxes above the ground [m] (≤ 0 in contact).
  double foot_clearance_m(TitanLeg leg) const;
  // Whole robot, from the current ODE state: Σ m g·h [J] and Σ ½mv² + ½ωᵀIω [J].
  double potential_energy_j() const;
  double kinetic_energy_j() const;

 private:
  struct JointRef {
    std::size_t joint = 0;  // model joint
    std::size_t child = 0;  // model bodies
    std::size_t parent = 0;
    std::size_t actuator = 0;
  };
  struct Geometry {  // start-of-step configuration
    Eigen::Vector3d anchor_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d child_com_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d parent_com_m = Eigen::Vector3d::Zero();
  };
  static std::size_t index(TitanLeg leg) { return static_cast<std::size_t>(leg); }

  const RobotModel& model_;
  const Rollout& rollout_;
  std::array<std::array<JointRef, 4>, 4> joints_{};
  std::array<std::array<Geometry, 4>, 4> geometry_{};
  std::array<int, 4> foot_body_{};
  std::array<TitanLegSample, 4> samples_{};
};

}  // namespace motoflex
