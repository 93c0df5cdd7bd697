#include "motoflex/io/bam_import.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "scratch_dir.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kBamDataDir = fs::path(MOTOFLEX_SOURCE_DIR) / ".." / "shared" / "data" / "bam";

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// What the round trip must preserve, computed straight from a BAM JSON document.
struct Reference {
  std::size_t samples = 0;
  double first_s = 0.0;
  double last_s = 0.0;
  double mean_abs_error_rad = 0.0;
  std::optional<double> torque_off_s;
};

Reference reference_from_json(const json& doc) {
  const json& entries = doc.at("entries");
  Reference ref;
  ref.samples = entries.size();
  ref.first_s = entries.front().at("timestamp").get<double>();
  ref.last_s = entries.back().at("timestamp").get<double>();
  double sum = 0.0;
  for (const json& entry : entries) {
    sum += std::abs(entry.at("goal_position").get<double>() - entry.at("position").get<double>());
    if (!ref.torque_off_s && entry.contains("torque_enable") &&
        !entry["torque_enable"].get<bool>()) {
      ref.torque_off_s = entry.at("timestamp").get<double>();
    }
  }
  ref.mean_abs_error_rad = sum / static_cast<double>(entries.size());
  return ref;
}

Reference reference_from_log(const JointLog& log) {
  Reference ref;
  ref.samples = log.frames();
  ref.first_s = log.time_s.front();
  ref.last_s = log.time_s.back();
  double sum = 0.0;
  for (std::size_t f = 0; f < log.frames(); ++f) {
    sum += std::abs(log.commanded(f, 0) - log.measured(f, 0));
  }
  ref.mean_abs_error_rad = sum / static_cast<double>(log.frames());
  return ref;
}

// The single-axis trajectory logs below the BAM data folder, found independently of the
// importer: JSON objects whose entries carry a position.
std::vector<fs::path> real_trajectory_logs() {
  std::vector<fs::path> found;
  for (const auto& entry : fs::recursive_directory_iterator(kBamDataDir)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".json") continue;
    const json doc = json::parse(read_text(entry.path()));
    if (doc.is_object() && doc.contains("entries") && doc["entries"].is_array() &&
        !doc["entries"].empty() && doc["entries"][0].contains("position")) {
      found.push_back(entry.path());
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

// A small valid raw log: 4 entries, torque on throughout.
json small_log() {
  json doc = {{"mass", 0.49},
              {"length", 0.1},
              {"kp", 400},
              {"vin", 7.4},
              {"motor", "xl330"},
              {"trajectory", "sin_sin"},
              {"entries", json::array()}};
  const double times[] = {0.0035, 0.0088, 0.0141, 0.0193};
  for (int i = 0; i < 4; ++i) {
    doc["entries"].push_back({{"position", 0.01 * i},
                              {"speed", 0.0},
                              {"load", 3},
                              {"input_volts", 7.3},
                              {"temp", 28},
                              {"timestamp", times[i]},
                              {"goal_position", 0.02 * i},
                              {"torque_enable", true}});
  }
  return doc;
}

class BamImportTest : public testing::ScratchFolderTest {
 protected:
  std::string write(const std::string& name, const std::string& text) const {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  std::string write(const std::string& name, const json& doc) const {
    return write(name, doc.dump());
  }

  // Imports `file` (shown as "shown.json"), which must fail with InputError on `field`;
  // returns the message.
  std::string expect_error(const std::string& file, const std::string& field, int line = 0) {
    try {
      import_bam_file(file, "shown.json");
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "shown.json") << e.what();
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      return e.message();
    }
    ADD_FAILURE() << "no InputError for field " << field;
    return "";
  }
};

TEST_F(BamImportTest, EveryRealTrajectoryLogRoundTripsExactly) {
  if (!fs::is_directory(kBamDataDir)) {
    GTEST_SKIP() << "BAM data folder " << kBamDataDir << " is absent";
  }
  const std::vector<fs::path> logs = real_trajectory_logs();
  ASSERT_FALSE(logs.empty()) << "no trajectory logs below " << kBamDataDir;
  for (const fs::path& file : logs) {
    SCOPED_TRACE(file.string());
    const json doc = json::parse(read_text(file));
    const Reference expected = reference_from_json(doc);
    const BamImport imported = import_bam_file(file.string(), file.filename().string());
    const std::string csv = path(file.stem().string() + ".csv");
    write_joint_log(csv, imported.log);
    JointLogRequirements requirements;
    requirements.need_measured = true;
    requirements.need_sidecar = true;
    requirements.joints = {"pendulum"};
    const JointLog back = read_joint_log(csv, requirements);
    const Reference actual = reference_from_log(back);

    EXPECT_EQ(actual.samples, expected.samples);
    EXPECT_EQ(actual.first_s, expected.first_s);
    EXPECT_EQ(actual.last_s, expected.last_s);
    EXPECT_EQ(actual.mean_abs_error_rad, expected.mean_abs_error_rad);
    EXPECT_EQ(imported.torque_off_s, expected.torque_off_s);
    EXPECT_EQ(imported.motor, doc.at("motor").get<std::string>());
    EXPECT_EQ(back.meta.robot, "servo_pendulum");
    EXPECT_EQ(back.meta.motion, doc.at("trajectory").get<std::string>());
    EXPECT_EQ(back.meta.origin, "imported from BAM " + file.filename().string());
    EXPECT_EQ(back.meta.parameters.at("bench.mass_kg"), doc.at("mass").get<double>());
    EXPECT_EQ(back.meta.parameters.at("bench.length_m"), doc.at("length").get<double>());
    EXPECT_EQ(back.meta.parameters.at("bench.kp"), doc.at("kp").get<double>());
    EXPECT_EQ(back.meta.parameters.at("bench.supply_v"), doc.at("vin").get<double>());
    if (doc.contains("dt")) {
      EXPECT_EQ(back.meta.rate_hz, 1.0 / doc["dt"].get<double>());
    } else {
      EXPECT_NEAR(back.meta.rate_hz, (expected.samples - 1) / (expected.last_s - expected.first_s),
                  1e-9);
    }
    if (imported.motor == "xl330") {
      EXPECT_NEAR(back.meta.parameters.at("bench.error_gain"), 0.0028774, 1e-7);
      EXPECT_EQ(back.meta.parameters.at("bench.max_duty"), 1.0);
    } else {
      EXPECT_FALSE(back.meta.parameters.contains("bench.error_gain"));
      EXPECT_FALSE(back.meta.parameters.contains("bench.max_duty"));
      EXPECT_NE(back.meta.notes.find("left out"), std::string::npos) << back.meta.notes;
    }
    if (expected.torque_off_s) {
      EXPECT_NE(back.meta.notes.find("torque released at t = "), std::string::npos);
    }
    // The servo's own supply reading becomes the supply_v column, value for value.
    const json& entries = doc.at("entries");
    if (entries.front().contains("input_volts")) {
      ASSERT_EQ(back.supply_v.size(), entries.size());
      for (std::size_t i = 0; i < entries.size(); i += 97) {
        EXPECT_EQ(back.supply_v[i], entries[i].at("input_volts").get<double>()) << i;
      }
    }
  }
}

TEST_F(BamImportTest, RealFolderImportsEveryTrajectoryLogAndSkipsTheRest) {
  if (!fs::is_directory(kBamDataDir)) {
    GTEST_SKIP() << "BAM data folder " << kBamDataDir << " is absent";
  }
  const std::vector<BamDirectoryItem> items = import_bam_directory(kBamDataDir.string());
  std::size_t imported = 0;
  for (const BamDirectoryItem& item : items) {
    SCOPED_TRACE(item.relative_path);
    if (item.import) {
      ++imported;
      EXPECT_TRUE(item.skip_reason.empty());
      EXPECT_EQ(item.import->log.meta.origin, "imported from BAM " + item.relative_path);
    } else {
      EXPECT_FALSE(item.skip_reason.empty());
    }
    const bool calibration_table =
        (item.relative_path.starts_with("mx64/") || item.relative_path.starts_with("mx106/")) &&
        item.relative_path.ends_with(".json");
    if (calibration_table) {
      EXPECT_FALSE(item.import);
      EXPECT_NE(item.skip_reason.find("calibration table"), std::string::npos);
    }
  }
  // BAM keeps a session both raw and processed under the same file names: each recording once.
  const std::vector<fs::path> logs = real_trajectory_logs();
  std::size_t raw_copies = 0;
  for (const fs::path& log : logs) {
    const bool processed = json::parse(read_text(log)).contains("dt");
    const bool has_processed_twin = std::any_of(logs.begin(), logs.end(), [&](const fs::path& p) {
      return p != log && p.filename() == log.filename() && json::parse(read_text(p)).contains("dt");
    });
    if (!processed && has_processed_twin) ++raw_copies;
  }
  EXPECT_GT(raw_copies, 0u);
  EXPECT_EQ(imported, logs.size() - raw_copies);
}

TEST_F(BamImportTest, RawLogKeepsItsClockAndGetsTheMeanRate) {
  const BamImport imported = import_bam_file(write("raw.json", small_log()), "raw.json");
  const JointLog& log = imported.log;
  EXPECT_EQ(log.joint_names, std::vector<std::string>{"pendulum"});
  EXPECT_EQ(log.time_s, (std::vector<double>{0.0035, 0.0088, 0.0141, 0.0193}));
  EXPECT_EQ(log.commanded_rad, (std::vector<double>{0.0, 0.02, 0.04, 0.06}));
  EXPECT_EQ(log.measured_rad, (std::vector<double>{0.0, 0.01, 0.02, 0.03}));
  EXPECT_DOUBLE_EQ(log.meta.rate_hz, 3.0 / (0.0193 - 0.0035));
  EXPECT_EQ(log.meta.motion, "sin_sin");
  EXPECT_EQ(log.meta.origin, "imported from BAM raw.json");
  EXPECT_DOUBLE_EQ(log.meta.parameters.at("bench.error_gain"),
                   (4096.0 / (2.0 * std::numbers::pi)) / (256.0 * 885.0));
  EXPECT_NE(log.meta.notes.find("raw log"), std::string::npos);
  EXPECT_FALSE(imported.torque_off_s);
}

TEST_F(BamImportTest, ProcessedLogUsesItsDtAndMustStayOnTheGrid) {
  json doc = small_log();
  doc["dt"] = 0.005;
  for (int i = 0; i < 4; ++i) doc["entries"][i]["timestamp"] = i * 0.005;
  const BamImport imported = import_bam_file(write("processed.json", doc), "p.json");
  EXPECT_EQ(imported.log.meta.rate_hz, 200.0);
  EXPECT_NE(imported.log.meta.notes.find("processed log"), std::string::npos);

  doc["entries"][2]["timestamp"] = 0.0101;
  const std::string message = expect_error(write("off_grid.json", doc), "entries[2].timestamp");
  EXPECT_NE(message.find("dt grid"), std::string::npos) << message;
}

TEST_F(BamImportTest, TorqueReleaseIsReturnedAndNoted) {
  json doc = small_log();
  doc["trajectory"] = "lift_and_drop";
  doc["entries"][2]["torque_enable"] = false;
  doc["entries"][3]["torque_enable"] = false;
  const BamImport imported = import_bam_file(write("drop.json", doc), "drop.json");
  ASSERT_TRUE(imported.torque_off_s);
  EXPECT_EQ(*imported.torque_off_s, 0.0141);
  EXPECT_EQ(imported.log.frames(), 4u);  // samples after the release are kept
  EXPECT_NE(imported.log.meta.notes.find("torque released at t = 0.0141 s"), std::string::npos)
      << imported.log.meta.notes;

  doc["entries"][3]["torque_enable"] = true;
  expect_error(write("reenabled.json", doc), "entries[3].torque_enable");
}

TEST_F(BamImportTest, OptionalHeaderValuesAreLeftOutWithANote) {
  json doc = small_log();
  doc.erase("kp");
  doc.erase("vin");
  doc["motor"] = "sts3250";
  const BamImport imported = import_bam_file(write("sts.json", doc), "sts.json");
  const JointLogMeta& meta = imported.log.meta;
  EXPECT_EQ(meta.parameters.size(), 3u);  // mass, length and the housing temperature only
  EXPECT_NE(meta.notes.find("no kp"), std::string::npos);
  EXPECT_NE(meta.notes.find("no vin"), std::string::npos);
  EXPECT_NE(meta.notes.find("'sts3250'"), std::string::npos);
  EXPECT_NE(meta.notes.find("set_p_gain"), std::string::npos);
}

// The servo's temperature readings give the log's housing temperature: their median, which one
// misread sample does not move (an STS3250 log reads 7 °C once amid 20-26 °C).
TEST_F(BamImportTest, HousingTemperatureIsTheMedianReading) {
  json doc = small_log();
  const double readings_c[] = {28.0, 7.0, 31.0, 30.0};
  for (int i = 0; i < 4; ++i) doc["entries"][i]["temp"] = readings_c[i];
  const BamImport imported = import_bam_file(write("warm.json", doc), "warm.json");
  // Sorted 7, 28, 30, 31: the upper of the two middle readings.
  EXPECT_EQ(imported.log.meta.parameters.at("motor.housing_temperature_c"), 30.0);
  EXPECT_NE(imported.log.meta.notes.find("median logged temp 30 C"), std::string::npos)
      << imported.log.meta.notes;

  // A reading missing in one entry (the first, so that no reading comes before the gap): no
  // temperature, and a note says why.
  doc["entries"][0].erase("temp");
  const BamImport partial = import_bam_file(write("partial.json", doc), "partial.json");
  EXPECT_EQ(partial.log.meta.parameters.count("motor.housing_temperature_c"), 0u);
  EXPECT_NE(partial.log.meta.notes.find("temp missing in some entries"), std::string::npos)
      << partial.log.meta.notes;

  doc = small_log();
  doc["entries"][1]["temp"] = "hot";
  expect_error(write("hot.json", doc), "entries[1].temp");
}

TEST_F(BamImportTest, NotJsonNamesTheLine) {
  const std::string message =
      expect_error(write("broken.json", std::string("{\"mass\": 0.49,\n\"length\": }")), "", 2);
  EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
}

TEST_F(BamImportTest, MissingKeysAreNamed) {
  for (const char* key : {"mass", "length", "entries"}) {
    json doc = small_log();
    doc.erase(key);
    expect_error(write(std::string("no_") + key + ".json", doc), key);
  }
  for (const char* key : {"timestamp", "position", "goal_position"}) {
    json doc = small_log();
    doc["entries"][1].erase(key);
    expect_error(write(std::string("no_") + key + ".json", doc), std::string("entries[1].") + key);
  }
}

TEST_F(BamImportTest, NonNumericValuesAreNamed) {
  json doc = small_log();
  doc["mass"] = "heavy";
  expect_error(write("mass.json", doc), "mass");
  doc = small_log();
  doc["entries"][2]["position"] = nullptr;
  expect_error(write("position.json", doc), "entries[2].position");
  doc = small_log();
  doc["entries"][0]["goal_position"] = true;
  expect_error(write("goal.json", doc), "entries[0].goal_position");
  doc = small_log();
  doc["entries"][0]["torque_enable"] = 1;
  expect_error(write("torque.json", doc), "entries[0].torque_enable");
  doc = small_log();
  doc["length"] = -0.1;
  expect_error(write("length.json", doc), "length");
}

TEST_F(BamImportTest, BareNanAndInfinityAreNamedByField) {
  std::string text = small_log().dump();
  const std::string goal = "\"goal_position\":0.04";
  text.replace(text.find(goal), goal.size(), "\"goal_position\":NaN");
  std::string message = expect_error(write("nan.json", text), "entries[2].goal_position");
  EXPECT_NE(message.find("NaN"), std::string::npos) << message;

  text = small_log().dump();
  text.replace(text.find("\"mass\":0.49"), 11, "\"mass\":-Infinity");
  message = expect_error(write("inf.json", text), "mass");
  EXPECT_NE(message.find("-Infinity"), std::string::npos) << message;
}

TEST_F(BamImportTest, FewerThanTwoEntriesIsAnError) {
  json doc = small_log();
  doc["entries"] = json::array({doc["entries"][0]});
  expect_error(write("one.json", doc), "entries");
}

TEST_F(BamImportTest, TimestampsMustStrictlyIncrease) {
  json doc = small_log();
  doc["entries"][2]["timestamp"] = doc["entries"][1]["timestamp"];  // an exact duplicate time
  std::string message = expect_error(write("equal.json", doc), "entries[2].timestamp");
  EXPECT_NE(message.find("strictly increase"), std::string::npos) << message;
  doc = small_log();
  doc["entries"][3]["timestamp"] = 0.001;
  expect_error(write("backwards.json", doc), "entries[3].timestamp");
}

TEST_F(BamImportTest, NonTrajectoryFilesSayWhatTheyAre) {
  const json pwm = {{"pwm_period", 42.6}, {"samples", json::array()}};
  std::string message = expect_error(write("pwm.json", pwm), "entries");
  EXPECT_NE(message.find("calibration table"), std::string::npos) << message;
  const json two_r = {{"mass", 0.5},
                      {"entries", {{{"timestamp", 0.0}, {"r1", {{"position", 0.0}}}}}}};
  expect_error(write("2r.json", two_r), "entries[0]");
}

TEST_F(BamImportTest, FolderImportNamesOutputsAndSkipsWithReasons) {
  write("in/xl330/raw/a.json", small_log());
  write("in/xl330/README.md", std::string("# notes\n"));
  write("in/mx64/velocity.json", json{{"1.0", 0.53}, {"2.0", 1.12}});
  const std::vector<BamDirectoryItem> items = import_bam_directory(path("in"));
  ASSERT_EQ(items.size(), 3u);
  EXPECT_EQ(items[0].relative_path, "mx64/velocity.json");
  EXPECT_FALSE(items[0].import);
  EXPECT_NE(items[0].skip_reason.find("speed vs voltage"), std::string::npos);
  EXPECT_EQ(items[1].relative_path, "xl330/README.md");
  EXPECT_EQ(items[1].skip_reason, "not a .json file");
  EXPECT_EQ(items[2].output_stem, "xl330_raw_a");
  ASSERT_TRUE(items[2].import);
  EXPECT_EQ(items[2].import->log.meta.origin, "imported from BAM xl330/raw/a.json");
}

TEST_F(BamImportTest, FolderImportTakesTheProcessedCopyOfARecordingOnly) {
  json processed = small_log();
  processed["dt"] = 0.005;
  for (int i = 0; i < 4; ++i) processed["entries"][i]["timestamp"] = i * 0.005;
  write("in/raw/a.json", small_log());
  write("in/processed/a.json", processed);
  write("in/raw/b.json", small_log());  // no processed copy
  json other_gain = small_log();        // same file name, another recording (kp 800)
  other_gain["kp"] = 800;
  write("in/raw/c.json", other_gain);
  write("in/processed/c.json", processed);
  const std::vector<BamDirectoryItem> items = import_bam_directory(path("in"));
  ASSERT_EQ(items.size(), 5u);
  std::map<std::string, const BamDirectoryItem*> by_path;
  for (const BamDirectoryItem& item : items) by_path[item.relative_path] = &item;
  EXPECT_TRUE(by_path.at("processed/a.json")->import);
  EXPECT_FALSE(by_path.at("raw/a.json")->import);
  EXPECT_NE(by_path.at("raw/a.json")->skip_reason.find("raw copy of processed/a.json"),
            std::string::npos)
      << by_path.at("raw/a.json")->skip_reason;
  EXPECT_TRUE(by_path.at("raw/b.json")->import);
  EXPECT_TRUE(by_path.at("raw/c.json")->import);
  EXPECT_TRUE(by_path.at("processed/c.json")->import);
}

TEST_F(BamImportTest, FolderImportFailsOnABrokenLogOrClashingNames) {
  write("bad/ok.json", small_log());
  json broken = small_log();
  broken.erase("mass");
  const std::string broken_path = write("bad/sub/broken.json", broken);
  try {
    import_bam_directory(path("bad"));
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), broken_path);
    EXPECT_EQ(e.field(), "mass");
  }

  write("clash/a/b.json", small_log());
  write("clash/a_b.json", small_log());
  EXPECT_THROW(import_bam_directory(path("clash")), InputError);
}

// Runs the motoflex binary with `arguments`; returns its exit code and fills `err`.
int run_motoflex(const std::string& arguments, const std::string& stderr_path, std::string& err) {
  const std::string command =
      std::string(MOTOFLEX_TEST_BINARY) + " " + arguments + " > /dev/null 2> '" + stderr_path + "'";
  const int status = std::system(command.c_str());
  err = read_text(stderr_path);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(BamImportTest, CliRejectsABadFileWithOneLineAndExitCode2) {
  json doc = small_log();
  doc["entries"][1]["position"] = "up";
  const std::string bad = write("bad_log.json", doc);
  std::string err;
  const int code =
      run_motoflex("import-bam '" + bad + "' --out '" + path("out") + "'", path("err.txt"), err);
  EXPECT_EQ(code, 2);
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find(bad), std::string::npos) << err;
  EXPECT_NE(err.find("entries[1].position"), std::string::npos) << err;
}

TEST_F(BamImportTest, CliImportsAFolder) {
  write("in/xl330/raw/a.json", small_log());
  write("in/mx64/pwm.json", json{{"pwm_period", 42.6}, {"samples", json::array()}});
  std::string err;
  const int code = run_motoflex("import-bam '" + path("in") + "' --out '" + path("out") + "'",
                                path("err.txt"), err);
  ASSERT_EQ(code, 0) << err;
  JointLogRequirements requirements;
  requirements.need_measured = true;
  requirements.need_sidecar = true;
  const JointLog log = read_joint_log(path("out/xl330_raw_a.csv"), requirements);
  EXPECT_EQ(log.frames(), 4u);
  EXPECT_EQ(log.meta.parameters.at("bench.kp"), 400.0);
  EXPECT_FALSE(fs::exists(path("out/mx64_pwm.csv")));
}

}  // namespace
}  // namespace motoflex
