#pragma once

#include <CLI/CLI.hpp>

namespace motoflex::cli {

// Each command registers its options on `app` and returns the function that runs it; the
// function returns the process exit code.
using CommandRunner = std::function<int()>;

CommandRunner add_simulate_command(CLI::App& app);
CommandRunner add_record_command(CLI::App& app);
CommandRunner add_bench_command(CLI::App& app);
CommandRunner add_fit_command(CLI::App& app);
CommandRunner add_resume_command(CLI::App& app);
CommandRunner add_import_bam_command(CLI::App& app);
CommandRunner add_calibrate_bam_command(CLI::App& app);
CommandRunner add_import_motoflex_command(CLI::App& app);
CommandRunner add_experiment_command(CLI::App& app);
CommandRunner add_titan_command(CLI::App& app);
CommandRunner add_export_command(CLI::App& app);
CommandRunner add_residuals_command(CLI::App& app);
CommandRunner add_loop_command(CLI::App& app);
CommandRunner add_init_robot_command(CLI::App& app);
CommandRunner add_check_robot_command(CLI::App& app);
CommandRunner add_report_command(CLI::App& app);
CommandRunner add_spread_command(CLI::App& app);

}  // namespace motoflex::cli
