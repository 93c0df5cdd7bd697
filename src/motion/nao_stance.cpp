#include "motoflex/motion/nao_stance.hpp"

#include <stdexcept>
#include <string>

#include "motoflex/model/body_kinematics.hpp"

namespace motoflex {
namespace {

constexpr double kSolveTolerance_m = 1e-10;
constexpr int kMaxSolveIterations = 60;

std::size_t actuator(const RobotModel& model, const std::string& name) {
  const auto index = model.actuator_index(name);
  if (!index) {
    throw std::invalid_argument("robot '" + model.name + "' has no actuated joint " + name +
                                " (Nao motions need the ten leg joints)");
  }
  return *index;
}

}  // namespace

NaoStance::NaoStance(const RobotModel& model, NaoJointLimits limits)
    : model_(&model), geometry_(NaoLegGeometry::of(model, limits)) {
  for (int j = 0; j < 5; ++j) {
    left_index_[j] = actuator(model, std::string("L") + nao_leg::kJointNames[j]);
    right_index_[j] = actuator(model, std::string("R") + nao_leg::kJointNames[j]);
  }
  base_pose_ = model.stand_pose_vector();
  for (const BodySpec& body : model.bodies) mass_kg_ += body.mass_kg;

  // The torso link frame in the torso body frame: at the build configuration the hip joint
  // (where HipRoll's axis is anchored) sits at hip_in_torso_m in the torso link frame.
  const Eigen::Matrix3d& R = model.R_torsoBody_torsoLink;
  if (!R.isApprox(Eigen::Matrix3d::Identity(), 1e-9)) {
    throw std::invalid_argument("robot '" + model.name +
                                "': the torso link is not upright at the build configuration");
  }
  const Eigen::Vector3d hip_W0 =
      model.joints[model.actuators[left_index_[nao_leg::kHipRoll]].joint].anchor_W0_m;
  const Eigen::Vector3d torso_origin_W0 = hip_W0 - R * geometry_.hip_in_torso_m(LegSide::kLeft);
  X_torsoBody_torsoLink_.setIdentity();
  X_torsoBody_torsoLink_.linear() = R;
  X_torsoBody_torsoLink_.translation() = torso_origin_W0 - model.bodies[model.torso_body].com_W0_m;
}

void NaoStance::write_actuator_angles(const Legs& legs, double* out) const {
  for (std::size_t i = 0; i < base_pose_.size(); ++i) out[i] = base_pose_[i];
  for (int j = 0; j < 5; ++j) {
    out[left_index_[j]] = legs.left[j];
    out[right_index_[j]] = legs.right[j];
  }
}

std::vector<double> NaoStance::actuator_angles(const Legs& legs) const {
  std::vector<double> out(base_pose_.size());
  write_actuator_angles(legs, out.data());
  return out;
}

Eigen::Vector3d NaoStance::com_in_torso_m(const Legs& legs) const {
  const std::vector<Eigen::Isometry3d> poses = body_poses(*model_, actuator_angles(legs));
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (std::size_t b = 0; b < poses.size(); ++b) {
    moment += model_->bodies[b].mass_kg * poses[b].translation();
  }
  const Eigen::Isometry3d X_W_torso = poses[model_->torso_body] * X_torsoBody_torsoLink_;
  return X_W_torso.inverse() * Eigen::Vector3d(moment / mass_kg_);
}

NaoStance::Legs NaoStance::legs_for_torso(const Eigen::Vector3d& torso_W_m,
                                          const NaoFootPose& left_sole_W,
                                          const NaoFootPose& right_sole_W) const {
  NaoFootPose left = left_sole_W, right = right_sole_W;
  left.position_m -= torso_W_m;
  right.position_m -= torso_W_m;
  return {nao_leg_inverse(LegSide::kLeft, left, geometry_),
          nao_leg_inverse(LegSide::kRight, right, geometry_)};
}

NaoStance::Legs NaoStance::legs_for_torso(const Eigen::Vector3d& torso_W_m,
                                          const NaoEdgeFoot& left_W, const NaoEdgeFoot& right_W,
                                          double* left_yaw_rad, double* right_yaw_rad) const {
  NaoEdgeFoot left = left_W, right = right_W;
  left.edge_m -= torso_W_m;
  right.edge_m -= torso_W_m;
  return {nao_leg_inverse_edge(LegSide::kLeft, left, geometry_, left_yaw_rad),
          nao_leg_inverse_edge(LegSide::kRight, right, geometry_, right_yaw_rad)};
}

template <typename LegsAt>
NaoStance::Solution NaoStance::solve_with(const Eigen::Vector3d& com_W_m, const Solution* hint,
                                          const LegsAt& legs_at) const {
  Solution solution;
  Eigen::Vector3d offset;
  if (hint != nullptr) {
    offset = com_in_torso_m(hint->legs);
  } else {
    // First guess: the offset with the torso straight above the feet at the CoM height.
    offset = Eigen::Vector3d(0.0, 0.0, -0.06);
  }
  solution.torso_W_m = com_W_m - offset;
  for (int iteration = 0; iteration < kMaxSolveIterations; ++iteration) {
    solution.legs = legs_at(solution.torso_W_m);
    const Eigen::Vector3d next = com_W_m - com_in_torso_m(solution.legs);
    const double change = (next - solution.torso_W_m).norm();
    solution.torso_W_m = next;
    if (change < kSolveTolerance_m) {
      solution.legs = legs_at(solution.torso_W_m);
      return solution;
    }
  }
  throw std::runtime_error("Nao stance: torso position for the requested CoM did not converge");
}

NaoStance::Solution NaoStance::solve(const Eigen::Vector3d& com_W_m, const NaoFootPose& left_sole_W,
                                     const NaoFootPose& right_sole_W, const Solution* hint) const {
  return solve_with(com_W_m, hint, [&](const Eigen::Vector3d& torso_W_m) {
    return legs_for_torso(torso_W_m, left_sole_W, right_sole_W);
  });
}

NaoStance::EdgeSolution NaoStance::solve(const Eigen::Vector3d& com_W_m, const NaoEdgeFoot& left_W,
                                         const NaoEdgeFoot& right_W, const Solution* hint) const {
  EdgeSolution solution;
  static_cast<Solution&>(solution) = solve_with(com_W_m, hint, [&](const Eigen::Vector3d& torso) {
    return legs_for_torso(torso, left_W, right_W, &solution.left_yaw_rad, &solution.right_yaw_rad);
  });
  return solution;
}

}  // namespace motoflex
