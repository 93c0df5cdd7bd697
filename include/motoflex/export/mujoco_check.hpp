#pragma once

#include <string>
#include <vector>

#include "motoflex/export/export_input.hpp"
#include "motoflex/motion/command_trajectory.hpp"

namespace motoflex {

struct MujocoCheckOptions {
  double settle_s = 0.0;    // both simulators hold the first commanded pose this long first
  bool hold_torso = false;  // motoflex: RolloutOptions::hold_torso; MuJoCo: root welded there
  int gear_substeps = 100;  // motoflex servo: gear sub-steps per physics step
  bool armature = true;     // MjcfOptions::armature
  int flex_sub_bodies = 1;  // for the report only: the model's structure
};

struct MujocoComparison {
  std::vector<std::string> joints;        // actuated joints, model order
  std::vector<double> rms_deg_per_joint;  // RMS of MuJoCo − motoflex joint angle, degrees
  double rms_deg = 0.0;                   // over all joints and steps
  double max_abs_deg = 0.0;               // largest single difference
  std::size_t steps = 0;                  // physics steps compared (settling excluded)
  double mujoco_steps_per_s = 0.0;        // wall-clock rate of mj_step (one thread)
  double motoflex_steps_per_s = 0.0;      // wall-clock rate of Rollout::step (one thread)
  // The same replay with dWorldQuickStep (reproducible: its own seed per rollout): its rate and
  // its RMS against MuJoCo, so a user sees both ODE solvers beside MuJoCo's.
  double motoflex_quick_steps_per_s = 0.0;
  double rms_deg_quick = 0.0;
  // And with motoflex's own solver for dWorldStep's LCP (solver `sparse`): its rate, its RMS
  // against MuJoCo, and its RMS against the dWorldStep replay (the same LCP up to rounding, so
  // the difference is what rounding grows into over the replay).
  double motoflex_sparse_steps_per_s = 0.0;
  double rms_deg_sparse = 0.0;
  double rms_deg_sparse_vs_step = 0.0;
  std::string motoflex_end;  // how the motoflex rollout ended ("completed", ...)
  std::string mujoco_version;
  std::size_t geoms = 0;         // geoms of the exported model (collision, visual, floor)
  std::size_t visual_geoms = 0;  // of those, the visual ones (group 1: what a viewer shows)
};

// Simulates the same commanded trajectory in motoflex (ODE, input.servo, dWorldStep) and in
// MuJoCo on export_mjcf(input) and compares the true joint angles after every physics step
// (time step input.dt_s in both). The MuJoCo controller sets each position actuator's ctrl to
// the commanded angle at the start of the step (the angle at its end for the ideal servo), the
// same samples motoflex's servos receive (linear interpolation of the log). A held torso is
// compared with the root welded where motoflex holds it (0.1 m foot clearance); a standing
// robot's contacts differ between the engines. Throws ModelError if either simulator cannot
// build the model and InputError if the trajectory does not match the robot.
MujocoComparison compare_with_mujoco(const ExportInput& input, const CommandTrajectory& commands,
                                     const MujocoCheckOptions& options);

}  // namespace motoflex
