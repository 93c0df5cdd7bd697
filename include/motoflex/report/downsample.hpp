#pragma once

// Thinning long traces for the HTML report: a browser draws a few thousand points per trace
// without effort, while a 100 Hz log of a minute has 6000 frames per joint and a report has
// dozens of traces.

#include <cstddef>
#include <span>
#include <vector>

namespace motoflex::report {

// The indices (increasing) of the samples of `y` to keep so that at most `max_points` remain
// while the drawn line keeps its envelope: the first and the last sample, and from each of
// equal buckets of the samples between them the smallest and the largest (in index order), so
// that no peak is cut off. Returns every index when y.size() <= max_points. max_points < 4 is
// treated as 4. NaN samples are never chosen as a bucket's extreme unless the bucket is all NaN.
std::vector<std::size_t> envelope_indices(std::span<const double> y, std::size_t max_points);

}  // namespace motoflex::report
