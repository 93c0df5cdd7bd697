// A loop folder resumes only the same loop: run again with another refit budget (or other data)
// the old loop's files move to previous-N and the loop starts afresh, instead of reusing a base
// fit and refits made under the old settings; threads do not count.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/cli_test_support.hpp"
#include "effect_test_support.hpp"
#include "fit/fit_test_support.hpp"
#include "motoflex/effects/loop_identity.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

TEST(LoopIdentity, AFolderResumesOnlyTheSameLoop) {
  const fs::path dir = fresh_dir("loop_identity");
  const fs::path out = dir / "loop";
  const std::string loop = "{candidates: 2, refit: {budget: {evaluations: 300}}}";
  const FitConfig first = load_fit_config(write_hidden_bench_fit(dir / "a", "stribeck", loop));
  EXPECT_EQ(check_loop_identity(first, out.string()), "");
  EXPECT_TRUE(fs::exists(out / "loop_identity.json"));
  fs::create_directories(out / "00_base");
  std::ofstream(out / "00_base" / "summary.json") << "{}";
  EXPECT_EQ(check_loop_identity(first, out.string()), "");  // the same loop again: resumes
  EXPECT_TRUE(fs::exists(out / "00_base" / "summary.json"));

  FitOverrides one_thread;
  one_thread.threads = 1;
  const FitConfig fewer_threads =
      load_fit_config(write_hidden_bench_fit(dir / "b", "stribeck", loop), one_thread);
  EXPECT_EQ(check_loop_identity(fewer_threads, out.string()), "");  // threads change no number

  // Another refit budget: the old loop moves to previous-1, nothing of it stays in the way.
  const FitConfig other_budget = load_fit_config(write_hidden_bench_fit(
      dir / "c", "stribeck", "{candidates: 2, refit: {budget: {evaluations: 900}}}"));
  const std::string budget = check_loop_identity(other_budget, out.string());
  EXPECT_NE(budget.find("the loop: section"), std::string::npos) << budget;
  EXPECT_EQ(budget.find("the base fit:"), std::string::npos) << budget;
  EXPECT_NE(budget.find("previous-1"), std::string::npos) << budget;
  EXPECT_TRUE(fs::exists(out / "previous-1" / "00_base" / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "00_base"));
  EXPECT_EQ(check_loop_identity(other_budget, out.string()), "");  // now it is this loop's

  // Other data: the base fit changed; the next free previous-N.
  const FitConfig other_data =
      load_fit_config(write_hidden_bench_fit(dir / "d", "load_friction", loop));
  const std::string data = check_loop_identity(other_data, out.string());
  EXPECT_NE(data.find("the base fit:"), std::string::npos) << data;
  EXPECT_NE(data.find("previous-2"), std::string::npos) << data;
  EXPECT_TRUE(fs::exists(out / "previous-2" / "loop_identity.json"));
  EXPECT_TRUE(fs::exists(out / "previous-1" / "loop_identity.json"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motoflex::testing
