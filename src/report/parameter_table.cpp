#include "motoflex/report/parameter_table.hpp"

#include <cmath>

#include "motoflex/model/parameters.hpp"
#include "motoflex/report/html_text.hpp"

namespace motoflex::report {
namespace {

double number_at(const nlohmann::json& object, const std::string& key) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number()) {
    return kNotAvailable;
  }
  return object[key].get<double>();
}

const nlohmann::json& fitted_values(const nlohmann::json& best, const nlohmann::json& summary) {
  static const nlohmann::json kEmpty = nlohmann::json::object();
  if (best.is_object() && best.contains("free") && best["free"].is_object()) return best["free"];
  if (summary.is_object() && summary.contains("free") && summary["free"].is_object()) {
    return summary["free"];
  }
  return kEmpty;
}

bool has_uncertainty(const std::vector<ParameterRow>& rows) {
  for (const auto& row : rows) {
    if (!std::isnan(row.interval.standard_error) || !std::isnan(row.interval.lower) ||
        !std::isnan(row.interval.upper)) {
      return true;
    }
  }
  return false;
}

std::string cell(double value) {
  return "<td class=\"num\">" + escape_html(format_number(value)) + "</td>";
}

}  // namespace

std::vector<ParameterRow> parameter_rows(const nlohmann::json& inputs, const nlohmann::json& best,
                                         const nlohmann::json& summary,
                                         const ParameterUncertainty& uncertainty) {
  const nlohmann::json& fitted = fitted_values(best, summary);
  std::vector<ParameterRow> rows;
  if (inputs.is_object() && inputs.contains("free") && inputs["free"].is_array()) {
    for (const auto& free : inputs["free"]) {
      ParameterRow row;
      row.name = free.value("name", std::string());
      row.unit = free.value("unit", unit_from_parameter_name(row.name));
      row.start = number_at(free, "start");
      row.lower = number_at(free, "lower");
      row.upper = number_at(free, "upper");
      row.log_scale = free.value("log", false);
      row.fitted = number_at(fitted, row.name);
      rows.push_back(std::move(row));
    }
  } else {
    for (auto it = fitted.begin(); it != fitted.end(); ++it) {
      ParameterRow row;
      row.name = it.key();
      row.unit = unit_from_parameter_name(row.name);
      row.fitted = it->is_number() ? it->get<double>() : kNotAvailable;
      rows.push_back(std::move(row));
    }
  }
  const nlohmann::json* sensitivity = nullptr;
  if (summary.is_object() && summary.contains("sensitivity") &&
      summary["sensitivity"].is_object() && summary["sensitivity"].contains("parameters")) {
    sensitivity = &summary["sensitivity"]["parameters"];
  }
  for (auto& row : rows) {
    if (const auto it = uncertainty.intervals.find(row.name); it != uncertainty.intervals.end()) {
      row.interval = it->second;
    }
    if (sensitivity != nullptr && sensitivity->is_object() && sensitivity->contains(row.name)) {
      const nlohmann::json& entry = (*sensitivity)[row.name];
      row.sensitivity = number_at(entry, "relative_fitness_change_per_bound_width");
      row.undetermined = entry.is_object() && !entry.value("determined", true);
    }
  }
  return rows;
}

bool at_bound(const ParameterRow& row) {
  const double width = row.upper - row.lower;
  if (!(width > 0.0) || std::isnan(row.fitted)) return false;
  return row.fitted - row.lower <= 0.01 * width || row.upper - row.fitted <= 0.01 * width;
}

std::string parameter_table_html(const std::vector<ParameterRow>& rows) {
  const bool uncertainty = has_uncertainty(rows);
  std::string html =
      "<table class=\"parameters\"><thead><tr><th>parameter</th><th>unit</th><th>start</th>"
      "<th>lower</th><th>upper</th><th>fitted</th><th>standard error</th>"
      "<th>95 % confidence interval</th><th title=\"relative fitness change per bound-width around "
      "the best point\">sensitivity</th></tr></thead><tbody>\n";
  for (const auto& row : rows) {
    html += "<tr><td><code>" + escape_html(row.name) + "</code>" +
            (row.log_scale ? " <span class=\"tag\">log</span>" : "") + "</td><td>" +
            escape_html(row.unit) + "</td>" + cell(row.start) + cell(row.lower) + cell(row.upper);
    html += at_bound(row) ? "<td class=\"num bound\" title=\"within 1 % of a bound\">" +
                                escape_html(format_number(row.fitted)) + " ⚠</td>"
                          : cell(row.fitted);
    if (!uncertainty) {
      html += "<td class=\"na\">not available</td><td class=\"na\">not available</td>";
    } else {
      html += cell(row.interval.standard_error);
      const std::string interval = "[" + escape_html(format_number(row.interval.lower)) + ", " +
                                   escape_html(format_number(row.interval.upper)) + "]";
      if (std::isnan(row.interval.lower) && std::isnan(row.interval.upper)) {
        html += "<td class=\"na\">n/a</td>";
      } else if (!row.interval.linear) {
        html +=
            "<td class=\"num bound\" title=\"the residual is not linear in this parameter "
            "over the Jacobian's step (" +
            escape_html(format_number(row.interval.nonlinearity)) +
            "): the interval does not hold\">" + interval + " ⚠ not linear</td>";
      } else if (!row.interval.identified) {
        html += "<td class=\"num bound\" title=\"the interval spans most of the bounds\">" +
                interval + " ⚠ not identified</td>";
      } else {
        html += "<td class=\"num\">" + interval + "</td>";
      }
    }
    html += row.undetermined
                ? "<td class=\"num bound\" title=\"the training data cannot determine "
                  "this value\">" +
                      escape_html(format_number(row.sensitivity)) + " ⚠ not determined</td>"
                : cell(row.sensitivity);
    html += "</tr>\n";
  }
  html += "</tbody></table>\n";
  if (rows.empty()) html += "<p class=\"na\">No free parameters recorded.</p>\n";
  if (!uncertainty) {
    html +=
        "<p class=\"note\">Standard errors and confidence intervals: not available (this "
        "summary.json has no <code>confidence_intervals</code> or <code>covariance</code>).</p>\n";
  }
  return html;
}

}  // namespace motoflex::report
