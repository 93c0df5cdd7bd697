#pragma once

#include <vector>

#include "motoflex/core/random_stream.hpp"

namespace motoflex {

// What separates an encoder reading from the true joint angle.
struct EncoderParams {
  int resolution_bits = 0;  // 0 = exact; otherwise readings are multiples of 2π/2^bits rad
  double noise_rad = 0.0;   // standard deviation of the Gaussian noise added to each reading
  double delay_s = 0.0;     // age of the angle a reading reports (transport + filter delay)
  double offset_rad = 0.0;  // calibration error added to the angle before quantisation
};

// A joint angle sensor with delay, offset, quantisation and noise, in that order:
//   reading = round((q(t − delay) + offset) / res) · res + noise_rad · N(0, 1)
// q(t − delay) interpolates linearly between the angles pushed at the physics steps; until the
// history reaches back far enough, the oldest stored angle stands in (before any push() or
// reset() the angle is 0). The history is a ring buffer sized once at construction, so push()
// and read() never allocate. One instance per joint, per rollout; the noise comes from the
// stream passed in, so readings are reproducible.
class JointEncoder {
 public:
  // Throws std::invalid_argument for physics_dt_s <= 0, negative delay or noise, a delay of
  // 1e7 physics steps or more, a non-finite offset, or resolution_bits outside 0..32.
  JointEncoder(const EncoderParams& params, double physics_dt_s, RandomStream noise);

  // Records the true angle of the physics step that just ended; call once per step.
  void push(double true_angle_rad);
  // The reading now (after the latest push). Takes one normal draw when noise_rad > 0.
  double read();
  // Fills the whole history with this angle, as if the joint had rested there forever.
  void reset(double angle_rad);

  const EncoderParams& params() const { return params_; }
  // Quantisation step in rad; 0 for an exact encoder.
  double resolution_rad() const { return resolution_rad_; }

 private:
  // The angle pushed `age` pushes ago (0 = latest), clamped to the oldest stored one.
  double stored_angle_rad(int age) const;

  EncoderParams params_;
  RandomStream noise_;
  double resolution_rad_ = 0.0;
  int delay_whole_steps_ = 0;        // floor(delay / dt)
  double delay_fraction_ = 0.0;      // delay / dt − floor(delay / dt), in [0, 1)
  std::vector<double> history_rad_;  // ring buffer, capacity floor(delay / dt) + 2
  int newest_ = -1;                  // index of the latest angle in history_rad_
  int stored_ = 0;                   // how many angles the history holds (<= capacity)
};

}  // namespace motoflex
