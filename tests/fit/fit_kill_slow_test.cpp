// Kill -9 at random moments - while rollouts run, between a generation's row and its
// checkpoint, inside an atomic write - and carry on with `resume` (or `fit` again when no
// checkpoint exists yet): the run ends bit-identical to one that was never interrupted, and
// leaves no temporary files behind.

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

pid_t spawn_motoflex(std::vector<std::string> args, const fs::path& log) {
  const std::string binary = MOTOFLEX_TEST_BINARY;
  args.insert(args.begin(), binary);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Waits up to `wait` for the process; kills it with SIGKILL if it is still running. Returns
// true when it finished on its own with exit code 0.
bool finish_or_kill(pid_t pid, std::chrono::milliseconds wait) {
  const auto end = std::chrono::steady_clock::now() + wait;
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) && WEXITSTATUS(status) == 0;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::size_t temp_files(const fs::path& dir) {
  std::size_t count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp-") != std::string::npos) ++count;
  }
  return count;
}

TEST(FitKill, KilledAtRandomMomentsEndsIdentical) {
  const fs::path dir = fresh_dir("fit_kill_random");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit =
      write_pendulum_fit(dir, dir / "data", "{kind: mu_plus_lambda, mu: 4, lambda: 12, kappa: 3}",
                         "{generations: 12}");
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(run_motoflex("fit " + fit + " --out " + (dir / "whole").string()).exit_code, 0);
  const auto whole_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::steady_clock::now() - start);

  std::random_device device;
  std::mt19937 random(device());
  std::uniform_int_distribution<long> moment(0, std::max<long>(1, whole_ms.count()));
  const fs::path run = dir / "killed";
  bool finished = false;
  int kills = 0;
  for (int attempt = 0; attempt < 8 && !finished; ++attempt) {
    const bool has_checkpoint = fs::exists(run / "checkpoint.json");
    const std::vector<std::string> args =
        has_checkpoint ? std::vector<std::string>{"resume", run.string()}
                       : std::vector<std::string>{"fit", fit, "--out", run.string()};
    // The last attempt runs to the end; the others are killed at a random moment.
    const auto wait = attempt == 7 ? std::chrono::milliseconds(600000)
                                   : std::chrono::milliseconds(moment(random) / 2);
    std::printf("attempt %d: %s, kill after %ld ms\n", attempt, args[0].c_str(),
                static_cast<long>(wait.count()));
    finished = finish_or_kill(spawn_motoflex(args, dir / "killed.log"), wait);
    kills += finished ? 0 : 1;
  }
  ASSERT_TRUE(finished) << read_text(dir / "killed.log");
  std::printf("%d kills before the run finished\n", kills);
  EXPECT_EQ(generations_without_seconds(dir / "whole"), generations_without_seconds(run));
  EXPECT_EQ(best_without_date(dir / "whole"), best_without_date(run));
  EXPECT_EQ(temp_files(run), 0u);
}

}  // namespace
}  // namespace motoflex::testing
