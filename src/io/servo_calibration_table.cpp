#include "motoflex/io/servo_calibration_table.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "motoflex/core/error.hpp"
#include "python_json.hpp"

namespace motoflex {
namespace {

using json = nlohmann::json;

constexpr double kTicksPerRev = 4096.0;
constexpr double kPwmFullScale = 885.0;

class TableFields {
 public:
  explicit TableFields(std::string shown) : shown_(std::move(shown)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    throw InputError(shown_, 0, field, message);
  }

  double number(const json& object, const char* key, const std::string& field) const {
    const auto found = object.find(key);
    if (found == object.end()) fail(field, "missing key");
    return number(*found, field);
  }

  double number(const json& value, const std::string& field) const {
    if (const auto word = bare_non_finite_word(value)) fail(field, *word + " is not a number");
    if (!value.is_number())
      fail(field, std::string("expected a number, found ") + value.type_name());
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(field, "number out of range");
    return x;
  }

  LineFit fit(const std::vector<double>& x, const std::vector<double>& y, bool intercept,
              const std::string& field) const {
    try {
      return fit_line(x, y, intercept);
    } catch (const std::invalid_argument& error) {
      fail(field, error.what());
    }
  }

 private:
  std::string shown_;
};

SpeedVoltageCalibration speed_table(const json& doc, const TableFields& f) {
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
  out.through_origin = f.fit(out.speed_rad_s, out.volts, false, "(table)");
  out.affine = f.fit(out.speed_rad_s, out.volts, true, "(table)");
  return out;
}

PwmGainCalibration pwm_table(const json& doc, const TableFields& f) {
  PwmGainCalibration out;
  out.pwm_period = f.number(doc, "pwm_period", "pwm_period");
  if (!(out.pwm_period > 0.0)) f.fail("pwm_period", "must be positive");
  const json& samples = doc.at("samples");
  if (!samples.is_array()) f.fail("samples", "expected a list");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const std::string at = "samples[" + std::to_string(i) + "]";
    const json& s = samples[i];
    if (!s.is_object()) f.fail(at, "expected an object");
    const double target_deg = f.number(s, "target", at + ".target");
    const double position_deg = f.number(s, "position", at + ".position");
    const double volts = f.number(s, "voltage", at + ".voltage");
    const double kp = f.number(s, "kp", at + ".kp");
    const double period = f.number(s, "period", at + ".period");
    if (!(volts > 0.0)) f.fail(at + ".voltage", "must be positive");
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
  out.through_origin = f.fit(out.kp_error_rad, out.winding_volts, false, "samples");
  out.affine = f.fit(out.kp_error_rad, out.winding_volts, true, "samples");
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
  const TableFields f(shown);
  if (!doc.is_object() || doc.empty()) f.fail("", "expected a JSON object (a calibration table)");
  ServoCalibrationTable table;
  if (doc.contains("pwm_period") || doc.contains("samples")) {
    if (!doc.contains("samples")) f.fail("samples", "missing key");
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
