// The 2011 MoToFlex command format (include/motoflex/io/motoflex_command_file.hpp): header of
// joint names, ';'-separated rows every 20 ms, LHipRoll and LAnkleRoll mirrored; the original's
// playback clock (zero pose at t = 0 in place of row 0). The files are written here.

#include "motoflex/io/motoflex_command_file.hpp"

#include <gtest/gtest.h>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const char* kHeader =
    "LHipRoll;LHipPitch;LKneePitch;LAnklePitch;LAnkleRoll;RHipRoll;RHipPitch;RKneePitch;"
    "RAnklePitch;RAnkleRoll\n";

// Row k: joint j holds (k + 1) / 10 + j / 100, so every value says where it came from.
std::string rows(int count, const char* end = "\n") {
  std::string text;
  for (int k = 0; k < count; ++k) {
    for (int j = 0; j < 10; ++j) {
      text += std::to_string(0.1 * (k + 1) + 0.01 * j) + (j < 9 ? ";" : end);
    }
  }
  return text;
}

fs::path write(const std::string& name, const std::string& text) {
  const fs::path dir = fresh_dir("motoflex_command_file");
  write_text(dir / name, text);
  return dir / name;
}

TEST(MotoflexCommandFile, OriginalClockStartsFromTheZeroPoseAndMirrorsTheLeftRolls) {
  const fs::path file = write("walk.csv", kHeader + rows(4));
  ASSERT_TRUE(is_motoflex_command_file(file.string()));
  const JointLog log = import_motoflex_commands(file.string());
  ASSERT_EQ(log.joints(), 10u);
  EXPECT_EQ(log.joint_names.front(), "LHipRoll");
  EXPECT_EQ(log.joint_names.back(), "RAnkleRoll");
  ASSERT_EQ(log.frames(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(log.time_s[k], 0.02 * k);
  for (std::size_t j = 0; j < 10; ++j) EXPECT_EQ(log.commanded(0, j), 0.0) << j;  // row 0 unused
  for (std::size_t k = 1; k < 4; ++k) {
    for (std::size_t j = 0; j < 10; ++j) {
      const double file_value = 0.1 * (k + 1) + 0.01 * j;
      const bool mirrored = j == 0 || j == 4;  // LHipRoll, LAnkleRoll
      EXPECT_NEAR(log.commanded(k, j), mirrored ? -file_value : file_value, 1e-12) << k << j;
    }
  }
  EXPECT_DOUBLE_EQ(log.meta.rate_hz, 50.0);
  EXPECT_TRUE(log.meta.robot.empty());
}

TEST(MotoflexCommandFile, PlainClockKeepsRowZeroAndTheSidecarNamesTheRobot) {
  const fs::path file = write("walk.csv", kHeader + rows(3));
  MotoflexCommandImportOptions options;
  options.clock = MotoflexCommandClock::kPlain;
  options.robot = "nao_motoflex_2011";
  const JointLog log = import_motoflex_commands(file.string(), options);
  ASSERT_EQ(log.frames(), 3u);
  EXPECT_NEAR(log.commanded(0, 1), 0.11, 1e-12);
  EXPECT_NEAR(log.commanded(0, 0), -0.10, 1e-12);
  EXPECT_DOUBLE_EQ(log.time_s[2], 0.04);
  EXPECT_EQ(log.meta.robot, "nao_motoflex_2011");
  // It is an ordinary joint log from here on.
  const fs::path out = file.parent_path() / "out.csv";
  write_joint_log(out.string(), log);
  const JointLog back = read_joint_log(out.string(), {});
  EXPECT_EQ(back.commanded_rad, log.commanded_rad);
}

TEST(MotoflexCommandFile, ColumnsAreReadByNameWithTrailingSemicolonsCrLfAndABom) {
  std::string header =
      "\xEF\xBB\xBFRAnkleRoll;LHipPitch;LKneePitch;LAnklePitch;LAnkleRoll;RHipRoll;"
      "RHipPitch;RKneePitch;RAnklePitch;LHipRoll;\r\n";
  const fs::path file = write("walk.csv", header + rows(2, ";\r\n"));
  ASSERT_TRUE(is_motoflex_command_file(file.string()));
  const JointLog log = import_motoflex_commands(file.string());
  EXPECT_EQ(log.joint_names.front(), "RAnkleRoll");
  EXPECT_NEAR(log.commanded(1, 0), 0.20, 1e-12);   // RAnkleRoll: as in the file
  EXPECT_NEAR(log.commanded(1, 9), -0.29, 1e-12);  // LHipRoll, last column: negated
}

TEST(MotoflexCommandFile, AJointLogIsNotACommandFile) {
  const fs::path file = write("log.csv", "time_s,LHipRoll.cmd\n0,0\n0.01,0\n");
  EXPECT_FALSE(is_motoflex_command_file(file.string()));
  EXPECT_FALSE(is_motoflex_command_file((file.parent_path() / "missing.csv").string()));
}

void expect_error(const std::string& text, int line, const std::string& field,
                  const std::string& words) {
  const fs::path file = write("bad.csv", text);
  try {
    import_motoflex_commands(file.string());
    ADD_FAILURE() << "no error for " << words;
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), line) << error.what();
    EXPECT_EQ(error.field(), field) << error.what();
    EXPECT_NE(error.message().find(words), std::string::npos) << error.what();
  }
}

TEST(MotoflexCommandFile, BadInputNamesLineAndField) {
  std::string unknown = kHeader;
  unknown.replace(0, 8, "LHipYaw");
  expect_error(unknown + rows(2), 1, "header", "'LHipYaw' is not a joint");
  std::string missing = "LHipRoll;LHipPitch\n0;0\n0;0\n";
  expect_error(missing, 1, "header", "missing LKneePitch");
  expect_error(std::string(kHeader) + rows(1) + "0;0;0\n", 3, "", "expected 10");
  std::string bad_number = std::string(kHeader) + rows(1) + rows(1);
  bad_number.replace(bad_number.rfind(';') + 1, 4, "nan?");
  expect_error(bad_number, 3, "RAnkleRoll", "not a finite number");
  expect_error(std::string(kHeader) + rows(1), 2, "", "at least 2 rows");
  expect_error("", 0, "", "empty file");
}

}  // namespace
}  // namespace motoflex::testing
