// `motoflex fit` / `motoflex resume` as a user runs them: killed runs resume exactly, SIGTERM
// checkpoints and exits cleanly, bad input is one line and exit code 2 with nothing overwritten.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <random>
#include <thread>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"

extern char** environ;

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const char* kSmallEs = "{kind: mu_plus_lambda, mu: 4, lambda: 12, kappa: 3}";

std::size_t generations_written(const fs::path& run_dir) {
  std::ifstream in(run_dir / "generations.csv");
  std::size_t lines = 0;
  std::string line;
  while (std::getline(in, line)) ++lines;
  return lines == 0 ? 0 : lines - 1;
}

// Starts `motoflex fit ...` in the background (stdout to a file) and returns its pid.
pid_t spawn_fit(const std::string& fit, const fs::path& out, const fs::path& log) {
  const std::string binary = MOTOFLEX_TEST_BINARY;
  const std::string out_text = out.string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = {binary, "fit", fit, "--out", out_text};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

bool wait_for_generations(const fs::path& run_dir, std::size_t count, pid_t pid) {
  for (int i = 0; i < 6000; ++i) {
    if (generations_written(run_dir) >= count) return true;
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return false;  // finished too early
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(FitCli, KilledAtARandomGenerationAndResumedEndsIdentical) {
  const fs::path dir = fresh_dir("fit_kill");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit = write_pendulum_fit(dir, dir / "data", kSmallEs, "{generations: 10}");
  ASSERT_EQ(run_motoflex("fit " + fit + " --out " + (dir / "whole").string()).exit_code, 0);

  std::random_device device;
  const std::size_t kill_after = 2 + device() % 5;  // 2..6
  std::printf("killing after generation %zu\n", kill_after);
  const pid_t pid = spawn_fit(fit, dir / "killed", dir / "killed.log");
  ASSERT_TRUE(wait_for_generations(dir / "killed", kill_after, pid));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_LT(generations_written(dir / "killed"), 10u);

  const auto resumed = run_motoflex("resume " + (dir / "killed").string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.stderr_text;
  EXPECT_EQ(generations_without_seconds(dir / "whole"),
            generations_without_seconds(dir / "killed"));
  EXPECT_EQ(best_without_date(dir / "whole"), best_without_date(dir / "killed"));
}

TEST(FitCli, SigtermWritesACheckpointAndExitsCleanly) {
  const fs::path dir = fresh_dir("fit_term");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit = write_pendulum_fit(dir, dir / "data", kSmallEs, "{generations: 200}");
  const pid_t pid = spawn_fit(fit, dir / "run", dir / "run.log");
  ASSERT_TRUE(wait_for_generations(dir / "run", 2, pid));
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 4);  // exit_code::kInterrupted
  EXPECT_TRUE(fs::exists(dir / "run" / "checkpoint.json"));
  EXPECT_TRUE(fs::exists(dir / "run" / "best.json"));
  EXPECT_NE(read_text(dir / "run.log").find("interrupted"), std::string::npos);
  EXPECT_LT(generations_written(dir / "run"), 200u);
}

TEST(FitCli, TwoWritersCannotShareAFolder) {
  const fs::path dir = fresh_dir("fit_two_writers");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit = write_pendulum_fit(dir, dir / "data", kSmallEs, "{generations: 200}");
  const pid_t pid = spawn_fit(fit, dir / "run", dir / "run.log");
  ASSERT_TRUE(wait_for_generations(dir / "run", 1, pid));
  const std::string rows_before = read_text(dir / "run" / "generations.csv");
  // A second fit and a resume into the running fit's folder fail at once, naming its PID.
  for (const std::string& command :
       {"fit " + fit + " --out " + (dir / "run").string(), "resume " + (dir / "run").string()}) {
    const CommandResult second = run_motoflex(command);
    EXPECT_EQ(second.exit_code, 2) << command;
    EXPECT_NE(second.stderr_text.find("pid " + std::to_string(pid)), std::string::npos)
        << second.stderr_text;
  }
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  // The first fit's rows are all its own: one row per generation, numbered 1, 2, 3, ...
  std::ifstream csv(dir / "run" / "generations.csv");
  std::string line;
  std::getline(csv, line);
  for (std::size_t expected = 1; std::getline(csv, line); ++expected) {
    EXPECT_EQ(std::stoul(line.substr(0, line.find(','))), expected) << line;
  }
  EXPECT_FALSE(rows_before.empty());
}

TEST(FitCli, FolderKilledBeforeItsFirstCheckpointSaysRerunFit) {
  const fs::path dir = fresh_dir("fit_no_checkpoint");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit = write_pendulum_fit(dir, dir / "data", kSmallEs, "{generations: 2}");
  fs::create_directories(dir / "run");
  write_text(dir / "run" / "run.json", "{\"fit\": \"" + fit + "\", \"overrides\": {}}");
  write_text(dir / "run" / ".checkpoint.json.tmp-1-0-1", "{\"half");
  const CommandResult resumed = run_motoflex("resume " + (dir / "run").string());
  EXPECT_EQ(resumed.exit_code, 2);
  EXPECT_NE(resumed.stderr_text.find("motoflex fit " + fit), std::string::npos)
      << resumed.stderr_text;
  // Fit then starts over in that folder and removes the killed run's temporary file.
  const CommandResult again = run_motoflex("fit " + fit + " --out " + (dir / "run").string());
  EXPECT_EQ(again.exit_code, 0) << again.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "run" / ".checkpoint.json.tmp-1-0-1"));
  EXPECT_TRUE(fs::exists(dir / "run" / "checkpoint.json"));
}

TEST(FitCli, ResumeAfterGenerationsCsvWasDeletedSaysSoAndGoesOn) {
  const fs::path dir = fresh_dir("fit_no_generations_csv");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit = write_pendulum_fit(dir, dir / "data", kSmallEs, "{generations: 2}");
  ASSERT_EQ(run_motoflex("fit " + fit + " --out " + (dir / "run").string()).exit_code, 0);
  fs::remove(dir / "run" / "generations.csv");
  const CommandResult resumed =
      run_motoflex("resume " + (dir / "run").string() + " --max-generations 3");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.stderr_text;
  EXPECT_NE(resumed.stderr_text.find("generations.csv: missing"), std::string::npos)
      << resumed.stderr_text;
  // The new file has its header and only the generation run after the checkpoint.
  std::ifstream csv(dir / "run" / "generations.csv");
  std::string header, row, extra;
  ASSERT_TRUE(std::getline(csv, header));
  EXPECT_EQ(header.rfind("generation,", 0), 0u) << header;
  ASSERT_TRUE(std::getline(csv, row));
  EXPECT_EQ(row.substr(0, row.find(',')), "3") << row;
  EXPECT_FALSE(std::getline(csv, extra)) << extra;
}

void expect_one_line_error(const CommandResult& result, const std::string& expected) {
  EXPECT_EQ(result.exit_code, 2) << result.stdout_text << result.stderr_text;
  EXPECT_EQ(std::count(result.stderr_text.begin(), result.stderr_text.end(), '\n'), 1)
      << result.stderr_text;
  EXPECT_NE(result.stderr_text.find(expected), std::string::npos) << result.stderr_text;
}

TEST(FitCli, BadInputIsOneLineAndNothingIsOverwritten) {
  const fs::path dir = fresh_dir("fit_bad");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string good = write_pendulum_fit(dir, dir / "data", kSmallEs, "{generations: 2}");
  const std::string good_text = read_text(good);

  // Unknown parameter name, and bounds with lower >= upper: file, line and field.
  write_text(good, good_text + "fixed: {motor.R_ohms: 3}\n");
  expect_one_line_error(run_motoflex("fit " + good + " --out " + (dir / "x").string()),
                        "fit.yaml:12: fixed.motor.R_ohms");
  std::string bounds = good_text;
  bounds.replace(bounds.find("lower: 0.1, upper: 3.0"), 22, "lower: 3.0, upper: 0.1");
  write_text(good, bounds);
  expect_one_line_error(run_motoflex("fit " + good + " --out " + (dir / "x").string()),
                        "free.bench.Kt_nm_per_a");
  EXPECT_FALSE(fs::exists(dir / "x"));
  write_text(good, good_text);

  // A finished run is not overwritten by a second fit into the same folder.
  ASSERT_EQ(run_motoflex("fit " + good + " --out " + (dir / "run").string()).exit_code, 0);
  const std::string checkpoint = read_text(dir / "run" / "checkpoint.json");
  expect_one_line_error(run_motoflex("fit " + good + " --out " + (dir / "run").string()),
                        "already holds a fit");
  EXPECT_EQ(read_text(dir / "run" / "checkpoint.json"), checkpoint);

  // A checkpoint from another config (the seed changed): hash mismatch.
  std::string other = good_text;
  other.replace(other.find("seed: 7"), 7, "seed: 8");
  write_text(good, other);
  expect_one_line_error(run_motoflex("resume " + (dir / "run").string()), "checkpoint.json");
  EXPECT_EQ(read_text(dir / "run" / "checkpoint.json"), checkpoint);
  write_text(good, good_text);

  // A truncated checkpoint.
  write_text(dir / "run" / "checkpoint.json", checkpoint.substr(0, checkpoint.size() / 2));
  expect_one_line_error(run_motoflex("resume " + (dir / "run").string()), "checkpoint.json");

  // An output folder that cannot be created.
  expect_one_line_error(run_motoflex("fit " + good + " --out /proc/motoflex/run"),
                        "/proc/motoflex");
}

}  // namespace
}  // namespace motoflex::testing
