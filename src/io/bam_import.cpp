#include "motoflex/io/bam_import.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string_view>

#include "json_fields.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/number_text.hpp"
#include "python_json.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Fields = detail::JsonFields;

constexpr const char* kRobot = "servo_pendulum";
constexpr const char* kJoint = "pendulum";
// A processed file's timestamps are arange(0, end, dt); anything further off than this is not
// the grid the file claims.
constexpr double kGridTolerance_s = 1e-6;

// BAM's voltage-controlled servo models (bam.md §2c): duty = clip(error_gain·kp·error,
// ±max_duty). Motors not listed (sts3250, xl330i, erob80_*) have no such model in BAM.
struct ServoGains {
  std::string_view motor;
  double error_gain;  // duty per (kp·rad)
  double max_duty;    // PWM limit as a fraction of full duty
  std::string_view source;
};

constexpr ServoGains kServoGains[] = {
    {"xl330", (4096.0 / (2.0 * std::numbers::pi)) / (256.0 * 885.0), 1.0,
     "BAM XL330Actuator: error_gain (4096/2pi)/(256*885), max_duty 1.0 (PWM limit 885/885)"},
    {"xl320", 0.05048199, 1.0, "BAM XL320Actuator: error_gain 0.05048199, max_duty 1.0"},
    {"mx64", 0.158, 0.9625, "BAM MXActuator: error_gain 0.158 (oscilloscope), max_duty 0.9625"},
    {"mx106", 0.158, 0.9625, "BAM MXActuator: error_gain 0.158 (oscilloscope), max_duty 0.9625"},
};

// Facts about a motor's logs that the numbers do not show (shared/data/bam/<motor>/README.md).
constexpr std::pair<std::string_view, std::string_view> kMotorRemarks[] = {
    {"sts3250",
     "kp is nominal only: the recorder's set_p_gain was a no-op, so the servo ran with its "
     "stored P gain; BAM has no STS3250 model (it ships STS3215, a different servo)"},
};

std::string fixed_text(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

// Why a document is not a single-axis trajectory log, and what it looks like instead.
struct NotATrajectory {
  std::string field;         // where import_bam_file reports it
  bool missing_key = false;  // `field` is absent (rather than present but unsupported)
  std::string looks_like;    // e.g. "PWM duty vs position error calibration table"
};

bool is_speed_vs_voltage_table(const json& doc) {
  if (doc.empty()) return false;
  for (const auto& item : doc.items()) {
    double volts = 0.0;
    const std::string& key = item.key();
    const auto parsed = std::from_chars(key.data(), key.data() + key.size(), volts);
    if (parsed.ec != std::errc() || parsed.ptr != key.data() + key.size()) return false;
    if (!item.value().is_number()) return false;
  }
  return true;
}

std::optional<NotATrajectory> classify(const json& doc) {
  if (!doc.is_object()) return NotATrajectory{"", false, "top level is not a JSON object"};
  if (const auto entries = doc.find("entries"); entries != doc.end()) {
    if (entries->is_array() && !entries->empty() && (*entries)[0].is_object() &&
        (*entries)[0].contains("r1") && !(*entries)[0].contains("position")) {
      return NotATrajectory{"entries[0]", false,
                            "2R arm log (entries hold joints r1, r2); only single-axis pendulum "
                            "logs are supported"};
    }
    return std::nullopt;
  }
  std::string looks_like = "no entries list: not a BAM trajectory log";
  if (doc.contains("pwm_period") && doc.contains("samples")) {
    looks_like =
        "PWM duty vs position error calibration table, not a trajectory log (motoflex "
        "calibrate-bam fits it)";
  } else if (doc.contains("positions") && doc.contains("timestamps")) {
    looks_like = "free pendulum position log without goal or torque state, not a trajectory log";
  } else if (is_speed_vs_voltage_table(doc)) {
    looks_like =
        "no-load speed vs voltage calibration table, not a trajectory log (motoflex "
        "calibrate-bam fits it)";
  }
  return NotATrajectory{"entries", true, looks_like};
}

// The value at `key`, or null when the object has no such key.
const json* find_key(const json& object, const char* key) {
  const auto found = object.find(key);
  return found == object.end() ? nullptr : &*found;
}

// The document's optional scalar keys (motor, trajectory, kp, vin, arm_mass) into the sidecar;
// returns the processed log's dt when the file has one.
std::optional<double> read_header(const json& doc, const Fields& fields, BamImport& result,
                                  std::vector<std::string>& notes) {
  JointLogMeta& meta = result.log.meta;
  if (const auto motor = find_key(doc, "motor")) result.motor = fields.text(*motor, "motor");
  if (const auto trajectory = find_key(doc, "trajectory")) {
    meta.motion = fields.text(*trajectory, "trajectory");
  } else {
    notes.push_back("no trajectory name in the log");
  }
  if (const auto kp = find_key(doc, "kp")) {
    const double value = fields.number(*kp, "kp");
    if (value < 0.0) fields.fail("kp", "must be >= 0, found " + number_text(value));
    meta.parameters["bench.kp"] = value;
  } else {
    notes.push_back("no kp in the log: bench.kp left out");
  }
  if (const auto vin = find_key(doc, "vin")) {
    meta.parameters["bench.supply_v"] = fields.positive(*vin, "vin");
  } else {
    notes.push_back("no vin in the log: bench.supply_v left out");
  }
  if (const auto arm_mass = find_key(doc, "arm_mass")) {
    const double value = fields.number(*arm_mass, "arm_mass");
    if (value != 0.0) {
      notes.push_back("arm_mass " + number_text(value) +
                      " kg ignored: the servo_pendulum arm is a massless rod with a point mass");
    }
  }
  std::optional<double> dt_s;
  if (const auto dt = find_key(doc, "dt")) dt_s = fields.positive(*dt, "dt");
  return dt_s;
}

// The entries into the log's rows (strictly increasing time, on the dt grid when there is one);
// returns the entry at which the torque was released, if it was.
std::optional<std::size_t> read_entries(const json& entries, const Fields& fields,
                                        std::optional<double> dt_s, JointLog& log) {
  const std::size_t count = entries.size();
  log.joint_names = {kJoint};
  log.time_s.reserve(count);
  log.commanded_rad.reserve(count);
  log.measured_rad.reserve(count);
  std::optional<std::size_t> torque_off_entry;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string prefix = "entries[" + std::to_string(i) + "]";
    const json& entry = entries[i];
    if (!entry.is_object()) {
      fields.fail(prefix, std::string("expected an object, found ") + entry.type_name());
    }
    const auto number_at = [&](const char* key) {
      const std::string field = prefix + "." + key;
      return fields.number(fields.required(entry, key, field), field);
    };
    const double t = number_at("timestamp");
    if (i > 0 && !(t > log.time_s.back())) {
      fields.fail(prefix + ".timestamp",
                  number_text(t) + " s does not come after the previous entry's " +
                      number_text(log.time_s.back()) + " s (timestamps must strictly increase)");
    }
    if (dt_s) {
      const double expected = log.time_s.empty() ? t : log.time_s.front() + i * *dt_s;
      if (std::abs(t - expected) > kGridTolerance_s) {
        fields.fail(prefix + ".timestamp", number_text(t) + " s is off the dt grid (expected " +
                                               number_text(expected) + " s for dt " +
                                               number_text(*dt_s) + " s)");
      }
    }
    log.time_s.push_back(t);
    log.commanded_rad.push_back(number_at("goal_position"));
    log.measured_rad.push_back(number_at("position"));
    // The servo's own supply reading (register/10, V): kept when every entry has one.
    const auto volts = find_key(entry, "input_volts");
    if (volts && (i == 0 || log.supply_v.size() == i)) {
      log.supply_v.push_back(fields.positive(*volts, prefix + ".input_volts"));
    }
    if (const auto enable = find_key(entry, "torque_enable")) {
      if (!enable->is_boolean()) {
        fields.fail(prefix + ".torque_enable",
                    std::string("expected true or false, found ") + enable->type_name());
      }
      const bool on = enable->get<bool>();
      if (!on && !torque_off_entry) torque_off_entry = i;
      if (on && torque_off_entry) {
        fields.fail(prefix + ".torque_enable", "torque enabled again after its release at entry " +
                                                   std::to_string(*torque_off_entry) +
                                                   "; only one release per log is supported");
      }
    }
  }
  return torque_off_entry;
}

// The sidecar's rate and a first note on how the file was sampled.
void describe_sampling(std::optional<double> dt_s, JointLog& log, std::vector<std::string>& notes) {
  JointLogMeta& meta = log.meta;
  const std::size_t count = log.time_s.size();
  const double span_s = log.time_s.back() - log.time_s.front();
  if (dt_s) {
    meta.rate_hz = 1.0 / *dt_s;
    notes.insert(notes.begin(), "BAM processed log (resampled every " + number_text(*dt_s) +
                                    " s by bam/process.py)");
    return;
  }
  meta.rate_hz = static_cast<double>(count - 1) / span_s;
  double min_period_s = span_s;
  double max_period_s = 0.0;
  for (std::size_t i = 1; i < count; ++i) {
    min_period_s = std::min(min_period_s, log.time_s[i] - log.time_s[i - 1]);
    max_period_s = std::max(max_period_s, log.time_s[i] - log.time_s[i - 1]);
  }
  notes.insert(notes.begin(), "BAM raw log: irregular timestamps kept as recorded (period mean " +
                                  fixed_text(1e3 / meta.rate_hz, 2) + " ms, min " +
                                  fixed_text(1e3 * min_period_s, 2) + " ms, max " +
                                  fixed_text(1e3 * max_period_s, 2) +
                                  " ms); rate_hz is the mean rate");
}

// The servo's own temperature readings (the entries' `temp`, °C) as the log's housing
// temperature motor.housing_temperature_c, when every entry has one: their median, which a
// single misread sample (the STS3250 logs read 7 °C once amid 20–26 °C) does not move. The
// bench law scales its winding resistance to it by motor.R_temperature_per_k.
void add_housing_temperature(const json& entries, const Fields& fields, JointLog& log,
                             std::vector<std::string>& notes) {
  std::vector<double> readings_c;
  readings_c.reserve(entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (const json* temp = find_key(entries[i], "temp")) {
      readings_c.push_back(fields.number(*temp, "entries[" + std::to_string(i) + "].temp"));
    }
  }
  if (readings_c.empty()) return;
  if (readings_c.size() != entries.size()) {
    notes.push_back("temp missing in some entries: not imported");
    return;
  }
  const auto middle = readings_c.begin() + static_cast<std::ptrdiff_t>(readings_c.size() / 2);
  std::nth_element(readings_c.begin(), middle, readings_c.end());
  log.meta.parameters["motor.housing_temperature_c"] = *middle;
  notes.push_back("the median logged temp " + number_text(*middle) +
                  " C is motor.housing_temperature_c");
}

// BAM's voltage-servo gains for the motor, or a note that BAM has none, plus known remarks.
void add_motor_facts(BamImport& result, std::vector<std::string>& notes) {
  const auto gains = std::find_if(std::begin(kServoGains), std::end(kServoGains),
                                  [&](const ServoGains& g) { return g.motor == result.motor; });
  if (gains != std::end(kServoGains)) {
    result.log.meta.parameters["bench.error_gain"] = gains->error_gain;
    result.log.meta.parameters["bench.max_duty"] = gains->max_duty;
    notes.push_back(std::string(gains->source));
  } else {
    notes.push_back("motor '" + result.motor +
                    "': BAM has no voltage-servo error_gain / max_duty for it, so "
                    "bench.error_gain and bench.max_duty are left out");
  }
  for (const auto& [motor, remark] : kMotorRemarks) {
    if (motor == result.motor) notes.push_back(std::string(remark));
  }
}

// `shown` names the file in errors; `origin_path` goes into the sidecar's origin.
BamImport import_document(const json& doc, const std::string& shown,
                          const std::string& origin_path) {
  if (const auto problem = classify(doc)) {
    throw InputError(
        shown, 0, problem->field,
        problem->missing_key ? "missing key (" + problem->looks_like + ")" : problem->looks_like);
  }
  const Fields fields(shown);
  const json& entries = fields.required(doc, "entries", "entries");
  if (!entries.is_array()) {
    fields.fail("entries", std::string("expected a list, found ") + entries.type_name());
  }

  BamImport result;
  std::vector<std::string> notes;
  JointLog& log = result.log;
  log.meta.robot = kRobot;
  log.meta.origin = "imported from BAM " + origin_path;
  log.meta.parameters["bench.mass_kg"] =
      fields.positive(fields.required(doc, "mass", "mass"), "mass");
  log.meta.parameters["bench.length_m"] =
      fields.positive(fields.required(doc, "length", "length"), "length");
  if (entries.size() < 2) {
    fields.fail("entries", "need at least 2 entries, found " + std::to_string(entries.size()));
  }
  const std::optional<double> dt_s = read_header(doc, fields, result, notes);
  result.processed = dt_s.has_value();
  const std::optional<std::size_t> torque_off_entry = read_entries(entries, fields, dt_s, log);
  describe_sampling(dt_s, log, notes);
  if (log.supply_v.size() != log.time_s.size()) {
    if (!log.supply_v.empty()) notes.push_back("input_volts missing in some entries: not imported");
    log.supply_v.clear();
  } else {
    notes.push_back("the logged input_volts is the supply_v column (servo: bench drives from it)");
  }
  add_housing_temperature(entries, fields, log, notes);
  if (torque_off_entry) {
    result.torque_off_s = log.time_s[*torque_off_entry];
    log.meta.parameters["bench.torque_off_s"] = *result.torque_off_s;
    notes.push_back("torque released at t = " + number_text(*result.torque_off_s) + " s (entry " +
                    std::to_string(*torque_off_entry) +
                    "); the later goal_position values were logged but not followed");
  }
  add_motor_facts(result, notes);
  for (std::size_t i = 0; i < notes.size(); ++i) {
    log.meta.notes += (i == 0 ? "" : ". ") + notes[i];
  }
  log.meta.notes += ".";
  return result;
}

// What identifies one recording across BAM's raw and processed copies: the file name and the
// header values the recorder wrote into both.
std::string recording_key(const BamDirectoryItem& item) {
  const BamImport& imported = *item.import;
  const auto kp = imported.log.meta.parameters.find("bench.kp");
  return fs::path(item.relative_path).filename().string() + "|" + imported.motor + "|" +
         imported.log.meta.motion + "|" +
         (kp == imported.log.meta.parameters.end() ? std::string() : number_text(kp->second));
}

// A raw log whose processed copy was also found is skipped (see import_bam_directory).
void skip_raw_copies(std::vector<BamDirectoryItem>& items) {
  std::map<std::string, std::string> processed;  // recording key → relative path
  for (const BamDirectoryItem& item : items) {
    if (item.import && item.import->processed) {
      processed.emplace(recording_key(item), item.relative_path);
    }
  }
  for (BamDirectoryItem& item : items) {
    if (!item.import || item.import->processed) continue;
    const auto copy = processed.find(recording_key(item));
    if (copy == processed.end()) continue;
    item.skip_reason = "the raw copy of " + copy->second +
                       ", which is imported instead (BAM fits on the processed copy)";
    item.import.reset();
  }
}

}  // namespace

BamImport import_bam_file(const std::string& path, const std::string& display_path) {
  return import_document(read_python_json(path, display_path), display_path, display_path);
}

std::string bam_output_stem(const std::string& relative_path) {
  std::string stem = relative_path;
  std::replace(stem.begin(), stem.end(), '/', '_');
  if (stem.ends_with(".json")) stem.resize(stem.size() - 5);
  return stem;
}

std::vector<BamDirectoryItem> import_bam_directory(const std::string& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) throw InputError(dir, 0, "", "not a folder");
  std::vector<fs::path> files;
  try {
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
      if (entry.is_regular_file()) files.push_back(entry.path());
    }
  } catch (const fs::filesystem_error& failure) {
    throw InputError(dir, 0, "", failure.code().message());
  }
  std::sort(files.begin(), files.end());

  std::vector<BamDirectoryItem> items;
  std::map<std::string, std::string> stem_owner;  // output stem → relative path
  for (const fs::path& file : files) {
    BamDirectoryItem item;
    item.relative_path = file.lexically_relative(dir).generic_string();
    item.output_stem = bam_output_stem(item.relative_path);
    const std::string shown = file.string();
    if (file.extension() != ".json") {
      item.skip_reason = "not a .json file";
    } else {
      const json doc = read_python_json(shown, shown);
      const auto problem = classify(doc);
      if (problem) {
        item.skip_reason = problem->looks_like;
      } else {
        item.import = import_document(doc, shown, item.relative_path);
        const auto [owner, inserted] = stem_owner.emplace(item.output_stem, item.relative_path);
        if (!inserted) {
          throw InputError(
              shown, 0, "",
              "its output name " + item.output_stem + " is also that of " + owner->second);
        }
      }
    }
    items.push_back(std::move(item));
  }
  skip_raw_copies(items);
  return items;
}

}  // namespace motoflex
