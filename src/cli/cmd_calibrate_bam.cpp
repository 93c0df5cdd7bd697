// motoflex calibrate-bam <table.json>... [--out FILE.json]
// Fits BAM's servo calibration tables (no-load speed vs voltage; PWM on-time vs position
// error): the back-EMF / torque constant and the firmware gain, each through the origin (BAM's
// fit) and with an intercept, with 95 % intervals (io/servo_calibration_table.hpp).

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "commands.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/io/servo_calibration_table.hpp"

namespace motoflex::cli {
namespace {

using json = nlohmann::ordered_json;

struct CalibrateBamArgs {
  std::vector<std::string> tables;
  std::string out;
};

json line_json(const LineFit& f) {
  json j = {{"slope", f.slope}, {"slope_ci95", f.slope_ci95}};
  if (f.with_intercept) {
    j["intercept"] = f.intercept;
    j["intercept_ci95"] = f.intercept_ci95;
  }
  j["residual_rms"] = f.residual_rms;
  j["r_squared"] = f.r_squared;
  j["points"] = f.points;
  return j;
}

// Whether the intercept's 95 % interval excludes 0.
const char* intercept_verdict(const LineFit& f) {
  return std::abs(f.intercept) > f.intercept_ci95 ? "significant" : "not significant";
}

json report_speed(const std::string& file, const SpeedVoltageCalibration& s) {
  const LineFit& o = s.through_origin;
  const LineFit& a = s.affine;
  std::printf("%s: no-load speed vs supply, %zu points\n", file.c_str(), o.points);
  std::printf("  V = k*w (BAM's fit):   k   = %.6f +- %.6f V*s/rad (95 %%), RMS %.4f V\n", o.slope,
              o.slope_ci95, o.residual_rms);
  std::printf(
      "  V = k_e*w + V0:        k_e = %.6f +- %.6f V*s/rad, V0 = %.4f +- %.4f V (%s), "
      "RMS %.4f V\n",
      a.slope, a.slope_ci95, a.intercept, a.intercept_ci95, intercept_verdict(a), a.residual_rms);
  std::printf(
      "  k_e is the joint-side torque constant K_t in N*m/A; V0 = R*I0, the winding drop "
      "of the no-load friction current\n");
  return {{"file", file},
          {"kind", "speed_vs_voltage"},
          {"torque_constant_through_origin", line_json(o)},
          {"torque_constant_with_offset", line_json(a)}};
}

json report_pwm(const std::string& file, const PwmGainCalibration& p) {
  const LineFit& o = p.through_origin;
  const LineFit& a = p.affine;
  std::printf("%s: PWM on-time vs position error, %zu samples at %.2f V\n", file.c_str(), o.points,
              p.supply_v);
  std::printf("  U = H*kp*e (BAM's fit): H = %.6f +- %.6f V per kp*rad (95 %%), RMS %.4f V\n",
              o.slope, o.slope_ci95, o.residual_rms);
  std::printf("  U = H*kp*e + U0:        H = %.6f +- %.6f, U0 = %.4f +- %.4f V (%s)\n", a.slope,
              a.slope_ci95, a.intercept, a.intercept_ci95, intercept_verdict(a));
  std::printf(
      "  error_gain = H/%.2f V = %.6f +- %.6f duty per kp*rad; dynamixel kp_divisor "
      "%.2f (4096 ticks, PWM 885)\n",
      p.supply_v, p.error_gain, p.error_gain_ci95, p.dynamixel_kp_divisor);
  return {{"file", file},
          {"kind", "pwm_vs_error"},
          {"supply_v", p.supply_v},
          {"gain_through_origin", line_json(o)},
          {"gain_with_offset", line_json(a)},
          {"error_gain", p.error_gain},
          {"error_gain_ci95", p.error_gain_ci95},
          {"dynamixel_kp_divisor", p.dynamixel_kp_divisor}};
}

int run(const CalibrateBamArgs& args) {
  json all = json::array();
  for (const std::string& file : args.tables) {
    const ServoCalibrationTable table = read_servo_calibration_table(file, file);
    all.push_back(table.kind == ServoCalibrationTable::Kind::kSpeedVoltage
                      ? report_speed(file, table.speed)
                      : report_pwm(file, table.pwm));
  }
  if (!args.out.empty()) {
    write_file_atomically(args.out, all.dump(2) + "\n");
    std::printf("wrote %s\n", args.out.c_str());
  }
  return 0;
}

}  // namespace

CommandRunner add_calibrate_bam_command(CLI::App& app) {
  auto args = std::make_shared<CalibrateBamArgs>();
  CLI::App* sub = app.add_subcommand(
      "calibrate-bam", "fit BAM's servo calibration tables (speed vs voltage, PWM vs error)");
  sub->add_option("tables", args->tables, "calibration tables (.json)")->required();
  sub->add_option("--out", args->out, "write the fits as JSON");
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
