// The TITAN-VIII motion keys of a scenario (titan_crawl, titan_updown, titan_stand): the bundled
// scenarios load into the planned commands, and bad values fail at their field.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "motoflex/core/error.hpp"
#include "motoflex/motion/titan_gait.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "scratch_dir.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

const std::string kScenarios = std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/titan/";

class TitanScenarioTest : public testing::ScratchFolderTest {
 protected:
  std::string write(const std::string& servo, const std::string& motion) {
    const fs::path path = dir_ / "scenario.yaml";
    std::ofstream(path) << "robot: " << MOTOFLEX_SOURCE_DIR << "/scenarios/robots/titan8\n"
                        << "servo: " << servo << "\nmotion:\n"
                        << motion;
    return path.string();
  }
};

TEST_F(TitanScenarioTest, BundledCrawlsLoadThePlannedGait) {
  for (const char* posture : {"A", "B", "C", "D"}) {
    const Scenario scenario = load_scenario(kScenarios + "crawl_" + posture + ".yaml");
    EXPECT_EQ(scenario.model->name, "titan8");
    EXPECT_EQ(scenario.rollout.servo, "velocity");
    EXPECT_EQ(scenario.commands.frames(), 3u * 480u + 1u) << posture;
    EXPECT_EQ(scenario.commands.joints(), 16u);
    EXPECT_DOUBLE_EQ(scenario.log_rate_hz, 100.0);
    EXPECT_NE(scenario.motion_description.find(std::string("posture ") + posture),
              std::string::npos)
        << scenario.motion_description;
    // The default servo lead of the velocity servo is in the commands.
    TitanCrawlOptions options;
    options.posture = *parse_titan_posture(posture);
    options.periods = 3;
    TitanCommandOptions command_options;
    command_options.lead_gain_per_s =
        velocity_servo_gains_per_s(*scenario.model, scenario.parameters);
    const CommandTrajectory expected = titan_command_trajectory(
        TitanKinematics(*scenario.model), TitanCrawl(options), command_options);
    EXPECT_EQ(scenario.commands.angles_rad(), expected.angles_rad()) << posture;
  }
}

TEST_F(TitanScenarioTest, BundledUpDownAndStandLoad) {
  const Scenario updown = load_scenario(kScenarios + "updown.yaml");
  EXPECT_EQ(updown.commands.frames(), 3u * 400u + 1u);
  EXPECT_NE(updown.motion_description.find("up-and-down"), std::string::npos);
  const Scenario stand = load_scenario(kScenarios + "stand.yaml");
  EXPECT_EQ(stand.commands.frames(), 501u);
  const std::vector<double> pose = stand.model->stand_pose_vector();
  for (std::size_t j = 0; j < 16; ++j) EXPECT_NEAR(stand.commands.angle_rad(500, j), pose[j], 3e-4);
}

TEST_F(TitanScenarioTest, PlainCommandsWithoutServoLead) {
  const Scenario scenario =
      load_scenario(write("velocity", "  titan_crawl: {posture: B, servo_lead: false}\n"));
  const CommandTrajectory expected = titan_command_trajectory(
      TitanKinematics(*scenario.model), TitanCrawl(TitanCrawlOptions{.posture = TitanPosture::kB}));
  EXPECT_EQ(scenario.commands.angles_rad(), expected.angles_rad());
  // The ideal servo has no lag to cancel: plain commands by default.
  const Scenario ideal = load_scenario(write("ideal", "  titan_crawl: {posture: B}\n"));
  EXPECT_EQ(ideal.commands.angles_rad(), expected.angles_rad());
}

TEST_F(TitanScenarioTest, BadValuesFailAtTheirField) {
  const auto expect_error = [&](const std::string& servo, const std::string& motion,
                                const std::string& field, const std::string& text) {
    try {
      load_scenario(write(servo, motion));
      ADD_FAILURE() << "expected an InputError for " << motion;
    } catch (const InputError& error) {
      EXPECT_EQ(error.field(), field) << error.what();
      EXPECT_NE(std::string(error.what()).find(text), std::string::npos) << error.what();
    }
  };
  expect_error("velocity", "  titan_crawl: {posture: E}\n", "motion.titan_crawl.posture",
               "A, B, C or D");
  expect_error("velocity", "  titan_crawl: {periods: 0}\n", "motion.titan_crawl.periods", ">= 1");
  expect_error("velocity", "  titan_crawl: {posture: A, stride: 2}\n", "motion.titan_crawl.stride",
               "");
  expect_error("ideal", "  titan_crawl: {servo_lead: true}\n", "motion.titan_crawl.servo_lead",
               "velocity servo");
  expect_error("velocity", "  titan_updown: {amplitude_m: 0.5}\n", "motion.titan_updown",
               "amplitude_m");
  expect_error("velocity", "  titan_stand: {posture: A}\n", "motion.titan_stand.duration_s",
               "duration_s");
  expect_error("velocity", "  titan_stand: {duration_s: 1}\n  stand: {duration_s: 1}\n", "motion",
               "exactly one");
}

TEST_F(TitanScenarioTest, OtherRobotsAreRejected) {
  const fs::path path = dir_ / "nao.yaml";
  std::ofstream(path) << "robot: " << MOTOFLEX_SOURCE_DIR << "/scenarios/robots/nao\n"
                      << "servo: ideal\nmotion:\n  titan_stand: {duration_s: 1}\n";
  try {
    load_scenario(path.string());
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "motion.titan_stand");
    EXPECT_NE(std::string(error.what()).find("FL_J1"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace motoflex
