#pragma once

#include <cstddef>
#include <vector>

namespace motoflex {

// The numbers seed 001's Section 5 reads off a walk (torso travel, falls, the torso's pitch
// oscillation), as plain functions of sampled signals. Times in s, samples strictly increasing
// in time; a window with too few samples gives NaN rather than an exception.

// Mean rate of change of x between t0_s and t1_s, in mm/s per m of x (i.e. x in m gives mm/s),
// with x linearly interpolated between samples: 1000·(x(t1) − x(t0))/(t1 − t0). NaN when
// t1_s <= t0_s or the window is not inside the samples' time span.
double mean_speed_mm_s(const std::vector<double>& time_s, const std::vector<double>& x_m,
                       double t0_s, double t1_s);

// Peak-to-peak range (max − min) of `signal` in each of the consecutive windows
// [start_s + k·period_s, start_s + (k+1)·period_s) that end by end_s; windows holding fewer
// than 2 samples are skipped. Empty when period_s <= 0.
std::vector<double> window_ranges(const std::vector<double>& time_s,
                                  const std::vector<double>& signal, double start_s, double end_s,
                                  double period_s);

// How much every second oscillation stands out (seed 001 §5: "every second oscillation is
// further forward and backward"): the mean of the ranges at even indices over the mean at odd
// indices, or its inverse, whichever is >= 1. 1 for an oscillation of constant amplitude, 2 for
// ranges 1, 2, 1, 2, ... (or 2, 1, 2, 1, ...). NaN with fewer than 2 ranges or a zero mean.
double alternation_ratio(const std::vector<double>& ranges);

enum class FallDirection { kForward, kBackward, kLeft, kRight };
const char* to_string(FallDirection direction);  // "forward", "backward", "left", "right"

// The way a torso with these Z-Y-X tilt angles is falling (motoflex's IMU convention: pitch > 0
// nose down, roll > 0 right side down): along the larger of |pitch| and |roll|.
FallDirection fall_direction(double roll_rad, double pitch_rad);

}  // namespace motoflex
