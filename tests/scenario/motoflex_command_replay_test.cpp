// A 2011 MoToFlex command file replayed as a scenario's motion (read_log_commands recognises the
// format): the left rolls are mirrored in the file, so a row with the same value for the left and
// the right joint is a mirror-symmetric pose, and the feet of the 2011 robot must move
// symmetrically; a positive file LHipRoll moves the left foot inward and a positive RHipRoll the
// right foot inward, as the reference's correlations say (motoflex_2011.md §2.1: file LHipRoll
// vs left foot y −0.92, file RHipRoll vs right foot y +0.91). The original's clock starts the
// replay from the zero pose.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

// Rows of the file: every joint of a leg gets the same value on both sides.
//   HipRoll, HipPitch, KneePitch, AnklePitch, AnkleRoll
std::string command_file(const std::vector<std::vector<double>>& legs) {
  std::string text =
      "LHipRoll;LHipPitch;LKneePitch;LAnklePitch;LAnkleRoll;RHipRoll;RHipPitch;RKneePitch;"
      "RAnklePitch;RAnkleRoll\n";
  for (const auto& leg : legs) {
    for (int side = 0; side < 2; ++side) {
      for (int j = 0; j < 5; ++j) {
        text += std::to_string(leg[j]) + (side == 1 && j == 4 ? "\n" : ";");
      }
    }
  }
  return text;
}

int body_of_link(const RobotModel& model, const std::string& link) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    for (const std::string& name : model.bodies[b].links) {
      if (name == link) return static_cast<int>(b);
    }
  }
  return -1;
}

struct Feet {
  Eigen::Vector3d left = Eigen::Vector3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
};

// Replays the file on the hanging 2011 robot with ideal servos; foot CoMs relative to the torso
// body at the end.
Feet replay(const fs::path& dir, const std::string& file_text, std::vector<double>* first_pose) {
  write_text(dir / "walk.csv", file_text);
  write_text(dir / "scenario.yaml", "robot: " + std::string(MOTOFLEX_SOURCE_DIR) +
                                        "/scenarios/robots/nao_motoflex_2011\nservo: ideal\n"
                                        "physics: {hold_torso: true}\n");
  ScenarioOverrides overrides;
  overrides.motion_log = (dir / "walk.csv").string();
  const Scenario s = load_scenario((dir / "scenario.yaml").string(), overrides);
  const RobotModel& model = *s.model;
  std::vector<double> now(model.actuators.size()), next(now.size());
  for (std::size_t j = 0; j < now.size(); ++j) now[j] = s.commands.angle_rad(0, j);
  if (first_pose != nullptr) *first_pose = now;
  Rollout rollout(model, s.parameters, s.rollout, now);
  const double end_s = s.commands.duration_s() + 0.2;  // the last row, then 0.2 s holding it
  std::size_t hint = 0;
  while (rollout.time_s() < end_s - 1e-9) {
    s.commands.sample(rollout.time_s(), now.data(), hint);
    s.commands.sample(rollout.time_s() + s.rollout.dt_s, next.data(), hint);
    EXPECT_TRUE(rollout.step(now.data(), next.data()));
  }
  const Eigen::Vector3d torso = rollout.body_state(model.torso_body).position_m;
  return {rollout.body_state(body_of_link(model, "l_foot")).position_m - torso,
          rollout.body_state(body_of_link(model, "r_foot")).position_m - torso};
}

TEST(MotoflexCommandReplay, EqualLeftAndRightFileValuesMoveTheFeetSymmetrically) {
  const fs::path dir = fresh_dir("motoflex_replay");
  // Row 0 (never commanded by the original's clock), then a crouch with the hips rolled.
  const std::vector<double> crouch = {0.15, -0.4, 0.8, -0.4, -0.1};
  std::vector<double> first;
  const Feet feet =
      replay(dir, command_file({{0.7, 0.7, 0.7, 0.7, 0.7}, crouch, crouch, crouch}), &first);
  for (const double angle : first) EXPECT_EQ(angle, 0.0);  // starts from the zero pose
  // Mirror images: x and z equal, y opposite (measured: equal to the last digit printed, 1e-12 m).
  EXPECT_NEAR(feet.left.x(), feet.right.x(), 1e-6);
  EXPECT_NEAR(feet.left.z(), feet.right.z(), 1e-6);
  EXPECT_NEAR(feet.left.y(), -feet.right.y(), 1e-6);
  // Both hip rolls at +0.15 in the file move both feet inward from y = ±0.05 m: measured foot CoM
  // y = +0.0210 (left) and −0.0210 m (right) relative to the torso body.
  EXPECT_LT(feet.left.y(), 0.05 - 0.02);
  EXPECT_GT(feet.left.y(), 0.0);
  EXPECT_GT(feet.right.y(), -0.05 + 0.02);
}

TEST(MotoflexCommandReplay, ASignErrorWouldShowAsAsymmetry) {
  // Control: the same values with the left roll written with Aldebaran's sign (negated in the
  // file) is not symmetric; both feet then move to the same side.
  const fs::path dir = fresh_dir("motoflex_replay_control");
  std::string text = command_file({{0, 0, 0, 0, 0}, {0.15, 0, 0, 0, 0}, {0.15, 0, 0, 0, 0}});
  // Flip the file's LHipRoll (first field of the data rows) to −0.15.
  for (std::size_t at = text.find("\n0.150000"); at != std::string::npos;
       at = text.find("\n0.150000", at + 1)) {
    text.replace(at + 1, 8, "-0.150000");
  }
  const Feet feet = replay(dir, text, nullptr);
  EXPECT_GT(feet.left.y() - 0.05, 0.01);   // left foot moved outward (+y) ...
  EXPECT_GT(feet.right.y() + 0.05, 0.01);  // ... and the right foot inward (+y): same side
}

}  // namespace
}  // namespace motoflex::testing
