#include "motoflex/io/joint_log.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>

#include "input_error_support.hpp"
#include "motoflex/core/error.hpp"
#include "scratch_dir.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

using testing::expect_input_error;

class JointLogTest : public testing::ScratchFolderTest {
 protected:
  std::vector<std::string> files_in_dir() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }
};

void expect_bit_identical(const std::vector<double>& expected, const std::vector<double>& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(expected[i]), std::bit_cast<std::uint64_t>(actual[i]))
        << "index " << i << ": " << expected[i] << " vs " << actual[i];
  }
}

JointLog make_log() {
  JointLog log;
  log.joint_names = {"LKneePitch", "RKneePitch", "HeadYaw"};
  const std::size_t frames = 50;
  for (std::size_t f = 0; f < frames; ++f) {
    log.time_s.push_back(0.01 * static_cast<double>(f) + 1.0 / 3.0);
    for (std::size_t j = 0; j < 3; ++j) {
      const double x = static_cast<double>(f * 3 + j);
      log.commanded_rad.push_back(std::sin(x) / 7.0);
      log.measured_rad.push_back(std::cos(x) * 1e-3 + 0.1);
    }
    log.imu_roll_rad.push_back(std::sqrt(static_cast<double>(f)) * 1e-5);
    log.imu_pitch_rad.push_back(-std::atan(static_cast<double>(f)));
    log.supply_v.push_back(7.4 - 0.1 * std::sin(static_cast<double>(f)) / 3.0);
  }
  // Values that a fixed-precision printer would not round-trip.
  log.commanded_rad[0] = -0.0;
  log.commanded_rad[1] = std::numeric_limits<double>::denorm_min();
  log.commanded_rad[2] = 1e300;
  log.measured_rad[0] = 0.1 + 0.2;
  log.measured_rad[1] = -std::numeric_limits<double>::min();
  log.measured_rad[2] = std::nextafter(1.0, 2.0);
  log.meta.robot = "nao";
  log.meta.rate_hz = 100.0;
  log.meta.motion = "walk forward: 0.1 m/s";
  log.meta.origin = "motoflex record truth=truth/nao_backlash.yaml seed=7";
  log.meta.parameters = {{"bench.mass_kg", 0.1 + 0.2}, {"bench.offset_rad", -0.0}};
  log.meta.notes = "line one\nline two: with colon, \"quotes\" and # hash\n";
  return log;
}

TEST_F(JointLogTest, SidecarPathReplacesExtension) {
  EXPECT_EQ(joint_log_sidecar_path("logs/walk.csv"), "logs/walk.yaml");
  EXPECT_EQ(joint_log_sidecar_path("/a/b.c/walk"), "/a/b.c/walk.yaml");
}

TEST_F(JointLogTest, RoundTripIsBitIdentical) {
  const JointLog log = make_log();
  const std::string csv = path("walk.csv");
  write_joint_log(csv, log);
  EXPECT_EQ(files_in_dir(), (std::vector<std::string>{"walk.csv", "walk.yaml"}));

  JointLogRequirements requirements;
  requirements.need_measured = true;
  requirements.need_sidecar = true;
  requirements.joints = {"HeadYaw", "LKneePitch"};
  const JointLog read = read_joint_log(csv, requirements);
  EXPECT_EQ(read.joint_names, log.joint_names);
  expect_bit_identical(log.time_s, read.time_s);
  expect_bit_identical(log.commanded_rad, read.commanded_rad);
  expect_bit_identical(log.measured_rad, read.measured_rad);
  expect_bit_identical(log.imu_roll_rad, read.imu_roll_rad);
  expect_bit_identical(log.imu_pitch_rad, read.imu_pitch_rad);
  expect_bit_identical(log.supply_v, read.supply_v);
  EXPECT_EQ(read.meta.robot, log.meta.robot);
  EXPECT_EQ(read.meta.rate_hz, log.meta.rate_hz);
  EXPECT_EQ(read.meta.motion, log.meta.motion);
  EXPECT_EQ(read.meta.units, "rad");
  EXPECT_EQ(read.meta.origin, log.meta.origin);
  EXPECT_EQ(read.meta.notes, log.meta.notes);
  ASSERT_EQ(read.meta.parameters.size(), 2u);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(read.meta.parameters.at("bench.mass_kg")),
            std::bit_cast<std::uint64_t>(0.1 + 0.2));
  EXPECT_TRUE(std::signbit(read.meta.parameters.at("bench.offset_rad")));
  EXPECT_EQ(read.frames(), 50u);
  EXPECT_EQ(read.joints(), 3u);
  EXPECT_EQ(read.commanded(7, 2), log.commanded(7, 2));
  EXPECT_EQ(read.measured(7, 1), log.measured(7, 1));
  EXPECT_EQ(read.joint_index("RKneePitch"), std::optional<std::size_t>(1));
  EXPECT_FALSE(read.joint_index("Nope").has_value());

  // Overwriting leaves no temporary files either.
  write_joint_log(csv, log);
  EXPECT_EQ(files_in_dir(), (std::vector<std::string>{"walk.csv", "walk.yaml"}));
}

TEST_F(JointLogTest, RoundTripWithoutOptionalColumnsAndEmptyMeta) {
  JointLog log;
  log.joint_names = {"a"};
  log.time_s = {0.0, 0.5};
  log.measured_rad = {1.0, 2.0};
  log.meta.robot = "bench";
  log.meta.rate_hz = 2.0;
  write_joint_log(path("m.csv"), log);
  JointLogRequirements requirements;
  requirements.need_commanded = false;
  requirements.need_measured = true;
  const JointLog read = read_joint_log(path("m.csv"), requirements);
  EXPECT_FALSE(read.has_commanded());
  EXPECT_TRUE(read.has_measured());
  EXPECT_TRUE(read.imu_roll_rad.empty());
  EXPECT_TRUE(read.imu_pitch_rad.empty());
  EXPECT_EQ(read.measured_rad, log.measured_rad);
  EXPECT_EQ(read.meta.motion, "");
  EXPECT_TRUE(read.meta.parameters.empty());
}

TEST_F(JointLogTest, ReadsHandWrittenLogInAnyColumnOrder) {
  const std::string csv = write("hand.csv",
                                "# recorded on the bench\r\n"
                                "# second comment\r\n"
                                "\r\n"
                                "time_s, b.meas, a.cmd ,imu.pitch, b.cmd, a.meas\r\n"
                                "0, 1, 2, 3, 4, 5\r\n"
                                "0.01,+1.1,1.2,1.3,1.4,1.5e-1\r\n");
  JointLogRequirements requirements;
  requirements.need_measured = true;
  const JointLog log = read_joint_log(csv, requirements);
  EXPECT_EQ(log.joint_names, (std::vector<std::string>{"b", "a"}));
  EXPECT_EQ(log.time_s, (std::vector<double>{0.0, 0.01}));
  EXPECT_EQ(log.commanded_rad, (std::vector<double>{4, 2, 1.4, 1.2}));
  EXPECT_EQ(log.measured_rad, (std::vector<double>{1, 5, 1.1, 0.15}));
  EXPECT_TRUE(log.imu_roll_rad.empty());
  EXPECT_EQ(log.imu_pitch_rad, (std::vector<double>{3, 1.3}));
  EXPECT_EQ(log.meta.rate_hz, 0.0);  // no sidecar, not required
}

TEST_F(JointLogTest, IgnoresUtf8ByteOrderMark) {
  const std::string csv = write("bom.csv", "\xEF\xBB\xBFtime_s,a.cmd\n0,1\n1,2\n");
  EXPECT_EQ(read_joint_log(csv, {}).commanded_rad, (std::vector<double>{1, 2}));
}

TEST_F(JointLogTest, MissingAndEmptyFiles) {
  const std::string missing = path("missing.csv");
  expect_input_error([&] { read_joint_log(missing, {}); }, missing, 0, "");
  const std::string empty = write("empty.csv", "");
  expect_input_error([&] { read_joint_log(empty, {}); }, empty, 0, "");
  const std::string comments = write("comments.csv", "# nothing\n\n# here\n");
  expect_input_error([&] { read_joint_log(comments, {}); }, comments, 3, "");
}

TEST_F(JointLogTest, HeaderErrors) {
  const std::string no_time = write("a.csv", "# c\ntime,a.cmd\n0,1\n1,2\n");
  expect_input_error([&] { read_joint_log(no_time, {}); }, no_time, 2, "time_s");
  const std::string time_second = write("b.csv", "a.cmd,time_s\n0,1\n1,2\n");
  expect_input_error([&] { read_joint_log(time_second, {}); }, time_second, 1, "time_s");
  const std::string bare = write("d.csv", "time_s,.cmd\n0,1\n1,2\n");
  expect_input_error([&] { read_joint_log(bare, {}); }, bare, 1, ".cmd");
  const std::string blank = write("e.csv", "time_s,a.cmd,\n0,1,2\n1,2,3\n");
  expect_input_error([&] { read_joint_log(blank, {}); }, blank, 1, "column 3");
  const std::string duplicate = write("f.csv", "time_s,a.cmd,b.cmd,a.cmd\n0,1,2,3\n1,2,3,4\n");
  expect_input_error([&] { read_joint_log(duplicate, {}); }, duplicate, 1, "a.cmd");
  const std::string duplicate_time = write("g.csv", "time_s,a.cmd,time_s\n0,1,2\n1,2,3\n");
  expect_input_error([&] { read_joint_log(duplicate_time, {}); }, duplicate_time, 1, "time_s");
}

TEST_F(JointLogTest, MissingCommandedOrMeasuredColumns) {
  const std::string meas_only = write("a.csv", "time_s,a.cmd,b.meas\n0,1,2\n1,2,3\n");
  const std::string message =
      expect_input_error([&] { read_joint_log(meas_only, {}); }, meas_only, 1, "b.cmd");
  EXPECT_NE(message.find("joint 'b'"), std::string::npos) << message;

  // Even when commanded angles are optional, a log cannot have them for some joints only.
  JointLogRequirements optional_cmd;
  optional_cmd.need_commanded = false;
  expect_input_error([&] { read_joint_log(meas_only, optional_cmd); }, meas_only, 1, "b.cmd");

  JointLogRequirements need_meas;
  need_meas.need_measured = true;
  const std::string cmd_only = write("b.csv", "time_s,a.cmd\n0,1\n1,2\n");
  expect_input_error([&] { read_joint_log(cmd_only, need_meas); }, cmd_only, 1, "a.meas");

  const std::string no_joints = write("c.csv", "time_s,imu.roll\n0,1\n1,2\n");
  expect_input_error([&] { read_joint_log(no_joints, {}); }, no_joints, 1, "header");
  JointLogRequirements nothing_needed;
  nothing_needed.need_commanded = false;
  EXPECT_EQ(read_joint_log(no_joints, nothing_needed).imu_roll_rad, (std::vector<double>{1, 2}));
}

TEST_F(JointLogTest, RequiredJointMissing) {
  const std::string csv = write("a.csv", "time_s,a.cmd,a.meas\n0,1,2\n1,2,3\n");
  JointLogRequirements requirements;
  requirements.joints = {"a", "knee"};
  const std::string message =
      expect_input_error([&] { read_joint_log(csv, requirements); }, csv, 1, "knee.cmd");
  EXPECT_NE(message.find("'knee'"), std::string::npos) << message;
  requirements.need_commanded = false;
  requirements.need_measured = true;
  expect_input_error([&] { read_joint_log(csv, requirements); }, csv, 1, "knee.meas");
}

TEST_F(JointLogTest, RowErrorsNameLineAndColumn) {
  const std::string header = "# log\ntime_s,a.cmd,b.cmd,imu.roll\n0,1,2,3\n";  // lines 1-3
  const auto check = [&](const std::string& name, const std::string& bad_row,
                         const std::string& field) {
    const std::string csv = write(name, header + "0.01,1,2,3\n\n" + bad_row + "\n0.5,1,1,1\n");
    return expect_input_error([&] { read_joint_log(csv, {}); }, csv, 6, field);
  };
  check("few.csv", "0.02,1,2", "row");
  check("many.csv", "0.02,1,2,3,4", "row");
  check("trailing_comma.csv", "0.02,1,2,3,", "row");
  const std::string word = check("word.csv", "0.02,1,abc,3", "b.cmd");
  EXPECT_NE(word.find("'abc'"), std::string::npos) << word;
  check("suffix.csv", "0.02,1,2x,3", "b.cmd");
  check("empty.csv", "0.02,,2,3", "a.cmd");
  check("nan.csv", "0.02,nan,2,3", "a.cmd");
  check("neg_nan.csv", "0.02,-nan,2,3", "a.cmd");
  check("inf.csv", "0.02,1,2,inf", "imu.roll");
  const std::string bad = write("supply.csv", "time_s,a.cmd,supply_v\n0,1,7.4\n0.02,1,-1\n");
  const std::string message =
      expect_input_error([&] { read_joint_log(bad, {}); }, bad, 3, "supply_v");
  EXPECT_NE(message.find("positive"), std::string::npos) << message;
  check("neg_inf.csv", "0.02,1,-infinity,3", "b.cmd");
  check("huge.csv", "0.02,1e999,2,3", "a.cmd");
  check("time_word.csv", "later,1,2,3", "time_s");
  check("decimal_comma.csv", "0.02,1;5,2,3", "a.cmd");
  const std::string equal = check("equal_time.csv", "0.01,1,2,3", "time_s");
  EXPECT_NE(equal.find("strictly increase"), std::string::npos) << equal;
  check("back_in_time.csv", "0.005,1,2,3", "time_s");
}

TEST_F(JointLogTest, TooFewRows) {
  const std::string one = write("one.csv", "time_s,a.cmd\n0,1\n");
  expect_input_error([&] { read_joint_log(one, {}); }, one, 2, "rows");
  const std::string none = write("none.csv", "time_s,a.cmd\n");
  expect_input_error([&] { read_joint_log(none, {}); }, none, 1, "rows");
}

TEST_F(JointLogTest, SidecarErrors) {
  const std::string csv = write("walk.csv", "time_s,a.cmd\n0,1\n0.01,2\n");
  const std::string yaml = path("walk.yaml");
  JointLogRequirements requirements;
  requirements.need_sidecar = true;
  expect_input_error([&] { read_joint_log(csv, requirements); }, yaml, 0, "");

  const auto check = [&](const std::string& text, int line, const std::string& field) {
    write("walk.yaml", text);
    return expect_input_error([&] { read_joint_log(csv, requirements); }, yaml, line, field);
  };
  check("robot: nao\nrate_hz: [100\n", 3, "");
  const std::string rate = check("robot: nao\nrate_hz: fast\n", 2, "rate_hz");
  EXPECT_NE(rate.find("'fast'"), std::string::npos) << rate;
  check("robot: nao\nrate_hz: .nan\n", 2, "rate_hz");
  check("robot: nao\nrate_hz: 0\n", 2, "rate_hz");
  check("robot: nao\nrate_hz: \"100\"\n", 2, "rate_hz");
  const std::string unknown = check("robot: nao\nrate_hz: 100\nrate: 100\n", 3, "rate");
  EXPECT_NE(unknown.find("did you mean 'rate_hz'?"), std::string::npos) << unknown;
  check("rate_hz: 100\n", 1, "robot");
  check("robot: nao\n", 1, "rate_hz");
  check("robot: nao\nrate_hz: 100\nunits: furlong\n", 3, "units");
  check("robot: nao\nrate_hz: 100\nunits: {cmd: grad}\n", 3, "units.cmd");
  check("robot: nao\nrate_hz: 100\nunits: {time: min}\n", 3, "units.time");
  check("robot: nao\nrate_hz: 100\nunits: {knee: deg}\n", 3, "units.knee");
  check("robot: nao\nrate_hz: 100\ncolumns: {knee: k}\n", 3, "columns.knee");
  check("robot: nao\nrate_hz: 100\ncolumns: [a]\n", 3, "columns");
  check("robot: nao\nrate_hz: 100\ncolumns:\n  a.cmd: x\n  a.meas: x\n", 5, "columns.a.meas");
  check("robot: nao\nrate_hz: 100\nparameters:\n  bench.mass_kg: heavy\n", 4,
        "parameters.bench.mass_kg");
  check("robot: nao\nrate_hz: 100\nparameters: 3\n", 3, "parameters");
  check("robot: nao\nrate_hz: 100\nrobot: titan\n", 3, "robot");
  check("- robot\n- nao\n", 1, "");

  // Present but broken sidecars are errors even when the sidecar is optional.
  write("walk.yaml", "robot: nao\nrate_hz: slow\n");
  expect_input_error([&] { read_joint_log(csv, {}); }, yaml, 2, "rate_hz");
}

TEST_F(JointLogTest, WriterRejectsLogsTheReaderWouldReject) {
  const JointLog good = make_log();
  const auto expect_rejected = [&](const std::function<void(JointLog&)>& spoil) {
    JointLog log = good;
    spoil(log);
    EXPECT_THROW(write_joint_log(path("bad.csv"), log), std::invalid_argument);
  };
  expect_rejected([](JointLog& log) { log.measured_rad[5] = std::nan(""); });
  expect_rejected([](JointLog& log) { log.imu_roll_rad[3] = INFINITY; });
  expect_rejected([](JointLog& log) { log.time_s[4] = log.time_s[3]; });
  expect_rejected([](JointLog& log) { log.commanded_rad.pop_back(); });
  expect_rejected([](JointLog& log) { log.imu_pitch_rad.pop_back(); });
  expect_rejected([](JointLog& log) { log.joint_names[1] = "a,b"; });
  expect_rejected([](JointLog& log) { log.joint_names[1] = " padded"; });
  expect_rejected([](JointLog& log) { log.joint_names[1] = log.joint_names[0]; });
  expect_rejected([](JointLog& log) { log.meta.robot.clear(); });
  expect_rejected([](JointLog& log) { log.meta.rate_hz = 0.0; });
  expect_rejected([](JointLog& log) { log.meta.units = "deg"; });
  expect_rejected([](JointLog& log) { log.meta.parameters["x"] = std::nan(""); });
  expect_rejected([](JointLog& log) {
    log.commanded_rad.clear();
    log.measured_rad.clear();
  });
  expect_rejected([](JointLog& log) {
    log.time_s.resize(1);
    log.commanded_rad.resize(3);
    log.measured_rad.resize(3);
    log.imu_roll_rad.resize(1);
    log.imu_pitch_rad.resize(1);
  });
  EXPECT_THROW(write_joint_log(path("bad.yaml"), good), std::invalid_argument);
  EXPECT_TRUE(files_in_dir().empty());
}

TEST_F(JointLogTest, WritingIntoMissingFolderThrowsInputErrorAndLeavesNothing) {
  const std::string csv = path("no/such/folder/walk.csv");
  try {
    write_joint_log(csv, make_log());
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), csv);
    EXPECT_NE(std::string(e.what()).find(csv), std::string::npos) << e.what();
  }
  EXPECT_TRUE(files_in_dir().empty());
}

}  // namespace
}  // namespace motoflex
