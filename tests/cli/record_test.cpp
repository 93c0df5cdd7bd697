// `motoflex record`: the same truth and seed give bit-identical logs, the committed reference
// data are exactly what scripts/make_reference_data produces, and the truth never lands beside
// the logs a fit reads.

#include <gtest/gtest.h>

#include "cli_test_support.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Record, SameSeedGivesBitIdenticalLogsAndMatchesTheCommittedReferenceData) {
  const fs::path dir = fresh_dir("record_twice");
  const std::string source = MOTOFLEX_SOURCE_DIR;
  const std::string truth = source + "/scenarios/truth/hidden/stribeck.yaml";
  for (const char* run : {"a", "b"}) {
    const auto result = run_motoflex("record " + truth + " --blind --out " + (dir / run).string() +
                                     " --truth-out " + (dir / run / "truth").string());
    ASSERT_EQ(result.exit_code, 0) << result.stderr_text;
  }
  const fs::path committed = fs::path(source) / "reference_data/hidden/stribeck";
  for (const char* log : {"train/multisine_slow.csv", "train/chirp.csv",
                          "validation/multisine_fast.csv", "train/chirp.yaml"}) {
    SCOPED_TRACE(log);
    const std::string a = read_all(dir / "a" / log);
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, read_all(dir / "b" / log));
    EXPECT_EQ(a, read_all(committed / log));
  }
  // The truth is written apart from the logs, and holds the hidden effect.
  EXPECT_FALSE(fs::exists(dir / "a" / "train" / "truth"));
  const std::string truth_json = read_all(dir / "a" / "truth" / "train" / "chirp.json");
  EXPECT_NE(truth_json.find("\"joint.pendulum.stribeck_nm\": 0.08"), std::string::npos);
  // The logs' sidecars do not leak it.
  EXPECT_EQ(read_all(dir / "a" / "train" / "chirp.yaml").find("stribeck_nm"), std::string::npos);
}

TEST(Record, ADifferentSeedChangesOnlyTheSensorNoise) {
  const fs::path dir = fresh_dir("record_seed");
  const std::string truth_text =
      read_all(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/truth/hidden/none.yaml");
  std::string other = truth_text;
  other.replace(other.find("seed: 17"), 8, "seed: 18");
  // Keep relative scenario paths valid: write the copies next to the originals' folder layout.
  const fs::path truth_dir = dir / "scenarios" / "truth" / "hidden";
  fs::create_directories(truth_dir);
  fs::copy(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/bench", dir / "scenarios" / "bench");
  fs::copy(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots", dir / "scenarios" / "robots",
           fs::copy_options::recursive);
  write_text(truth_dir / "a.yaml", truth_text);
  write_text(truth_dir / "b.yaml", other);
  for (const char* run : {"a", "b"}) {
    const auto result =
        run_motoflex("record " + (truth_dir / (std::string(run) + ".yaml")).string() + " --out " +
                     (dir / run).string());
    ASSERT_EQ(result.exit_code, 0) << result.stderr_text;
  }
  EXPECT_NE(read_all(dir / "a" / "train" / "chirp.csv"),
            read_all(dir / "b" / "train" / "chirp.csv"));
}

}  // namespace
}  // namespace motoflex::testing
