#include "motoflex/report/downsample.hpp"

#include <algorithm>
#include <cmath>

namespace motoflex::report {

std::vector<std::size_t> envelope_indices(std::span<const double> y, std::size_t max_points) {
  const std::size_t n = y.size();
  max_points = std::max<std::size_t>(max_points, 4);
  std::vector<std::size_t> keep;
  if (n <= max_points) {
    keep.resize(n);
    for (std::size_t i = 0; i < n; ++i) keep[i] = i;
    return keep;
  }
  // Two points (min and max) per bucket, plus the two ends.
  const std::size_t buckets = (max_points - 2) / 2;
  const std::size_t inner = n - 2;  // samples 1 .. n-2
  keep.reserve(2 * buckets + 2);
  keep.push_back(0);
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t begin = 1 + b * inner / buckets;
    const std::size_t end = 1 + (b + 1) * inner / buckets;
    if (begin >= end) continue;
    std::size_t lo = begin, hi = begin;
    for (std::size_t i = begin; i < end; ++i) {
      if (std::isnan(y[i])) continue;
      if (std::isnan(y[lo]) || y[i] < y[lo]) lo = i;
      if (std::isnan(y[hi]) || y[i] > y[hi]) hi = i;
    }
    keep.push_back(std::min(lo, hi));
    if (lo != hi) keep.push_back(std::max(lo, hi));
  }
  keep.push_back(n - 1);
  return keep;
}

}  // namespace motoflex::report
