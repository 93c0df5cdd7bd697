#pragma once

// Frequency-domain validation: how a joint follows its command, read from a log as a Bode plot
// (gain and phase of the measured angle against the commanded one over frequency), for the
// measured and the simulated angle side by side. A fit can match a log's angles on average and
// still put a resonance at the wrong frequency or damp what the real joint rings with; the
// frequency response shows that where the time series hides it.
//
// The estimate is Welch's H1 = S_xy / S_xx (input x = commanded angle, output y = measured or
// simulated angle) over Hann-windowed, mean-removed segments with 50 % overlap, evaluated on a
// logarithmic frequency grid, with the magnitude-squared coherence γ² = |S_xy|² / (S_xx·S_yy):
// near 1 where the output follows the command linearly, low where the log has no excitation
// there, or noise, or a nonlinearity. Only frequencies where both coherences reach
// kMinCoherence are compared.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

namespace motoflex::report {

// The coherence (γ², 0..1) a frequency needs in both the measured and the simulated response
// to be compared.
inline constexpr double kMinCoherence = 0.8;

struct FrequencyResponse {
  std::vector<double> frequency_hz;  // log-spaced, increasing
  std::vector<double> gain_db;       // 20·log10 |H1|
  std::vector<double> phase_deg;     // arg H1, unwrapped along frequency from the lowest one
  std::vector<double> coherence;     // γ², 0..1
};

struct FrequencyResponseOptions {
  std::size_t segments = 7;  // Welch segments (equal length, 50 % overlap); at least 1
  std::size_t points = 48;   // frequencies on the grid
  // The grid runs from two periods per segment up to this fraction of the Nyquist frequency.
  double max_fraction_of_nyquist = 0.8;
};

// The response of `output` to `input`, both sampled at `time_s` (strictly increasing; a log's
// own, irregular steps allowed: both are resampled onto a uniform grid at the median step by
// linear interpolation). A NaN in either ends the usable span there (a simulation that fell
// early). nullopt when fewer than 64 samples are usable, or the input has no power (constant).
std::optional<FrequencyResponse> estimate_frequency_response(
    const std::vector<double>& time_s, const std::vector<double>& input,
    const std::vector<double>& output, const FrequencyResponseOptions& options = {});

struct FrequencyComparison {
  FrequencyResponse measured;
  FrequencyResponse simulated;  // on the same grid
  // Over the frequencies where both coherences reach kMinCoherence; NaN when there is none.
  std::size_t coherent_points = 0;
  double gain_rms_db = 0.0;    // RMS of measured − simulated gain
  double phase_rms_deg = 0.0;  // RMS of measured − simulated phase, wrapped to ±180°
  // The largest gain among those frequencies (a resonance, when the curve has a peak there).
  double measured_peak_hz = 0.0;
  double measured_peak_db = 0.0;
  double simulated_peak_hz = 0.0;
  double simulated_peak_db = 0.0;
};

// Both responses to the same `command`, over the span where all three are finite (the
// simulated angle ends early when the simulation did). nullopt when either estimate is.
std::optional<FrequencyComparison> compare_frequency_responses(
    const std::vector<double>& time_s, const std::vector<double>& command,
    const std::vector<double>& measured, const std::vector<double>& simulated,
    const FrequencyResponseOptions& options = {});

// {"f_hz", "measured": {"gain_db", "phase_deg", "coherence"}, "simulated": {...},
//  "coherent_points", "gain_rms_db", "phase_rms_deg", "measured_peak_hz", "measured_peak_db",
//  "simulated_peak_hz", "simulated_peak_db"}; 5 significant digits, NaN as null.
nlohmann::json frequency_comparison_json(const FrequencyComparison& comparison);

}  // namespace motoflex::report
