#include "joint_log_sidecar.hpp"

#include <optional>

#include "motoflex/io/yaml_reader.hpp"

namespace motoflex::detail {
namespace {

AngleUnit angle_unit(const YamlValue& value) {
  const std::string unit = value.as_string();
  if (unit == "rad") return AngleUnit::kRad;
  if (unit == "deg") return AngleUnit::kDeg;
  value.fail("unsupported angle unit '" + unit + "' (rad or deg)");
}

double seconds_per_unit(const YamlValue& value) {
  const std::string unit = value.as_string();
  if (unit == "s") return 1.0;
  if (unit == "ms") return 1e-3;
  if (unit == "us" || unit == "µs") return 1e-6;
  if (unit == "ns") return 1e-9;
  value.fail("unsupported time unit '" + unit + "' (s, ms, us, µs or ns)");
}

// `units: rad|deg` for every angle column, or per group:
// `units: {time: ms, angles: deg, cmd: rad, meas: deg, imu: rad}` (a group overrides `angles`).
ColumnUnits read_units(const YamlValue& units) {
  ColumnUnits out;
  if (units.is_scalar()) {
    out.cmd = out.meas = out.imu = angle_unit(units);
    return out;
  }
  if (!units.is_map()) units.fail("expected rad, deg or a mapping of column groups to units");
  units.require_keys_within({"time", "angles", "cmd", "meas", "imu"});
  if (const std::optional<YamlValue> time = units.find("time")) {
    out.seconds_per_time_unit = seconds_per_unit(*time);
  }
  if (const std::optional<YamlValue> angles = units.find("angles")) {
    out.cmd = out.meas = out.imu = angle_unit(*angles);
  }
  if (const std::optional<YamlValue> cmd = units.find("cmd")) out.cmd = angle_unit(*cmd);
  if (const std::optional<YamlValue> meas = units.find("meas")) out.meas = angle_unit(*meas);
  if (const std::optional<YamlValue> imu = units.find("imu")) out.imu = angle_unit(*imu);
  return out;
}

std::vector<ColumnMapping> read_columns(const YamlValue& columns) {
  std::vector<ColumnMapping> out;
  if (columns.is_null()) return out;
  if (!columns.is_map()) columns.fail("expected a mapping: our column name -> the file's column");
  for (const auto& [ours, value] : columns.entries()) {
    if (!is_our_column_name(ours)) {
      value.fail("'" + ours +
                 "' is not one of our column names (time_s, <joint>.cmd, <joint>.meas, "
                 "imu.roll, imu.pitch, supply_v)");
    }
    const std::string file_column = value.as_string();
    for (const ColumnMapping& earlier : out) {
      if (earlier.file_column == file_column) {
        value.fail("the file's column '" + file_column + "' is already mapped to '" + earlier.ours +
                   "'");
      }
    }
    out.push_back({ours, file_column, value.line()});
  }
  return out;
}

}  // namespace

bool is_our_column_name(const std::string& name) {
  // "<joint>.cmd" with an empty joint counts too, so that the reader can say what is wrong.
  return name == "time_s" || name == "imu.roll" || name == "imu.pitch" || name == "supply_v" ||
         name.ends_with(".cmd") || name.ends_with(".meas");
}

Sidecar read_joint_log_sidecar(const std::string& path) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within(
      {"robot", "rate_hz", "motion", "units", "columns", "origin", "parameters", "notes"});
  Sidecar sidecar;
  sidecar.path = path;
  JointLogMeta& meta = sidecar.meta;
  const YamlValue robot = root.at("robot");
  meta.robot = robot.as_string();
  if (meta.robot.empty()) robot.fail("must not be empty");
  const YamlValue rate = root.at("rate_hz");
  meta.rate_hz = rate.as_double();
  sidecar.rate_line = rate.line();
  if (meta.rate_hz <= 0.0) rate.fail("must be positive");
  if (meta.rate_hz > 1.0e6) rate.fail("must be at most 1 MHz");
  meta.motion = root.get_string("motion", "");
  if (const std::optional<YamlValue> units = root.find("units")) sidecar.units = read_units(*units);
  if (const std::optional<YamlValue> columns = root.find("columns")) {
    sidecar.columns = read_columns(*columns);
  }
  meta.origin = root.get_string("origin", "");
  if (const std::optional<YamlValue> parameters = root.find("parameters")) {
    for (const auto& [name, value] : parameters->entries()) {
      meta.parameters[name] = value.as_double();
    }
  }
  meta.notes = root.get_string("notes", "");
  return sidecar;
}

}  // namespace motoflex::detail
