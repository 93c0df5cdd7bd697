// `motoflex calibrate-bam`: a synthetic speed table and a PWM table fitted from the command
// line, printed and written as JSON; a trajectory log is refused with the file and field.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_support.hpp"

namespace motoflex::testing {
namespace {

TEST(CalibrateBam, FitsBothTablesAndWritesJson) {
  const auto dir = fresh_dir("calibrate_bam");
  // V = 2·ω exactly; U = 1.5 V per kp·rad at 10 V (on-time over a period of 10).
  std::ofstream(dir / "speed.json") << R"({"2.0": 1.0, "4.0": 2.0, "6.0": 3.0, "8.0": 4.0})";
  std::ofstream(dir / "pwm.json") << R"({"pwm_period": 10.0, "samples": [
        {"target": 0.0, "position": 57.29577951308232, "voltage": 10.0, "kp": 1, "period": 1.5},
        {"target": 0.0, "position": 114.59155902616465, "voltage": 10.0, "kp": 1, "period": 3.0},
        {"target": 0.0, "position": 57.29577951308232, "voltage": 10.0, "kp": 3, "period": 4.5}]})";
  const auto out = dir / "fits.json";
  const CommandResult r = run_motoflex("calibrate-bam " + (dir / "speed.json").string() + " " +
                                       (dir / "pwm.json").string() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find("k   = 2.000000"), std::string::npos) << r.stdout_text;
  EXPECT_NE(r.stdout_text.find("H = 1.500000"), std::string::npos) << r.stdout_text;
  std::ifstream in(out);
  const nlohmann::json fits = nlohmann::json::parse(in);
  ASSERT_EQ(fits.size(), 2u);
  EXPECT_EQ(fits[0]["kind"], "speed_vs_voltage");
  EXPECT_NEAR(fits[0]["torque_constant_through_origin"]["slope"].get<double>(), 2.0, 1e-12);
  EXPECT_EQ(fits[1]["kind"], "pwm_vs_error");
  EXPECT_NEAR(fits[1]["error_gain"].get<double>(), 0.15, 1e-12);
}

TEST(CalibrateBam, RefusesATrajectoryLogNamingTheField) {
  const auto dir = fresh_dir("calibrate_bam_log");
  std::ofstream(dir / "log.json") << R"({"mass": 0.5, "length": 0.1, "entries": []})";
  const CommandResult r = run_motoflex("calibrate-bam " + (dir / "log.json").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.stderr_text.find("log.json"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("entries"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("import-bam"), std::string::npos) << r.stderr_text;
}

}  // namespace
}  // namespace motoflex::testing
