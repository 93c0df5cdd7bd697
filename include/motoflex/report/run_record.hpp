#pragma once

// What a run dir holds, as the report needs it. A fit run dir (`motoflex fit`, `resume`) has
// run.json, inputs.json (fit_inputs.hpp), generations.csv, best.json, summary.json, the best
// parameters' simulated logs in best/<log>.csv and best/validation/<log>.csv, and, once
// `motoflex residuals` ran, residuals/residuals.md and its PNGs. A loop's out dir (`motoflex
// loop`) has loop.json and report.md, and one fit run dir per fit; the report shows the loop
// and the final model's fit. Anything optional that is missing is recorded in `notes`.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace motoflex::report {

// One row of generations.csv.
struct GenerationRow {
  std::uint64_t generation = 0;
  std::uint64_t evaluations = 0;
  double best = 0.0;    // best fitness so far
  double median = 0.0;  // median fitness of the generation's batch (may be inf)
  double mean_sigma = 0.0;
  double seconds = 0.0;
};

// A measured log and the best parameters' simulation of it.
struct LogFiles {
  std::string name;            // the log's stem
  std::string set;             // "training" | "validation"
  std::string measured_path;   // empty when unknown (no inputs.json)
  std::string simulated_path;  // empty when the fit wrote none (no finished generation)
};

struct RunRecord {
  std::string dir;      // as given
  std::string fit_dir;  // the fit the report shows: `dir`, or a loop's final fit; "" for none
  // The fit's files, null when absent.
  nlohmann::json run, inputs, best, summary;
  std::vector<GenerationRow> generations;
  std::vector<LogFiles> logs;
  std::string residuals_dir;  // fit_dir/residuals when it has residuals.md, else ""
  std::string residuals_markdown;
  // A loop's files (dir/loop.json, dir/report.md), null/empty for a plain fit.
  nlohmann::json loop;
  std::string loop_markdown;
  std::vector<std::string> notes;  // optional things that are missing, for the page
};

// Reads `dir`. Throws InputError(dir, 0, "", ...) when it is no fit or loop run dir (none of
// run.json, summary.json, loop.json), and InputError naming the file (and the line, for
// generations.csv) when a file that is there cannot be parsed.
RunRecord read_run_dir(const std::string& dir);

// The rows of a generations.csv (header generation,evaluations,best,median,mean_sigma,seconds;
// "inf" and "nan" read as such). Throws InputError(path, line, column, ...) for a bad row.
std::vector<GenerationRow> read_generations_csv(const std::string& path);

}  // namespace motoflex::report
