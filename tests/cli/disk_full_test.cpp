// A full disk, simulated with a file-size limit (ulimit -f, SIGXFSZ ignored: every write past
// the limit fails with EFBIG as a write to a full disk fails with ENOSPC): each command exits 3
// (README exit codes) naming the file, leaves no half-written file or temp file behind, and a fit
// stopped that way loses nothing: `resume` without the limit finishes it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_support.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

// Runs motoflex with every file it writes limited to limit_kib KiB.
CommandResult run_with_file_limit(const std::string& arguments, int limit_kib) {
  return run_motoflex_with_timeout(arguments, 0,
                                   "trap '' XFSZ; ulimit -f " + std::to_string(limit_kib));
}

std::string source(const std::string& relative) {
  return std::string(MOTOFLEX_SOURCE_DIR) + "/" + relative;
}

// Files whose name marks them as an atomic writer's temporary.
int temp_files_in(const fs::path& dir) {
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().filename().string().find(".tmp") != std::string::npos) ++count;
  }
  return count;
}

// A two-generation pendulum fit into `run` with every file limited to limit_kib KiB: it must
// stop with exit 3 on a write that does not fit, leaving no temporary file in `dir`.
CommandResult fit_with_file_limit(const fs::path& dir, const fs::path& run, int limit_kib) {
  const CommandResult r =
      run_with_file_limit("fit " + source("scenarios/fit/bench_hidden.yaml") +
                              " --max-generations 2 --threads 1 --out " + run.string(),
                          limit_kib);
  EXPECT_EQ(r.exit_code, 3) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find(": cannot write: File too large"), std::string::npos)
      << r.stderr_text;
  EXPECT_EQ(temp_files_in(dir), 0);
  return r;
}

TEST(DiskFullTest, SimulateExitsThreeAndLeavesNoPartialLog) {
  const fs::path dir = fresh_dir("disk_full_simulate");
  // The log is 23 KB; 8 KiB is not enough.
  const CommandResult r =
      run_with_file_limit("simulate " + source("scenarios/servo_pendulum_replay.yaml") + " --out " +
                              (dir / "run.csv").string(),
                          8);
  EXPECT_EQ(r.exit_code, 3) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find((dir / "run.csv").string() + ": cannot write"), std::string::npos)
      << r.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "run.csv"));
  EXPECT_EQ(temp_files_in(dir), 0);
}

TEST(DiskFullTest, FitStoppedBeforeItsFirstCheckpointSaysToStartAgain) {
  const fs::path dir = fresh_dir("disk_full_checkpoint");
  const fs::path run = dir / "run";
  // 2 KiB per file: run.json or the first checkpoint (~3 KB) cannot be written, depending on
  // how long the folder's path is.
  const CommandResult r = fit_with_file_limit(dir, run, 2);
  EXPECT_NE(r.stderr_text.find(run.string() + "/"), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(run / "checkpoint.json"));

  const CommandResult resumed = run_motoflex("resume " + run.string());
  EXPECT_EQ(resumed.exit_code, 2) << resumed.stderr_text;
  EXPECT_NE(resumed.stderr_text.find("start it again with `motoflex fit "), std::string::npos)
      << resumed.stderr_text;
}

TEST(DiskFullTest, FitStoppedAtAnOutputResumesToTheEnd) {
  const fs::path dir = fresh_dir("disk_full_output");
  const fs::path run = dir / "run";
  // 16 KiB holds the checkpoint and best.json but not the best fit's replayed logs.
  fit_with_file_limit(dir, run, 16);
  ASSERT_TRUE(fs::exists(run / "checkpoint.json"));
  const auto checkpoint = nlohmann::json::parse(std::ifstream(run / "checkpoint.json"));
  EXPECT_TRUE(checkpoint.is_object());

  const CommandResult resumed = run_motoflex("resume " + run.string());
  EXPECT_EQ(resumed.exit_code, 0) << resumed.stderr_text;
  EXPECT_TRUE(fs::exists(run / "summary.json"));
  EXPECT_TRUE(fs::exists(run / "best" / "chirp.csv"));
}

}  // namespace
}  // namespace motoflex::testing
