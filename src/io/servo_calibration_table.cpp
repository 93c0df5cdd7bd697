#include "motoflex/io/servo_calibration_table.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "json_fields.hpp"
#include "python_json.hpp"

namespace motoflex {
namespace {

using json = nlohmann::json;

constexpr double kTicksPerRev = 4096.0;
constexpr double kPwmFullScale = 885.0;

using Fields = detail::JsonFields;

LineFit fit(const Fields& f, const std::vector<double>& x, const std::vector<double>& y,
            bool intercept, const std::string& field) {
  try {
    return fit_line(x, y, intercept);
  } catch (const std::invalid_argument& error) {
    f.fail(field, error.what());
  }
}

SpeedVoltageCalibration speed_table(const json& doc, const Fields& f) {
  SpeedVoltageCalibration out;
  for (const auto& item : doc.items()) {
    const std::string& key = item.key();
    double volts = 0.0;
    const auto parsed = std::from_chars(key.data(), key.data() + key.size(), volts);
    if (parsed.ec != std::errc() || parsed.ptr != key.data() + key.size() || !(volts > 0.0)) {
      f.fail(key, "a speed table's keys are supply voltages (positive numbers)");
    }
    out.volts.push_back(volts);
    out.speed_rad_s.push_back(f.number(item.value(), key));
  }
  out.through_origin = fit(f, out.speed_rad_s, out.volts, false, "(table)");
  out.affine = fit(f, out.speed_rad_s, out.volts, true, "(table)");
  return out;
}

PwmGainCalibration pwm_table(const json& doc, const Fields& f) {
  PwmGainCalibration out;
  out.pwm_period = f.positive(f.required(doc, "pwm_period", "pwm_period"), "pwm_period");
  const json& samples = f.required(doc, "samples", "samples");
  if (!samples.is_array()) f.fail("samples", "expected a list");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const std::string at = "samples[" + std::to_string(i) + "]";
    const json& s = samples[i];
    if (!s.is_object()) f.fail(at, "expected an object");
    const auto number = [&](const char* key) {
      return f.number(f.required(s, key, at + "." + key), at + "." + key);
    };
    const double target_deg = number("target");
    const double position_deg = number("position");
    const double volts = f.positive(f.required(s, "voltage", at + ".voltage"), at + ".voltage");
    const double kp = number("kp");
    const double period = number("period");
    if (i == 0) out.supply_v = volts;
    if (volts != out.supply_v) {
      f.fail(at + ".voltage", "every sample must be at the same supply (first: " +
                                  std::to_string(out.supply_v) + " V)");
    }
    if (period < 0.0 || period > out.pwm_period) {
      f.fail(at + ".period", "the on-time must lie between 0 and pwm_period");
    }
    const double error_rad = std::abs(target_deg - position_deg) * std::numbers::pi / 180.0;
    out.kp_error_rad.push_back(kp * error_rad);
    out.winding_volts.push_back(volts * period / out.pwm_period);
  }
  out.through_origin = fit(f, out.kp_error_rad, out.winding_volts, false, "samples");
  out.affine = fit(f, out.kp_error_rad, out.winding_volts, true, "samples");
  out.error_gain = out.through_origin.slope / out.supply_v;
  out.error_gain_ci95 = out.through_origin.slope_ci95 / out.supply_v;
  out.dynamixel_kp_divisor =
      kTicksPerRev / (2.0 * std::numbers::pi) / (out.error_gain * kPwmFullScale);
  return out;
}

}  // namespace

ServoCalibrationTable read_servo_calibration_table(const std::string& path,
                                                   const std::string& shown) {
  const json doc = read_python_json(path, shown);
  const Fields f(shown);
  if (!doc.is_object() || doc.empty()) f.fail("", "expected a JSON object (a calibration table)");
  ServoCalibrationTable table;
  if (doc.contains("pwm_period") || doc.contains("samples")) {
    table.kind = ServoCalibrationTable::Kind::kPwmGain;
    table.pwm = pwm_table(doc, f);
    return table;
  }
  if (doc.contains("entries")) {
    f.fail("entries", "a BAM trajectory log, not a calibration table: use `motoflex import-bam`");
  }
  table.kind = ServoCalibrationTable::Kind::kSpeedVoltage;
  table.speed = speed_table(doc, f);
  return table;
}

}  // namespace motoflex
