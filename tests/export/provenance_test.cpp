// Every export says where its numbers came from: the fit's run, config hash and fitness, each
// log it was fitted and validated on with the hash of the file, and the fitted values with the
// 95 % intervals the fit's summary.json carries (issue 22 item 5).

#include <gtest/gtest.h>
#include <tinyxml.h>

#include <nlohmann/json.hpp>
#include <string>

#include "export_test_support.hpp"
#include "motoflex/export/exporter.hpp"

namespace motoflex {
namespace {

std::string exported(const ExportInput& input, const std::string& format) {
  const Exporter* exporter = find_exporter(format);
  EXPECT_NE(exporter, nullptr);
  const ExportedFile file = exporter->write(input, {});
  EXPECT_EQ(exporter->read_back_errors(file), "") << format;
  return file.text;
}

TEST(ExportProvenance, EveryFormatNamesTheRunTheDataAndTheIntervals) {
  const auto f = testing::fitted_fixture("servo_pendulum", "bench");
  const FitProvenance& p = f.input->provenance;
  ASSERT_EQ(p.data.size(), 2u);
  ASSERT_EQ(p.fitted.size(), 2u);
  EXPECT_EQ(p.fitted[1].name, "motor.R_ohm");
  EXPECT_EQ(p.fitted[1].lower, 6.25);
  EXPECT_EQ(p.fitted[1].upper, 6.75);
  EXPECT_TRUE(std::isnan(p.fitted[0].lower));  // no interval for the tie
  for (const std::string format : {"mjcf", "sdf", "urdf"}) {
    const std::string text = exported(*f.input, format);
    EXPECT_NE(text.find("data: train logs/walk.csv #0123abcd"), std::string::npos) << format;
    EXPECT_NE(text.find("data: validation logs/kick.csv #4567ef"), std::string::npos) << format;
    EXPECT_NE(text.find("fitted: motor.R_ohm = 6.5 [6.25, 6.75] (95 %)"), std::string::npos)
        << format;
    EXPECT_NE(text.find("fitted: joint.*.friction_nm = 0.5\n"), std::string::npos) << format;
    EXPECT_NE(text.find("config_hash: abc123"), std::string::npos) << format;
    EXPECT_NE(text.find("run: " + p.run_dir), std::string::npos) << format;
    EXPECT_NE(text.find("exported_by: motoflex "), std::string::npos) << format;
  }
  const auto json = nlohmann::json::parse(exported(*f.input, "json"));
  EXPECT_EQ(json["provenance"]["data"][0]["hash"], "0123abcd");
  EXPECT_EQ(json["provenance"]["fitted"]["motor.R_ohm"]["ci95_upper"], 6.75);
  EXPECT_TRUE(json["provenance"]["fitted"]["joint.*.friction_nm"]["ci95_lower"].is_null());
}

TEST(ExportProvenance, ADoubleHyphenInAPathCannotBreakTheXmlComment) {
  auto f = testing::fitted_fixture("servo_pendulum", "bench");
  f.input->provenance.data.push_back({"train", "logs/a--b.csv", "99"});
  TiXmlDocument document;
  document.Parse(exported(*f.input, "mjcf").c_str());
  EXPECT_FALSE(document.Error()) << document.ErrorDesc();
}

}  // namespace
}  // namespace motoflex
