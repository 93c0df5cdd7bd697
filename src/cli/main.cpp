// motoflex: one binary, `motoflex <command>`. Bad input prints one line
// "motoflex: <file>:<line>: <field>: <message>" and exits with code 2.

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
  runners["import-motoflex"] = motoflex::cli::add_import_motoflex_command(app);
  runners["experiment"] = motoflex::cli::add_experiment_command(app);
  runners["titan"] = motoflex::cli::add_titan_command(app);
  runners["export"] = motoflex::cli::add_export_command(app);
  runners["residuals"] = motoflex::cli::add_residuals_command(app);
  runners["loop"] = motoflex::cli::add_loop_command(app);
  runners["init-robot"] = motoflex::cli::add_init_robot_command(app);
  runners["check-robot"] = motoflex::cli::add_check_robot_command(app);
  runners["report"] = motoflex::cli::add_report_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }
  try {
    for (const auto* sub : app.get_subcommands()) return runners.at(sub->get_name())();
  } catch (const motoflex::InputErrors& errors) {
    for (const auto& error : errors.errors()) std::fprintf(stderr, "motoflex: %s\n", error.what());
    return 2;
  } catch (const motoflex::InputError& error) {
    std::fprintf(stderr, "motoflex: %s\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "motoflex: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
