#pragma once

#include <Eigen/Core>
#include <vector>

#include "motoflex/motion/nao_walk.hpp"

namespace motoflex::detail {

// One step of a straight walk: a double-support phase in which the reference ZMP moves from
// the previous support foot to this one, then single support while the other foot swings.
struct NaoFootstep {
  bool support_left = true;
  double start_s = 0.0;       // the step's double-support transfer begins
  double swing_from_x = 0.0;  // swing foot before and after the step
  double swing_to_x = 0.0;
  Eigen::Vector2d zmp_m = Eigen::Vector2d::Zero();  // reference ZMP when single support begins
  double zmp_travel_m = 0.0;                        // ... rolling this far forward until its end

  Eigen::Vector2d zmp_end() const { return zmp_m + Eigen::Vector2d(zmp_travel_m, 0.0); }
};

// Footstep planner for straight walking (timing: NaoWalkParams): the first step puts the swing
// foot half a step length ahead of the parallel stance (the CoM starts from rest and lags
// behind; a full first step would have to reach ahead of it), every further step one step length
// ahead of the support foot, and the closing step brings it beside the support foot. World
// frame: origin on the ground midway between the ankles at the start.
class NaoFootsteps {
 public:
  NaoFootsteps(const NaoWalkParams& params, double step_length_m);

  double step_s() const { return step_s_; }
  double walk_end_s() const { return steps_.back().start_s + step_s_; }
  const std::vector<NaoFootstep>& steps() const { return steps_; }

  // Reference ZMP at t: standing in the middle, moved linearly to the support foot in each
  // double support, rolling heel to toe in single support, back to the middle at the end.
  Eigen::Vector2d zmp_ref(double t) const;

  // Sole points of both feet (flat) and the support state at t. The swing foot follows a
  // quintic smoothstep forward and lifts to `step_height_m` and back down with zero vertical
  // speed at lift-off and touch-down.
  void feet(double t, double step_height_m, Eigen::Vector3d& left, Eigen::Vector3d& right,
            NaoSupport& support) const;

 private:
  // Index of the step running at t, −1 before the first, steps.size() after the last.
  int step_at(double t) const;

  double step_s_ = 0.0, double_support_s_ = 0.0, single_support_s_ = 0.0;
  double half_spacing_m_ = 0.0;
  Eigen::Vector2d stand_zmp_start_m_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d stand_zmp_end_m_ = Eigen::Vector2d::Zero();
  double end_transfer_s_ = 0.0;
  std::vector<NaoFootstep> steps_;
};

}  // namespace motoflex::detail
