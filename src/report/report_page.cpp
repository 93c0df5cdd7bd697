#include "motoflex/report/report_page.hpp"

#include <ctime>
#include <filesystem>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/build_info.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/report/figure_data.hpp"
#include "motoflex/report/frequency_response.hpp"
#include "motoflex/report/html_text.hpp"
#include "motoflex/report/page_assets.hpp"
#include "motoflex/report/parameter_table.hpp"
#include "motoflex/report/report_sections.hpp"

namespace motoflex::report {
namespace {

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return buffer;
}

// A fit is named by its config's `name`; a loop by its fit config's file (the final fit's name
// carries the added effects, "bench_hidden+stribeck").
std::string title_of(const RunRecord& record) {
  std::string name;
  if (!record.loop.is_null()) {
    if (record.loop.is_object() && record.loop.contains("fit") && record.loop["fit"].is_string()) {
      name = std::filesystem::path(record.loop["fit"].get<std::string>()).stem().string();
    }
  } else if (record.summary.is_object()) {
    name = record.summary.value("name", std::string());
  }
  if (name.empty()) name = std::filesystem::path(record.dir).lexically_normal().filename().string();
  return (record.loop.is_null() ? "motoflex fit " : "motoflex loop ") + name;
}

std::string notes_html(const std::vector<std::string>& notes) {
  if (notes.empty()) return "";
  std::string html = "<section id=\"notes\"><h2>Notes</h2><ul class=\"notes\">\n";
  for (const auto& note : notes) html += "<li>" + escape_html(note) + "</li>\n";
  return html + "</ul></section>\n";
}

// A script element's text may not contain "</script" (any case); the vendored and our own
// scripts do not (tests/report/page_assets_test.cpp checks), so they go in as they are.
std::string script(std::string_view code) {
  return "<script>\n" + std::string(code) + "\n</script>\n";
}

}  // namespace

std::string render_report(const RunRecord& record, const ReportOptions& options) {
  std::vector<std::string> notes = record.notes;
  const std::vector<LogComparison> logs =
      load_log_comparisons(record, options.max_points_per_trace, notes);
  const std::string summary_file =
      (std::filesystem::path(record.fit_dir.empty() ? record.dir : record.fit_dir) / "summary.json")
          .string();
  // The uncertainty keys are written by a later stage of the fit; if their shape ever differs
  // from what parameter_uncertainty.hpp reads, the page says so and shows the rest.
  ParameterUncertainty uncertainty;
  try {
    uncertainty = read_parameter_uncertainty(record.summary, summary_file);
  } catch (const InputError& error) {
    notes.push_back(std::string("parameter uncertainty not shown: ") + error.what());
  }
  const std::vector<ParameterRow> rows =
      parameter_rows(record.inputs, record.best, record.summary, uncertainty);

  nlohmann::json data;
  data["convergence"] = convergence_json(record.generations);
  data["logs"] = nlohmann::json::array();
  for (const auto& log : logs) data["logs"].push_back(log_comparison_json(log));
  data["correlation"] = correlation_json(uncertainty.correlation);
  data["min_coherence"] = kMinCoherence;  // the frequency responses' threshold

  const std::string title = title_of(record);
  const std::string revision = source_revision();
  std::string html;
  html.reserve(plotly_js().size() + (1u << 20));
  html +=
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta name=\"generator\" content=\"motoflex " +
      escape_html(version()) + "\">\n<title>" + escape_html(title) + "</title>\n<style>\n" +
      std::string(report_page_css()) + "</style>\n</head>\n<body>\n";
  html += "<header><h1>" + escape_html(title) + "</h1><p>Report written " + now_utc() +
          " by motoflex " + escape_html(version()) +
          (revision.empty() ? std::string() : " (git " + escape_html(revision) + ")") +
          " · plots by plotly.js " + escape_html(std::string(plotly_version())) +
          " (MIT licence), inlined: this page works offline.</p></header>\n<main>\n";
  html += summary_section_html(record);
  html += loop_section_html(record);
  html += convergence_section_html(record);
  html += logs_section_html(logs, options.max_points_per_trace);
  html += parameters_section_html(rows, !uncertainty.correlation.empty());
  html += residuals_section_html(record);
  html += notes_html(notes);
  html += "</main>\n<script type=\"application/json\" id=\"motoflex-data\">" +
          json_for_script(data) + "</script>\n";
  html += script(plotly_js());
  html += script(report_page_js());
  html += "</body>\n</html>\n";
  return html;
}

std::string write_report(const std::string& run_dir, const std::string& out,
                         const ReportOptions& options) {
  const RunRecord record = read_run_dir(run_dir);
  std::string path = out.empty() ? (std::filesystem::path(run_dir) / "report.html").string() : out;
  write_file_atomically(path, render_report(record, options));
  return path;
}

}  // namespace motoflex::report
