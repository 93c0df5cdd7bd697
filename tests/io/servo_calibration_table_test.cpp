// BAM's servo calibration tables: synthetic tables with known constants are recovered, errors
// name the file and field, and on the real MX-64/MX-106 tables (../shared/data/bam, skipped
// when absent) the through-origin fits give BAM's published constants while the fit with an
// offset finds the no-load friction drop BAM's fit folds into K_t.

#include "motoflex/io/servo_calibration_table.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "motoflex/core/error.hpp"
#include "scratch_dir.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

const fs::path kBamDataDir = fs::path(MOTOFLEX_SOURCE_DIR) / ".." / "shared" / "data" / "bam";

std::string write_table(const std::string& name, const std::string& text) {
  const fs::path dir = motoflex::testing::scratch_root() / "calibration";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

std::string error_of(const std::string& path) {
  try {
    read_servo_calibration_table(path, path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ServoCalibrationTableTest, SpeedTableRecoversTheBackEmfConstantAndTheFrictionDrop) {
  // V = 1.5·ω + 0.3 exactly: the fit with an offset recovers both; through the origin the
  // offset is folded into a larger constant, Σω·V/Σω².
  std::string text = "{";
  double swv = 0.0, sww = 0.0;
  for (int v = 1; v <= 6; ++v) {
    const double w = (v - 0.3) / 1.5;
    swv += w * v;
    sww += w * w;
    text +=
        (v > 1 ? ", " : "") + std::string("\"") + std::to_string(v) + ".0\": " + std::to_string(w);
  }
  text += "}";
  const ServoCalibrationTable t =
      read_servo_calibration_table(write_table("speed.json", text), "s");
  ASSERT_EQ(t.kind, ServoCalibrationTable::Kind::kSpeedVoltage);
  EXPECT_NEAR(t.speed.affine.slope, 1.5, 1e-5);  // std::to_string keeps 6 decimals
  EXPECT_NEAR(t.speed.affine.intercept, 0.3, 1e-5);
  EXPECT_NEAR(t.speed.through_origin.slope, swv / sww, 1e-5);
  EXPECT_GT(t.speed.through_origin.slope, 1.5 + 0.02);
}

TEST(ServoCalibrationTableTest, PwmTableGivesTheFirmwareGainAndTheDynamixelDivisor) {
  // U = 2.0 V per kp·rad at 12 V: on-time = U/12·P with P = 40; errors in degrees.
  std::string samples;
  const double errors_deg[] = {5.0, 10.0, 20.0, 8.0};
  const int gains[] = {4, 4, 8, 16};
  for (int i = 0; i < 4; ++i) {
    const double u = 2.0 * gains[i] * errors_deg[i] * std::numbers::pi / 180.0;
    samples += (i ? "," : "") + std::string("{\"target\": 100.0, \"position\": ") +
               std::to_string(100.0 + errors_deg[i]) +
               ", \"voltage\": 12.0, \"kp\": " + std::to_string(gains[i]) +
               ", \"period\": " + std::to_string(u / 12.0 * 40.0) + "}";
  }
  const std::string path =
      write_table("pwm.json", "{\"pwm_period\": 40.0, \"samples\": [" + samples + "]}");
  const ServoCalibrationTable t = read_servo_calibration_table(path, path);
  ASSERT_EQ(t.kind, ServoCalibrationTable::Kind::kPwmGain);
  EXPECT_NEAR(t.pwm.through_origin.slope, 2.0, 1e-5);
  EXPECT_NEAR(t.pwm.error_gain, 2.0 / 12.0, 1e-6);
  // (4096/2π)/(g·885), the mapping of README "Servo laws".
  EXPECT_NEAR(t.pwm.dynamixel_kp_divisor, 4096.0 / (2.0 * std::numbers::pi) / (2.0 / 12.0 * 885.0),
              1e-4);
  EXPECT_NEAR(t.pwm.affine.intercept, 0.0, 1e-5);
}

TEST(ServoCalibrationTableTest, ErrorsNameTheFileAndTheField) {
  const std::string mixed = write_table(
      "mixed.json",
      "{\"pwm_period\": 40, \"samples\": [{\"target\": 1, \"position\": 5, \"voltage\": 12, "
      "\"kp\": 4, \"period\": 3}, {\"target\": 1, \"position\": 9, \"voltage\": 15, \"kp\": 4, "
      "\"period\": 6}]}");
  EXPECT_NE(error_of(mixed).find("samples[1].voltage"), std::string::npos) << error_of(mixed);
  EXPECT_NE(error_of(mixed).find("mixed.json"), std::string::npos);
  const std::string missing = write_table(
      "missing.json", "{\"pwm_period\": 40, \"samples\": [{\"target\": 1, \"position\": 5}]}");
  EXPECT_NE(error_of(missing).find("samples[0].voltage"), std::string::npos) << error_of(missing);
  const std::string log = write_table("log.json", "{\"entries\": []}");
  EXPECT_NE(error_of(log).find("import-bam"), std::string::npos) << error_of(log);
  const std::string word = write_table("word.json", "{\"1.0\": NaN, \"2.0\": 1.0, \"3.0\": 2}");
  EXPECT_NE(error_of(word).find("1.0"), std::string::npos) << error_of(word);
  const std::string one = write_table("one.json", "{\"1.0\": 0.5}");
  EXPECT_NE(error_of(one).find("more points"), std::string::npos) << error_of(one);
}

TEST(ServoCalibrationTableTest, RealMxTablesGiveBamsConstantsAndAFrictionDrop) {
  if (!fs::is_directory(kBamDataDir / "mx64")) {
    GTEST_SKIP() << "no BAM calibration tables at " << kBamDataDir;
  }
  struct Case {
    const char* servo;
    double kt_bam, h_bam;  // the tables' READMEs (BAM commit c50ae40)
  };
  for (const Case c :
       {Case{"mx64", 1.71626206, 2.39115541}, Case{"mx106", 2.42458085, 2.36318685}}) {
    const fs::path dir = kBamDataDir / c.servo;
    const std::string speed = (dir / ("velocity_" + std::string(c.servo) + ".json")).string();
    const std::string pwm = (dir / ("pwm_" + std::string(c.servo) + ".json")).string();
    const SpeedVoltageCalibration s = read_servo_calibration_table(speed, speed).speed;
    const PwmGainCalibration p = read_servo_calibration_table(pwm, pwm).pwm;
    std::printf(
        "[ %-5s ] K_t %.6f (BAM %.6f), with offset %.6f +- %.6f, V0 %.4f +- %.4f V; "
        "H %.6f (BAM %.6f), error_gain %.6f\n",
        c.servo, s.through_origin.slope, c.kt_bam, s.affine.slope, s.affine.slope_ci95,
        s.affine.intercept, s.affine.intercept_ci95, p.through_origin.slope, c.h_bam, p.error_gain);
    EXPECT_NEAR(s.through_origin.slope, c.kt_bam, 1e-7) << c.servo;
    EXPECT_NEAR(p.through_origin.slope, c.h_bam, 1e-7) << c.servo;
    // The no-load friction drop is real (its interval excludes 0), so K_t through the origin
    // is too large by more than the offset fit's own interval.
    EXPECT_GT(s.affine.intercept, s.affine.intercept_ci95) << c.servo;
    EXPECT_GT(s.through_origin.slope - s.affine.slope, s.affine.slope_ci95) << c.servo;
    // BAM's later MX model uses error_gain 0.158 "determined using an oscilloscope" (bam.md):
    // within 1 % of these tables.
    EXPECT_NEAR(p.error_gain, 0.158, 0.01 * 0.158) << c.servo;
  }
}

}  // namespace
}  // namespace motoflex
