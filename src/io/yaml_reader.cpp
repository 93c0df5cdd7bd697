#include "motoflex/io/yaml_reader.hpp"

#include "motoflex/core/error_collector.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>
#include <yaml-cpp/yaml.h>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

// yaml-cpp tags: "?" for plain scalars, "!" for quoted ones, the full URI for explicit tags.
constexpr std::string_view kPlainTag = "?";
constexpr std::string_view kFloatTag = "tag:yaml.org,2002:float";
constexpr std::string_view kIntTag = "tag:yaml.org,2002:int";

int line_of(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

std::string join_field(const std::string& parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  return parent + "." + std::string(key);
}

// Short, quoted rendering of a value for error messages.
std::string describe(const YAML::Node& node) {
  if (node.IsNull()) return "an empty value";
  if (node.IsMap()) return "a mapping";
  if (node.IsSequence()) return "a sequence";
  std::string text = node.Scalar();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  if (node.Tag() != kPlainTag) return "the quoted string '" + text + "'";
  return "'" + text + "'";
}

bool is_yaml_special_float(std::string_view text) {
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) text.remove_prefix(1);
  static constexpr std::string_view kSpecial[] = {".nan", ".NaN", ".NAN", ".inf", ".Inf", ".INF"};
  return std::find(std::begin(kSpecial), std::end(kSpecial), text) != std::end(kSpecial);
}

// YAML allows a leading '+', std::from_chars does not.
std::string_view strip_plus(std::string_view text) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '+' && text[1] != '-') {
    text.remove_prefix(1);
  }
  return text;
}

// Limits on what a config may make us walk: aliases share nodes, so "a: &a [*b, *b, ...]"
// nested ten deep is a small file that expands to billions of nodes (an alias bomb), and deep
// nesting recurses once per level.
constexpr std::size_t kMaxYamlNodes = 1000000;  // after alias expansion; our largest is ~3000
constexpr int kMaxYamlDepth = 64;               // our deepest config is 5 levels
constexpr std::size_t kMaxYamlBytes = 64u << 20;

// Counts documents without building them. yaml-cpp 0.7's LoadAll can loop forever on some
// malformed input, pushing one null document per turn (found by fuzz/yaml_config_fuzzer.cpp;
// upstream jbeder/yaml-cpp#1319), so the documents are counted here, at most two.
class DocumentCounter final : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ == 2) second_line_ = mark.line >= 0 ? mark.line + 1 : 0;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
  int documents() const { return documents_; }
  int second_line() const { return second_line_; }

 private:
  int documents_ = 0;
  int second_line_ = 0;
};

struct KeyCheck {
  const std::string& file;
  std::size_t nodes = 0;
};

// Rejects duplicate and non-scalar keys everywhere in the tree: yaml-cpp accepts both silently
// (and then returns the first duplicate), which would hide a config mistake. Counts the nodes
// (aliases expanded) and the depth against the limits above.
void check_keys(const YAML::Node& node, KeyCheck& check, const std::string& field, int depth) {
  if (++check.nodes > kMaxYamlNodes) {
    throw InputError(check.file, line_of(node), field,
                     "more than " + std::to_string(kMaxYamlNodes) +
                         " values once aliases are expanded (an alias bomb?)");
  }
  if (depth > kMaxYamlDepth) {
    throw InputError(check.file, line_of(node), field,
                     "nested more than " + std::to_string(kMaxYamlDepth) + " levels deep");
  }
  if (node.IsMap()) {
    std::set<std::string> seen;
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (!it->first.IsScalar()) {
        throw InputError(check.file, line_of(it->first), field,
                         "mapping keys must be plain scalars");
      }
      const std::string& key = it->first.Scalar();
      const std::string child_field = join_field(field, key);
      if (!seen.insert(key).second) {
        throw InputError(check.file, line_of(it->first), child_field,
                         "duplicate key '" + key + "'");
      }
      check_keys(it->second, check, child_field, depth + 1);
    }
  } else if (node.IsSequence()) {
    std::size_t index = 0;
    for (auto it = node.begin(); it != node.end(); ++it, ++index) {
      check_keys(*it, check, field + "[" + std::to_string(index) + "]", depth + 1);
    }
  }
}

}  // namespace

int edit_distance(std::string_view a, std::string_view b) {
  std::vector<int> previous(b.size() + 1);
  std::vector<int> current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

YamlValue::YamlValue(const YAML::Node& node, std::string file, std::string field, int line)
    : node_(std::make_shared<const YAML::Node>(node)),
      file_(std::move(file)),
      field_(std::move(field)),
      line_(line) {}

bool YamlValue::is_null() const {
  return node_->IsNull();
}
bool YamlValue::is_map() const {
  return node_->IsMap();
}
bool YamlValue::is_sequence() const {
  return node_->IsSequence();
}
bool YamlValue::is_scalar() const {
  return node_->IsScalar();
}

YamlValue YamlValue::load_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw InputError(path, 0, "", "file not found");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(path, 0, "", "is a directory, expected a YAML file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "", "read error");
  return parse(text.str(), path);
}

YamlValue YamlValue::parse(std::string_view text, const std::string& file) {
  if (text.size() > kMaxYamlBytes) {
    throw InputError(file, 0, "",
                     "larger than " + std::to_string(kMaxYamlBytes >> 20) + " MB; not a config");
  }
  YAML::Node root;
  int documents = 0;
  try {
    std::istringstream stream{std::string(text)};
    YAML::Parser parser(stream);
    DocumentCounter counter;
    while (counter.documents() < 2 && parser.HandleNextDocument(counter)) {
    }
    documents = counter.documents();
    if (documents > 1) {
      throw InputError(file, counter.second_line(), "",
                       "expected one YAML document, found more (a '---' line?)");
    }
    if (documents == 1) root = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    throw InputError(file, e.mark.line >= 0 ? e.mark.line + 1 : 0, "",
                     "YAML syntax error: " + e.msg);
  }
  KeyCheck check{file};
  check_keys(root, check, "", 0);
  return YamlValue(root, file, "", documents == 0 ? 0 : std::max(line_of(root), 1));
}

void YamlValue::fail(const std::string& message) const {
  throw InputError(file_, line_, field_, message);
}

YamlValue YamlValue::child(const YAML::Node& key, const YAML::Node& value) const {
  // The key's line, not the value's: yaml-cpp marks an empty value at the following token, and
  // a nested block mapping at its first inner key.
  return YamlValue(value, file_, join_field(field_, key.Scalar()), line_of(key));
}

void YamlValue::require_map() const {
  if (!node_->IsMap() && !node_->IsNull()) fail("expected a mapping, got " + describe(*node_));
}

void YamlValue::require_sequence() const {
  if (!node_->IsSequence() && !node_->IsNull())
    fail("expected a sequence, got " + describe(*node_));
}

void YamlValue::require_plain_scalar(const char* expected) const {
  if (!node_->IsScalar() || node_->Tag() == "!") {
    fail(std::string("expected ") + expected + ", got " + describe(*node_));
  }
  const std::string& tag = node_->Tag();
  if (tag != kPlainTag && tag != kFloatTag && tag != kIntTag) {
    fail(std::string("expected ") + expected + ", got a value tagged '" + tag + "'");
  }
}

std::optional<YamlValue> YamlValue::find(std::string_view key) const {
  require_map();
  if (node_->IsNull()) return std::nullopt;
  for (auto it = node_->begin(); it != node_->end(); ++it) {
    if (it->first.Scalar() == key) return child(it->first, it->second);
  }
  return std::nullopt;
}

bool YamlValue::has(std::string_view key) const {
  return find(key).has_value();
}

YamlValue YamlValue::at(std::string_view key) const {
  std::optional<YamlValue> value = find(key);
  if (!value) throw InputError(file_, line_, join_field(field_, key), "missing required key");
  return *value;
}

std::vector<std::pair<std::string, YamlValue>> YamlValue::entries() const {
  require_map();
  std::vector<std::pair<std::string, YamlValue>> result;
  if (node_->IsNull()) return result;
  for (auto it = node_->begin(); it != node_->end(); ++it) {
    result.emplace_back(it->first.Scalar(), child(it->first, it->second));
  }
  return result;
}

namespace {

// "unknown key 'k' (did you mean 'x'?)" or the list of allowed keys.
std::string unknown_key_message(const std::string& key,
                                std::initializer_list<std::string_view> allowed) {
  std::string_view closest;
  int closest_distance = 3;  // suggest only within edit distance 2
  for (std::string_view candidate : allowed) {
    const int distance = edit_distance(key, candidate);
    if (distance < closest_distance) {
      closest_distance = distance;
      closest = candidate;
    }
  }
  // Our keys carry their unit ("rate_hz", "dt_s"): a key without its unit is a likely slip.
  for (std::string_view candidate : allowed) {
    if (!closest.empty()) break;
    if (candidate.size() > key.size() + 1 && candidate.substr(0, key.size()) == key &&
        candidate[key.size()] == '_') {
      closest = candidate;
    }
  }
  std::string message = "unknown key '" + key + "'";
  if (!closest.empty()) {
    message += " (did you mean '" + std::string(closest) + "'?)";
  } else {
    message += " (allowed:";
    for (std::string_view candidate : allowed) message += " " + std::string(candidate);
    message += ")";
  }
  return message;
}

}  // namespace

void YamlValue::require_keys_within(std::initializer_list<std::string_view> allowed) const {
  for (const auto& [key, value] : entries()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    value.fail(unknown_key_message(key, allowed));
  }
}

void YamlValue::check_keys_within(std::initializer_list<std::string_view> allowed,
                                  ErrorCollector& errors) const {
  errors.check([&] {
    for (const auto& [key, value] : entries()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      errors.add(value.file(), value.line(), value.field(), unknown_key_message(key, allowed));
    }
  });
}

std::vector<YamlValue> YamlValue::items() const {
  require_sequence();
  std::vector<YamlValue> result;
  if (node_->IsNull()) return result;
  std::size_t index = 0;
  for (auto it = node_->begin(); it != node_->end(); ++it, ++index) {
    const int item_line = line_of(*it);
    result.push_back(YamlValue(*it, file_, field_ + "[" + std::to_string(index) + "]",
                               item_line > 0 ? item_line : line_));
  }
  return result;
}

double YamlValue::as_double() const {
  require_plain_scalar("a number");
  const std::string& text = node_->Scalar();
  if (is_yaml_special_float(text)) fail("non-finite number '" + text + "' is not allowed");
  const std::string_view digits = strip_plus(text);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range) fail("number '" + text + "' is out of range");
  if (ec != std::errc() || end != digits.data() + digits.size()) {
    fail("expected a number, got " + describe(*node_));
  }
  if (!std::isfinite(value)) fail("non-finite number '" + text + "' is not allowed");
  return value;
}

int YamlValue::as_int() const {
  require_plain_scalar("an integer");
  const std::string& text = node_->Scalar();
  const std::string_view digits = strip_plus(text);
  int value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range) fail("integer '" + text + "' is out of range");
  if (ec != std::errc() || end != digits.data() + digits.size()) {
    fail("expected an integer, got " + describe(*node_));
  }
  return value;
}

bool YamlValue::as_bool() const {
  require_plain_scalar("true or false");
  const std::string& text = node_->Scalar();
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  fail("expected true or false, got " + describe(*node_));
}

std::string YamlValue::as_string() const {
  if (!node_->IsScalar()) fail("expected a string, got " + describe(*node_));
  return node_->Scalar();
}

std::vector<double> YamlValue::as_double_list() const {
  std::vector<double> result;
  for (const YamlValue& item : items()) result.push_back(item.as_double());
  return result;
}

std::vector<std::string> YamlValue::as_string_list() const {
  std::vector<std::string> result;
  for (const YamlValue& item : items()) result.push_back(item.as_string());
  return result;
}

double YamlValue::get_double(std::string_view key, double default_value) const {
  const std::optional<YamlValue> value = find(key);
  return value ? value->as_double() : default_value;
}

int YamlValue::get_int(std::string_view key, int default_value) const {
  const std::optional<YamlValue> value = find(key);
  return value ? value->as_int() : default_value;
}

bool YamlValue::get_bool(std::string_view key, bool default_value) const {
  const std::optional<YamlValue> value = find(key);
  return value ? value->as_bool() : default_value;
}

std::string YamlValue::get_string(std::string_view key, const std::string& default_value) const {
  const std::optional<YamlValue> value = find(key);
  return value ? value->as_string() : default_value;
}

std::string YamlValue::resolve_path(const std::string& relative) const {
  const std::filesystem::path path(relative);
  if (relative.empty() || path.is_absolute()) return relative;
  const std::filesystem::path folder = std::filesystem::path(file_).parent_path();
  if (folder.empty()) return path.lexically_normal().string();
  return (folder / path).lexically_normal().string();
}

}  // namespace motoflex
