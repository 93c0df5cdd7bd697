// The parameter table: start and bounds from inputs.json, the fitted value from best.json, and
// the uncertainty columns only when summary.json carries them.

#include "motoflex/report/parameter_table.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "motoflex/core/error.hpp"

namespace motoflex::report {
namespace {

using json = nlohmann::json;

json inputs_json() {
  return json::parse(R"({"free": [
    {"name": "pid.kp_v_per_rad", "unit": "V/rad", "start": 150, "lower": 50, "upper": 2000,
     "log": true},
    {"name": "joint.*Roll.friction_nm", "unit": "N·m", "start": 0.4, "lower": 0.01,
     "upper": 5, "log": false}]})");
}

json best_json() {
  return json::parse(R"({"free": {"pid.kp_v_per_rad": 321.5, "joint.*Roll.friction_nm": 4.99}})");
}

TEST(ParameterRows, StartBoundsAndFittedValueWithoutUncertainty) {
  const json summary = json::parse(R"({"best_fitness": 1e-6})");
  const auto rows = parameter_rows(inputs_json(), best_json(), summary,
                                   read_parameter_uncertainty(summary, "summary.json"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].name, "pid.kp_v_per_rad");
  EXPECT_EQ(rows[0].unit, "V/rad");
  EXPECT_EQ(rows[0].start, 150.0);
  EXPECT_EQ(rows[0].lower, 50.0);
  EXPECT_EQ(rows[0].upper, 2000.0);
  EXPECT_EQ(rows[0].fitted, 321.5);
  EXPECT_TRUE(rows[0].log_scale);
  EXPECT_TRUE(std::isnan(rows[0].interval.standard_error));
  EXPECT_FALSE(at_bound(rows[0]));
  EXPECT_TRUE(at_bound(rows[1]));  // 4.99 of [0.01, 5]

  const std::string html = parameter_table_html(rows);
  EXPECT_NE(html.find("<code>pid.kp_v_per_rad</code>"), std::string::npos);
  EXPECT_NE(html.find("321.5"), std::string::npos);
  EXPECT_NE(html.find("not available"), std::string::npos);
  EXPECT_NE(html.find("within 1 % of a bound"), std::string::npos);
}

TEST(ParameterRows, IntervalsAndCorrelationFromTheSummary) {
  const json summary = json::parse(R"({
    "confidence_intervals": {
      "pid.kp_v_per_rad": {"standard_error": 12.5, "lower": 297.0, "upper": 346.0},
      "joint.*Roll.friction_nm": [4.9, 5.0]},
    "correlation": {"names": ["pid.kp_v_per_rad", "joint.*Roll.friction_nm"],
                    "matrix": [[1, -0.83], [-0.83, 1]]}})");
  const ParameterUncertainty uncertainty = read_parameter_uncertainty(summary, "summary.json");
  const auto rows = parameter_rows(inputs_json(), best_json(), summary, uncertainty);
  EXPECT_EQ(rows[0].interval.standard_error, 12.5);
  EXPECT_EQ(rows[0].interval.lower, 297.0);
  EXPECT_EQ(rows[0].interval.upper, 346.0);
  EXPECT_TRUE(std::isnan(rows[1].interval.standard_error));
  EXPECT_EQ(rows[1].interval.lower, 4.9);
  ASSERT_EQ(uncertainty.correlation.names.size(), 2u);
  EXPECT_EQ(uncertainty.correlation.values[0][1], -0.83);

  const std::string html = parameter_table_html(rows);
  EXPECT_EQ(html.find("not available"), std::string::npos);
  EXPECT_NE(html.find("[297, 346]"), std::string::npos);
  EXPECT_NE(html.find("12.5"), std::string::npos);
}

TEST(ParameterTableHtml, IntervalsTheFitDoesNotTrustAreMarked) {
  // kp: the residual is not linear in it over the Jacobian's step (a chaotic walk); friction:
  // its interval spans most of the bounds.
  const json summary = json::parse(R"({
    "confidence_intervals": {
      "pid.kp_v_per_rad": {"standard_error": 0.1, "lower": 321.3, "upper": 321.7,
                           "nonlinearity": 0.93, "linear": false, "identified": false},
      "joint.*Roll.friction_nm": {"standard_error": 2.0, "lower": 0.5, "upper": 5.0,
                                  "nonlinearity": 0.01, "linear": true, "identified": false}}})");
  const ParameterUncertainty uncertainty = read_parameter_uncertainty(summary, "summary.json");
  const auto rows = parameter_rows(inputs_json(), best_json(), summary, uncertainty);
  EXPECT_FALSE(rows[0].interval.linear);
  EXPECT_DOUBLE_EQ(rows[0].interval.nonlinearity, 0.93);
  EXPECT_TRUE(rows[1].interval.linear);
  EXPECT_FALSE(rows[1].interval.identified);
  const std::string html = parameter_table_html(rows);
  EXPECT_NE(html.find("[321.3, 321.7] ⚠ not linear"), std::string::npos);
  EXPECT_NE(html.find("[0.5, 5] ⚠ not identified"), std::string::npos);
  const json bad = json::parse(R"({"confidence_intervals": {"a": {"linear": 1}}})");
  try {
    read_parameter_uncertainty(bad, "run/summary.json");
    FAIL() << "a non-boolean verdict was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "confidence_intervals.a.linear");
  }
}

TEST(ParameterUncertaintyTest, CovarianceGivesStandardErrorsAndCorrelation) {
  // Object-of-objects form.
  const json summary = json::parse(R"({"covariance": {
    "a": {"a": 4.0, "b": 3.0},
    "b": {"a": 3.0, "b": 9.0}}})");
  const ParameterUncertainty u = read_parameter_uncertainty(summary, "summary.json");
  EXPECT_DOUBLE_EQ(u.intervals.at("a").standard_error, 2.0);
  EXPECT_DOUBLE_EQ(u.intervals.at("b").standard_error, 3.0);
  EXPECT_TRUE(std::isnan(u.intervals.at("a").lower));
  ASSERT_EQ(u.correlation.names, (std::vector<std::string>{"a", "b"}));
  EXPECT_DOUBLE_EQ(u.correlation.values[0][1], 0.5);
  EXPECT_DOUBLE_EQ(u.correlation.values[1][1], 1.0);
}

TEST(ParameterUncertaintyTest, MalformedKeysNameTheFileAndField) {
  const json not_square = json::parse(R"({"correlation": {"names": ["a", "b"],
                                                          "matrix": [[1, 0], [0]]}})");
  try {
    read_parameter_uncertainty(not_square, "run/summary.json");
    FAIL() << "a ragged matrix was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "run/summary.json");
    EXPECT_EQ(error.field(), "correlation.matrix[1]");
  }
  const json bad_interval = json::parse(R"({"confidence_intervals": {"a": {"lower": "x"}}})");
  EXPECT_THROW(read_parameter_uncertainty(bad_interval, "s.json"), InputError);
  // Absent keys and a missing summary are simply "not available".
  EXPECT_TRUE(read_parameter_uncertainty(json(), "s.json").intervals.empty());
  EXPECT_TRUE(read_parameter_uncertainty(json::object(), "s.json").correlation.empty());
}

TEST(ParameterRows, WithoutInputsTheFittedValuesAloneWithUnitsFromTheirNames) {
  const auto rows = parameter_rows(json(), best_json(), json(), {});
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    EXPECT_TRUE(std::isnan(row.start));
    EXPECT_TRUE(std::isnan(row.lower));
    EXPECT_FALSE(at_bound(row));
  }
  // best.json's object is read in name order.
  EXPECT_EQ(rows[0].name, "joint.*Roll.friction_nm");
  EXPECT_EQ(rows[0].unit, "N·m");
  EXPECT_EQ(rows[1].unit, "V/rad");
  EXPECT_EQ(rows[1].fitted, 321.5);
  EXPECT_NE(parameter_table_html(rows).find("n/a"), std::string::npos);
  EXPECT_NE(parameter_table_html({}).find("No free parameters"), std::string::npos);
}

TEST(ParameterTableHtml, NamesAreEscaped) {
  ParameterRow row;
  row.name = "<b>x</b>";
  const std::string html = parameter_table_html({row});
  EXPECT_EQ(html.find("<b>x</b>"), std::string::npos);
  EXPECT_NE(html.find("&lt;b&gt;x&lt;/b&gt;"), std::string::npos);
}

TEST(ParameterRows, SensitivityFromTheSummaryAndTheUndeterminedFlagged) {
  const json summary = json::parse(R"({"sensitivity": {"parameters": {
    "pid.kp_v_per_rad": {"relative_fitness_change_per_bound_width": 46.5, "determined": true},
    "joint.*Roll.friction_nm": {"relative_fitness_change_per_bound_width": 0.0,
                                "determined": false}}}})");
  const auto rows = parameter_rows(inputs_json(), best_json(), summary,
                                   read_parameter_uncertainty(summary, "summary.json"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].sensitivity, 46.5);
  EXPECT_FALSE(rows[0].undetermined);
  EXPECT_EQ(rows[1].sensitivity, 0.0);
  EXPECT_TRUE(rows[1].undetermined);
  const std::string html = parameter_table_html(rows);
  EXPECT_NE(html.find("<th title=\"relative fitness change per bound-width"), std::string::npos);
  EXPECT_NE(html.find("not determined"), std::string::npos) << html;
  // A summary without the field (older runs): not available, nothing flagged.
  const auto old_rows = parameter_rows(inputs_json(), best_json(), json::object(), {});
  EXPECT_TRUE(std::isnan(old_rows[0].sensitivity));
  EXPECT_EQ(parameter_table_html(old_rows).find("not determined"), std::string::npos);
}

}  // namespace
}  // namespace motoflex::report
