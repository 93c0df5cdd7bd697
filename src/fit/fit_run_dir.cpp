#include "fit_run_dir.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_inputs.hpp"
#include "motoflex_es/checkpoint.hpp"
#include "motoflex_es/cma_es.hpp"
#include "motoflex_es/mu_plus_lambda.hpp"

namespace motoflex::detail {
namespace {

namespace fs = std::filesystem;

const char* kCsvHeader = "generation,evaluations,best,median,mean_sigma,seconds\n";

std::string format_double(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

void truncate_generations_csv(const fs::path& path, std::uint64_t generation) {
  std::ifstream in(path);
  std::string line, kept = kCsvHeader;
  std::getline(in, line);  // header
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    std::uint64_t row_generation = 0;
    const std::size_t comma = std::min(line.find(','), line.size());
    const auto [end, ec] = std::from_chars(line.data(), line.data() + comma, row_generation);
    if (ec != std::errc() || end != line.data() + comma) {
      throw InputError(path.string(), number, "generation",
                       "not a generation number: '" + line.substr(0, comma) + "'");
    }
    if (row_generation <= generation) kept += line + "\n";
  }
  write_file_atomically(path.string(), kept);
}

}  // namespace

RunDir::RunDir(const FitConfig& config) : config_(config), dir_(config.out_dir) {}

void RunDir::take_lock() {
  lock_ = std::make_unique<FolderLock>(dir_);  // creates the folder
  if (const int removed = remove_stale_temp_files(dir_)) {
    std::fprintf(stderr, "motoflex: %s: removed %d temporary file(s) of an interrupted run\n",
                 dir_.c_str(), removed);
  }
}

RunDirState RunDir::start() {
  const fs::path dir = dir_;
  // The lock first: a second writer learns the running one's PID whatever the folder holds.
  take_lock();
  if (fs::exists(dir / "checkpoint.json")) {
    throw InputError(dir.string(), 0, "out",
                     "already holds a fit; continue it with `motoflex resume " + dir.string() +
                         "` or choose another --out");
  }
  write_file_atomically((dir / "generations.csv").string(), kCsvHeader);
  return {};
}

RunDirState RunDir::resume(motoflex_es::Strategy& strategy, FitProblem& problem) {
  take_lock();
  const fs::path checkpoint_path = fs::path(dir_) / "checkpoint.json";
  if (fs::is_directory(checkpoint_path)) {
    throw InputError(checkpoint_path.string(), 0, "", "is a folder, not a checkpoint file");
  }
  if (!fs::exists(checkpoint_path)) {
    throw InputError(dir_, 0, "checkpoint.json",
                     "missing: the fit stopped before its first checkpoint; start it again with "
                     "`motoflex fit " +
                         config_.path + " --out " + dir_ + "`");
  }
  if (!fs::exists(fs::path(dir_) / "generations.csv")) {
    std::fprintf(stderr,
                 "motoflex: %s: generations.csv: missing; the generations before the checkpoint "
                 "are not in the new one\n",
                 dir_.c_str());
  }
  motoflex_es::Checkpoint checkpoint;
  try {
    checkpoint = motoflex_es::read_checkpoint(checkpoint_path.string(), config_.hash);
    strategy.load_state(checkpoint.strategy_state);
  } catch (const motoflex_es::CheckpointError& error) {
    // The es library's message starts with the path already; print it once.
    std::string message = error.what();
    const std::string prefix = checkpoint_path.string() + ": ";
    if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
    throw InputError(checkpoint_path.string(), 0, "", message);
  }
  const auto& extra = checkpoint.extra;
  problem.set_counters(extra.value("stopped_early", std::uint64_t{0}),
                       extra.value("frames_simulated", std::uint64_t{0}),
                       extra.value("frames_saved", std::uint64_t{0}),
                       extra.value("invalid_candidates", std::uint64_t{0}),
                       extra.value("invalid_reasons", std::vector<std::string>{}));
  RunDirState state;
  state.seconds_before = extra.value("seconds", 0.0);
  state.main_done = extra.value("main_done", false);
  state.converged = extra.value("converged", false);
  state.convergence = extra.value("convergence", std::string());
  if (extra.contains("stall_anchor_fitness") && extra["stall_anchor_fitness"].is_number()) {
    state.stall_anchor_fitness = extra["stall_anchor_fitness"].get<double>();
    state.stall_anchor_evaluations = extra.value("stall_anchor_evaluations", std::uint64_t{0});
  }
  truncate_generations_csv(fs::path(dir_) / "generations.csv", strategy.generation());
  return state;
}

void RunDir::write_run_json() const {
  nlohmann::ordered_json run;
  run["fit"] = config_.path;
  run["overrides"] = config_.overrides;
  run["config_hash"] = config_.hash;
  run["identity"] = config_.identity;
  write_file_atomically((fs::path(dir_) / "run.json").string(), run.dump(2) + "\n");
  // What a report of the run needs besides its results: the measured logs, units and bounds.
  write_file_atomically((fs::path(dir_) / "inputs.json").string(),
                        fit_inputs_json(config_).dump(2) + "\n");
}

void RunDir::append_generation(const motoflex_es::GenerationReport& report, double sigma,
                               double seconds) const {
  std::ofstream csv(fs::path(dir_) / "generations.csv", std::ios::app);
  csv << report.generation << ',' << report.evaluations << ',' << format_double(report.best_fitness)
      << ',' << format_double(report.batch_median) << ',' << format_double(sigma) << ','
      << format_double(seconds) << '\n';
  csv.flush();
  if (!csv) {
    throw IoError((fs::path(dir_) / "generations.csv").string(), 0, "",
                  std::string("cannot append a row: ") + std::strerror(errno));
  }
}

void RunDir::write_checkpoint(const motoflex_es::Strategy& strategy, const FitProblem& problem,
                              const RunDirState& state, double seconds) const {
  motoflex_es::Checkpoint checkpoint;
  checkpoint.config_hash = config_.hash;
  checkpoint.strategy_state = strategy.save_state();
  checkpoint.extra = {{"stopped_early", problem.stopped_early()},
                      {"frames_simulated", problem.frames_simulated()},
                      {"frames_saved", problem.frames_saved()},
                      {"invalid_candidates", problem.invalid_candidates()},
                      {"invalid_reasons", problem.invalid_reasons()},
                      {"seconds", seconds},
                      {"main_done", state.main_done}};
  // JSON has no infinity: the anchor is written once a generation has set it.
  if (std::isfinite(state.stall_anchor_fitness)) {
    checkpoint.extra["stall_anchor_fitness"] = state.stall_anchor_fitness;
    checkpoint.extra["stall_anchor_evaluations"] = state.stall_anchor_evaluations;
  }
  if (state.main_done) {
    checkpoint.extra["converged"] = state.converged;
    checkpoint.extra["convergence"] = state.convergence;
  }
  motoflex_es::write_checkpoint((fs::path(dir_) / "checkpoint.json").string(), checkpoint);
}

double mean_sigma(const motoflex_es::Strategy& strategy) {
  if (const auto* es = dynamic_cast<const motoflex_es::MuPlusLambda*>(&strategy)) {
    double sum = 0.0;
    std::size_t count = 0;
    for (const auto& individual : es->population()) {
      for (std::size_t i = 0; i < individual.step.size(); ++i) {
        sum += individual.step[i] / strategy.bounds().width(i);
        ++count;
      }
    }
    return count == 0 ? 0.0 : sum / count;
  }
  if (const auto* cma = dynamic_cast<const motoflex_es::CmaEs*>(&strategy)) return cma->sigma();
  return 0.0;
}

}  // namespace motoflex::detail
