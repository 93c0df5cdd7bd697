// `mpirun -np N motoflex fit` on one machine: a fit distributed over MPI ranks gives the same
// generations.csv (minus seconds), best.json and summary as one process, bit for bit — for 2
// ranks, for 3 ranks × 2 threads (uneven slices) and across a distributed resume — and an error
// on rank 0 ends every rank instead of hanging. Skipped (with the reason) without mpirun or
// without MPI support in the build.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex_es/mpi_world.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

// λ = 10 over 3 ranks is 4, 3, 3 individuals.
const char* kSmallEs = "{kind: mu_plus_lambda, mu: 4, lambda: 10, kappa: 3}";
const std::string kHiddenNone =
    std::string(MOTOFLEX_SOURCE_DIR) + "/reference_data/hidden/none/train";

struct ShellResult {
  int exit_code = -1;
  std::string stdout_text, stderr_text;
};

// Runs `command` through the shell with stdout and stderr to files in `dir`.
ShellResult run_shell(const std::string& command, const fs::path& dir, const std::string& name) {
  const fs::path out = dir / (name + ".out"), err = dir / (name + ".err");
  const int status =
      std::system((command + " > '" + out.string() + "' 2> '" + err.string() + "'").c_str());
  ShellResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.stdout_text = read_text(out);
  result.stderr_text = read_text(err);
  return result;
}

// mpirun as it works in a container as root on a 2-core machine: the ALLOW_RUN_AS_ROOT pair
// (ignored for other users), --oversubscribe (more ranks than cores), --bind-to none (ranks
// with several OpenMP threads), no single-copy (CMA) mechanism (containers forbid
// process_vm_readv). `timeout` turns a hang into a failure (exit code 124).
std::string mpirun(int ranks, const std::string& arguments) {
  return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
         "OMPI_MCA_btl_vader_single_copy_mechanism=none timeout 300 mpirun --oversubscribe "
         "--bind-to none -np " +
         std::to_string(ranks) + " " + MOTOFLEX_TEST_BINARY + " " + arguments;
}

// Why the MPI tests cannot run here, or "" if they can.
std::string skip_reason() {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0) return "mpirun not found";
  if (!motoflex_es::mpi_built_in()) return "motoflex was built without MPI";
  return "";
}

nlohmann::json read_json(const fs::path& path) {
  return nlohmann::json::parse(read_text(path));
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

// The run in `other` matches the one-process run in `reference`, bit for bit.
void expect_same_run(const fs::path& reference, const fs::path& other) {
  EXPECT_EQ(generations_without_seconds(reference), generations_without_seconds(other));
  EXPECT_EQ(best_without_date(reference), best_without_date(other));
  const nlohmann::json a = read_json(reference / "summary.json");
  const nlohmann::json b = read_json(other / "summary.json");
  // Compared as bits: JSON stores the shortest round-trip text of the double.
  EXPECT_EQ(a["best_fitness"].get<double>(), b["best_fitness"].get<double>());
  EXPECT_EQ(a["evaluations"], b["evaluations"]);
  EXPECT_EQ(a["rms_deg"], b["rms_deg"]);
  // The workers' early-termination counts reach rank 0.
  EXPECT_EQ(a["early_termination"], b["early_termination"]);
}

TEST(FitMpi, TwoAndThreeRanksGiveTheRunOfOneProcess) {
  const std::string why = skip_reason();
  if (!why.empty()) GTEST_SKIP() << why;
  const fs::path dir = fresh_dir("fit_mpi");
  const std::string fit = write_pendulum_fit(dir, kHiddenNone, kSmallEs, "{generations: 3}");

  const auto one = run_motoflex("fit " + fit + " --threads 1 --out " + (dir / "one").string());
  ASSERT_EQ(one.exit_code, 0) << one.stderr_text;
  EXPECT_GT(
      read_json(dir / "one" / "summary.json")["early_termination"]["individuals_stopped_early"]
          .get<int>(),
      0);  // so that summing the workers' counters is tested

  const auto two = run_shell(
      mpirun(2, "fit " + fit + " --threads 1 --out " + (dir / "two").string()), dir, "two");
  ASSERT_EQ(two.exit_code, 0) << two.stdout_text << two.stderr_text;
  EXPECT_EQ(count_of(two.stdout_text, "done ("), 1u) << "only rank 0 reports:\n" << two.stdout_text;
  EXPECT_EQ(count_of(two.stdout_text, "gen    3"), 1u) << two.stdout_text;
  EXPECT_EQ(read_json(dir / "two" / "summary.json")["evaluator"], "mpi(2 ranks x 1 thread)");
  expect_same_run(dir / "one", dir / "two");

  const auto three = run_shell(
      mpirun(3, "fit " + fit + " --threads 2 --out " + (dir / "three").string()), dir, "three");
  ASSERT_EQ(three.exit_code, 0) << three.stdout_text << three.stderr_text;
  EXPECT_EQ(read_json(dir / "three" / "summary.json")["evaluator"], "mpi(3 ranks x 2 threads)");
  expect_same_run(dir / "one", dir / "three");
}

TEST(FitMpi, DistributedResumeEndsLikeAnUninterruptedRun) {
  const std::string why = skip_reason();
  if (!why.empty()) GTEST_SKIP() << why;
  const fs::path dir = fresh_dir("fit_mpi_resume");
  const std::string fit = write_pendulum_fit(dir, kHiddenNone, kSmallEs, "{generations: 4}");
  ASSERT_EQ(run_motoflex("fit " + fit + " --out " + (dir / "whole").string()).exit_code, 0);

  const auto first =
      run_shell(mpirun(2, "fit " + fit + " --max-generations 2 --out " + (dir / "split").string()),
                dir, "first");
  ASSERT_EQ(first.exit_code, 0) << first.stdout_text << first.stderr_text;
  const auto second = run_shell(
      mpirun(2, "resume " + (dir / "split").string() + " --max-generations 4"), dir, "second");
  ASSERT_EQ(second.exit_code, 0) << second.stdout_text << second.stderr_text;
  EXPECT_EQ(count_of(second.stdout_text, "gen    3"), 1u) << second.stdout_text;
  expect_same_run(dir / "whole", dir / "split");
}

TEST(FitMpi, AnErrorOnRankZeroEndsEveryRank) {
  const std::string why = skip_reason();
  if (!why.empty()) GTEST_SKIP() << why;
  const fs::path dir = fresh_dir("fit_mpi_error");
  const std::string fit = write_pendulum_fit(dir, kHiddenNone, kSmallEs, "{generations: 1}");
  ASSERT_EQ(run_motoflex("fit " + fit + " --out " + (dir / "run").string()).exit_code, 0);
  const std::string checkpoint = read_text(dir / "run" / "checkpoint.json");

  // Rank 0 refuses the existing run folder after every rank loaded the config: the workers
  // are already waiting for batches and must be released (a hang would be exit code 124).
  const auto taken =
      run_shell(mpirun(2, "fit " + fit + " --out " + (dir / "run").string()), dir, "taken");
  EXPECT_EQ(taken.exit_code, 2) << taken.stdout_text << taken.stderr_text;
  EXPECT_EQ(count_of(taken.stderr_text, "already holds a fit"), 1u) << taken.stderr_text;
  EXPECT_EQ(read_text(dir / "run" / "checkpoint.json"), checkpoint);

  // Bad input in the config: reported once (by rank 0), every rank exits.
  write_text(fit, read_text(fit) + "fixed: {motor.R_ohms: 3}\n");
  const auto bad =
      run_shell(mpirun(2, "fit " + fit + " --out " + (dir / "bad").string()), dir, "bad");
  EXPECT_EQ(bad.exit_code, 2) << bad.stdout_text << bad.stderr_text;
  EXPECT_EQ(count_of(bad.stderr_text, "fixed.motor.R_ohms"), 1u) << bad.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "bad"));
}

}  // namespace
}  // namespace motoflex::testing
