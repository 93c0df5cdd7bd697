// motoflex import-bam <file.json|DIR> --out OUT_DIR
// Turns BAM pendulum-bench logs (shared/data/bam) into joint logs of the servo_pendulum robot:
// one CSV + sidecar YAML per trajectory log. A folder is searched recursively; files that are
// not trajectory logs are listed with the reason they were skipped.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "commands.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/bam_import.hpp"
#include "motoflex/io/joint_log.hpp"

namespace motoflex::cli {
namespace {

namespace fs = std::filesystem;

struct ImportBamArgs {
  std::string input;
  std::string out;
};

double mean_abs_goal_error_rad(const JointLog& log) {
  double sum = 0.0;
  for (std::size_t f = 0; f < log.frames(); ++f) {
    sum += std::abs(log.commanded(f, 0) - log.measured(f, 0));
  }
  return sum / static_cast<double>(log.frames());
}

void write_and_report(const BamImport& imported, const std::string& source,
                      const fs::path& csv_path) {
  write_joint_log(csv_path.string(), imported.log);
  const JointLog& log = imported.log;
  std::printf("imported %s -> %s: %zu samples, t %.6f..%.6f s, mean |goal-pos| %.6f rad",
              source.c_str(), csv_path.string().c_str(), log.frames(), log.time_s.front(),
              log.time_s.back(), mean_abs_goal_error_rad(log));
  if (imported.torque_off_s) std::printf(", torque off at %.6f s", *imported.torque_off_s);
  std::printf("\n");
}

int run(const ImportBamArgs& args) {
  std::error_code error;
  if (!fs::exists(args.input, error)) throw InputError(args.input, 0, "", "no such file or folder");
  const fs::path out_dir(args.out);
  // Called once the input has been read and checked, so a bad input leaves no empty folder.
  const auto make_out_dir = [&] {
    fs::create_directories(out_dir, error);
    if (error) throw InputError(args.out, 0, "--out", "cannot create folder: " + error.message());
  };

  if (!fs::is_directory(args.input)) {
    const BamImport imported = import_bam_file(args.input, args.input);
    make_out_dir();
    const std::string stem = fs::path(args.input).stem().string();
    write_and_report(imported, args.input, out_dir / (stem + ".csv"));
    return 0;
  }

  // Everything is read and checked before the first file is written.
  const std::vector<BamDirectoryItem> items = import_bam_directory(args.input);
  std::size_t imported = 0;
  for (const BamDirectoryItem& item : items) {
    if (item.import) ++imported;
  }
  if (imported == 0) {
    throw InputError(args.input, 0, "", "no BAM trajectory logs below this folder");
  }
  make_out_dir();
  for (const BamDirectoryItem& item : items) {
    if (item.import) {
      write_and_report(*item.import, item.relative_path, out_dir / (item.output_stem + ".csv"));
    } else {
      std::printf("skipped %s: %s\n", item.relative_path.c_str(), item.skip_reason.c_str());
    }
  }
  std::printf("imported %zu trajectory logs into %s, skipped %zu files\n", imported,
              out_dir.string().c_str(), items.size() - imported);
  return 0;
}

}  // namespace

CommandRunner add_import_bam_command(CLI::App& app) {
  auto args = std::make_shared<ImportBamArgs>();
  CLI::App* sub =
      app.add_subcommand("import-bam", "convert BAM pendulum-bench logs into joint logs");
  sub->add_option("input", args->input, "a BAM trajectory log (.json) or a folder of them")
      ->required();
  sub->add_option("--out", args->out, "output folder (CSV + sidecar YAML per log)")->required();
  return [args] { return run(*args); };
}

}  // namespace motoflex::cli
