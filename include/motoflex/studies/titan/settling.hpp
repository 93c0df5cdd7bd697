#pragma once

#include <vector>

namespace motoflex {

// Seed 000 §III-A's "time to converge": the earliest sample time t ≥ from_s after which every
// sample of `values` stays within ±band of `final_value`. Returns from_s when the series never
// leaves the band after from_s, and +infinity when its last sample is outside the band (it has
// not converged). `time_s` must increase and have the size of `values`; throws
// std::invalid_argument otherwise or when band < 0.
double settling_time_s(const std::vector<double>& time_s, const std::vector<double>& values,
                       double final_value, double band, double from_s);

// Mean of the samples with time ≥ time_s.back() − window_s (the series' final value). Throws
// std::invalid_argument for empty or mismatched series.
double tail_mean(const std::vector<double>& time_s, const std::vector<double>& values,
                 double window_s);

}  // namespace motoflex
