// Logs as other recorders write them: a sidecar `columns:` map from our names to the file's
// columns, `units:` for the angle groups and the time, extra columns kept with one warning, and
// angles that look like degrees without a declaration refused with a hint.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "input_error_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "scratch_dir.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

class JointLogFormatsTest : public testing::ScratchFolderTest {
 protected:
  // Writes NAME.csv and, when `sidecar` is not empty, NAME.yaml; returns the CSV path.
  std::string write(const std::string& name, const std::string& csv,
                    const std::string& sidecar = "") const {
    std::ofstream(dir_ / (name + ".csv"), std::ios::binary) << csv;
    if (!sidecar.empty()) std::ofstream(dir_ / (name + ".yaml"), std::ios::binary) << sidecar;
    return (dir_ / (name + ".csv")).string();
  }
  std::string sidecar_of(const std::string& name) const {
    return (dir_ / (name + ".yaml")).string();
  }
};

using testing::expect_input_error_thrown;

const std::string kHeader = "robot: arm\nrate_hz: 100\n";

TEST_F(JointLogFormatsTest, ColumnsMapNamesTheFilesColumnsAndKeepsTheRest) {
  // A recorder's own names, time not first, and two columns we do not read.
  const std::string csv = write("rec",
                                "temp_c,pos_elbow,t,goal_elbow,mode\n"
                                "31.5,0.10,0.000,0.20,hold\n"
                                "31.6,0.12,0.010,0.25,move\n",
                                kHeader +
                                    "columns:\n  time_s: t\n  elbow.meas: pos_elbow\n"
                                    "  elbow.cmd: goal_elbow\n");
  JointLogRequirements requirements;
  requirements.need_measured = true;
  requirements.joints = {"elbow"};
  const JointLog log = read_joint_log(csv, requirements);
  EXPECT_EQ(log.joint_names, (std::vector<std::string>{"elbow"}));
  EXPECT_EQ(log.time_s, (std::vector<double>{0.0, 0.01}));
  EXPECT_EQ(log.commanded_rad, (std::vector<double>{0.20, 0.25}));
  EXPECT_EQ(log.measured_rad, (std::vector<double>{0.10, 0.12}));
  // Kept as written, ignored, and named once in one warning.
  EXPECT_EQ(log.extra_column_names, (std::vector<std::string>{"temp_c", "mode"}));
  EXPECT_EQ(log.extra_values, (std::vector<std::string>{"31.5", "hold", "31.6", "move"}));
  ASSERT_EQ(log.warnings.size(), 1u);
  EXPECT_NE(log.warnings[0].find("2 extra column(s)"), std::string::npos) << log.warnings[0];
  EXPECT_NE(log.warnings[0].find("temp_c, mode"), std::string::npos) << log.warnings[0];
  EXPECT_EQ(log.warnings[0].rfind(csv + ":1:", 0), 0u) << log.warnings[0];

  // A bad value in a mapped column is reported under the file's name for it.
  const std::string bad = write("bad", "pos_elbow,t,goal_elbow\n0.1,0,0.2\n0.1,0.01,x\n",
                                kHeader +
                                    "columns: {time_s: t, elbow.meas: pos_elbow, "
                                    "elbow.cmd: goal_elbow}\n");
  expect_input_error_thrown([&] { read_joint_log(bad, {}); }, bad, 3, "goal_elbow");
}

TEST_F(JointLogFormatsTest, ColumnsMapErrorsPointAtTheSidecar) {
  // A mapped column the header lacks: the sidecar's line, under the mapped name.
  const std::string csv =
      write("missing", "t,a\n0,1\n1,2\n", kHeader + "columns:\n  time_s: t\n  elbow.cmd: goal\n");
  const InputError e = expect_input_error_thrown([&] { read_joint_log(csv, {}); },
                                                 sidecar_of("missing"), 5, "columns.elbow.cmd");
  EXPECT_NE(std::string(e.what()).find("no column 'goal'"), std::string::npos) << e.what();
  // Without a mapping our time column comes first: the message says how to map another.
  const std::string unmapped = write("unmapped", "t,elbow.cmd\n0,1\n1,2\n");
  const InputError first =
      expect_input_error_thrown([&] { read_joint_log(unmapped, {}); }, unmapped, 1, "time_s");
  EXPECT_NE(std::string(first.what()).find("columns: {time_s: t}"), std::string::npos)
      << first.what();
  // A column mapped twice to one of ours cannot happen (keys are unique); a literal column of
  // the same name as a mapped one is an extra column.
  const std::string literal = write("literal", "t,elbow.cmd,goal\n0,1,0.5\n1,2,0.6\n",
                                    kHeader + "columns: {time_s: t, elbow.cmd: goal}\n");
  const JointLog log = read_joint_log(literal, {});
  EXPECT_EQ(log.commanded_rad, (std::vector<double>{0.5, 0.6}));
  EXPECT_EQ(log.extra_column_names, (std::vector<std::string>{"elbow.cmd"}));
}

TEST_F(JointLogFormatsTest, DegreesAreConvertedPerColumnGroup) {
  const std::string all = write("all", "time_s,a.cmd,a.meas,imu.roll\n0,90,-45,180\n1,30,60,1\n",
                                kHeader + "units: deg\n");
  JointLogRequirements requirements;
  requirements.need_measured = true;
  JointLog log = read_joint_log(all, requirements);
  const double deg = std::numbers::pi / 180.0;
  EXPECT_DOUBLE_EQ(log.commanded_rad[0], std::numbers::pi / 2.0);
  EXPECT_DOUBLE_EQ(log.measured_rad[0], -std::numbers::pi / 4.0);
  EXPECT_DOUBLE_EQ(log.imu_roll_rad[0], std::numbers::pi);
  EXPECT_DOUBLE_EQ(log.commanded_rad[1], 30.0 * deg);
  EXPECT_EQ(log.meta.units, "rad");  // in memory: always rad
  // Per group: the commands in degrees, the measurements in radians (`angles` for the rest).
  const std::string mixed = write("mixed", "time_s,a.cmd,a.meas\n0,90,1.5\n1,30,0.5\n",
                                  kHeader + "units: {angles: rad, cmd: deg}\n");
  log = read_joint_log(mixed, requirements);
  EXPECT_DOUBLE_EQ(log.commanded_rad[0], std::numbers::pi / 2.0);
  EXPECT_EQ(log.measured_rad[0], 1.5);
}

TEST_F(JointLogFormatsTest, UndeclaredDegreesAreAnErrorWithAHint) {
  // No sidecar at all: the knee reads 35 at line 3.
  const std::string bare = write("bare", "time_s,knee.cmd\n0,0.5\n0.01,35\n");
  const InputError e =
      expect_input_error_thrown([&] { read_joint_log(bare, {}); }, bare, 3, "knee.cmd");
  const std::string message = e.what();
  EXPECT_NE(message.find("looks like it is in degrees"), std::string::npos) << message;
  EXPECT_NE(message.find("units: deg"), std::string::npos) << message;
  EXPECT_NE(message.find(sidecar_of("bare") + " (there is none yet)"), std::string::npos)
      << message;
  // A sidecar that declares other groups only: still undeclared for the measurements.
  const std::string partial = write("partial", "time_s,knee.cmd,knee.meas\n0,10,0.1\n1,20,-7\n",
                                    kHeader + "units: {cmd: deg}\n");
  JointLogRequirements requirements;
  requirements.need_measured = true;
  const InputError meas = expect_input_error_thrown([&] { read_joint_log(partial, requirements); },
                                                    partial, 3, "knee.meas");
  EXPECT_NE(std::string(meas.what()).find("{meas: deg}"), std::string::npos) << meas.what();
  // Declared radians beyond 2π are accepted (a multi-turn joint).
  const std::string turns =
      write("turns", "time_s,wheel.cmd\n0,0\n1,31.4\n", kHeader + "units: rad\n");
  EXPECT_EQ(read_joint_log(turns, {}).commanded_rad[1], 31.4);
}

TEST_F(JointLogFormatsTest, TimeInMillisecondsMicrosecondsAndNanoseconds) {
  const struct {
    const char* unit;
    const char* t1;
  } cases[] = {
      {"s", "0.25"}, {"ms", "250"}, {"us", "250000"}, {"µs", "250000"}, {"ns", "250000000"}};
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    const std::string csv = write("time_" + std::to_string(i),
                                  std::string("time_s,a.cmd\n0,0.1\n") + cases[i].t1 + ",0.2\n",
                                  kHeader + "units: {time: " + cases[i].unit + "}\n");
    EXPECT_NEAR(read_joint_log(csv, {}).time_s[1], 0.25, 1e-15) << cases[i].unit;
  }
  // Strict increase is checked after the conversion, and reported in seconds.
  const std::string back =
      write("back", "time_s,a.cmd\n5,0\n4,0\n", kHeader + "units: {time: ms}\n");
  const InputError e =
      expect_input_error_thrown([&] { read_joint_log(back, {}); }, back, 3, "time_s");
  EXPECT_NE(std::string(e.what()).find("0.005 s"), std::string::npos) << e.what();
}

TEST_F(JointLogFormatsTest, IrregularSampleTimesAreFine) {
  // A recorder's clock with jitter (BAM's raw XL330 logs: 3.4 to 7.1 ms apart).
  const std::string csv = write("jitter",
                                "time_s,a.cmd\n0.0035,0\n0.0070,0.1\n0.0141,0.3\n"
                                "0.0193,0.2\n0.0200,0.25\n");
  const JointLog log = read_joint_log(csv, {});
  EXPECT_EQ(log.time_s, (std::vector<double>{0.0035, 0.0070, 0.0141, 0.0193, 0.0200}));
  EXPECT_TRUE(log.warnings.empty());
}

}  // namespace
}  // namespace motoflex
