#pragma once

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace YAML {
class Node;
}

namespace motoflex {

class ErrorCollector;

// One value of a YAML config together with where it came from: the file, the 1-based line and
// the dotted field path ("physics.dt_s", "joints[3].name"). Every accessor is strict and throws
// InputError("<file>", line, "<field>", ...) for anything that is not exactly what was asked
// for, so a config error always reaches the user as one line pointing at the culprit.
//
// Typing rules (YAML 1.2 core schema, stricter than yaml-cpp's own conversions):
//   - numbers must be plain (unquoted) scalars; "1.5" in quotes is a string and is rejected;
//   - doubles must be finite: .nan, .inf, nan, inf and out-of-range values are rejected;
//   - ints are decimal integers in int range (1.5, 1e3 and 0x10 are rejected);
//   - bools are true/True/TRUE/false/False/FALSE (yes/no/on/off are rejected);
//   - strings are any scalar; an empty value ("key:" with nothing after it) is not a string.
// An empty value where a mapping or sequence is expected counts as an empty one. Duplicate keys
// and non-scalar keys are rejected when the file is loaded.
//
// Copies are cheap (yaml-cpp nodes share their data); values stay valid after the YamlValue they
// came from is gone.
class YamlValue {
 public:
  // Reads and parses a file. Throws InputError for a missing or unreadable file, a YAML syntax
  // error (with yaml-cpp's line), more than one document, duplicate keys or non-scalar keys.
  static YamlValue load_file(const std::string& path);

  // Parses `text` as if it had been read from `file` (used in error messages and by
  // resolve_path). Same checks as load_file.
  static YamlValue parse(std::string_view text, const std::string& file);

  const std::string& file() const { return file_; }
  // Dotted path of this value from the document root; empty for the root itself.
  const std::string& field() const { return field_; }
  // 1-based line of this value (of its key, for mapping entries); 0 when unknown.
  int line() const { return line_; }
  bool is_null() const;
  bool is_map() const;
  bool is_sequence() const;
  bool is_scalar() const;

  // Mapping access. Throws InputError if this value is neither a mapping nor empty.
  bool has(std::string_view key) const;
  // Throws InputError "missing required key '<key>'" (at this mapping's line) if absent.
  YamlValue at(std::string_view key) const;
  std::optional<YamlValue> find(std::string_view key) const;
  // All entries in document order.
  std::vector<std::pair<std::string, YamlValue>> entries() const;
  // Throws InputError at the first key not in `allowed`, suggesting the closest allowed key when
  // it is within edit distance 2 or is the key plus a unit suffix ("dt" → "dt_s"): "did you
  // mean 'dt_s'?"; otherwise the message lists the allowed keys.
  void require_keys_within(std::initializer_list<std::string_view> allowed) const;
  // The same check, every unknown key recorded in `errors` (none thrown).
  void check_keys_within(std::initializer_list<std::string_view> allowed,
                         ErrorCollector& errors) const;

  // Sequence access, in document order; item fields are "<field>[i]" (0-based). Throws
  // InputError if this value is neither a sequence nor empty.
  std::vector<YamlValue> items() const;

  // Typed scalars; throw InputError naming the field when the value has another type.
  double as_double() const;
  int as_int() const;
  bool as_bool() const;
  std::string as_string() const;
  std::vector<double> as_double_list() const;
  std::vector<std::string> as_string_list() const;

  // Optional keys: the default when `key` is absent; InputError when present but ill-typed
  // (including an empty value).
  double get_double(std::string_view key, double default_value) const;
  int get_int(std::string_view key, int default_value) const;
  bool get_bool(std::string_view key, bool default_value) const;
  std::string get_string(std::string_view key, const std::string& default_value) const;

  // A path written in this file, resolved against the folder of the file: absolute paths are
  // returned unchanged, relative ones are joined to the file's folder and normalised.
  std::string resolve_path(const std::string& relative) const;

  // Throws InputError(file(), line(), field(), message): for checks only the caller can make
  // ("must be positive", "unknown robot 'x'").
  [[noreturn]] void fail(const std::string& message) const;

 private:
  YamlValue(const YAML::Node& node, std::string file, std::string field, int line);

  YamlValue child(const YAML::Node& key, const YAML::Node& value) const;
  void require_map() const;
  void require_sequence() const;
  void require_plain_scalar(const char* expected) const;

  // yaml-cpp stays out of this header: the node lives behind a pointer (yaml-cpp nodes are
  // handles to shared data, so a copy of the pointer is as cheap as a copy of the node).
  std::shared_ptr<const YAML::Node> node_;
  std::string file_;
  std::string field_;
  int line_ = 0;
};

// Levenshtein distance (insertions, deletions, substitutions); used for key suggestions.
int edit_distance(std::string_view a, std::string_view b);

}  // namespace motoflex
