// TITAN-VIII leg kinematics: the geometry read from the model is the README's, the analytic
// inverse undoes the forward kinematics, and the forward kinematics agrees with both the model's
// body poses and the bodies of an ODE rollout.

#include "motoflex/motion/titan_leg_kinematics.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "motoflex/model/body_kinematics.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

const RobotModel& titan_model() {
  static const RobotModel model = load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/titan8", StructureOptions{});
  return model;
}

const JointSpec& model_joint(const RobotModel& model, const std::string& name) {
  return model.joints[model.actuators[*model.actuator_index(name)].joint];
}

// The mirrored body-frame position of the FL point (x, y, z) for another leg.
Eigen::Vector3d mirrored(TitanLeg leg, double x, double y, double z) {
  const bool fore = leg == TitanLeg::kFL || leg == TitanLeg::kFR;
  const bool left = leg == TitanLeg::kFL || leg == TitanLeg::kHL;
  return {fore ? x : -x, left ? y : -y, z};
}

TEST(TitanLegKinematics, GeometryComesFromTheModelAsTheReadmeDescribes) {
  const TitanKinematics kinematics(titan_model());
  for (const TitanLeg leg : kTitanLegs) {
    const TitanLegGeometry& g = kinematics.geometry(leg);
    const bool left = leg == TitanLeg::kFL || leg == TitanLeg::kHL;
    EXPECT_LT((g.hip_m - mirrored(leg, 0.15, 0.12, 0.0)).norm(), 1e-12) << to_string(leg);
    EXPECT_NEAR(g.zero_heading_rad, left ? std::numbers::pi / 2 : -std::numbers::pi / 2, 1e-12);
    EXPECT_NEAR(g.hip_link_m, 0.05, 1e-12);
    EXPECT_NEAR(g.thigh_m, 0.25, 1e-12);
    EXPECT_NEAR(g.shank_m, 0.20, 1e-12);
    EXPECT_NEAR(g.foot_height_m, 0.043, 1e-12);
    EXPECT_DOUBLE_EQ(g.lower_rad[0], -1.3);
    EXPECT_DOUBLE_EQ(g.upper_rad[2], 1.6);
    // Actuator indices follow robot.yaml: J1..J4 of FL, FR, HL, HR.
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(kinematics.actuators(leg)[i], 4 * static_cast<std::size_t>(leg) + i);
    }
  }
}

TEST(TitanLegKinematics, ZeroPoseIsTheReadmeStandingPose) {
  const TitanKinematics kinematics(titan_model());
  for (const TitanLeg leg : kTitanLegs) {
    const TitanLegPoints p = titan_leg_points(kinematics.geometry(leg), {});
    EXPECT_LT((p.sole_m - mirrored(leg, 0.15, 0.42, -0.243)).norm(), 1e-12) << to_string(leg);
  }
}

TEST(TitanLegKinematics, StandardPostureIsTheModelsStandPose) {
  const TitanKinematics kinematics(titan_model());
  std::array<Eigen::Vector3d, 4> soles;
  for (const TitanLeg leg : kTitanLegs) {
    soles[static_cast<std::size_t>(leg)] = mirrored(leg, 0.25, 0.4028, -0.243);
  }
  const std::vector<double> pose = kinematics.pose_rad(soles);
  const std::vector<double> stand = titan_model().stand_pose_vector();
  ASSERT_EQ(pose.size(), stand.size());
  // The README rounds J1 to 4 decimals and Y to 0.1 mm (the exact GDA point is
  // Y = 0.12 + √0.08 = 0.402843 m), which moves J2/J3 by 2e-4 rad.
  for (std::size_t j = 0; j < pose.size(); ++j) EXPECT_NEAR(pose[j], stand[j], 3e-4) << j;
  // Thigh horizontal, shank vertical up to the rounding of Y = 0.4028.
  for (const TitanLeg leg : kTitanLegs) {
    const TitanLegAngles q = kinematics.leg_angles(leg, pose);
    EXPECT_NEAR(q.j2_rad, 0.0, 1e-4);
    EXPECT_NEAR(q.j2_rad + q.j3_rad, 0.0, 1e-3);
  }
}

TEST(TitanLegKinematics, ForwardOfInverseIsTheTarget) {
  const TitanKinematics kinematics(titan_model());
  double worst_m = 0.0;
  int solved = 0;
  for (const TitanLeg leg : kTitanLegs) {
    const TitanLegGeometry& g = kinematics.geometry(leg);
    for (double x = 0.05; x <= 0.45; x += 0.025) {
      for (double y = 0.25; y <= 0.52; y += 0.0225) {
        for (double z = -0.32; z <= -0.15; z += 0.017) {
          const Eigen::Vector3d target = mirrored(leg, x, y, z);
          TitanLegAngles q;
          try {
            q = titan_leg_ik(g, target);
          } catch (const TitanUnreachable&) {
            continue;  // outside the workspace or the joint limits
          }
          ++solved;
          EXPECT_NEAR(q.j4_rad, -(q.j2_rad + q.j3_rad), 1e-15);
          const TitanLegPoints p = titan_leg_points(g, q);
          worst_m = std::max(worst_m, (p.sole_m - target).norm());
          // The sole is parallel to the body: straight below the ankle.
          EXPECT_NEAR(p.ankle_m.z() - p.sole_m.z(), g.foot_height_m, 1e-12);
        }
      }
    }
  }
  EXPECT_GT(solved, 4000);
  EXPECT_LT(worst_m, 1e-9);
}

TEST(TitanLegKinematics, InverseOfForwardIsTheAngles) {
  const TitanKinematics kinematics(titan_model());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> j1(-1.2, 1.2), j2(-0.6, 0.6), j3(-0.8, 0.8);
  int checked = 0;
  for (const TitanLeg leg : kTitanLegs) {
    const TitanLegGeometry& g = kinematics.geometry(leg);
    for (int k = 0; k < 200; ++k) {
      TitanLegAngles q{j1(rng), j2(rng), j3(rng), 0.0};
      q.j4_rad = -(q.j2_rad + q.j3_rad);
      const TitanLegPoints p = titan_leg_points(g, q);
      // Only the knee-up branch is returned: the knee above the line from J2 to the ankle.
      const Eigen::Vector3d line = p.ankle_m - p.thigh_m;
      const Eigen::Vector3d to_knee = p.knee_m - p.thigh_m;
      const Eigen::Vector3d bend =
          Eigen::Vector3d(line.x(), line.y(), 0).cross(Eigen::Vector3d::UnitZ());
      if (line.cross(to_knee).dot(bend) <= 0.0 || std::abs(q.j4_rad) > 1.5) continue;
      ++checked;
      const TitanLegAngles back = titan_leg_ik(g, p.sole_m);
      EXPECT_NEAR(back.j1_rad, q.j1_rad, 1e-9);
      EXPECT_NEAR(back.j2_rad, q.j2_rad, 1e-9);
      EXPECT_NEAR(back.j3_rad, q.j3_rad, 1e-9);
      EXPECT_NEAR(back.j4_rad, q.j4_rad, 1e-9);
    }
  }
  EXPECT_GT(checked, 300);
}

TEST(TitanLegKinematics, UnreachableTargetsThrowAClearError) {
  const TitanKinematics kinematics(titan_model());
  const TitanLegGeometry& fl = kinematics.geometry(TitanLeg::kFL);
  // Too far: the leg spans at most 0.45 m from J2 to the ankle.
  try {
    titan_leg_ik(fl, {0.25, 0.9, -0.243});
    FAIL() << "expected TitanUnreachable";
  } catch (const TitanUnreachable& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("FL"), std::string::npos) << message;
    EXPECT_NE(message.find("out of reach"), std::string::npos) << message;
  }
  // Too close to J2 (closer than thigh − shank).
  EXPECT_THROW(titan_leg_ik(fl, {0.15, 0.19, 0.0}), TitanUnreachable);
  // Straight below the J1 axis: the heading is undefined.
  EXPECT_THROW(titan_leg_ik(fl, {0.15, 0.12, -0.3}), TitanUnreachable);
  // Reachable, but J1 would pass its ±1.3 rad limit (foot behind the hip, pointing inward).
  try {
    titan_leg_ik(fl, {-0.1, 0.15, -0.243});
    FAIL() << "expected TitanUnreachable";
  } catch (const TitanUnreachable& error) {
    EXPECT_NE(std::string(error.what()).find("J1"), std::string::npos) << error.what();
  }
  EXPECT_THROW(titan_leg_ik(fl, {std::nan(""), 0.4, -0.243}), TitanUnreachable);
}

// Ankle of a leg from the model's pose of its foot body (whose frame sits at the foot's CoM).
Eigen::Vector3d ankle_from_foot_body(const RobotModel& model, const std::string& leg,
                                     const Eigen::Isometry3d& X_WF) {
  const JointSpec& j4 = model_joint(model, leg + "_J4");
  return X_WF * (j4.anchor_W0_m - model.bodies[j4.child_body].com_W0_m);
}

TEST(TitanLegKinematics, ForwardKinematicsMatchesTheModelsBodyPoses) {
  const RobotModel& model = titan_model();
  const TitanKinematics kinematics(model);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(-0.9, 0.9);
  for (int k = 0; k < 20; ++k) {
    std::vector<double> pose(model.actuators.size());
    for (double& q : pose) q = angle(rng);
    const std::vector<Eigen::Isometry3d> poses = body_poses(model, pose);
    for (const TitanLeg leg : kTitanLegs) {
      const std::string name = to_string(leg);
      const JointSpec& j4 = model_joint(model, name + "_J4");
      const TitanLegPoints p =
          titan_leg_points(kinematics.geometry(leg), kinematics.leg_angles(leg, pose));
      const Eigen::Isometry3d& X_WF = poses[j4.child_body];
      EXPECT_LT((ankle_from_foot_body(model, name, X_WF) - p.ankle_m).norm(), 1e-12);
      // The sole centre: foot_height below the ankle along the foot's own −z.
      const Eigen::Vector3d sole_W = ankle_from_foot_body(model, name, X_WF) -
                                     kinematics.geometry(leg).foot_height_m * X_WF.linear().col(2);
      EXPECT_LT((sole_W - p.sole_m).norm(), 1e-12);
    }
  }
}

TEST(TitanLegKinematics, ForwardKinematicsMatchesTheOdeBodies) {
  const RobotModel& model = titan_model();
  const TitanKinematics kinematics(model);
  const ParameterSet parameters(model.parameters);
  RolloutOptions options;
  options.servo = "velocity";
  // An asymmetric pose: every leg at a different point of a posture-B-like stroke, FL lifted.
  const std::array<Eigen::Vector3d, 4> soles = {
      Eigen::Vector3d(0.21, 0.35, -0.20), Eigen::Vector3d(0.30, -0.33, -0.243),
      Eigen::Vector3d(-0.17, 0.36, -0.243), Eigen::Vector3d(-0.33, -0.44, -0.25)};
  const std::vector<double> pose = kinematics.pose_rad(soles);
  const Rollout rollout(model, parameters, options, pose);

  // Body frame of the ODE robot from its root body (placed above the ground, not at W0).
  const Rollout::BodyState root = rollout.body_state(static_cast<std::size_t>(model.root_body));
  const Eigen::Matrix3d R_WB = root.R_WB;
  const Eigen::Vector3d x_WB = root.position_m - R_WB * model.bodies[model.root_body].com_W0_m;

  for (const TitanLeg leg : kTitanLegs) {
    const std::string name = to_string(leg);
    const JointSpec& j4 = model_joint(model, name + "_J4");
    const Rollout::BodyState foot = rollout.body_state(static_cast<std::size_t>(j4.child_body));
    Eigen::Isometry3d X_WF = Eigen::Isometry3d::Identity();
    X_WF.linear() = foot.R_WB;
    X_WF.translation() = foot.position_m;
    const Eigen::Vector3d ankle_B =
        R_WB.transpose() * (ankle_from_foot_body(model, name, X_WF) - x_WB);
    const TitanLegPoints fk =
        titan_leg_points(kinematics.geometry(leg), kinematics.leg_angles(leg, pose));
    EXPECT_LT((ankle_B - fk.ankle_m).norm(), 1e-6) << name;
    // The foot body's CoM itself, 0.0215 m below the ankle with the sole parallel.
    const Eigen::Vector3d foot_com_B = R_WB.transpose() * (X_WF.translation() - x_WB);
    EXPECT_LT((foot_com_B - (fk.ankle_m - Eigen::Vector3d(0, 0, 0.0215))).norm(), 1e-6) << name;
    EXPECT_LT((fk.sole_m - soles[static_cast<std::size_t>(leg)]).norm(), 1e-9) << name;
  }
}

}  // namespace
}  // namespace motoflex
