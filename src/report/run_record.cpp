#include "motoflex/report/run_record.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "motoflex/core/error.hpp"

namespace motoflex::report {
namespace {

namespace fs = std::filesystem;

// The file's JSON, or null when it does not exist; InputError when it does but is not JSON.
nlohmann::json read_optional_json(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return nullptr;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw InputError(path.string(), 0, "", std::string("corrupt JSON: ") + error.what());
  }
}

std::string read_optional_text(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return "";
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

double parse_number(const std::string& field, const std::string& path, int line,
                    const std::string& column) {
  // strtod reads "inf" and "nan", which generations.csv holds for a batch without a median.
  const char* begin = field.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin || *end != '\0') throw InputError(path, line, column, "not a number: " + field);
  return value;
}

// A loop's final run dir as loop.json names it; the folder of the same name inside the loop
// dir when that path is gone (a loop dir that was moved or copied).
std::string locate_run_dir(const fs::path& loop_dir, const std::string& recorded) {
  if (recorded.empty()) return "";
  const fs::path path(recorded);
  if (fs::exists(path / "summary.json")) return path.string();
  const fs::path inside = loop_dir / path.filename();
  if (fs::exists(inside / "summary.json")) return inside.string();
  return "";
}

std::vector<std::string> string_list(const nlohmann::json& json, const char* key) {
  std::vector<std::string> out;
  if (!json.is_object() || !json.contains(key) || !json[key].is_array()) return out;
  for (const auto& item : json[key]) {
    if (item.is_string()) out.push_back(item.get<std::string>());
  }
  return out;
}

void add_logs(RunRecord& record, const std::vector<std::string>& measured, const char* set,
              const fs::path& simulated_dir) {
  for (const auto& path : measured) {
    LogFiles files;
    files.name = fs::path(path).stem().string();
    files.set = set;
    files.measured_path = path;
    const fs::path simulated = simulated_dir / (files.name + ".csv");
    if (fs::exists(simulated)) files.simulated_path = simulated.string();
    record.logs.push_back(std::move(files));
  }
}

// The simulated logs in `folder` (*.csv, sorted), for a run dir without inputs.json.
void add_simulated_only(RunRecord& record, const fs::path& folder, const char* set) {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    if (entry.is_regular_file() && entry.path().extension() == ".csv") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (const auto& path : files) {
    record.logs.push_back({path.stem().string(), set, "", path.string()});
  }
}

void read_fit(RunRecord& record, const fs::path& dir) {
  record.run = read_optional_json(dir / "run.json");
  record.inputs = read_optional_json(dir / "inputs.json");
  record.best = read_optional_json(dir / "best.json");
  record.summary = read_optional_json(dir / "summary.json");
  if (record.summary.is_null()) {
    record.notes.push_back("no summary.json: the fit has not finished a generation yet");
  }
  if (fs::exists(dir / "generations.csv")) {
    record.generations = read_generations_csv((dir / "generations.csv").string());
  } else {
    record.notes.push_back("no generations.csv: no convergence plot");
  }
  if (record.inputs.is_object()) {
    add_logs(record, string_list(record.inputs, "train_logs"), "training", dir / "best");
    add_logs(record, string_list(record.inputs, "validation_logs"), "validation",
             dir / "best" / "validation");
  } else {
    record.notes.push_back(
        "no inputs.json (a run dir of an older motoflex): the measured logs and the parameters' "
        "start and bounds are unknown");
    add_simulated_only(record, dir / "best", "training");
    add_simulated_only(record, dir / "best" / "validation", "validation");
  }
  const fs::path residuals = dir / "residuals";
  record.residuals_markdown = read_optional_text(residuals / "residuals.md");
  if (!record.residuals_markdown.empty()) {
    record.residuals_dir = residuals.string();
  } else {
    record.notes.push_back("no residual analysis (run `motoflex residuals " + dir.string() +
                           "` to add it)");
  }
}

}  // namespace

std::vector<GenerationRow> read_generations_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "", "cannot read");
  static const char* kColumns[] = {"generation", "evaluations", "best",
                                   "median",     "mean_sigma",  "seconds"};
  std::vector<GenerationRow> rows;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1 || line.empty()) continue;  // the header
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, ',')) fields.push_back(field);
    if (fields.size() != 6) {
      throw InputError(path, number, "",
                       "expected 6 fields, found " + std::to_string(fields.size()));
    }
    double values[6];
    for (int c = 0; c < 6; ++c) values[c] = parse_number(fields[c], path, number, kColumns[c]);
    rows.push_back({static_cast<std::uint64_t>(values[0]), static_cast<std::uint64_t>(values[1]),
                    values[2], values[3], values[4], values[5]});
  }
  return rows;
}

RunRecord read_run_dir(const std::string& dir_text) {
  const fs::path dir(dir_text);
  RunRecord record;
  record.dir = dir_text;
  const bool fit = fs::exists(dir / "run.json") || fs::exists(dir / "summary.json");
  const bool loop = fs::exists(dir / "loop.json");
  if (!fit && !loop) {
    throw InputError(dir_text, 0, "",
                     "not a fit or loop run folder (no run.json, summary.json or loop.json)");
  }
  if (loop) {
    record.loop = read_optional_json(dir / "loop.json");
    record.loop_markdown = read_optional_text(dir / "report.md");
    if (record.loop_markdown.empty()) record.notes.push_back("no report.md in the loop folder");
  }
  if (fit) {
    record.fit_dir = dir_text;
  } else {
    const std::string recorded =
        record.loop.is_object() ? record.loop.value("final_run_dir", std::string()) : "";
    record.fit_dir = locate_run_dir(dir, recorded);
    if (record.fit_dir.empty()) {
      record.notes.push_back("the loop's final fit (" + recorded + ") is not there");
    }
  }
  if (!record.fit_dir.empty()) read_fit(record, record.fit_dir);
  return record;
}

}  // namespace motoflex::report
