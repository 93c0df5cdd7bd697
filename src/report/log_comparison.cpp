#include "motoflex/report/log_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "json_numbers.hpp"
#include "motoflex/report/downsample.hpp"

namespace motoflex::report {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
// Six significant digits print short and are far below what a plot or a reader resolves.
constexpr int kSignificant = 6;

// Value of the series (times `t`, values `y`) at time `at` by linear interpolation; NaN outside
// the series' span. `cursor` remembers where the previous (earlier) lookup ended.
double interpolate(const std::vector<double>& t, const std::vector<double>& y, double at,
                   std::size_t& cursor) {
  if (t.empty() || at < t.front() - 1e-9 || at > t.back() + 1e-9) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  while (cursor + 1 < t.size() && t[cursor + 1] <= at) ++cursor;
  if (cursor + 1 >= t.size() || t[cursor] >= at) return y[cursor];
  const double w = (at - t[cursor]) / (t[cursor + 1] - t[cursor]);
  return y[cursor] + w * (y[cursor + 1] - y[cursor]);
}

std::vector<double> column_deg(const JointLog& log, std::size_t joint) {
  std::vector<double> out(log.frames());
  for (std::size_t f = 0; f < log.frames(); ++f) out[f] = log.measured(f, joint) * kDegPerRad;
  return out;
}

std::vector<double> scaled(const std::vector<double>& rad) {
  std::vector<double> out(rad.size());
  for (std::size_t i = 0; i < rad.size(); ++i) out[i] = rad[i] * kDegPerRad;
  return out;
}

// The commanded angle of `joint` in `log` (deg); empty when the log has no commands.
std::vector<double> command_deg(const JointLog& log, std::size_t joint) {
  if (!log.has_commanded()) return {};
  std::vector<double> out(log.frames());
  for (std::size_t f = 0; f < log.frames(); ++f) out[f] = log.commanded(f, joint) * kDegPerRad;
  return out;
}

// `command_deg` (on the measured frames; empty: none) adds the frequency response.
ChannelComparison compare_channel(const std::string& name, const std::vector<double>& measured_t,
                                  const std::vector<double>& measured_deg,
                                  const std::vector<double>& simulated_t,
                                  const std::vector<double>& simulated_deg, std::size_t max_points,
                                  const std::vector<double>& command_deg = {}) {
  ChannelComparison out;
  out.name = name;
  const std::size_t n = measured_t.size();
  std::vector<double> simulated(n);
  std::size_t cursor = 0;
  for (std::size_t f = 0; f < n; ++f) {
    simulated[f] = interpolate(simulated_t, simulated_deg, measured_t[f], cursor);
  }
  std::vector<double> residual(n);
  double sum = 0.0, largest = 0.0;
  std::size_t count = 0;
  for (std::size_t f = 0; f < n; ++f) {
    residual[f] = measured_deg[f] - simulated[f];
    if (std::isnan(residual[f])) continue;
    sum += residual[f] * residual[f];
    largest = std::max(largest, std::abs(residual[f]));
    ++count;
  }
  if (command_deg.size() == n) {
    out.frequency = compare_frequency_responses(measured_t, command_deg, measured_deg, simulated);
  }
  out.rms_deg = count == 0 ? std::numeric_limits<double>::quiet_NaN() : std::sqrt(sum / count);
  out.max_abs_deg = count == 0 ? std::numeric_limits<double>::quiet_NaN() : largest;
  if (n > max_points) {
    // A third of the budget for each trace's envelope; the three share the union of frames so
    // that the residual drawn is exactly measured − simulated at every drawn point.
    const std::size_t each = max_points / 3;
    std::set<std::size_t> frames;
    const std::vector<double>* traces[] = {&measured_deg, &simulated, &residual};
    for (const auto* series : traces) {
      for (const std::size_t f : envelope_indices(*series, each)) frames.insert(f);
    }
    out.frames.assign(frames.begin(), frames.end());
    for (const std::size_t f : out.frames) {
      out.measured_deg.push_back(measured_deg[f]);
      out.simulated_deg.push_back(simulated[f]);
    }
  } else {
    out.measured_deg = measured_deg;
    out.simulated_deg = std::move(simulated);
  }
  return out;
}

nlohmann::json times_json(const std::vector<double>& time_s) {
  nlohmann::json out = nlohmann::json::array();
  for (const double t : time_s) out.push_back(std::round(t * 1e6) / 1e6);
  return out;
}

}  // namespace

LogComparison compare_logs(const JointLog& measured, const JointLog& simulated,
                           std::size_t max_points) {
  LogComparison out;
  out.time_s = measured.time_s;
  out.frames_simulated = simulated.frames();
  out.simulated_end_s = simulated.time_s.empty() ? 0.0 : simulated.time_s.back();
  if (measured.has_measured() && simulated.has_measured()) {
    for (std::size_t j = 0; j < simulated.joints(); ++j) {
      const auto m = measured.joint_index(simulated.joint_names[j]);
      if (!m) continue;
      out.channels.push_back(compare_channel(
          simulated.joint_names[j], measured.time_s, column_deg(measured, *m), simulated.time_s,
          column_deg(simulated, j), max_points, command_deg(measured, *m)));
    }
  }
  if (!measured.imu_roll_rad.empty() && !simulated.imu_roll_rad.empty()) {
    out.channels.push_back(compare_channel("imu.roll", measured.time_s,
                                           scaled(measured.imu_roll_rad), simulated.time_s,
                                           scaled(simulated.imu_roll_rad), max_points));
  }
  if (!measured.imu_pitch_rad.empty() && !simulated.imu_pitch_rad.empty()) {
    out.channels.push_back(compare_channel("imu.pitch", measured.time_s,
                                           scaled(measured.imu_pitch_rad), simulated.time_s,
                                           scaled(simulated.imu_pitch_rad), max_points));
  }
  for (const auto& channel : out.channels) out.thinned = out.thinned || !channel.frames.empty();
  return out;
}

nlohmann::json log_comparison_json(const LogComparison& comparison) {
  nlohmann::json out;
  out["name"] = comparison.name;
  out["set"] = comparison.set;
  out["t"] = times_json(comparison.time_s);
  out["frames_simulated"] = comparison.frames_simulated;
  out["simulated_end_s"] = comparison.simulated_end_s;
  out["thinned"] = comparison.thinned;
  nlohmann::json channels = nlohmann::json::array();
  for (const auto& channel : comparison.channels) {
    nlohmann::json item;
    item["name"] = channel.name;
    item["rms_deg"] = detail::number_json(channel.rms_deg, kSignificant);
    item["max_abs_deg"] = detail::number_json(channel.max_abs_deg, kSignificant);
    if (!channel.frames.empty()) {
      std::vector<double> t;
      for (const std::size_t f : channel.frames) t.push_back(comparison.time_s[f]);
      item["t"] = times_json(t);
    }
    item["measured"] = detail::numbers_json(channel.measured_deg, kSignificant);
    item["simulated"] = detail::numbers_json(channel.simulated_deg, kSignificant);
    if (channel.frequency) item["frequency"] = frequency_comparison_json(*channel.frequency);
    channels.push_back(std::move(item));
  }
  out["channels"] = std::move(channels);
  return out;
}

}  // namespace motoflex::report
