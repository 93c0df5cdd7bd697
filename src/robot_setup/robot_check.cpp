#include "motoflex/robot_setup/robot_check.hpp"

#include <filesystem>

#include "motoflex/core/error_collector.hpp"
#include "motoflex/core/number_text.hpp"
#include "motoflex/robot_setup/robot_folder_tools.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"

namespace motoflex {

RobotCheckReport check_robot_folder(const std::string& robot_dir, double duration_s) {
  RobotCheckReport report;
  ErrorCollector errors;
  const std::optional<RobotModel> model = load_robot(robot_dir, StructureOptions{}, errors);
  if (!errors.empty() || !model) {
    report.problems = errors.errors();
    return report;
  }
  report.summary = describe_robot(*model);
  const RolloutResult held = hold_stand_pose(*model, duration_s);
  const std::string what = "stand pose held " + number_text(duration_s) + " s" +
                           (model->fixed_base ? "" : " (base held 0.1 m above the ground)");
  if (held.end != RolloutEnd::kCompleted) {
    report.problems.emplace_back(model->source.yaml_path, 0, "simulation",
                                 what + ": " + to_string(held.end) + " at " +
                                     number_text(held.end_time_s) + " s: " + held.end_detail);
  }
  report.summary.push_back(what + ": " + to_string(held.end));
  return report;
}

}  // namespace motoflex
