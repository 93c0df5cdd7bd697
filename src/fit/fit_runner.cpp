#include "motoflex/fit/fit_runner.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/build_info.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_inputs.hpp"
#include "motoflex/fit/fit_report.hpp"
#include "motoflex/io/plot_script.hpp"
#include "motoflex_es/checkpoint.hpp"
#include "motoflex_es/cma_es.hpp"
#include "motoflex_es/driver.hpp"
#include "motoflex_es/mu_plus_lambda.hpp"
#include "motoflex_es/nlopt_optimizer.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

// The one piece of process-global mutable state: a signal handler may only set a flag.
volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void request_stop(int signal) {
  g_stop_signal = signal;
}

std::string format_double(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// Mean step size relative to the bound widths (μ+λ: over the population; CMA-ES: σ).
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

const char* kCsvHeader = "generation,evaluations,best,median,mean_sigma,seconds\n";

// Keeps the rows of generations <= `generation` (a kill between the CSV row and the
// checkpoint leaves one row too many).
void truncate_generations_csv(const fs::path& path, std::uint64_t generation) {
  std::ifstream in(path);
  std::string line, kept = kCsvHeader;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (std::stoull(line.substr(0, line.find(','))) <= generation) kept += line + "\n";
  }
  write_file_atomically(path.string(), kept);
}

struct RunState {
  double seconds_before = 0.0;  // wall time of earlier sessions of this run
  bool main_done = false;       // the main strategy finished (the polish may follow)
};

nlohmann::json counters_json(const FitProblem& problem, const RunState& state, double seconds) {
  return {{"stopped_early", problem.stopped_early()},
          {"frames_simulated", problem.frames_simulated()},
          {"frames_saved", problem.frames_saved()},
          {"seconds", seconds},
          {"main_done", state.main_done}};
}

std::string now_iso8601() {
  const std::time_t t = std::time(nullptr);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buffer;
}

void write_outputs(const FitConfig& config, const motoflex_es::Strategy& strategy,
                   const FitProblem& problem, const std::string& stop_reason, double seconds,
                   const std::string& evaluator) {
  const fs::path dir = config.out_dir;
  const std::vector<double>& x = strategy.best_x();
  if (x.empty()) return;
  const ParameterSet best = config.space->apply(x);

  nlohmann::ordered_json best_json;
  best_json["fitness"] = strategy.best_fitness();
  nlohmann::ordered_json free = nlohmann::ordered_json::object();
  for (const auto& [name, value] : config.space->values(x)) free[name] = value;
  best_json["free"] = free;
  best_json["parameters"] = nlohmann::ordered_json::parse(parameter_set_to_json(best));
  best_json["provenance"] = {{"fit", config.path},
                             {"config_hash", config.hash},
                             {"robot", config.scenario->model->name},
                             {"date", now_iso8601()},
                             {"motoflex_version", version()}};
  write_file_atomically((dir / "best.json").string(), best_json.dump(2) + "\n");

  const DetailedEvaluation train = evaluate_in_detail(*config.train, best);
  nlohmann::ordered_json summary;
  summary["name"] = config.name;
  summary["best_fitness"] = strategy.best_fitness();
  summary["evaluations"] = strategy.evaluations();
  summary["generations"] = strategy.generation();
  summary["stop_reason"] = stop_reason;
  summary["seconds"] = seconds;
  summary["strategy"] = strategy.name();
  summary["evaluator"] = evaluator;  // e.g. "openmp(2 threads)", "mpi(2 ranks x 1 thread)"
  summary["rms_deg"] = rms_json(*config.train, train);
  summary["robots"] = cases_json(*config.train, train);
  summary["free"] = free;
  if (config.validation) {
    const DetailedEvaluation validation = evaluate_in_detail(*config.validation, best);
    summary["validation"] = {{"fitness", validation.breakdown.fitness},
                             {"rms_deg", rms_json(*config.validation, validation)},
                             {"robots", cases_json(*config.validation, validation)}};
    write_simulated_logs((dir / "best" / "validation").string(), *config.validation, validation,
                         "motoflex fit " + config.name + " (best, validation)");
  }
  summary["early_termination"] = {{"individuals_stopped_early", problem.stopped_early()},
                                  {"frames_simulated", problem.frames_simulated()},
                                  {"frames_saved", problem.frames_saved()}};
  summary["config_hash"] = config.hash;
  write_file_atomically((dir / "summary.json").string(), summary.dump(2) + "\n");
  write_simulated_logs((dir / "best").string(), *config.train, train,
                       "motoflex fit " + config.name + " (best)");

  std::vector<std::string> arguments = {dir.string()};
  for (const auto& log : config.train_logs) arguments.push_back(log);
  run_plot_script("plot_fit.py", arguments);
}

}  // namespace

int run_fit(const FitConfig& config, bool resume, motoflex_es::Evaluator* evaluator) {
  const fs::path dir = config.out_dir;
  const fs::path checkpoint_path = dir / "checkpoint.json";
  const fs::path csv_path = dir / "generations.csv";
  auto strategy = make_strategy(config);
  FitProblem problem(config);
  RunState state;

  if (resume) {
    motoflex_es::Checkpoint checkpoint;
    try {
      checkpoint = motoflex_es::read_checkpoint(checkpoint_path.string(), config.hash);
      strategy->load_state(checkpoint.strategy_state);
    } catch (const motoflex_es::CheckpointError& error) {
      throw InputError(checkpoint_path.string(), 0, "", error.what());
    }
    const auto& extra = checkpoint.extra;
    problem.set_counters(extra.value("stopped_early", std::uint64_t{0}),
                         extra.value("frames_simulated", std::uint64_t{0}),
                         extra.value("frames_saved", std::uint64_t{0}));
    state.seconds_before = extra.value("seconds", 0.0);
    state.main_done = extra.value("main_done", false);
    truncate_generations_csv(csv_path, strategy->generation());
  } else {
    if (fs::exists(checkpoint_path)) {
      throw InputError(dir.string(), 0, "out",
                       "already holds a fit; continue it with `motoflex resume " + dir.string() +
                           "` or choose another --out");
    }
    std::error_code error;
    fs::create_directories(dir, error);
    if (error) throw InputError(dir.string(), 0, "out", "cannot create: " + error.message());
    write_file_atomically((dir / "generations.csv").string(), kCsvHeader);
  }
  nlohmann::ordered_json run;
  run["fit"] = config.path;
  run["overrides"] = config.overrides;
  run["config_hash"] = config.hash;
  run["identity"] = config.identity;
  write_file_atomically((dir / "run.json").string(), run.dump(2) + "\n");
  write_file_atomically((dir / "inputs.json").string(), fit_inputs_json(config).dump(2) + "\n");

  std::unique_ptr<motoflex_es::Evaluator> own_evaluator;
  if (evaluator == nullptr) {
    if (config.threads > 1) {
      own_evaluator = std::make_unique<motoflex_es::OpenMpEvaluator>(config.threads);
    } else {
      own_evaluator = std::make_unique<motoflex_es::SerialEvaluator>();
    }
    evaluator = own_evaluator.get();
  }

  g_stop_signal = 0;
  auto previous_int = std::signal(SIGINT, request_stop);
  auto previous_term = std::signal(SIGTERM, request_stop);
  const auto start = std::chrono::steady_clock::now();
  auto seconds_now = [&] {
    return state.seconds_before +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };

  std::string stop_reason;
  if (!state.main_done) {
    motoflex_es::Budget budget;
    budget.max_generations = config.budget.max_generations;
    budget.max_evaluations = config.budget.max_evaluations;
    budget.max_seconds = config.budget.max_seconds;
    motoflex_es::RunCallbacks callbacks;
    callbacks.on_generation = [&](const motoflex_es::Strategy& s,
                                  const motoflex_es::GenerationReport& report) {
      const double seconds = seconds_now();
      {
        std::ofstream csv(csv_path, std::ios::app);
        csv << report.generation << ',' << report.evaluations << ','
            << format_double(report.best_fitness) << ',' << format_double(report.batch_median)
            << ',' << format_double(mean_sigma(s)) << ',' << format_double(seconds) << '\n';
      }
      motoflex_es::Checkpoint checkpoint;
      checkpoint.config_hash = config.hash;
      checkpoint.strategy_state = s.save_state();
      checkpoint.extra = counters_json(problem, state, seconds);
      motoflex_es::write_checkpoint(checkpoint_path.string(), checkpoint);
      std::printf(
          "gen %4llu  evals %7llu  best %.6g  median %.4g  sigma %.3g  early-stopped %llu  %.1f "
          "s\n",
          static_cast<unsigned long long>(report.generation),
          static_cast<unsigned long long>(report.evaluations), report.best_fitness,
          report.batch_median, mean_sigma(s),
          static_cast<unsigned long long>(problem.stopped_early()), seconds);
      std::fflush(stdout);
      return g_stop_signal == 0;
    };
    const motoflex_es::RunSummary summary =
        motoflex_es::run_optimisation(*strategy, problem, *evaluator, budget, callbacks);
    stop_reason = g_stop_signal != 0 ? std::string("interrupted")
                                     : std::string(motoflex_es::to_string(summary.reason));
    if (summary.reason == motoflex_es::RunStopReason::kStrategy) {
      stop_reason = std::string("strategy: ") + motoflex_es::to_string(strategy->stop_reason());
      if (!strategy->stop_detail().empty()) stop_reason += " (" + strategy->stop_detail() + ")";
    }
    // Only a strategy that stopped by itself is finished; a budget stop can be resumed with a
    // larger budget.
    if (g_stop_signal == 0 && summary.reason == motoflex_es::RunStopReason::kStrategy) {
      state.main_done = true;
      motoflex_es::Checkpoint checkpoint;
      checkpoint.config_hash = config.hash;
      checkpoint.strategy_state = strategy->save_state();
      checkpoint.extra = counters_json(problem, state, seconds_now());
      motoflex_es::write_checkpoint(checkpoint_path.string(), checkpoint);
    }
  } else {
    stop_reason = "finished before resume";
  }

  // Optional local polish of the best point (NLopt keeps its state inside the library, so a
  // killed polish starts again from the main strategy's best).
  double best_fitness = strategy->best_fitness();
  std::vector<double> best_x = strategy->best_x();
  std::uint64_t polish_evaluations = 0;
  if (g_stop_signal == 0 && !config.strategy.polish.empty() && !best_x.empty()) {
    motoflex_es::NloptOptions options;
    options.algorithm = config.strategy.polish == "sbplx" ? motoflex_es::NloptAlgorithm::kSbplx
                                                          : motoflex_es::NloptAlgorithm::kBobyqa;
    options.start_point = best_x;
    options.initial_step_relative = 0.02;
    options.max_evaluations = config.strategy.polish_evaluations;
    options.seed = config.seed;
    motoflex_es::NloptOptimizer polish(strategy->bounds(), options);
    motoflex_es::SerialEvaluator serial;
    motoflex_es::Budget budget;
    budget.max_evaluations = config.strategy.polish_evaluations;
    const auto result = motoflex_es::run_optimisation(polish, problem, serial, budget);
    polish_evaluations = result.evaluations;
    if (polish.best_fitness() < best_fitness) {
      best_fitness = polish.best_fitness();
      best_x = polish.best_x();
    }
    std::printf("polish (%s): %llu evaluations, best %.6g\n", config.strategy.polish.c_str(),
                static_cast<unsigned long long>(polish_evaluations), best_fitness);
  }
  std::signal(SIGINT, previous_int);
  std::signal(SIGTERM, previous_term);

  // Report the best of main + polish through a strategy-shaped view.
  struct BestView final : motoflex_es::Strategy {
    BestView(const motoflex_es::Strategy& main, std::vector<double> x, double f,
             std::uint64_t extra_evaluations)
        : motoflex_es::Strategy(main.bounds()), main_name(main.name()) {
      best_x_ = std::move(x);
      best_fitness_ = f;
      generation_ = main.generation();
      evaluations_ = main.evaluations() + extra_evaluations;
    }
    std::string name() const override { return main_name; }
    std::vector<std::vector<double>> ask() override { return {}; }
    void tell(const std::vector<double>&) override {}
    std::size_t next_batch_size() const override { return 0; }
    nlohmann::json save_state() const override { return {}; }
    void load_state(const nlohmann::json&) override {}
    std::string main_name;
  } view(*strategy, best_x, best_fitness, polish_evaluations);
  write_outputs(config, view, problem, stop_reason, seconds_now(), evaluator->name());
  if (g_stop_signal != 0) {
    std::printf("interrupted: checkpoint written; continue with `motoflex resume %s`\n",
                dir.c_str());
  } else {
    std::printf("done (%s): best fitness %.6g after %llu evaluations; see %s/summary.json\n",
                stop_reason.c_str(), best_fitness,
                static_cast<unsigned long long>(view.evaluations()), dir.c_str());
  }
  return 0;
}

}  // namespace motoflex
