#include "motoflex/io/motoflex_command_file.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

// The original's column order (eaconfig.h) and whether its file sign is mirrored against
// Aldebaran's (motoflex_2011.md §2.1; reasoning in the header).
struct FileJoint {
  const char* name;
  bool mirrored;
};
constexpr std::array<FileJoint, 10> kJoints = {{{"LHipRoll", true},
                                                {"LHipPitch", false},
                                                {"LKneePitch", false},
                                                {"LAnklePitch", false},
                                                {"LAnkleRoll", true},
                                                {"RHipRoll", false},
                                                {"RHipPitch", false},
                                                {"RKneePitch", false},
                                                {"RAnklePitch", false},
                                                {"RAnkleRoll", false}}};

std::optional<std::size_t> known_joint(std::string_view name) {
  for (std::size_t i = 0; i < kJoints.size(); ++i) {
    if (name == kJoints[i].name) return i;
  }
  return std::nullopt;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\r')) {
    text.remove_prefix(1);
  }
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  return text;
}

// Fields of a ';'-separated row; one trailing empty field (a row ending in ';') is dropped.
std::vector<std::string_view> split_row(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t semicolon = line.find(';', start);
    if (semicolon == std::string_view::npos) {
      fields.push_back(trim(line.substr(start)));
      break;
    }
    fields.push_back(trim(line.substr(start, semicolon - start)));
    start = semicolon + 1;
  }
  if (fields.size() > 1 && fields.back().empty()) fields.pop_back();
  return fields;
}

std::string_view without_bom(std::string_view line) {
  if (line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
  return line;
}

// Column → index into kJoints, or nullopt when the line is not such a header.
std::optional<std::vector<std::size_t>> header_columns(std::string_view line) {
  std::vector<std::size_t> columns;
  for (const std::string_view field : split_row(line)) {
    const auto joint = known_joint(field);
    if (!joint) return std::nullopt;
    columns.push_back(*joint);
  }
  return columns;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::optional<std::size_t> motoflex_2011_column(std::string_view joint) {
  return known_joint(joint);
}

bool is_motoflex_command_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool first = true;
  while (in && std::getline(in, line)) {
    std::string_view content = trim(first ? without_bom(line) : std::string_view(line));
    first = false;
    if (content.empty()) continue;
    return content.find(';') != std::string_view::npos && header_columns(content).has_value();
  }
  return false;
}

JointLog import_motoflex_commands(const std::string& path,
                                  const MotoflexCommandImportOptions& options) {
  const std::string text = read_text(path);
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  std::vector<std::size_t> columns;  // file column → kJoints index
  std::vector<std::vector<double>> rows;
  while (std::getline(lines, line)) {
    ++number;
    const std::string_view content = trim(number == 1 ? without_bom(line) : std::string_view(line));
    if (content.empty()) continue;
    const std::vector<std::string_view> fields = split_row(content);
    if (columns.empty()) {
      for (const std::string_view field : fields) {
        const auto joint = known_joint(field);
        if (!joint) {
          throw InputError(path, number, "header",
                           "'" + std::string(field) +
                               "' is not a joint of the MoToFlex command format (LHipRoll, "
                               "LHipPitch, LKneePitch, LAnklePitch, LAnkleRoll, RHipRoll, "
                               "RHipPitch, RKneePitch, RAnklePitch, RAnkleRoll; ';'-separated)");
        }
        for (const std::size_t seen : columns) {
          if (seen == *joint)
            throw InputError(path, number, "header", "duplicate " + std::string(field));
        }
        columns.push_back(*joint);
      }
      for (std::size_t j = 0; j < kJoints.size(); ++j) {
        bool present = false;
        for (const std::size_t c : columns) present = present || c == j;
        if (!present) {
          throw InputError(path, number, "header", std::string("missing ") + kJoints[j].name);
        }
      }
      continue;
    }
    if (fields.size() != columns.size()) {
      throw InputError(path, number, "",
                       "expected " + std::to_string(columns.size()) +
                           " ';'-separated values, got " + std::to_string(fields.size()));
    }
    std::vector<double> row(columns.size());
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string_view field = fields[c];
      double value = 0.0;
      const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
      if (error != std::errc() || end != field.data() + field.size() || !std::isfinite(value)) {
        throw InputError(path, number, kJoints[columns[c]].name,
                         "'" + std::string(field) + "' is not a finite number");
      }
      row[c] = kJoints[columns[c]].mirrored ? -value : value;
    }
    rows.push_back(std::move(row));
  }
  if (columns.empty()) throw InputError(path, 0, "", "empty file: no header row of joint names");
  if (rows.size() < 2) throw InputError(path, number, "", "need at least 2 rows of angles");

  JointLog log;
  for (const std::size_t c : columns) log.joint_names.emplace_back(kJoints[c].name);
  const bool original = options.clock == MotoflexCommandClock::kOriginal;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    log.time_s.push_back(kMotoflex2011RowPeriod_s * static_cast<double>(k));
    // The original's playback: the zero pose in place of row 0 (motoflex_2011.md §2.2).
    if (original && k == 0) {
      log.commanded_rad.insert(log.commanded_rad.end(), columns.size(), 0.0);
    } else {
      log.commanded_rad.insert(log.commanded_rad.end(), rows[k].begin(), rows[k].end());
    }
  }
  const std::string file = std::filesystem::path(path).filename().string();
  log.meta.robot = options.robot;
  log.meta.rate_hz = 1.0 / kMotoflex2011RowPeriod_s;
  log.meta.motion = "MoToFlex 2011 command file " + file;
  log.meta.origin = "imported from MoToFlex command file " + path;
  log.meta.notes =
      std::string("LHipRoll and LAnkleRoll negated (the file mirrors them); ") +
      (original ? "original playback clock: zero pose at t = 0 in place of row 0, row k at 20k ms"
                : "plain clock: row k at 20k ms");
  return log;
}

}  // namespace motoflex
