// Reading a run dir: what a fit wrote, what is optional, and what is not a run dir at all.

#include "motoflex/report/run_record.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "motoflex/core/error.hpp"
#include "report_test_support.hpp"

namespace motoflex::report {
namespace {

namespace fs = std::filesystem;
using motoflex::testing::fresh_dir;
using motoflex::testing::write_text;

TEST(ReadRunDir, AFullFitRunDir) {
  const fs::path dir = fresh_dir("report_record_full");
  motoflex::testing::write_fit_run_dir(dir);
  const RunRecord record = read_run_dir(dir.string());
  EXPECT_EQ(record.fit_dir, dir.string());
  EXPECT_EQ(record.summary["name"], "toy_fit");
  EXPECT_EQ(record.inputs["seed"], 3);
  ASSERT_EQ(record.generations.size(), 3u);
  EXPECT_EQ(record.generations[2].evaluations, 48u);
  EXPECT_TRUE(std::isinf(record.generations[0].median));
  ASSERT_EQ(record.logs.size(), 1u);
  EXPECT_EQ(record.logs[0].name, "walk");
  EXPECT_EQ(record.logs[0].set, "training");
  EXPECT_EQ(record.logs[0].simulated_path, (dir / "best" / "walk.csv").string());
  EXPECT_TRUE(record.loop.is_null());
  EXPECT_TRUE(record.residuals_dir.empty());
  ASSERT_EQ(record.notes.size(), 1u);  // only: no residual analysis
  EXPECT_NE(record.notes[0].find("motoflex residuals"), std::string::npos);
}

TEST(ReadRunDir, MissingOptionalFilesAreNotesNotErrors) {
  const fs::path dir = fresh_dir("report_record_sparse");
  motoflex::testing::write_fit_run_dir(dir, false);
  const RunRecord record = read_run_dir(dir.string());
  EXPECT_TRUE(record.inputs.is_null());
  EXPECT_TRUE(record.generations.empty());
  EXPECT_TRUE(record.logs.empty());
  std::string notes;
  for (const auto& note : record.notes) notes += note + "\n";
  EXPECT_NE(notes.find("no generations.csv"), std::string::npos) << notes;
  EXPECT_NE(notes.find("no inputs.json"), std::string::npos) << notes;
}

TEST(ReadRunDir, NotARunDirAndCorruptFilesAreInputErrors) {
  const fs::path empty = fresh_dir("report_record_empty");
  try {
    read_run_dir(empty.string());
    FAIL() << "an empty folder was read as a run dir";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), empty.string());
    EXPECT_NE(error.message().find("not a fit or loop run folder"), std::string::npos);
  }
  const fs::path corrupt = fresh_dir("report_record_corrupt");
  motoflex::testing::write_fit_run_dir(corrupt);
  write_text(corrupt / "summary.json", "{\"name\": ");
  try {
    read_run_dir(corrupt.string());
    FAIL() << "a corrupt summary.json was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), (corrupt / "summary.json").string());
  }
}

TEST(ReadGenerationsCsv, ABadRowNamesItsLineAndColumn) {
  const fs::path dir = fresh_dir("report_generations_bad");
  write_text(dir / "generations.csv",
             "generation,evaluations,best,median,mean_sigma,seconds\n1,16,0.1,0.2,0.1,1\n"
             "2,32,oops,0.2,0.1,2\n");
  try {
    read_generations_csv((dir / "generations.csv").string());
    FAIL() << "a non-numeric best was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), 3);
    EXPECT_EQ(error.field(), "best");
  }
  write_text(dir / "generations.csv",
             "generation,evaluations,best,median,mean_sigma,seconds\n1,2\n");
  EXPECT_THROW(read_generations_csv((dir / "generations.csv").string()), InputError);
}

TEST(ReadRunDir, ALoopDirShowsItsFinalFitAlsoWhenTheLoopDirWasMoved) {
  const fs::path dir = fresh_dir("report_record_loop");
  motoflex::testing::write_fit_run_dir(dir / "01_stribeck");
  // loop.json names the final run dir where the loop once was.
  write_text(dir / "loop.json", R"({"iterations": [], "final_run_dir": "/gone/loop/01_stribeck"})");
  write_text(dir / "report.md", "# Closing the loop: toy\n");
  const RunRecord record = read_run_dir(dir.string());
  EXPECT_EQ(record.fit_dir, (dir / "01_stribeck").string());
  EXPECT_EQ(record.summary["name"], "toy_fit");
  EXPECT_NE(record.loop_markdown.find("Closing the loop"), std::string::npos);
}

}  // namespace
}  // namespace motoflex::report
