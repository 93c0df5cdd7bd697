// The Nao motion keys of a scenario (walk, kick): the bundled scenarios load into the planned
// commands, and bad or infeasible values fail at their field.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "motoflex/core/error.hpp"
#include "motoflex/motion/nao_kick.hpp"
#include "motoflex/motion/nao_walk.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "scratch_dir.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

const std::string kWalks = std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/walks/";

class NaoScenarioTest : public testing::ScratchFolderTest {
 protected:
  std::string write(const std::string& motion) {
    const fs::path path = dir_ / "scenario.yaml";
    std::ofstream(path) << "robot: " << MOTOFLEX_SOURCE_DIR << "/scenarios/robots/nao\n"
                        << "servo: ideal\nmotion:\n"
                        << motion;
    return path.string();
  }
};

TEST_F(NaoScenarioTest, BundledWalksLoadAsPlanned) {
  for (const auto& [speed, duration] : std::vector<std::pair<int, int>>{
           {50, 1}, {100, 1}, {150, 1}, {200, 1}, {50, 2}, {100, 2}, {150, 2}, {200, 2}}) {
    const std::string name = "nao_walk_" + std::to_string(speed) + "_" + std::to_string(duration);
    const Scenario scenario = load_scenario(kWalks + name + ".yaml");
    EXPECT_EQ(scenario.name, name);
    EXPECT_EQ(scenario.rollout.servo, "ideal");
    EXPECT_EQ(scenario.model->structure.flex_sub_bodies, 1);
    EXPECT_DOUBLE_EQ(scenario.rollout.settle_s, 0.5);
    EXPECT_NEAR(scenario.log_rate_hz, 100.0, 1e-9);
    NaoWalkParams p;
    p.speed_mm_s = speed;
    p.step_duration_s = duration;
    if (duration == 2 && speed > 100) {  // 0.15 and 0.2 m steps: toe-off and heel strike
      p.double_support_ratio = 0.4;
      p.toe_off_rad = 0.8;
      p.heel_strike_rad = 0.6;
    }
    const CommandTrajectory expected = nao_walk_trajectory(*scenario.model, p);
    EXPECT_EQ(scenario.commands.angles_rad(), expected.angles_rad()) << name;
    EXPECT_NE(scenario.motion_description.find("walk"), std::string::npos);
  }
  const Scenario kick = load_scenario(kWalks + "nao_kick.yaml");
  EXPECT_EQ(kick.commands.angles_rad(), nao_kick_trajectory(*kick.model, {}).angles_rad());
}

TEST_F(NaoScenarioTest, OptionsReachThePlanner) {
  const Scenario walk = load_scenario(
      write("  walk: {speed_mm_s: 80, step_duration_s: 1.2, duration_s: 6, rate_hz: 50,\n"
            "         com_height_m: 0.245, first_swing: left, toe_off_rad: 0.5,\n"
            "         heel_strike_rad: 0.3}\n"));
  EXPECT_NEAR(walk.commands.duration_s(), 6.0, 1e-9);
  EXPECT_EQ(walk.commands.frames(), 301u);
  NaoWalkParams p;
  p.speed_mm_s = 80;
  p.step_duration_s = 1.2;
  p.duration_s = 6;
  p.rate_hz = 50;
  p.com_height_m = 0.245;
  p.first_swing_left = true;
  p.toe_off_rad = 0.5;
  p.heel_strike_rad = 0.3;
  EXPECT_EQ(walk.commands.angles_rad(), nao_walk_trajectory(*walk.model, p).angles_rad());

  const Scenario kick = load_scenario(write("  kick: {kick_leg: left, reach_m: 0.08}\n"));
  NaoKickParams k;
  k.kick_left = true;
  k.reach_m = 0.08;
  EXPECT_EQ(kick.commands.angles_rad(), nao_kick_trajectory(*kick.model, k).angles_rad());
}

TEST_F(NaoScenarioTest, InfeasibleValuesFailAtTheirField) {
  struct Case {
    std::string motion;
    int line;  // of the offending key (line 1 is robot:, 3 is motion:)
    std::string field;
    std::string message_start;
  };
  for (const Case& c : std::vector<Case>{
           {"  walk:\n    step_duration_s: 1\n    speed_mm_s: 400\n", 6, "motion.walk.speed_mm_s",
            "speed_mm_s = 400: step length 0.200 m"},
           {"  walk:\n    com_height_m: 0.31\n", 5, "motion.walk.com_height_m",
            "com_height_m = 0.31: out of reach"},
           {"  walk:\n    speed_mm_s: 100\n    step_duration_s: 0\n", 6,
            "motion.walk.step_duration_s", "step_duration_s = 0: must be positive"},
           {"  walk:\n    speed_mm_s: 200\n    step_duration_s: 2\n", 5, "motion.walk.speed_mm_s",
            "speed_mm_s = 200"},
           {"  walk: {first_swing: middle}\n", 4, "motion.walk.first_swing",
            "expected 'left' or 'right'"},
           {"  walk: {joint_limits: none}\n", 4, "motion.walk.joint_limits",
            "expected 'urdf' (the URDF's limits) or 'stops'"},
           {"  walk:\n    speed_mm_s: 100\n    toe_off_rad: 1.5\n", 6, "motion.walk.toe_off_rad",
            "toe_off_rad = 1.5: must be within [0, 1] rad"},
           {"  walk:\n    speed_mm_s: 250\n    step_duration_s: 2\n    toe_off_rad: 0.8\n"
            "    heel_strike_rad: 0.6\n    double_support_ratio: 0.4\n",
            5, "motion.walk.speed_mm_s", "speed_mm_s = 250: step length 0.250 m"},
           {"  walk: {speed: 100}\n", 4, "motion.walk.speed", ""},
           {"  kick:\n    reach_m: 0.3\n", 4, "motion.kick", "kick phase 'kick'"},
           {"  kick:\n    kick_s: -1\n", 5, "motion.kick.kick_s", "kick_s = -1: must be positive"},
       }) {
    try {
      load_scenario(write(c.motion));
      ADD_FAILURE() << "expected an InputError for " << c.motion;
    } catch (const InputError& error) {
      EXPECT_EQ(error.line(), c.line) << error.what();
      EXPECT_EQ(error.field(), c.field) << error.what();
      EXPECT_EQ(error.message().rfind(c.message_start, 0), 0u) << error.what();
    }
  }
}

TEST_F(NaoScenarioTest, WalkNeedsANao) {
  const fs::path path = dir_ / "titan_walk.yaml";
  std::ofstream(path) << "robot: " << MOTOFLEX_SOURCE_DIR << "/scenarios/robots/titan8\n"
                      << "servo: ideal\nmotion:\n  walk: {speed_mm_s: 100}\n";
  try {
    load_scenario(path.string());
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "motion.walk");
    EXPECT_NE(error.message().find("LHipRoll"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace motoflex
