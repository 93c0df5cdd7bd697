#include "motoflex/motion/nao_leg_kinematics.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "motoflex/model/body_kinematics.hpp"
#include "motoflex/model/robot_loader.hpp"

namespace motoflex {
namespace {

const RobotModel& nao() {
  static const RobotModel model =
      load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/nao", {});
  return model;
}

void expect_pose_near(const NaoFootPose& a, const NaoFootPose& b, double tolerance) {
  EXPECT_NEAR((a.position_m - b.position_m).norm(), 0.0, tolerance);
  EXPECT_NEAR(a.roll_rad, b.roll_rad, tolerance);
  EXPECT_NEAR(a.pitch_rad, b.pitch_rad, tolerance);
  EXPECT_NEAR(a.yaw_rad, b.yaw_rad, tolerance);
}

std::string message_of(LegSide side, const NaoFootPose& target) {
  try {
    nao_leg_inverse(side, target);
  } catch (const NaoLegUnreachable& error) {
    return error.what();
  }
  return "";
}

TEST(NaoLegKinematics, ZeroPoseHasTheSoleStraightBelowTheHip) {
  const NaoLegGeometry g;
  for (const LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    const NaoFootPose pose = nao_leg_forward(side, {0, 0, 0, 0, 0});
    const double y = side == LegSide::kLeft ? 0.05 : -0.05;
    EXPECT_NEAR((pose.position_m - Eigen::Vector3d(0, y, -0.33309)).norm(), 0.0, 1e-12);
    EXPECT_EQ(pose.roll_rad, 0.0);
    EXPECT_EQ(pose.pitch_rad, 0.0);
    EXPECT_EQ(pose.yaw_rad, 0.0);
    EXPECT_NEAR(g.leg_length_m(), 0.2029, 1e-12);
  }
}

TEST(NaoLegKinematics, SignConventionsFollowTheUrdf) {
  // Positive HipPitch swings the leg backward; positive LHipRoll moves the left foot outward.
  EXPECT_LT(nao_leg_forward(LegSide::kLeft, {0, 0.3, 0, 0, 0}).position_m.x(), -0.05);
  EXPECT_GT(nao_leg_forward(LegSide::kLeft, {0.2, 0, 0, 0, 0}).position_m.y(), 0.09);
  EXPECT_LT(nao_leg_forward(LegSide::kRight, {-0.2, 0, 0, 0, 0}).position_m.y(), -0.09);
  // Positive AnklePitch points the toes down: the foot pitches positively (x tips toward −z).
  EXPECT_GT(nao_leg_forward(LegSide::kLeft, {0, 0, 0, 0.2, 0}).pitch_rad, 0.19);
}

// FK(IK(x)) = x over a grid of reachable flat or rolled targets (pitch 0: the foot may roll at
// any lateral position) and pitched targets straight below the hip (hip roll 0).
TEST(NaoLegKinematics, ForwardOfInverseReproducesTheTargetOnAGrid) {
  int solved = 0, unreachable = 0;
  for (const LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    const double hip_y = side == LegSide::kLeft ? 0.05 : -0.05;
    for (double x = -0.06; x <= 0.0601; x += 0.02) {
      for (double dy = -0.02; dy <= 0.0301; dy += 0.01) {
        for (double z = -0.31; z <= -0.2499; z += 0.02) {
          for (double roll = -0.1; roll <= 0.101; roll += 0.1) {
            for (const double pitch : {0.0, -0.2, 0.15}) {
              NaoFootPose target;
              target.position_m = {x, hip_y + (pitch == 0.0 ? dy : 0.0), z};
              target.roll_rad = pitch == 0.0 ? roll : 0.0;
              target.pitch_rad = pitch;
              try {
                const NaoLegAngles q = nao_leg_inverse(side, target);
                expect_pose_near(nao_leg_forward(side, q), target, 1e-9);
                ++solved;
              } catch (const NaoLegUnreachable&) {
                ++unreachable;
              }
            }
          }
        }
      }
    }
  }
  std::printf("[ grid     ] %d targets solved, %d out of reach\n", solved, unreachable);
  EXPECT_GT(solved, 1500);
  EXPECT_LT(unreachable, solved / 4);  // only the corners of the grid are out of reach
}

// IK(FK(q)) = q for joint angles inside the URDF limits whose foot pose has zero yaw.
TEST(NaoLegKinematics, InverseOfForwardRecoversTheAngles) {
  std::mt19937 rng(7);
  const NaoLegGeometry g;
  int checked = 0;
  for (int i = 0; i < 4000 && checked < 500; ++i) {
    const LegSide side = i % 2 ? LegSide::kLeft : LegSide::kRight;
    NaoLegAngles q;
    for (int j = 0; j < 5; ++j) {
      const auto& limit = g.limits(side)[j];
      q[j] = std::uniform_real_distribution<double>(limit[0], limit[1])(rng);
    }
    q[nao_leg::kKneePitch] = std::abs(q[nao_leg::kKneePitch]) + 0.05;  // knee-forward branch
    // Zero yaw: either the foot is flat in pitch (θ = 0) or the hip does not roll.
    if (i % 3 == 0) {
      q[nao_leg::kHipRoll] = 0.0;
    } else {
      q[nao_leg::kAnklePitch] = -q[nao_leg::kHipPitch] - q[nao_leg::kKneePitch];
    }
    bool inside = true;
    for (int j = 0; j < 5; ++j) {
      inside = inside && q[j] >= g.limits(side)[j][0] && q[j] <= g.limits(side)[j][1];
    }
    const NaoFootPose pose = nao_leg_forward(side, q);
    if (!inside || std::abs(pose.yaw_rad) > 1e-12) continue;
    const NaoLegAngles back = nao_leg_inverse(side, pose);
    for (int j = 0; j < 5; ++j) EXPECT_NEAR(back[j], q[j], 1e-8) << "joint " << j;
    ++checked;
  }
  EXPECT_EQ(checked, 500);
}

// The analytic chain agrees with the model's body kinematics built from the URDF.
TEST(NaoLegKinematics, ForwardMatchesTheModelBodyKinematics) {
  const RobotModel& model = nao();
  const NaoLegGeometry g;
  std::mt19937 rng(3);
  const auto hip = model.joints[model.actuators[*model.actuator_index("LHipRoll")].joint];
  const Eigen::Vector3d torso_W0 = hip.anchor_W0_m - g.hip_in_torso_m(LegSide::kLeft);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> angles(model.actuators.size(), 0.0);
    NaoLegAngles left, right;
    for (int j = 0; j < 5; ++j) {
      left[j] = std::uniform_real_distribution<double>(-0.3, 0.3)(rng);
      right[j] = std::uniform_real_distribution<double>(-0.3, 0.3)(rng);
      angles[*model.actuator_index(std::string("L") + nao_leg::kJointNames[j])] = left[j];
      angles[*model.actuator_index(std::string("R") + nao_leg::kJointNames[j])] = right[j];
    }
    const auto poses = body_poses(model, angles);
    for (const LegSide side : {LegSide::kLeft, LegSide::kRight}) {
      const char* prefix = side == LegSide::kLeft ? "L" : "R";
      const JointSpec& ankle =
          model.joints[model.actuators[*model.actuator_index(std::string(prefix) + "AnkleRoll")]
                           .joint];
      const BodySpec& foot = model.bodies[ankle.child_body];
      const Eigen::Isometry3d& X = poses[ankle.child_body];
      const Eigen::Vector3d ankle_W = X * (ankle.anchor_W0_m - foot.com_W0_m);
      const Eigen::Vector3d sole_W = ankle_W + X.linear() * Eigen::Vector3d(0, 0, -g.foot_height_m);
      const NaoFootPose fk = nao_leg_forward(side, side == LegSide::kLeft ? left : right);
      EXPECT_NEAR((fk.position_m - (sole_W - torso_W0)).norm(), 0.0, 1e-12);
    }
  }
}

TEST(NaoLegKinematics, LimitsMatchTheModel) {
  const NaoLegGeometry from_model = NaoLegGeometry::with_limits_of(nao());
  const NaoLegGeometry defaults;
  for (int j = 0; j < 5; ++j) {
    for (int k = 0; k < 2; ++k) {
      EXPECT_DOUBLE_EQ(from_model.left_limits_rad[j][k], defaults.left_limits_rad[j][k]);
      EXPECT_DOUBLE_EQ(from_model.right_limits_rad[j][k], defaults.right_limits_rad[j][k]);
    }
  }
}

// A foot pitched about its toe or heel edge under a hip that is off to the side: the leg has
// no hip yaw, so the foot turns a little (tan ψ = −sin(pitch)·tan(AnkleRoll)), but the edge
// stays on target, horizontal (roll 0) and the pitch is the one asked for; FK(IK(x)) = x.
TEST(NaoLegKinematics, EdgeFootKeepsItsEdgeOnTargetWithTheYawTheLegNeeds) {
  int solved = 0, turned = 0;
  for (const LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    const double hip_y = side == LegSide::kLeft ? 0.05 : -0.05;
    for (const double edge_x : {0.10, -0.05}) {
      for (const double pitch : {0.3, 0.6, -0.2, -0.5}) {
        for (double x = -0.12; x <= 0.1201; x += 0.04) {
          for (double dy = -0.02; dy <= 0.0201; dy += 0.01) {
            for (double z = -0.30; z <= -0.2199; z += 0.02) {
              NaoEdgeFoot target;
              target.edge_m = {x, hip_y + dy, z};
              target.edge_x_m = edge_x;
              target.pitch_rad = pitch;
              double yaw = 1.0;
              NaoLegAngles q;
              try {
                q = nao_leg_inverse_edge(side, target, {}, &yaw);
              } catch (const NaoLegUnreachable&) {
                continue;
              }
              const NaoFootPose fk = nao_leg_forward(side, q);
              const Eigen::Matrix3d R = (Eigen::AngleAxisd(fk.yaw_rad, Eigen::Vector3d::UnitZ()) *
                                         Eigen::AngleAxisd(fk.pitch_rad, Eigen::Vector3d::UnitY()) *
                                         Eigen::AngleAxisd(fk.roll_rad, Eigen::Vector3d::UnitX()))
                                            .matrix();
              const Eigen::Vector3d edge = fk.position_m + R * Eigen::Vector3d(edge_x, 0, 0);
              EXPECT_NEAR((edge - target.edge_m).norm(), 0.0, 1e-9);
              EXPECT_NEAR(fk.pitch_rad, pitch, 1e-9);
              EXPECT_NEAR(fk.roll_rad, 0.0, 1e-9);
              EXPECT_NEAR(fk.yaw_rad, yaw, 1e-9);
              EXPECT_NEAR(std::tan(yaw), -std::sin(pitch) * std::tan(q[nao_leg::kAnkleRoll]),
                          1e-12);
              ++solved;
              if (std::abs(yaw) > 1e-3) ++turned;
            }
          }
        }
      }
    }
  }
  std::printf("[ edges    ] %d pitched targets solved, %d of them turned > 1 mrad\n", solved,
              turned);
  EXPECT_GT(solved, 1000);
  EXPECT_GT(turned, solved / 4);
}

TEST(NaoLegKinematics, EdgeFootWithoutPitchIsTheFlatFoot) {
  NaoEdgeFoot edge;
  edge.edge_m = {0.13, 0.06, -0.28};
  edge.edge_x_m = 0.10;
  NaoFootPose flat;
  flat.position_m = {0.03, 0.06, -0.28};
  double yaw = 1.0;
  const NaoLegAngles a = nao_leg_inverse_edge(LegSide::kLeft, edge, {}, &yaw);
  const NaoLegAngles b = nao_leg_inverse(LegSide::kLeft, flat);
  for (int j = 0; j < 5; ++j) EXPECT_EQ(a[j], b[j]);
  EXPECT_EQ(yaw, 0.0);
  // Out of reach: the same messages as the flat inverse.
  edge.edge_m = {-0.2, 0.05, -0.30};
  edge.pitch_rad = 0.5;
  try {
    nao_leg_inverse_edge(LegSide::kLeft, edge);
    ADD_FAILURE() << "reached";
  } catch (const NaoLegUnreachable& error) {
    EXPECT_NE(std::string(error.what()).find("left leg: "), std::string::npos) << error.what();
  }
}

TEST(NaoLegKinematics, UnreachableTargetsNameTheLimit) {
  NaoFootPose far;
  far.position_m = {0.0, 0.05, -0.34};
  EXPECT_NE(message_of(LegSide::kLeft, far).find("exceeds the leg length 0.2029 m"),
            std::string::npos);

  NaoFootPose behind;  // far back: the hip cannot extend that much
  behind.position_m = {-0.16, 0.05, -0.24};
  const std::string hip = message_of(LegSide::kLeft, behind);
  EXPECT_NE(hip.find("left leg: L"), std::string::npos) << hip;
  EXPECT_NE(hip.find("outside its URDF limits"), std::string::npos) << hip;

  NaoFootPose inward;  // left foot far inside: LHipRoll below −0.3794
  inward.position_m = {0.0, -0.04, -0.27};
  EXPECT_NE(message_of(LegSide::kLeft, inward).find("LHipRoll"), std::string::npos);

  NaoFootPose yawed;
  yawed.position_m = {0.0, 0.05, -0.3};
  yawed.yaw_rad = 0.1;
  EXPECT_NE(message_of(LegSide::kLeft, yawed).find("yaw"), std::string::npos);

  NaoFootPose pitched_aside;  // pitch with the foot off to the side needs HipYawPitch
  pitched_aside.position_m = {0.0, 0.09, -0.28};
  pitched_aside.pitch_rad = 0.2;
  EXPECT_NE(message_of(LegSide::kLeft, pitched_aside).find("HipYawPitch"), std::string::npos);
}

}  // namespace
}  // namespace motoflex
