#include "motoflex/report/report_sections.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include "motoflex/report/frequency_response.hpp"
#include "motoflex/report/html_text.hpp"
#include "motoflex/report/markdown_html.hpp"

namespace motoflex::report {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The value at a path of object keys, or null.
const json& at(const json& root, std::initializer_list<const char*> keys) {
  static const json kNull;
  const json* node = &root;
  for (const char* key : keys) {
    if (!node->is_object() || !node->contains(key)) return kNull;
    node = &(*node)[key];
  }
  return *node;
}

std::string text_of(const json& value) {
  if (value.is_null()) return "";
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number_float()) return format_number(value.get<double>());
  return value.dump();
}

void add_row(std::string& html, const std::string& label, const json& value,
             const std::string& suffix = "") {
  const std::string text = text_of(value);
  if (text.empty()) return;
  html +=
      "<tr><td>" + escape_html(label) + "</td><td>" + escape_html(text + suffix) + "</td></tr>\n";
}

std::string seconds_text(double seconds) {
  if (seconds < 120.0) return format_number(seconds, 3) + " s";
  return format_number(seconds, 4) + " s (" + format_number(seconds / 60.0, 3) + " min)";
}

std::string robot_rows(const json& robots, const char* set) {
  std::string html;
  if (!robots.is_array()) return html;
  for (const auto& robot : robots) {
    const std::string end = text_of(at(robot, {"end"}));
    html += "<tr><td>" + escape_html(text_of(at(robot, {"name"}))) + "</td><td>" + set +
            "</td><td class=\"num\">" + escape_html(text_of(at(robot, {"fitness"}))) +
            "</td><td class=\"num\">" + escape_html(text_of(at(robot, {"rms_deg"}))) +
            "</td><td class=\"num\">" + escape_html(text_of(at(robot, {"frames"}))) + " / " +
            escape_html(text_of(at(robot, {"frames_requested"}))) + "</td><td>" + escape_html(end) +
            "</td></tr>\n";
  }
  return html;
}

// The joint with the largest residual RMS: the channel a log opens on. The torso IMU is shown
// only when no joint is (a fit scores the IMU only with imu_weight > 0, so its error is often
// large and beside the point).
std::size_t worst_channel(const LogComparison& log) {
  std::optional<std::size_t> worst;
  for (std::size_t c = 0; c < log.channels.size(); ++c) {
    const double rms = log.channels[c].rms_deg;
    if (log.channels[c].name.rfind("imu.", 0) == 0 || !std::isfinite(rms)) continue;
    if (!worst || rms > log.channels[*worst].rms_deg) worst = c;
  }
  return worst.value_or(0);
}

double number_or_nan(const json& value) {
  return value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// The frequency-response columns of a channel's row: "–" where there is none, "no coherent
// frequency" where the log does not excite the joint enough.
std::string frequency_cells(const ChannelComparison& channel) {
  if (!channel.frequency) return "<td>–</td><td>–</td><td>–</td>";
  const FrequencyComparison& f = *channel.frequency;
  if (f.coherent_points == 0) return "<td colspan=\"3\" class=\"na\">no coherent frequency</td>";
  return "<td class=\"num\">" + escape_html(format_number(f.gain_rms_db, 3)) +
         "</td><td class=\"num\">" + escape_html(format_number(f.phase_rms_deg, 3)) +
         "</td><td class=\"num\">" + escape_html(format_number(f.measured_peak_hz, 3)) + " / " +
         escape_html(format_number(f.simulated_peak_hz, 3)) + "</td>";
}

}  // namespace

std::string summary_section_html(const RunRecord& record) {
  const json& s = record.summary;
  const json& inputs = record.inputs;
  std::string html = "<section id=\"summary\"><h2>Run</h2><table class=\"summary\">\n";
  add_row(html, "run folder", json(record.dir));
  if (record.fit_dir != record.dir && !record.fit_dir.empty()) {
    add_row(html, "fit shown", json(record.fit_dir + " (the loop's final model)"));
  }
  add_row(html, "name", at(s, {"name"}));
  json config = at(inputs, {"fit"});
  if (config.is_null()) config = at(record.run, {"fit"});
  add_row(html, "fit config", config);
  add_row(html, "scenario", at(inputs, {"scenario"}));
  json robot = at(inputs, {"robot"});
  if (robot.is_null()) robot = at(record.best, {"provenance", "robot"});
  add_row(html, "robot", robot);
  add_row(html, "strategy", at(s, {"strategy"}));
  add_row(html, "seed", at(inputs, {"seed"}));
  add_row(html, "evaluator", at(s, {"evaluator"}));
  add_row(html, "evaluations", at(s, {"evaluations"}));
  add_row(html, "generations", at(s, {"generations"}));
  add_row(html, "best fitness", at(s, {"best_fitness"}));
  add_row(html, "stop reason", at(s, {"stop_reason"}));
  add_row(html, "converged", at(s, {"converged"}));
  if (at(s, {"seconds"}).is_number()) {
    add_row(html, "wall time", json(seconds_text(at(s, {"seconds"}).get<double>())));
  }
  add_row(html, "training RMS error", at(s, {"rms_deg", "overall"}), " deg");
  add_row(html, "validation RMS error", at(s, {"validation", "rms_deg", "overall"}), " deg");
  add_row(html, "validation fitness", at(s, {"validation", "fitness"}));
  const json& early = at(s, {"early_termination"});
  if (early.is_object()) {
    const double simulated = number_or_nan(at(early, {"frames_simulated"}));
    const double saved = number_or_nan(at(early, {"frames_saved"}));
    std::string text = text_of(at(early, {"individuals_stopped_early"})) + " rollouts";
    if (simulated + saved > 0.0) {
      text += ", " + format_number(100.0 * saved / (simulated + saved), 3) + " % of frames saved";
    }
    add_row(html, "stopped early", json(text));
  }
  add_row(html, "fitted with motoflex", at(record.best, {"provenance", "motoflex_version"}));
  add_row(html, "finished", at(record.best, {"provenance", "date"}));
  add_row(html, "config hash", at(s, {"config_hash"}));
  html += "</table>\n";
  if (record.summary.is_null()) {
    html += "<p class=\"na\">No summary.json: the fit has not finished a generation.</p>\n";
  }
  const std::string rows = robot_rows(at(s, {"robots"}), "training") +
                           robot_rows(at(s, {"validation", "robots"}), "validation");
  if (!rows.empty()) {
    html +=
        "<h3>Per log</h3><table><thead><tr><th>log</th><th>set</th><th>fitness</th>"
        "<th>RMS (deg)</th><th>frames scored / requested</th><th>end</th></tr></thead><tbody>\n" +
        rows + "</tbody></table>\n";
  }
  return html + "</section>\n";
}

std::string convergence_section_html(const RunRecord& record) {
  std::string html = "<section id=\"convergence-section\"><h2>Convergence</h2>\n";
  if (record.generations.empty()) {
    return html + "<p class=\"na\">Not available (no generations.csv rows).</p></section>\n";
  }
  return html +
         "<p class=\"note\">Best fitness so far and the median of each generation's batch, "
         "log scale. Drag to zoom, double-click to reset.</p>\n"
         "<div id=\"convergence\" class=\"plot\"></div></section>\n";
}

std::string logs_section_html(const std::vector<LogComparison>& logs, std::size_t max_points) {
  std::string html = "<section id=\"logs\"><h2>Measured vs simulated</h2>\n";
  if (logs.empty()) {
    return html +
           "<p class=\"na\">Not available (no log with both a measured and a simulated "
           "file; see the notes at the end).</p></section>\n";
  }
  bool thinned = false;
  for (const auto& log : logs) thinned = thinned || log.thinned;
  html +=
      "<p class=\"note\">The measured angle, the best parameters' simulated angle and the "
      "residual beneath (shared time axis: drag to zoom either). Each log opens on the joint "
      "with the largest residual RMS; the selector holds the others (and the torso IMU). Below "
      "it, the joint's frequency response: the gain and phase of the measured and of the "
      "simulated angle against the commanded one (Welch's H1 estimate, Hann-windowed segments "
      "of a quarter of the log), drawn where both coherences reach " +
      format_number(kMinCoherence, 2) +
      ", i.e. where the log excites the joint and it follows linearly; a resonance or a damping "
      "the model misses shows there as a shifted peak or a gain gap.";
  if (thinned) {
    html += " Logs longer than " + std::to_string(max_points) + " frames are thinned to at most " +
            std::to_string(max_points) +
            " points per trace, keeping each bucket's minimum and maximum of the measured, "
            "simulated and residual angle, so peaks are kept; the RMS values are over every "
            "frame.";
  }
  html += "</p>\n";
  for (std::size_t i = 0; i < logs.size(); ++i) {
    const LogComparison& log = logs[i];
    const std::size_t worst = worst_channel(log);
    const std::string id = "log-" + std::to_string(i);
    html += "<div class=\"log\"><div class=\"log-head\"><h3>" + escape_html(log.name) +
            " <span class=\"tag\">" + escape_html(log.set) +
            "</span></h3><label>channel <select id=\"" + id + "-channel\">";
    for (std::size_t c = 0; c < log.channels.size(); ++c) {
      html += "<option value=\"" + std::to_string(c) + "\"" + (c == worst ? " selected" : "") +
              ">" + escape_html(log.channels[c].name) + " (RMS " +
              escape_html(format_number(log.channels[c].rms_deg, 3)) + " deg)</option>";
    }
    html +=
        "</select></label><span class=\"note\">" + std::to_string(log.time_s.size()) + " frames";
    if (log.thinned) html += ", thinned for drawing";
    if (!log.time_s.empty() && log.simulated_end_s < log.time_s.back() - 1e-9) {
      html +=
          "; the simulation ends at " + format_number(log.simulated_end_s, 4) + " s (dotted line)";
    }
    html += "</span></div>\n<div id=\"" + id + "-plot\" class=\"plot tall\"></div>\n";
    html += "<div id=\"" + id + "-bode\" class=\"plot tall\"></div>\n";
    html +=
        "<details><summary class=\"note\">residual and frequency response per "
        "channel</summary><table class=\"channels\"><thead><tr><th>channel</th><th>RMS "
        "(deg)</th><th>largest |error| (deg)</th><th>gain error (dB RMS)</th><th>phase error "
        "(deg RMS)</th><th>gain peak, measured / simulated (Hz)</th></tr></thead><tbody>";
    for (const auto& channel : log.channels) {
      html += "<tr><td>" + escape_html(channel.name) + "</td><td class=\"num\">" +
              escape_html(format_number(channel.rms_deg, 4)) + "</td><td class=\"num\">" +
              escape_html(format_number(channel.max_abs_deg, 4)) + "</td>" +
              frequency_cells(channel) + "</tr>";
    }
    html += "</tbody></table></details></div>\n";
  }
  return html + "</section>\n";
}

std::string parameters_section_html(const std::vector<ParameterRow>& rows, bool correlation) {
  std::string html = "<section id=\"parameters\"><h2>Parameters</h2>\n" +
                     parameter_table_html(rows) + "<h3>Correlation of the fitted parameters</h3>\n";
  if (correlation) {
    html += "<div id=\"correlation\" class=\"plot\"></div>\n";
  } else {
    html +=
        "<p class=\"na\">Not available (this summary.json has no <code>correlation</code> or "
        "<code>covariance</code>).</p>\n";
  }
  return html + "</section>\n";
}

std::string residuals_section_html(const RunRecord& record) {
  std::string html = "<section id=\"residuals\"><h2>Residual analysis</h2>\n";
  if (record.residuals_dir.empty()) {
    return html + "<p class=\"na\">Not available: run <code>motoflex residuals " +
           escape_html(record.fit_dir.empty() ? record.dir : record.fit_dir) +
           "</code> and then <code>motoflex report</code> again.</p></section>\n";
  }
  html += markdown_to_html(record.residuals_markdown, record.residuals_dir, 1);
  // residuals.md names its plots in a sentence; show them.
  std::vector<fs::path> plots;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(record.residuals_dir, error)) {
    if (entry.path().extension() == ".png") plots.push_back(entry.path());
  }
  std::sort(plots.begin(), plots.end());
  for (const auto& plot : plots) {
    const std::string uri = png_data_uri(plot.string());
    if (uri.empty()) continue;
    html += "<figure><img src=\"" + uri + "\" alt=\"" + escape_html(plot.filename().string()) +
            "\"><figcaption>" + escape_html(plot.filename().string()) + "</figcaption></figure>\n";
  }
  return html + "</section>\n";
}

std::string loop_section_html(const RunRecord& record) {
  if (record.loop.is_null()) return "";
  std::string html = "<section id=\"loop\"><h2>Closing the loop: before and after</h2>\n";
  const json& iterations = at(record.loop, {"iterations"});
  if (iterations.is_array() && !iterations.empty()) {
    html +=
        "<table><thead><tr><th>iteration</th><th>added effect</th><th>training RMS before → "
        "after (deg)</th><th>validation RMS before → after (deg)</th><th>change</th>"
        "</tr></thead><tbody>\n";
    for (std::size_t i = 0; i < iterations.size(); ++i) {
      const json& it = iterations[i];
      const double before = number_or_nan(at(it, {"val_rms_before"}));
      const double after = number_or_nan(at(it, {"val_rms_after"}));
      const json& added = at(it, {"added_effect"});
      const json& reoptimised = at(it, {"reoptimised"});
      const std::string what =
          added.is_string() ? added.get<std::string>()
          : reoptimised.is_boolean() && reoptimised.get<bool>()
              ? "– (re-optimised: " + text_of(at(it, {"reoptimised_from"})) + ")"
              : "–";
      html +=
          "<tr><td>" + std::to_string(i + 1) + "</td><td>" + escape_html(what) +
          "</td><td class=\"num\">" +
          escape_html(format_number(number_or_nan(at(it, {"train_rms_before"})), 4)) + " → " +
          escape_html(format_number(number_or_nan(at(it, {"train_rms_after"})), 4)) +
          "</td><td class=\"num\">" + escape_html(format_number(before, 4)) + " → " +
          escape_html(format_number(after, 4)) + "</td><td class=\"num\">" +
          (before > 0.0 ? escape_html(format_number(100.0 * (after - before) / before, 3)) + " %"
                        : std::string("n/a")) +
          "</td></tr>\n";
    }
    html += "</tbody></table>\n";
  }
  if (!record.loop_markdown.empty()) {
    html += "<details open><summary>report.md of the loop</summary>\n" +
            markdown_to_html(record.loop_markdown, record.dir, 1) + "</details>\n";
  }
  return html + "</section>\n";
}

}  // namespace motoflex::report
