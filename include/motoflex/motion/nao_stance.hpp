#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/nao_leg_kinematics.hpp"

namespace motoflex {

// Whole-body kinematics of a Nao-class robot for motion generation: where the robot's centre of
// mass is for given leg angles (from the model's bodies, so arms and head count), and which leg
// angles put both soles at given world poses while the whole-body CoM sits at a given point and
// the torso stays upright. Built once from a RobotModel; const methods are thread-safe.
class NaoStance {
 public:
  // Throws std::invalid_argument unless the model has the ten Nao leg actuators (LHipRoll …
  // RAnkleRoll) and an upright torso frame at its build configuration.
  // `limits`: which joint limits bound the legs (NaoLegGeometry::of).
  explicit NaoStance(const RobotModel& model, NaoJointLimits limits = NaoJointLimits::kUrdf);

  struct Legs {
    NaoLegAngles left{};
    NaoLegAngles right{};
  };
  struct Solution {
    Legs legs;
    Eigen::Vector3d torso_W_m = Eigen::Vector3d::Zero();  // torso frame origin, world
  };

  const NaoLegGeometry& geometry() const { return geometry_; }
  double mass_kg() const { return mass_kg_; }

  // Whole-body CoM in the (upright) torso frame for the given leg angles.
  Eigen::Vector3d com_in_torso_m(const Legs& legs) const;

  // Torso position and leg angles such that both soles are at the given world poses (yaw 0)
  // and the whole-body CoM is at com_W_m, the torso upright. Fixed-point iteration on the
  // torso position (the CoM offset depends weakly on the leg angles), warm-started from
  // `hint` when given. Throws NaoLegUnreachable when a leg cannot reach, std::runtime_error
  // if the iteration does not converge to 1e-10 m.
  Solution solve(const Eigen::Vector3d& com_W_m, const NaoFootPose& left_sole_W,
                 const NaoFootPose& right_sole_W, const Solution* hint = nullptr) const;

  // The same for feet that may be pitched about an edge (toe-off, swing with the toes down;
  // nao_leg_inverse_edge), world frame; the feet's resulting yaws go to the solution.
  struct EdgeSolution : Solution {
    double left_yaw_rad = 0.0;
    double right_yaw_rad = 0.0;
  };
  EdgeSolution solve(const Eigen::Vector3d& com_W_m, const NaoEdgeFoot& left_W,
                     const NaoEdgeFoot& right_W, const Solution* hint = nullptr) const;

  // Leg angles for an upright torso at torso_W_m (no CoM condition).
  Legs legs_for_torso(const Eigen::Vector3d& torso_W_m, const NaoFootPose& left_sole_W,
                      const NaoFootPose& right_sole_W) const;
  Legs legs_for_torso(const Eigen::Vector3d& torso_W_m, const NaoEdgeFoot& left_W,
                      const NaoEdgeFoot& right_W, double* left_yaw_rad = nullptr,
                      double* right_yaw_rad = nullptr) const;

  // The model's actuator vector (model order) with the leg joints set from `legs` and every
  // other actuator at the robot's stand pose.
  std::vector<double> actuator_angles(const Legs& legs) const;
  void write_actuator_angles(const Legs& legs, double* out) const;

 private:
  // Fixed-point iteration of solve(): `legs_at(torso)` gives the leg angles for a torso position.
  template <typename LegsAt>
  Solution solve_with(const Eigen::Vector3d& com_W_m, const Solution* hint,
                      const LegsAt& legs_at) const;

  const RobotModel* model_;
  NaoLegGeometry geometry_;
  std::array<std::size_t, 5> left_index_{};
  std::array<std::size_t, 5> right_index_{};
  std::vector<double> base_pose_;            // stand pose, model order
  Eigen::Isometry3d X_torsoBody_torsoLink_;  // torso link frame in the torso body frame
  double mass_kg_ = 0.0;
};

}  // namespace motoflex
