#include "motoflex/fit/residual_autocorrelation.hpp"

#include <algorithm>
#include <stdexcept>

namespace motoflex {

ResidualAutocorrelation residual_autocorrelation(const std::vector<double>& residuals,
                                                 const std::vector<std::size_t>& frames_per_series,
                                                 std::size_t channels) {
  std::size_t total = 0;
  for (const std::size_t frames : frames_per_series) total += frames * channels;
  if (channels == 0 || total != residuals.size()) {
    throw std::invalid_argument("residual autocorrelation: the series do not cover the residuals");
  }
  double energy = 0.0, lagged = 0.0;
  std::size_t start = 0;
  for (const std::size_t frames : frames_per_series) {
    for (std::size_t t = 0; t < frames; ++t) {
      for (std::size_t k = 0; k < channels; ++k) {
        const double r = residuals[start + t * channels + k];
        energy += r * r;
        if (t > 0) lagged += r * residuals[start + (t - 1) * channels + k];
      }
    }
    start += frames * channels;
  }
  ResidualAutocorrelation out;
  const auto n = static_cast<double>(residuals.size());
  out.effective = n;
  if (energy <= 0.0) return out;
  constexpr double kMaxLag1 = 1.0 - 1e-6;
  out.lag1 = std::min(lagged / energy, kMaxLag1);
  if (out.lag1 > 0.0) out.inflation = (1.0 + out.lag1) / (1.0 - out.lag1);
  out.effective = n / out.inflation;
  return out;
}

}  // namespace motoflex
