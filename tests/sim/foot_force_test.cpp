// The foot force sensors: standing still, the ground carries the robot's weight.

#include <gtest/gtest.h>

#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

double total_mass_kg(const RobotModel& model) {
  double mass = 0.0;
  for (const auto& body : model.bodies) mass += body.mass_kg;
  return mass;
}

TEST(FootForce, StandingRobotsCarryTheirWeightOnTheirFeet) {
  for (const char* robot : {"nao", "titan8"}) {
    SCOPED_TRACE(robot);
    const RobotModel model =
        load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/" + robot, {});
    const ParameterSet parameters(model.parameters);
    RolloutOptions options;
    options.servo = model.default_servo == "motoflex" ? "ideal" : model.default_servo;
    const std::vector<double> pose = model.stand_pose_vector();
    const CommandTrajectory commands = keyframe_trajectory({{0.0, pose}, {3.0, pose}}, 100.0);
    const RolloutResult result = run_rollout(model, parameters, commands, options);
    ASSERT_EQ(result.end, RolloutEnd::kCompleted) << result.end_detail;
    const std::size_t feet = robot == std::string("nao") ? 2 : 4;
    ASSERT_EQ(result.foot_force_z_n.size(), result.frames_completed * feet);
    // After 2 s at rest the feet carry m·g (within 1 %), each foot a positive share.
    const std::size_t frame = result.frames_completed - 1;
    double total_n = 0.0;
    for (std::size_t f = 0; f < feet; ++f) {
      const double force = result.foot_force_z_n[frame * feet + f];
      EXPECT_GT(force, 0.0);
      total_n += force;
    }
    EXPECT_NEAR(total_n, total_mass_kg(model) * 9.81, 0.01 * total_mass_kg(model) * 9.81);
  }
}

}  // namespace
}  // namespace motoflex
