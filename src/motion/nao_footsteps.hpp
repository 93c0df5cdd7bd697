#pragma once

#include <Eigen/Core>
#include <vector>

#include "motoflex/motion/nao_walk.hpp"

namespace motoflex::detail {

// Sole outline around the ankle (B-Human robotDimensions, nao.md §1.1; the URDF's collision
// box): back edge, front (toe) edge, inner and outer edge.
inline constexpr double kSoleBack_m = 0.05;
inline constexpr double kSoleFront_m = 0.10;
inline constexpr double kSoleInner_m = 0.03877;
inline constexpr double kSoleOuter_m = 0.05002;
// The heel rises only once the reference ZMP is this far ahead of the toe edge: from then on the
// rear foot carries load on that edge alone.
inline constexpr double kToeOffZmpMargin_m = 0.01;
// A heel rise (toe-off) or roll-down (heel strike) gets its full angle when the double support
// leaves at least this long for it, proportionally less in less time: the foot's pitch rate
// stays bounded and the angle grows continuously with the step length from 0 (flat feet).
inline constexpr double kFullEdgeRoll_s = 0.25;

// One step of a straight walk: a double-support phase in which the reference ZMP moves from
// the previous support foot to this one, then single support while the other foot swings.
struct NaoFootstep {
  bool support_left = true;
  double start_s = 0.0;       // the step's double-support transfer begins
  double swing_from_x = 0.0;  // swing foot before and after the step
  double swing_to_x = 0.0;
  Eigen::Vector2d zmp_m = Eigen::Vector2d::Zero();  // reference ZMP when single support begins
  double zmp_travel_m = 0.0;                        // ... rolling this far forward until its end
  // Toe-off (NaoWalkParams::toe_off_rad): in the double support the swing foot's heel rises
  // from toe_off_start_s after the step's start, pivoting on the toe edge, to lift_off_pitch_rad
  // at lift-off; 0 keeps the foot flat.
  double toe_off_start_s = 0.0;
  double lift_off_pitch_rad = 0.0;
  // Heel strike (NaoWalkParams::heel_strike_rad): the swing foot lands on its heel edge pitched
  // by touch_down_pitch_rad (< 0: toes up; 0 lands flat) and rolls flat about that edge in the
  // next step's double support, flat heel_flat_s after that step's start.
  double touch_down_pitch_rad = 0.0;
  double heel_flat_s = 0.0;

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
  // The full-length steps run from the end of the first (half) step to here: the start of the
  // closing step, or of the half step before it in walks with toe-off.
  double steady_end_s() const { return steady_end_s_; }
  const std::vector<NaoFootstep>& steps() const { return steps_; }

  // Reference ZMP at t: standing in the middle, moved to the support foot in each double
  // support along transfer(), rolling heel to toe in single support, back to the middle at the
  // end.
  Eigen::Vector2d zmp_ref(double t) const;

  // Both feet and the support state at t. A flat foot is given by its sole point (edge_x_m 0,
  // pitch 0). The swing foot follows a quintic smoothstep forward and lifts to `step_height_m`
  // and back down with zero vertical speed at lift-off and touch-down. Between a toe-off and a
  // heel strike it also turns from toes down to toes up, with its lowest edge on that path.
  void feet(double t, double step_height_m, NaoEdgeFoot& left, NaoEdgeFoot& right,
            NaoSupport& support) const;

 private:
  // Share of a double-support ZMP transfer done at share u of its time: linear, blended with
  // the quintic smoothstep by NaoWalkParams::zmp_transfer_smoothing. transfer_inverse is its
  // inverse (the share of time at which a share of the way is done).
  double transfer(double u) const;
  double transfer_inverse(double share) const;
  // Index of the step running at t, −1 before the first, steps.size() after the last.
  int step_at(double t) const;
  // Toe-off and heel-strike timing of every step.
  void plan_edge_contacts(const NaoWalkParams& params);

  double step_s_ = 0.0, double_support_s_ = 0.0, single_support_s_ = 0.0;
  double half_spacing_m_ = 0.0;
  double transfer_smoothing_ = 0.0;
  Eigen::Vector2d stand_zmp_start_m_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d stand_zmp_end_m_ = Eigen::Vector2d::Zero();
  double end_transfer_s_ = 0.0;
  double steady_end_s_ = 0.0;
  std::vector<NaoFootstep> steps_;
};

}  // namespace motoflex::detail
