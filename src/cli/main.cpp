// motoflex: one binary, `motoflex <command>`. Bad input prints one line
// "motoflex: <file>:<line>: <field>: <message>" and exits with code 2; exit codes are those of
// motoflex::exit_code (README, "Exit codes").

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "commands.hpp"
#include "motoflex/core/build_info.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/error_collector.hpp"

int main(int argc, char** argv) {
  CLI::App app{"motoflex: make robot simulations match real robots (MoToFlex on ODE)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("motoflex ") + motoflex::version());
  std::map<std::string, motoflex::cli::CommandRunner> runners;
  runners["simulate"] = motoflex::cli::add_simulate_command(app);
  runners["record"] = motoflex::cli::add_record_command(app);
  runners["bench"] = motoflex::cli::add_bench_command(app);
  runners["fit"] = motoflex::cli::add_fit_command(app);
  runners["resume"] = motoflex::cli::add_resume_command(app);
  runners["import-bam"] = motoflex::cli::add_import_bam_command(app);
  runners["calibrate-bam"] = motoflex::cli::add_calibrate_bam_command(app);
  runners["import-motoflex"] = motoflex::cli::add_import_motoflex_command(app);
  runners["experiment"] = motoflex::cli::add_experiment_command(app);
  runners["titan"] = motoflex::cli::add_titan_command(app);
  runners["export"] = motoflex::cli::add_export_command(app);
  runners["residuals"] = motoflex::cli::add_residuals_command(app);
  runners["loop"] = motoflex::cli::add_loop_command(app);
  runners["init-robot"] = motoflex::cli::add_init_robot_command(app);
  runners["check-robot"] = motoflex::cli::add_check_robot_command(app);
  runners["report"] = motoflex::cli::add_report_command(app);
  runners["spread"] = motoflex::cli::add_spread_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == 0) return app.exit(error);  // --help, --version
    // One line, as every other error: "motoflex: --threads: Value 0 not in range ...".
    std::string text = error.what();
    for (char& c : text) c = c == '\n' ? ' ' : c;
    std::fprintf(stderr, "motoflex: %s (see motoflex --help)\n", text.c_str());
    return motoflex::exit_code::kBadInput;
  }
  try {
    for (const auto* sub : app.get_subcommands()) return runners.at(sub->get_name())();
  } catch (const motoflex::InputErrors& errors) {
    for (const auto& error : errors.errors()) std::fprintf(stderr, "motoflex: %s\n", error.what());
    return motoflex::exit_code::kBadInput;
  } catch (const motoflex::IoError& error) {
    std::fprintf(stderr, "motoflex: %s\n", error.what());
    return motoflex::exit_code::kIo;
  } catch (const motoflex::InputError& error) {
    std::fprintf(stderr, "motoflex: %s\n", error.what());
    return motoflex::exit_code::kBadInput;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "motoflex: out of memory (an input too large for this machine?)\n");
    return motoflex::exit_code::kIo;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "motoflex: error: %s\n", error.what());
    return motoflex::exit_code::kInternal;
  }
  return motoflex::exit_code::kOk;
}
