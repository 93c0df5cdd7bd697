// NaoLegGeometry::of reads a Nao-class robot's leg from its model: our nao gives exactly the
// Aldebaran lengths the planner always used, the 2011 MoToFlex box robot its own shorter tibia
// and taller ankle (nao.md §3.2), and a walk planned for that robot puts its soles where the plan
// says.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "motoflex/model/body_kinematics.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/nao_leg_kinematics.hpp"
#include "motoflex/motion/nao_walk.hpp"

namespace motoflex {
namespace {

RobotModel robot(const std::string& name) {
  return load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/" + name, {});
}

TEST(NaoLegGeometry, OurNaoGivesTheDefaultsBitForBit) {
  const NaoLegGeometry g = NaoLegGeometry::of(robot("nao"));
  const NaoLegGeometry defaults;
  EXPECT_EQ(g.hip_offset_y_m, defaults.hip_offset_y_m);
  EXPECT_EQ(g.hip_offset_z_m, defaults.hip_offset_z_m);
  EXPECT_EQ(g.thigh_m, defaults.thigh_m);
  EXPECT_EQ(g.tibia_m, defaults.tibia_m);
  EXPECT_EQ(g.foot_height_m, defaults.foot_height_m);
}

TEST(NaoLegGeometry, TheOriginalsBoxRobotHasItsOwnLeg) {
  const NaoLegGeometry g = NaoLegGeometry::of(robot("nao_motoflex_2011"));
  EXPECT_EQ(g.hip_offset_y_m, 0.05);             // hip anchors (0, ±0.05, 0.246)
  EXPECT_EQ(g.thigh_m, 0.1);                     // knee at 0.146
  EXPECT_EQ(g.tibia_m, 0.1);                     // ankle at 0.046
  EXPECT_EQ(g.foot_height_m, 0.046);             // foot box bottom on the ground
  EXPECT_EQ(g.left_limits_rad[4][1], 0.768992);  // the real Nao's limits, for the IK
}

// The planned soles, put through the model's own kinematics: at every command frame both soles
// of the 2011 robot lie where the plan put them (relative to each other), flat feet on flat
// ground at the same height when both stand.
TEST(NaoLegGeometry, AWalkPlannedForTheBoxRobotPutsItsSolesWhereThePlanSays) {
  const RobotModel model = robot("nao_motoflex_2011");
  NaoWalkParams params;
  params.speed_mm_s = 50.0;
  params.step_duration_s = 2.0;
  params.duration_s = 6.0;
  const NaoWalkPlan plan = plan_nao_walk(model, params);
  std::vector<double> pose(model.actuators.size());
  double worst_m = 0.0;
  int compared = 0;
  for (std::size_t f = 0; f < plan.samples.size(); f += 10) {
    const NaoWalkSample& s = plan.samples[f];
    if (s.left_foot.pitch_rad != 0.0 || s.right_foot.pitch_rad != 0.0) continue;
    for (std::size_t j = 0; j < pose.size(); ++j) pose[j] = plan.commands.angle_rad(f, j);
    const std::vector<Eigen::Isometry3d> poses = body_poses(model, pose);
    // Lowest corner of each foot box, in the model's frame.
    double lowest[2] = {INFINITY, INFINITY};
    Eigen::Vector3d centre[2];
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      for (const CollisionShape& box : model.bodies[b].collisions) {
        if (box.kind != ShapeKind::kBox) continue;
        if (!box.is_foot) continue;
        const int side = box.link == "l_foot" ? 0 : 1;
        const Eigen::Isometry3d X = poses[b] * box.X_BG;
        centre[side] = X.translation();
        for (int c = 0; c < 8; ++c) {
          const Eigen::Vector3d local(((c & 1) ? 0.5 : -0.5) * box.size_m.x(),
                                      ((c & 2) ? 0.5 : -0.5) * box.size_m.y(),
                                      ((c & 4) ? 0.5 : -0.5) * box.size_m.z());
          lowest[side] = std::min(lowest[side], (X * local).z());
        }
      }
    }
    const Eigen::Vector3d planned = s.left_sole_m - s.right_sole_m;
    const Eigen::Vector3d modelled(centre[0].x() - centre[1].x(), centre[0].y() - centre[1].y(),
                                   lowest[0] - lowest[1]);
    worst_m = std::max(worst_m, (planned - modelled).norm());
    ++compared;
  }
  EXPECT_GT(compared, 20);
  EXPECT_LT(worst_m, 1e-9);  // measured: exact to rounding
}

}  // namespace
}  // namespace motoflex
