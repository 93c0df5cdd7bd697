#include "motoflex/report/parameter_spread.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "json_numbers.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/report/html_text.hpp"
#include "motoflex/report/parameter_table.hpp"
#include "motoflex/report/run_record.hpp"

namespace motoflex::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A run's parameter rows, by name.
std::vector<ParameterRow> rows_of(const RunRecord& record) {
  const std::string summary_file =
      (std::filesystem::path(record.fit_dir) / "summary.json").string();
  return parameter_rows(record.inputs, record.best, record.summary,
                        read_parameter_uncertainty(record.summary, summary_file));
}

const ParameterRow* find_row(const std::vector<ParameterRow>& rows, const std::string& name) {
  for (const auto& row : rows) {
    if (row.name == name) return &row;
  }
  return nullptr;
}

// The fit's own scale: ln for a log parameter (spreads become relative), else the value.
double to_scale(double value, bool log_scale) {
  return log_scale ? std::log(value) : value;
}
double from_scale(double u, bool log_scale) {
  return log_scale ? std::exp(u) : u;
}

// Fills mean, spreads and range of `p` from its values and standard errors.
void summarise(ParameterSpread& p, double k) {
  const std::size_t n = p.values.size();
  double mean_u = 0.0;
  std::vector<double> u(n), se_u(n);
  for (std::size_t r = 0; r < n; ++r) {
    u[r] = to_scale(p.values[r], p.log_scale);
    // A log parameter's standard error in ln units: ln(1 + se/value), se/value to first order,
    // and no absurd factor where a fit leaves the parameter undetermined (se ≫ value).
    se_u[r] = p.log_scale ? std::log1p(p.standard_errors[r] / p.values[r]) : p.standard_errors[r];
    mean_u += u[r] / static_cast<double>(n);
  }
  double between_u = kNaN;
  if (n >= 2) {
    double sum = 0.0;
    for (const double x : u) sum += (x - mean_u) * (x - mean_u);
    between_u = std::sqrt(sum / static_cast<double>(n - 1));
  }
  double se_sum = 0.0;
  std::size_t se_count = 0;
  double low_u = std::numeric_limits<double>::infinity();
  double high_u = -low_u;
  for (std::size_t r = 0; r < n; ++r) {
    const double se = std::isfinite(se_u[r]) ? se_u[r] : 0.0;
    if (std::isfinite(se_u[r])) {
      se_sum += se_u[r] * se_u[r];
      ++se_count;
    }
    low_u = std::min(low_u, u[r] - k * se);
    high_u = std::max(high_u, u[r] + k * se);
  }
  if (std::isfinite(between_u)) {
    low_u = std::min(low_u, mean_u - k * between_u);
    high_u = std::max(high_u, mean_u + k * between_u);
  }
  const double within_u = se_count ? std::sqrt(se_sum / static_cast<double>(se_count)) : kNaN;
  p.mean = from_scale(mean_u, p.log_scale);
  p.between_runs = p.log_scale ? std::exp(between_u) : between_u;
  p.within_run = p.log_scale ? std::exp(within_u) : within_u;
  p.lower = from_scale(low_u, p.log_scale);
  p.upper = from_scale(high_u, p.log_scale);
  if (std::isfinite(p.bound_lower) && p.lower < p.bound_lower) {
    p.lower = p.bound_lower;
    p.clipped = true;
  }
  if (std::isfinite(p.bound_upper) && p.upper > p.bound_upper) {
    p.upper = p.bound_upper;
    p.clipped = true;
  }
}

std::string cell(double value) {
  return std::isfinite(value) ? format_number(value, 4) : "–";
}

// A spread: "×" after a log parameter's factor, nothing after "–".
std::string spread_cell(double value, bool log_scale) {
  return cell(value) + (log_scale && std::isfinite(value) ? " ×" : "");
}

}  // namespace

SpreadReport parameter_spread(const std::vector<std::string>& run_dirs, double k) {
  if (run_dirs.empty()) throw InputError("", 0, "runs", "give at least one run folder");
  if (!(k > 0.0)) throw InputError("", 0, "k", "must be positive");
  SpreadReport report;
  report.k = k;
  std::vector<std::vector<ParameterRow>> rows;
  std::vector<std::string> best_files;
  for (const auto& dir : run_dirs) {
    const RunRecord record = read_run_dir(dir);
    best_files.push_back((std::filesystem::path(record.fit_dir) / "best.json").string());
    rows.push_back(rows_of(record));
    report.runs.push_back(record.fit_dir);
  }
  if (rows.front().empty()) {
    throw InputError(best_files.front(), 0, "free", "no fitted parameters in this run");
  }
  for (const ParameterRow& first : rows.front()) {
    ParameterSpread p;
    p.name = first.name;
    p.unit = first.unit;
    p.log_scale = first.log_scale;
    p.bound_lower = first.lower;
    p.bound_upper = first.upper;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const ParameterRow* row = find_row(rows[r], first.name);
      if (row == nullptr || !std::isfinite(row->fitted)) {
        throw InputError(best_files[r], 0, "free." + first.name,
                         "this run has no fitted value for a parameter of " + best_files.front());
      }
      if (p.log_scale && !(row->fitted > 0.0)) {
        throw InputError(best_files[r], 0, "free." + first.name,
                         "a log-scale parameter must be positive");
      }
      p.values.push_back(row->fitted);
      p.standard_errors.push_back(row->interval.standard_error);
    }
    summarise(p, k);
    report.parameters.push_back(std::move(p));
  }
  return report;
}

nlohmann::json spread_json(const SpreadReport& report) {
  nlohmann::json out;
  out["k"] = report.k;
  out["runs"] = report.runs;
  out["parameters"] = nlohmann::json::array();
  for (const auto& p : report.parameters) {
    out["parameters"].push_back(
        {{"name", p.name},
         {"unit", p.unit},
         {"log", p.log_scale},
         {"values", detail::numbers_json(p.values)},
         {"standard_errors", detail::numbers_json(p.standard_errors)},
         {"mean", detail::number_json(p.mean)},
         {"between_runs", detail::number_json(p.between_runs)},
         {"within_run", detail::number_json(p.within_run)},
         {"lower", detail::number_json(p.lower)},
         {"upper", detail::number_json(p.upper)},
         {"bounds", {detail::number_json(p.bound_lower), detail::number_json(p.bound_upper)}},
         {"clipped", p.clipped}});
  }
  return out;
}

std::string spread_markdown(const SpreadReport& report) {
  std::string md = "| parameter | unit | runs | mean | between runs | within run (se) | range (±" +
                   format_number(report.k, 3) + ") |\n|---|---|---|---|---|---|---|\n";
  for (const auto& p : report.parameters) {
    md += "| " + p.name + " | " + p.unit + " | " + std::to_string(p.values.size()) + " | " +
          cell(p.mean) + " | " + spread_cell(p.between_runs, p.log_scale) + " | " +
          spread_cell(p.within_run, p.log_scale) + " | " + cell(p.lower) + " – " + cell(p.upper) +
          (p.clipped ? " (at a bound)" : "") + " |\n";
  }
  return md;
}

}  // namespace motoflex::report
