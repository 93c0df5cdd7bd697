// A loop folder resumes only the same loop: run again with another refit budget (or other data)
// the loop refuses the folder, naming its loop_identity.json and what changed, instead of
// reusing refits made under the old settings; threads do not count.

#include <gtest/gtest.h>

#include <filesystem>

#include "cli/cli_test_support.hpp"
#include "effect_test_support.hpp"
#include "fit/fit_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/effects/loop_identity.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

std::string error_of(const FitConfig& config, const fs::path& out) {
  try {
    check_loop_identity(config, out.string());
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(LoopIdentity, AFolderResumesOnlyTheSameLoop) {
  const fs::path dir = fresh_dir("loop_identity");
  const fs::path out = dir / "loop";
  const std::string loop = "{candidates: 2, refit: {budget: {evaluations: 300}}}";
  const FitConfig first = load_fit_config(write_hidden_bench_fit(dir / "a", "stribeck", loop));
  check_loop_identity(first, out.string());
  EXPECT_TRUE(fs::exists(out / "loop_identity.json"));
  EXPECT_EQ(error_of(first, out), "");  // the same loop again: resumes

  FitOverrides more_threads;
  more_threads.threads = 1;
  const FitConfig one_thread =
      load_fit_config(write_hidden_bench_fit(dir / "b", "stribeck", loop), more_threads);
  EXPECT_EQ(error_of(one_thread, out), "");  // threads change no number

  const FitConfig other_budget = load_fit_config(write_hidden_bench_fit(
      dir / "c", "stribeck", "{candidates: 2, refit: {budget: {evaluations: 900}}}"));
  const std::string budget = error_of(other_budget, out);
  EXPECT_NE(budget.find("loop_identity.json"), std::string::npos) << budget;
  EXPECT_NE(budget.find("the loop: section"), std::string::npos) << budget;
  EXPECT_EQ(budget.find("the base fit ("), std::string::npos) << budget;

  const FitConfig other_data =
      load_fit_config(write_hidden_bench_fit(dir / "d", "load_friction", loop));
  const std::string data = error_of(other_data, out);
  EXPECT_NE(data.find("the base fit ("), std::string::npos) << data;
  EXPECT_NE(data.find("--out"), std::string::npos) << data;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motoflex::testing
