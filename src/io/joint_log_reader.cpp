#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "motoflex/core/error.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/io/yaml_reader.hpp"

namespace motoflex {
namespace {

enum class ColumnKind { kTime, kCommanded, kMeasured, kImuRoll, kImuPitch };

struct Column {
  ColumnKind kind;
  std::size_t joint = 0;  // for kCommanded / kMeasured
  std::string name;
};

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

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
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

Layout parse_header(const std::vector<std::string_view>& names, const std::string& path, int line) {
  Layout layout;
  if (names.front() != "time_s") {
    throw InputError(
        path, line, "time_s",
        "the first column must be 'time_s', found '" + std::string(names.front()) + "'");
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string name(names[i]);
    for (std::size_t j = 0; j < i; ++j) {
      if (names[j] == names[i]) {
        throw InputError(path, line, name,
                         "duplicate column (columns " + std::to_string(j + 1) + " and " +
                             std::to_string(i + 1) + ")");
      }
    }
    Column column{ColumnKind::kTime, 0, name};
    if (i == 0) {
      layout.columns.push_back(column);
      continue;
    }
    std::string_view joint;
    if (name == "imu.roll") {
      column.kind = ColumnKind::kImuRoll;
      layout.has_roll = true;
    } else if (name == "imu.pitch") {
      column.kind = ColumnKind::kImuPitch;
      layout.has_pitch = true;
    } else if (ends_with(name, ".cmd") && name.size() > 4) {
      column.kind = ColumnKind::kCommanded;
      joint = names[i].substr(0, name.size() - 4);
    } else if (ends_with(name, ".meas") && name.size() > 5) {
      column.kind = ColumnKind::kMeasured;
      joint = names[i].substr(0, name.size() - 5);
    } else if (name.empty()) {
      throw InputError(path, line, "column " + std::to_string(i + 1), "empty column name");
    } else {
      throw InputError(path, line, name,
                       "unknown column (expected time_s, <joint>.cmd, <joint>.meas, imu.roll or "
                       "imu.pitch)");
    }
    if (!joint.empty()) {
      std::size_t index = 0;
      while (index < layout.joints.size() && layout.joints[index] != joint) ++index;
      if (index == layout.joints.size()) {
        layout.joints.emplace_back(joint);
        layout.joint_has_commanded.push_back(false);
        layout.joint_has_measured.push_back(false);
      }
      column.joint = index;
      if (column.kind == ColumnKind::kCommanded) {
        layout.joint_has_commanded[index] = true;
        layout.has_commanded = true;
      } else {
        layout.joint_has_measured[index] = true;
        layout.has_measured = true;
      }
    }
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

JointLogMeta read_sidecar(const std::string& path) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within(
      {"robot", "rate_hz", "motion", "units", "origin", "parameters", "notes"});
  JointLogMeta meta;
  const YamlValue robot = root.at("robot");
  meta.robot = robot.as_string();
  if (meta.robot.empty()) robot.fail("must not be empty");
  const YamlValue rate = root.at("rate_hz");
  meta.rate_hz = rate.as_double();
  if (meta.rate_hz <= 0.0) rate.fail("must be positive");
  meta.motion = root.get_string("motion", "");
  if (const std::optional<YamlValue> units = root.find("units")) {
    meta.units = units->as_string();
    if (meta.units != "rad") {
      units->fail("unsupported units '" + meta.units + "' (joint logs are in rad)");
    }
  }
  meta.origin = root.get_string("origin", "");
  if (const std::optional<YamlValue> parameters = root.find("parameters")) {
    for (const auto& [name, value] : parameters->entries()) {
      meta.parameters[name] = value.as_double();
    }
  }
  meta.notes = root.get_string("notes", "");
  return meta;
}

}  // namespace

std::string joint_log_sidecar_path(const std::string& csv_path) {
  return std::filesystem::path(csv_path).replace_extension(".yaml").string();
}

JointLog read_joint_log(const std::string& csv_path, const JointLogRequirements& requirements) {
  const std::string text = read_whole_file(csv_path);
  if (text.empty()) throw InputError(csv_path, 0, "", "empty file (expected a header row)");

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
  const Layout layout = parse_header(fields, csv_path, header_line);
  check_layout(layout, requirements, csv_path, header_line);

  JointLog log;
  log.joint_names = layout.joints;
  const std::size_t joint_count = layout.joints.size();
  const std::size_t expected_fields = layout.columns.size();
  while (lines.next(line)) {
    if (is_ignored(line)) continue;
    const int number = lines.number();
    split_fields(line, fields);
    if (fields.size() != expected_fields) {
      throw InputError(csv_path, number, "row",
                       "expected " + std::to_string(expected_fields) +
                           " fields as in the header, found " + std::to_string(fields.size()));
    }
    const std::size_t base = log.time_s.size() * joint_count;
    if (layout.has_commanded) log.commanded_rad.resize(base + joint_count);
    if (layout.has_measured) log.measured_rad.resize(base + joint_count);
    for (std::size_t i = 0; i < expected_fields; ++i) {
      const Column& column = layout.columns[i];
      const double value = parse_value(fields[i], csv_path, number, column.name);
      switch (column.kind) {
        case ColumnKind::kTime:
          if (!log.time_s.empty() && value <= log.time_s.back()) {
            throw InputError(csv_path, number, "time_s",
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
      }
    }
  }
  if (log.frames() < 2) {
    throw InputError(
        csv_path, lines.number(), "rows",
        "a joint log needs at least 2 data rows, found " + std::to_string(log.frames()));
  }

  const std::string sidecar = joint_log_sidecar_path(csv_path);
  std::error_code ec;
  if (std::filesystem::exists(sidecar, ec)) {
    log.meta = read_sidecar(sidecar);
  } else if (requirements.need_sidecar) {
    throw InputError(sidecar, 0, "",
                     "sidecar file not found (required next to '" + csv_path + "')");
  }
  return log;
}

}  // namespace motoflex
