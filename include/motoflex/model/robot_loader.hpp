#pragma once

#include <optional>
#include <string>
#include <vector>

#include "motoflex/core/error_collector.hpp"
#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// Loads `<robot_dir>/robot.yaml` and the URDF it names into an immutable RobotModel: links
// welded by fixed or held joints (and massless frame links welded to them) become one body,
// declared hinge pairs become universal joints (if enabled), flexible links are split into
// sub-bodies, collision meshes become convex hulls or trimeshes. Throws InputError naming file,
// line and field (InputErrors: every problem of both files at once). The parameter names are
// checked against the servo laws one layer up (load_robot in
// motoflex/sim/robot_parameter_check.hpp); call that one.
RobotModel load_robot_model(const std::string& robot_dir, const StructureOptions& structure);

// The same, with every problem added to `errors` instead of thrown. Returns the model built
// from what could be read (entries with problems left out), or nullopt when robot.yaml or the
// URDF cannot be read at all.
std::optional<RobotModel> load_robot_model(const std::string& robot_dir,
                                           const StructureOptions& structure,
                                           ErrorCollector& errors);

}  // namespace motoflex
