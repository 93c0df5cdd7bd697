// The logs of a fit's `data:` / `--data` source: a folder that holds BAM JSON logs only in
// subfolders (BAM's own layout, raw/ and processed/) is imported like a flat one, each recording
// once; a folder with neither CSV nor JSON logs is an error naming the folder and the field.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_config.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

// A BAM trajectory log of four samples; `dt_s` > 0 makes it a processed one.
nlohmann::json bam_log(double dt_s) {
  nlohmann::json doc = {{"mass", 0.49},
                        {"length", 0.1},
                        {"kp", 400},
                        {"vin", 7.4},
                        {"motor", "xl330"},
                        {"trajectory", "sin_sin"},
                        {"entries", nlohmann::json::array()}};
  if (dt_s > 0.0) doc["dt"] = dt_s;
  for (int i = 0; i < 4; ++i) {
    doc["entries"].push_back({{"position", 0.01 * i},
                              {"timestamp", dt_s > 0.0 ? i * dt_s : 0.0035 + 0.0053 * i},
                              {"goal_position", 0.02 * i},
                              {"torque_enable", true}});
  }
  return doc;
}

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  write_text(path, text);
}

TEST(FitLogs, AFolderWithBamLogsInSubfoldersIsImportedOncePerRecording) {
  const fs::path dir = fresh_dir("fit_logs_bam_tree");
  write(dir / "xl330" / "raw" / "a.json", bam_log(0.0).dump());
  write(dir / "xl330" / "processed" / "a.json", bam_log(0.005).dump());
  write(dir / "xl330" / "raw" / "b.json", bam_log(0.0).dump());
  write(dir / "xl330" / "README.md", "# notes\n");
  const std::vector<std::string> logs = logs_of(
      {{(dir / "xl330").string(), SourceRef{"fit.yaml", 3, "data"}}}, (dir / "imported").string());
  ASSERT_EQ(logs.size(), 2u);
  EXPECT_EQ(fs::path(logs[0]).filename(), "processed_a.csv");
  EXPECT_EQ(fs::path(logs[1]).filename(), "raw_b.csv");
}

// Neither logs nor, in the second folder, anything but a JSON file that is no trajectory log (a
// run folder's summary, say): the error names the folder given, not the import folder.
TEST(FitLogs, AFolderWithoutLogsNamesTheFolderAndTheField) {
  const fs::path dir = fresh_dir("fit_logs_empty");
  write(dir / "empty" / "sub" / "notes.txt", "nothing here\n");
  write(dir / "run" / "sub" / "summary.json", R"({"evaluations": 12})");
  for (const char* folder : {"empty", "run"}) {
    try {
      logs_of({{(dir / folder).string(), SourceRef{"fit.yaml", 3, "data"}}},
              (dir / "imported").string());
      ADD_FAILURE() << "no InputError for " << folder;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), (dir / folder).string());
      EXPECT_EQ(e.field(), "data");
      EXPECT_NE(std::string(e.what()).find("no *.csv logs"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace motoflex::testing
