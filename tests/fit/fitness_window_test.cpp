// fitness.window_s: a fit that simulates and scores only the opening seconds of each log equals,
// bit for bit, a fit on logs cut to that length by hand; bad windows name the field.

#include <gtest/gtest.h>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_config.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

// Keeps the frames with t − t0 <= keep_s.
void cut_log(const fs::path& from, const fs::path& to, double keep_s) {
  JointLog log = read_joint_log(from.string(), JointLogRequirements{});
  std::size_t frames = 0;
  while (frames < log.frames() && log.time_s[frames] - log.time_s[0] <= keep_s + 1e-9) ++frames;
  const std::size_t row = log.joints();
  log.time_s.resize(frames);
  if (log.has_commanded()) log.commanded_rad.resize(frames * row);
  if (log.has_measured()) log.measured_rad.resize(frames * row);
  if (!log.imu_roll_rad.empty()) log.imu_roll_rad.resize(frames);
  if (!log.imu_pitch_rad.empty()) log.imu_pitch_rad.resize(frames);
  fs::create_directories(to.parent_path());
  write_joint_log(to.string(), log);
  if (fs::exists(joint_log_sidecar_path(from.string()))) {
    fs::copy_file(joint_log_sidecar_path(from.string()), joint_log_sidecar_path(to.string()),
                  fs::copy_options::overwrite_existing);
  }
}

TEST(FitnessWindow, EqualsAFitOnLogsCutByHand) {
  const fs::path dir = fresh_dir("fitness_window");
  record_pendulum_log(dir / "data", "sin_sin");
  const double window_s = 1.5;
  cut_log(dir / "data" / "sin_sin.csv", dir / "cut" / "sin_sin.csv", window_s);

  const FitConfig whole = pendulum_fitness_config(dir / "whole", dir / "data", "{m: 2}");
  const FitConfig windowed =
      pendulum_fitness_config(dir / "windowed", dir / "data", "{m: 2, window_s: 1.5}");
  const FitConfig cut = pendulum_fitness_config(dir / "cut_fit", dir / "cut", "{m: 2}");
  const std::size_t whole_frames = whole.train->cases()[0].commands.frames();
  const std::size_t window_frames = windowed.train->cases()[0].commands.frames();
  ASSERT_EQ(window_frames, cut.train->cases()[0].commands.frames());
  ASSERT_LT(window_frames, whole_frames);
  // The last kept frame is the last one within 1.5 s of the start.
  const CommandTrajectory& all = whole.train->cases()[0].commands;
  EXPECT_LE(all.time_s(window_frames - 1) - all.time_s(0), window_s + 1e-9);
  EXPECT_GT(all.time_s(window_frames) - all.time_s(0), window_s);

  // An off-truth point, so that every frame adds error.
  const ParameterSet point = windowed.space->apply(windowed.space->start());
  const FitnessBreakdown a = windowed.train->evaluate(point);
  const FitnessBreakdown b = cut.train->evaluate(point);
  const FitnessBreakdown c = whole.train->evaluate(point);
  EXPECT_EQ(a.fitness, b.fitness);
  EXPECT_EQ(a.cases[0].frames, b.cases[0].frames);
  EXPECT_LT(a.cases[0].frames, c.cases[0].frames);
  EXPECT_NE(windowed.hash, whole.hash);
  EXPECT_EQ(pendulum_fitness_config(dir / "zero", dir / "data", "{m: 2, window_s: 0}").hash,
            whole.hash);
}

TEST(FitnessWindow, BadWindowsNameTheField) {
  const fs::path dir = fresh_dir("fitness_window_bad");
  record_pendulum_log(dir / "data", "sin_sin");
  for (const std::string fitness : {"{m: 2, window_s: -1}", "{m: 2, window_s: 0.001}"}) {
    try {
      pendulum_fitness_config(dir, dir / "data", fitness);
      FAIL() << "accepted " << fitness;
    } catch (const InputError& error) {
      EXPECT_EQ(error.field(), "fitness.window_s") << fitness;
    }
  }
}

}  // namespace
}  // namespace motoflex::testing
