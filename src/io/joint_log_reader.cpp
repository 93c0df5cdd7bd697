#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <system_error>

#include "joint_log_sidecar.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"

namespace motoflex {
namespace {

using detail::AngleUnit;
using detail::Sidecar;

enum class ColumnKind { kTime, kCommanded, kMeasured, kImuRoll, kImuPitch, kSupply, kExtra };

struct Column {
  ColumnKind kind;
  std::size_t joint = 0;       // for kCommanded / kMeasured; the index among extras for kExtra
  std::string name;            // the file's column name (errors name it)
  std::string ours;            // our name for it, when the sidecar maps it to another
  double scale = 1.0;          // to s or rad
  bool check_degrees = false;  // an angle whose unit nobody declared
  bool declared_rad = false;   // an angle the sidecar says is in rad
  mutable bool warned_turns = false;  // the "more than two turns" warning was printed
};

// A joint, declared in rad, that turned more than two turns: the numbers may be degrees (a
// degree log read as rad gave a fit 3511° RMS of error without a word), or a continuous joint
// counting its turns. The declaration wins; the reader warns once per column.
constexpr double kMaxDeclaredRad = 4.0 * std::numbers::pi;
// Longest time a log may span: the fit simulates all of it (a row at 1e7 s would run for days).
constexpr double kMaxLogSpanS = 3600.0;

// What the header row says is in the file.
struct Layout {
  std::vector<Column> columns;
  std::vector<std::string> joints;
  std::vector<bool> joint_has_commanded;
  std::vector<bool> joint_has_measured;
  bool has_commanded = false;  // some joint has a .cmd column
  bool has_measured = false;
  bool has_roll = false;
  bool has_pitch = false;
  bool has_supply = false;
  std::vector<std::string> extras;  // the file's columns we do not read, in file order
};

// A file cut into numbered lines, without their "\n" or "\r\n".
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (position_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', position_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(position_, end - position_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    position_ = end + 1;
    ++number_;
    return true;
  }
  int number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  int number_ = 0;
};

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

bool is_ignored(std::string_view line) {
  const std::string_view content = trim(line);
  return content.empty() || content.front() == '#';
}

void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      fields.push_back(trim(line.substr(start)));
      return;
    }
    fields.push_back(trim(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

std::string shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

std::string read_whole_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path, 0, "", "joint log not found");
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(path, 0, "", "is a directory, expected a joint log CSV file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", "cannot open joint log");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "", "read error");
  return text.str();
}

// Our name for a file column: the sidecar's mapping, else its own name when it is one of ours
// and the sidecar does not take that name from another column; empty = an extra column.
std::string our_name(const std::string& name, const Sidecar* sidecar) {
  if (sidecar != nullptr) {
    for (const detail::ColumnMapping& m : sidecar->columns) {
      if (m.file_column == name) return m.ours;
    }
    for (const detail::ColumnMapping& m : sidecar->columns) {
      if (m.ours == name) return "";
    }
  }
  return detail::is_our_column_name(name) ? name : "";
}

bool maps_time(const Sidecar* sidecar) {
  if (sidecar == nullptr) return false;
  for (const detail::ColumnMapping& m : sidecar->columns) {
    if (m.ours == "time_s") return true;
  }
  return false;
}

// The scale to rad of an angle group, and whether its values must be checked for degrees.
void angle_scale(AngleUnit unit, Column& column) {
  column.scale = unit == AngleUnit::kDeg ? std::numbers::pi / 180.0 : 1.0;
  column.check_degrees = unit == AngleUnit::kUndeclared;
  column.declared_rad = unit == AngleUnit::kRad;
}

// Every column named, no name twice, and every column the sidecar maps present.
void check_header_names(const std::vector<std::string_view>& names, const Sidecar* sidecar,
                        const std::string& path, int line) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) {
      throw InputError(path, line, "column " + std::to_string(i + 1), "empty column name");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (names[j] == names[i]) {
        throw InputError(path, line, std::string(names[i]),
                         "duplicate column (columns " + std::to_string(j + 1) + " and " +
                             std::to_string(i + 1) + ")");
      }
    }
  }
  if (sidecar != nullptr) {
    for (const detail::ColumnMapping& m : sidecar->columns) {
      bool found = false;
      for (const std::string_view name : names) found = found || name == m.file_column;
      if (!found) {
        throw InputError(sidecar->path, m.line, "columns." + m.ours,
                         "no column '" + m.file_column + "' in the header of " + path);
      }
    }
  }
}

// A joint's .cmd or .meas column: the joint's index (a new joint is added) and its flags; a
// second column for the same joint and kind is an error.
void register_joint_column(const std::string& joint, Column& column, Layout& layout,
                           const std::string& path, int line) {
  std::size_t index = 0;
  while (index < layout.joints.size() && layout.joints[index] != joint) ++index;
  if (index == layout.joints.size()) {
    layout.joints.push_back(joint);
    layout.joint_has_commanded.push_back(false);
    layout.joint_has_measured.push_back(false);
  }
  column.joint = index;
  const bool commanded = column.kind == ColumnKind::kCommanded;
  std::vector<bool>& has = commanded ? layout.joint_has_commanded : layout.joint_has_measured;
  if (has[index]) {
    throw InputError(path, line, column.name, "a second column for '" + column.ours + "'");
  }
  has[index] = true;
  (commanded ? layout.has_commanded : layout.has_measured) = true;
}

Layout parse_header(const std::vector<std::string_view>& names, const Sidecar* sidecar,
                    const std::string& path, int line) {
  check_header_names(names, sidecar, path, line);
  Layout layout;
  const detail::ColumnUnits units = sidecar != nullptr ? sidecar->units : detail::ColumnUnits{};
  const bool time_anywhere = maps_time(sidecar);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string name(names[i]);
    Column column{ColumnKind::kExtra, 0, name, our_name(name, sidecar)};
    const std::string& ours = column.ours;
    const bool is_time = ours == "time_s";
    if (is_time != (i == 0) && !time_anywhere) {
      // Without a mapping the time comes first, as our own logs write it.
      throw InputError(path, line, "time_s",
                       i == 0 ? "the first column must be 'time_s', found '" + name +
                                    "' (another recorder's time column can be named in the "
                                    "sidecar: columns: {time_s: " +
                                    name + "})"
                              : "'time_s' must be the first column");
    }
    std::string joint;
    if (is_time) {
      column.kind = ColumnKind::kTime;
      column.scale = units.seconds_per_time_unit;
    } else if (ours == "imu.roll" || ours == "imu.pitch") {
      column.kind = ours == "imu.roll" ? ColumnKind::kImuRoll : ColumnKind::kImuPitch;
      (ours == "imu.roll" ? layout.has_roll : layout.has_pitch) = true;
      angle_scale(units.imu, column);
    } else if (ours == "supply_v") {
      if (layout.has_supply) throw InputError(path, line, name, "a second 'supply_v' column");
      column.kind = ColumnKind::kSupply;  // V, not an angle: no unit conversion
      layout.has_supply = true;
    } else if (ours.ends_with(".cmd") || ours.ends_with(".meas")) {
      const bool commanded = ours.ends_with(".cmd");
      joint = ours.substr(0, ours.size() - (commanded ? 4 : 5));
      if (joint.empty()) {
        throw InputError(path, line, name, "no joint name before '" + ours + "'");
      }
      column.kind = commanded ? ColumnKind::kCommanded : ColumnKind::kMeasured;
      angle_scale(commanded ? units.cmd : units.meas, column);
    } else {
      column.joint = layout.extras.size();
      layout.extras.push_back(name);
    }
    if (!joint.empty()) register_joint_column(joint, column, layout, path, line);
    layout.columns.push_back(column);
  }
  return layout;
}

// Checks the header against the requirements and against the all-or-none rule per column kind
// (a frame-major array cannot hold angles for only some joints).
void check_layout(const Layout& layout, const JointLogRequirements& requirements,
                  const std::string& path, int line) {
  for (const std::string& wanted : requirements.joints) {
    bool present = false;
    for (const std::string& joint : layout.joints) present = present || joint == wanted;
    const std::string column = wanted + (requirements.need_commanded ? ".cmd" : ".meas");
    if (!present) {
      throw InputError(path, line, column,
                       "required joint '" + wanted + "' is missing (no column '" + column + "')");
    }
  }
  if ((requirements.need_commanded || requirements.need_measured) && layout.joints.empty()) {
    throw InputError(path, line, "header",
                     std::string("no joint columns (expected <joint>") +
                         (requirements.need_commanded ? ".cmd" : ".meas") + " columns)");
  }
  // Commanded columns first: they are what most callers need, and the more useful complaint.
  for (std::size_t j = 0; j < layout.joints.size(); ++j) {
    const std::string& joint = layout.joints[j];
    if (layout.joint_has_commanded[j]) continue;
    if (!requirements.need_commanded && !layout.has_commanded) continue;
    const std::string reason = requirements.need_commanded ? "commanded angles are required"
                                                           : "other joints have .cmd columns";
    throw InputError(
        path, line, joint + ".cmd",
        "missing column: joint '" + joint + "' has no '" + joint + ".cmd' (" + reason + ")");
  }
  for (std::size_t j = 0; j < layout.joints.size(); ++j) {
    const std::string& joint = layout.joints[j];
    if (layout.joint_has_measured[j]) continue;
    if (!requirements.need_measured && !layout.has_measured) continue;
    const std::string reason = requirements.need_measured ? "measured angles are required"
                                                          : "other joints have .meas columns";
    throw InputError(
        path, line, joint + ".meas",
        "missing column: joint '" + joint + "' has no '" + joint + ".meas' (" + reason + ")");
  }
}

double parse_value(std::string_view text, const std::string& path, int line,
                   const std::string& column) {
  if (text.empty()) throw InputError(path, line, column, "empty value");
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range) {
    throw InputError(path, line, column, "number '" + std::string(text) + "' is out of range");
  }
  if (ec != std::errc() || end != digits.data() + digits.size()) {
    throw InputError(path, line, column, "expected a number, found '" + std::string(text) + "'");
  }
  if (!std::isfinite(value)) {
    throw InputError(path, line, column, "non-finite value '" + std::string(text) + "'");
  }
  return value;
}

// An angle beyond ±2π in a column whose unit nobody declared is almost surely in degrees.
void check_not_degrees(double value, const Column& column, const std::string& path, int line,
                       const std::string& sidecar, bool has_sidecar) {
  if (column.declared_rad && std::abs(value) > kMaxDeclaredRad && !column.warned_turns) {
    column.warned_turns = true;
    std::fprintf(stderr,
                 "motoflex: warning: %s:%d: %s: angle %s rad is more than two turns: a continuous "
                 "joint, or degrees although the sidecar %s declares rad?\n",
                 path.c_str(), line, column.name.c_str(), shortest(value).c_str(), sidecar.c_str());
  }
  if (!column.check_degrees || std::abs(value) <= 2.0 * std::numbers::pi) return;
  const std::string group = column.kind == ColumnKind::kCommanded  ? "cmd"
                            : column.kind == ColumnKind::kMeasured ? "meas"
                                                                   : "imu";
  throw InputError(path, line, column.name,
                   "angle " + shortest(value) +
                       " is beyond ±2π rad: the log looks like it is in degrees; declare its "
                       "units in the sidecar " +
                       sidecar + (has_sidecar ? "" : " (there is none yet)") +
                       ": `units: deg`, or `units: {" + group +
                       ": deg}` for this group (`units: rad` if these are radians)");
}

// The rows' time axis against the limits and the sidecar: a bounded span, and a row spacing
// against the declared rate_hz. A factor of 100 or more is an error (times in ms read as s are
// 1000x off); a smaller disagreement (a log thinned or resampled after its sidecar was written,
// a nominal rate) is a warning, since the fit uses the rows' own times.
void check_time_axis(JointLog& log, const std::optional<Sidecar>& sidecar,
                     const std::string& csv_path, int last_line) {
  const double span_s = log.time_s.back() - log.time_s.front();
  if (span_s > kMaxLogSpanS) {
    throw InputError(csv_path, last_line, "time_s",
                     "the log spans " + shortest(span_s) + " s (at most " + shortest(kMaxLogSpanS) +
                         " s): a time jump, or times in ms? (sidecar `units: {time: ms}`)");
  }
  if (!sidecar) return;
  std::vector<double> steps(log.frames() - 1);
  for (std::size_t i = 0; i + 1 < log.frames(); ++i) steps[i] = log.time_s[i + 1] - log.time_s[i];
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  const double rows_hz = 1.0 / steps[steps.size() / 2];
  const double ratio = rows_hz / sidecar->meta.rate_hz;
  const std::string disagreement = shortest(sidecar->meta.rate_hz) + " Hz, but the rows of " +
                                   csv_path + " are " + shortest(rows_hz) + " Hz apart (median)";
  if (ratio < 0.01 || ratio > 100.0) {
    throw InputError(
        sidecar->path, sidecar->rate_line, "rate_hz",
        disagreement +
            // Times in ms read as s: rows 1000x further apart than declared.
            (ratio > 0.0005 && ratio < 0.002 ? ": times in ms? (`units: {time: ms}`)" : ""));
  }
  if (ratio < 0.5 || ratio > 2.0) {
    log.warnings.push_back(sidecar->path + ":" + std::to_string(sidecar->rate_line) +
                           ": rate_hz: " + disagreement + " (the rows' times are used)");
  }
}

// Where the data rows are read and every value is checked against its column.
struct RowContext {
  const Layout& layout;
  const std::string& csv_path;
  const std::string& sidecar_path;
  bool has_sidecar;
};

// One data row's values into the log (time strictly increasing, angles scaled to rad).
void store_row(const std::vector<std::string_view>& fields, int number, const RowContext& context,
               JointLog& log) {
  const Layout& layout = context.layout;
  const std::string& csv_path = context.csv_path;
  const std::size_t joint_count = layout.joints.size();
  const std::size_t expected_fields = layout.columns.size();
  if (fields.size() != expected_fields) {
    throw InputError(csv_path, number, "row",
                     "expected " + std::to_string(expected_fields) +
                         " fields as in the header, found " + std::to_string(fields.size()));
  }
  const std::size_t base = log.time_s.size() * joint_count;
  if (layout.has_commanded) log.commanded_rad.resize(base + joint_count);
  if (layout.has_measured) log.measured_rad.resize(base + joint_count);
  const std::size_t extra_base = log.extra_values.size();
  log.extra_values.resize(extra_base + layout.extras.size());
  for (std::size_t i = 0; i < expected_fields; ++i) {
    const Column& column = layout.columns[i];
    if (column.kind == ColumnKind::kExtra) {
      log.extra_values[extra_base + column.joint] = std::string(fields[i]);
      continue;
    }
    const double raw = parse_value(fields[i], csv_path, number, column.name);
    check_not_degrees(raw, column, csv_path, number, context.sidecar_path, context.has_sidecar);
    const double value = column.scale == 1.0 ? raw : raw * column.scale;
    switch (column.kind) {
      case ColumnKind::kTime:
        if (!log.time_s.empty() && value <= log.time_s.back()) {
          throw InputError(csv_path, number, column.name,
                           "time must strictly increase (previous row " +
                               shortest(log.time_s.back()) + " s, this row " + shortest(value) +
                               " s)");
        }
        log.time_s.push_back(value);
        break;
      case ColumnKind::kCommanded:
        log.commanded_rad[base + column.joint] = value;
        break;
      case ColumnKind::kMeasured:
        log.measured_rad[base + column.joint] = value;
        break;
      case ColumnKind::kImuRoll:
        log.imu_roll_rad.push_back(value);
        break;
      case ColumnKind::kImuPitch:
        log.imu_pitch_rad.push_back(value);
        break;
      case ColumnKind::kSupply:
        if (!(value > 0.0)) {
          throw InputError(csv_path, number, column.name,
                           "a supply voltage must be positive, found " + shortest(value));
        }
        log.supply_v.push_back(value);
        break;
      case ColumnKind::kExtra:
        break;
    }
  }
}

}  // namespace

std::string joint_log_sidecar_path(const std::string& csv_path) {
  return std::filesystem::path(csv_path).replace_extension(".yaml").string();
}

JointLog read_joint_log(const std::string& csv_path, const JointLogRequirements& requirements) {
  const std::string text = read_whole_file(csv_path);
  if (text.empty()) throw InputError(csv_path, 0, "", "empty file (expected a header row)");
  // The sidecar first: it may say which column is which and in what units.
  const std::string sidecar_path = joint_log_sidecar_path(csv_path);
  std::optional<Sidecar> sidecar;
  std::error_code ec;
  if (std::filesystem::exists(sidecar_path, ec)) {
    sidecar = detail::read_joint_log_sidecar(sidecar_path);
  } else if (requirements.need_sidecar) {
    throw InputError(sidecar_path, 0, "",
                     "sidecar file not found (required next to '" + csv_path + "')");
  }

  std::string_view body = text;
  // Spreadsheet programs like to start a CSV with a UTF-8 byte order mark.
  if (body.substr(0, 3) == "\xEF\xBB\xBF") body.remove_prefix(3);
  Lines lines(body);
  std::string_view line;
  bool found_header = false;
  while (!found_header && lines.next(line)) found_header = !is_ignored(line);
  if (!found_header) {
    throw InputError(csv_path, lines.number(), "",
                     "no header row (the file has only comments and blank lines)");
  }
  const int header_line = lines.number();
  std::vector<std::string_view> fields;
  split_fields(line, fields);
  const Layout layout = parse_header(fields, sidecar ? &*sidecar : nullptr, csv_path, header_line);
  check_layout(layout, requirements, csv_path, header_line);

  JointLog log;
  log.joint_names = layout.joints;
  log.extra_column_names = layout.extras;
  const RowContext context{layout, csv_path, sidecar_path, sidecar.has_value()};
  while (lines.next(line)) {
    if (is_ignored(line)) continue;
    split_fields(line, fields);
    store_row(fields, lines.number(), context, log);
  }
  if (log.frames() < 2) {
    throw InputError(
        csv_path, lines.number(), "rows",
        "a joint log needs at least 2 data rows, found " + std::to_string(log.frames()));
  }
  check_time_axis(log, sidecar, csv_path, lines.number());
  if (sidecar) log.meta = sidecar->meta;
  if (!layout.extras.empty()) {
    std::string list;
    for (const std::string& name : layout.extras) list += (list.empty() ? "" : ", ") + name;
    log.warnings.push_back(csv_path + ":" + std::to_string(header_line) + ": " +
                           std::to_string(layout.extras.size()) +
                           " extra column(s) kept but not used: " + list +
                           " (not time_s, <joint>.cmd, <joint>.meas or imu.*, nor mapped by "
                           "the sidecar's columns:)");
  }
  for (const std::string& warning : log.warnings) {
    std::fprintf(stderr, "motoflex: warning: %s\n", warning.c_str());
  }
  return log;
}

}  // namespace motoflex
