#include "motoflex/robot_setup/robot_init.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <map>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/number_text.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/robot_setup/robot_folder_tools.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "motoflex/sim/robot_parameter_defaults.hpp"
#include "robot_joint_plan.hpp"
#include "robot_yaml_writer.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

std::string default_servo() {
  return find_servo_law(kDefaultInitServo) != nullptr ? kDefaultInitServo : "velocity";
}

// The URDF as robot.yaml should name it: relative to the folder when they share a root.
std::string urdf_reference(const fs::path& urdf, const fs::path& out_dir) {
  const fs::path folder = fs::absolute(out_dir).lexically_normal();
  const fs::path relative = urdf.lexically_relative(folder);
  // Only when they share more than the root folder (a folder moved with its URDF keeps
  // working); otherwise the absolute path.
  const bool share = *std::next(urdf.begin()) == *std::next(folder.begin());
  return relative.empty() || !share ? urdf.string() : relative.string();
}

// Welded or floating, and why.
bool guess_fixed_base(const UrdfTree& tree, const RobotModel& draft,
                      const std::vector<double>& pose, std::vector<Assumption>& assumptions) {
  for (const UrdfJoint& joint : tree.joints) {
    if (joint.type == UrdfJointType::kFloating) {
      assumptions.push_back(
          {"base", "floating", "the URDF's root joint '" + joint.name + "' floats"});
      return false;
    }
  }
  const std::vector<std::string> lowest = lowest_leaf_links(tree, draft, pose, true);
  if (lowest.size() >= 2) {
    assumptions.push_back({"base", "floating",
                           std::to_string(lowest.size()) +
                               " leaf links share the lowest height: it stands on them "
                               "(--fixed-base if it is mounted)"});
    return false;
  }
  assumptions.push_back({"base", "fixed (welded, no ground)",
                         "fewer than two leaf links share the lowest height: an arm or a bench "
                         "(--floating-base if it walks)"});
  return true;
}

RobotModel load_draft(const std::string& yaml_path, const std::string& out_dir,
                      const detail::RobotFolderSpec& spec) {
  write_file_atomically(yaml_path, detail::robot_yaml_text(spec));
  return load_robot_model(out_dir, StructureOptions{});
}

}  // namespace

RobotInitResult init_robot(const RobotInitOptions& options) {
  const fs::path urdf = fs::absolute(options.urdf_path).lexically_normal();
  ErrorCollector errors;
  const UrdfTree tree = read_urdf_tree(urdf.string(), errors);
  errors.throw_if_any();

  RobotInitResult result;
  const detail::JointPlan plan = detail::plan_joints(tree, result.assumptions);
  if (plan.actuated.empty()) {
    throw InputError(urdf.string(), 0, "", "no revolute, continuous or prismatic joint to actuate");
  }
  detail::RobotFolderSpec spec;
  spec.header = "Written by `motoflex init-robot` from " + urdf.string() +
                ".\nEvery assumption it made was printed; the sources of the parameter values "
                "are\nin the comments. Edit freely (format: scenarios/robots/README.md).";
  spec.name = tree.robot_name.empty() ? urdf.stem().string() : tree.robot_name;
  spec.urdf = urdf_reference(urdf, options.out_dir);
  spec.base_link = tree.links[tree.root_link].name;
  spec.servo = options.servo.empty() ? default_servo() : options.servo;
  if (find_servo_law(spec.servo) == nullptr) {
    throw InputError("", 0, "--servo",
                     "unknown servo '" + spec.servo + "' (" + servo_law_names() + ")");
  }
  if (options.servo.empty()) {
    result.assumptions.push_back({"servo", spec.servo, "default law (--servo to choose)"});
  }
  if (!servo_law(spec.servo).drives_prismatic) {
    std::string slider_law;
    for (const ServoLawInfo& law : servo_laws()) {
      if (law.drives_prismatic && slider_law.empty()) slider_law = law.name;
    }
    for (const std::string& joint : plan.actuated) {
      if (tree.joints[tree.joint_index(joint)].type != UrdfJointType::kPrismatic) continue;
      spec.servos.emplace_back(joint, slider_law);
      result.assumptions.push_back({joint + " servo", slider_law,
                                    "prismatic: '" + spec.servo + "' drives revolute joints only"});
    }
  }
  spec.actuated = plan.actuated;
  spec.held = plan.held;
  spec.universal_pairs = plan.universal_pairs;
  spec.joint_limits = plan.joint_limits;
  spec.stand_pose = plan.stand_pose;

  fs::create_directories(options.out_dir);
  result.robot_yaml = (fs::path(options.out_dir) / "robot.yaml").string();
  const RobotModel draft = load_draft(result.robot_yaml, options.out_dir, spec);
  const std::vector<double> pose = draft.stand_pose_vector();
  spec.fixed_base = options.fixed_base ? *options.fixed_base
                                       : guess_fixed_base(tree, draft, pose, result.assumptions);
  spec.ground = !spec.fixed_base;
  if (!spec.fixed_base) {
    spec.feet = lowest_leaf_links(tree, draft, pose);
    std::string feet;
    for (const auto& foot : spec.feet) feet += (feet.empty() ? "" : ", ") + foot;
    result.assumptions.push_back({"feet", feet.empty() ? "none" : feet,
                                  feet.empty() ? "no link has collision geometry"
                                               : "the lowest leaf links with collision geometry"});
  }

  const RobotModel placed = load_draft(result.robot_yaml, options.out_dir, spec);
  std::vector<JointHints> hints;
  for (const ActuatorSpec& a : placed.actuators) hints.push_back(plan.hints.at(a.name));
  for (ParameterDefault& p : robot_parameter_defaults(placed, "", hints)) {
    if (p.source == "neutral (model effect)") continue;  // the loader adds these itself
    if (p.source == kNoDefault) {
      result.assumptions.push_back({p.name, "[0, 0, 1]", "no documented default: set it by hand"});
    }
    spec.parameters.push_back(std::move(p));
  }
  write_file_atomically(result.robot_yaml, detail::robot_yaml_text(spec));
  const RobotModel model = load_robot(options.out_dir, StructureOptions{});
  result.check = hold_stand_pose(model, options.check_duration_s);
  return result;
}

std::string assumptions_table(const std::vector<Assumption>& assumptions) {
  std::size_t subject_width = 10, choice_width = 6;
  for (const Assumption& a : assumptions) {
    subject_width = std::max(subject_width, a.subject.size());
    choice_width = std::max(choice_width, a.choice.size());
  }
  const auto row = [&](const std::string& subject, const std::string& choice,
                       const std::string& reason) {
    return subject + std::string(subject_width - subject.size() + 2, ' ') + choice +
           std::string(choice_width - choice.size() + 2, ' ') + reason + "\n";
  };
  std::string out = row("assumption", "choice", "why");
  for (const Assumption& a : assumptions) out += row(a.subject, a.choice, a.reason);
  return out;
}

}  // namespace motoflex
