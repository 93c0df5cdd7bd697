#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {

// How simulated and measured angles are compared (seed 001, eq. 2).
struct FitnessOptions {
  // F = Σ_t Σ_i w_i (q_real − q_sim)² / T^m per robot. m = 0 would reward falling at once
  // (fewer frames, less error), m = 1 is the mean error, which still rewards falling as soon
  // as the walk starts to go wrong; m > 1 makes surviving longer worth more than the error it
  // adds, so a fit first learns to stay up and then to match the angles (seed 001 §4). Default 2.
  double m = 2.0;
  // Frames before this time (s from the log start) are simulated but not scored.
  double settle_s = 0.0;
  // Per-joint weights w_i in model actuator order (empty: all 1).
  std::vector<double> joint_weights;
  // Weight of the torso IMU's roll and pitch errors (rad², like the joints): F then adds
  // imu_weight · Σ_t [(roll_real − roll_sim)² + (pitch_real − pitch_sim)²] to each robot's sum
  // before dividing by T^m. 0 (default) is seed 001's joint-only F. Link bending, foot slip and
  // ground compliance move the torso far more than they move the joint encoders, so a log
  // with IMU columns tells them apart; every log of the fit must then have imu.roll and
  // imu.pitch.
  double imu_weight = 0.0;
  // Simulate and score only the first window_s seconds of every log (0 = whole logs). A fit
  // on the opening seconds is cheaper per evaluation in proportion; the strategy benchmark
  // uses it so that eighteen 810-evaluation runs fit in a sitting on 2 cores.
  double window_s = 0.0;
  // How a frame's error enters the sum: squared, (q_real − q_sim)² (seed 001, default), or
  // absolute, |q_real − q_sim| (BAM's loss: the mean absolute error). Real servo logs have
  // stretches no model of the family reproduces (a stall whose hold angle sits on a knife
  // edge); squared errors let those few stretches decide the whole fit, absolute ones do not.
  bool absolute_error = false;
};

// One robot of a fit: a commanded motion, what the real robot measured, and how to simulate it.
struct FitCase {
  std::string name;                  // log name, for reports
  CommandTrajectory commands;        // commanded angles (the log's .cmd columns)
  std::vector<double> measured_rad;  // the log's .meas columns, frame-major, model order
  // The log's imu.roll, imu.pitch per frame ([frame * 2 + 0|1], rad); empty without them.
  std::vector<double> measured_imu_rad;
  RolloutOptions options;
  // Per-log model parameters (sidecar `parameters`, e.g. a bench's mass), applied on top.
  std::vector<std::pair<std::size_t, double>> parameter_overrides;
};

// The first frame of a case that is scored (the frames before settle_s only settle the robot).
std::size_t first_scored_frame(const FitCase& fit_case, double settle_s);

struct CaseScore {
  // Σ_t Σ_i w_i (q_real − q_sim)² (+ the IMU term) over the scored frames; Σ w_i·|q_real − q_sim|
  // (rad) with FitnessOptions::absolute_error.
  double squared_error_rad2 = 0.0;
  std::size_t frames = 0;  // T: scored frames simulated before the end or a fall
  std::size_t frames_requested = 0;
  double fitness = 0.0;  // squared_error / T^m (+inf for a failed rollout)
  RolloutEnd end = RolloutEnd::kCompleted;
  std::string end_detail;
};

struct FitnessBreakdown {
  double fitness = 0.0;  // Σ over cases
  std::vector<CaseScore> cases;
  bool stopped_early = false;  // the fitness is a lower bound >= the threshold
};

// Evaluates parameter sets on a fixed list of cases. Immutable after construction; evaluate()
// may be called from several threads at once.
class FitnessFunction {
 public:
  FitnessFunction(std::shared_ptr<const RobotModel> model, std::vector<FitCase> cases,
                  FitnessOptions options);

  // Simulates every case in order. If `stop_threshold` is finite, a rollout stops as soon as
  // Σ_cases (error so far)/T_max^m — a lower bound of the final fitness, since errors only grow
  // and T <= T_max — reaches it; the result is then that bound (>= the threshold), which ranks
  // exactly as the full value would against anything below the threshold.
  // Without a threshold, `threads` > 1 simulates the cases in parallel (OpenMP; call it
  // outside any parallel region); the result is the same, bit for bit.
  FitnessBreakdown evaluate(const ParameterSet& parameters,
                            double stop_threshold = std::numeric_limits<double>::infinity(),
                            std::vector<RolloutResult>* rollouts = nullptr, int threads = 1) const;

  const RobotModel& model() const { return *model_; }
  const std::vector<FitCase>& cases() const { return cases_; }
  const FitnessOptions& options() const { return options_; }

  // The scored channels of a frame: the actuated joints (model order), then the IMU's roll and
  // pitch when imu_weight > 0. A channel's value is √weight × angle (rad), so the squared
  // distance of two channel vectors summed over the scored frames is the fitness's error sum;
  // residual analyses and effect signatures work in these channels.
  bool scores_imu() const { return options_.imu_weight > 0.0; }
  std::size_t channels() const { return weights_.size() + (scores_imu() ? 2 : 0); }
  // Writes channels() values of frame `frame` of a rollout / of case `c`'s measurements.
  void simulated_channels(const RolloutResult& result, std::size_t frame, double* out) const;
  void measured_channels(std::size_t c, std::size_t frame, double* out) const;
  // "LHipRoll", ..., then "imu.roll", "imu.pitch".
  std::string channel_name(std::size_t channel) const;
  // The residual of a channel whose measured − simulated value is `difference`: its square is
  // the frame's term of the error sum (difference itself for squared errors; the signed root
  // √(√w·|difference|) = √(w·|e|) for absolute ones), for a least-squares polish.
  double channel_residual(std::size_t channel, double difference) const;
  // A frame's error term before weighting: e² or |e| (FitnessOptions::absolute_error).
  double frame_error(double e) const { return options_.absolute_error ? std::fabs(e) : e * e; }

 private:
  // Simulates and scores case c. The rollout stops early once finished_fitness (of the cases
  // before it) plus its own lower bound reaches stop_threshold; `stopped` says so.
  CaseScore score_case(std::size_t c, const ParameterSet& parameters, double finished_fitness,
                       double stop_threshold, RolloutResult& result, bool& stopped) const;

  std::shared_ptr<const RobotModel> model_;
  std::vector<FitCase> cases_;
  FitnessOptions options_;
  std::vector<double> weights_;
  std::vector<std::size_t> first_scored_frame_;  // per case
};

}  // namespace motoflex
