// The JSON export is lossless: every parameter with its unit and bounds, the provenance of
// best.json, and the joint-level values the other formats carry.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "export_test_support.hpp"
#include "motoflex/core/build_info.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "motoflex/export/json_export.hpp"

namespace motoflex {
namespace {

using testing::fitted_fixture;

TEST(JsonExport, CarriesEveryParameterWithUnitAndTheProvenance) {
  const auto f = fitted_fixture("nao", "motoflex");
  const nlohmann::json out = nlohmann::json::parse(export_json(*f.input));
  EXPECT_EQ(out["format"], "motoflex-parameters");
  EXPECT_EQ(out["robot"], "nao");
  EXPECT_EQ(out["servo"], "motoflex");
  const ParameterRegistry& registry = f.model->parameters;
  ASSERT_EQ(out["parameters"].size(), registry.size());
  for (std::size_t i = 0; i < registry.size(); ++i) {
    const ParameterSpec& spec = registry.spec(i);
    const nlohmann::json& p = out["parameters"][spec.name];
    EXPECT_EQ(p["value"].get<double>(), f.input->parameters.get(i)) << spec.name;  // bit-exact
    EXPECT_EQ(p["unit"], spec.unit) << spec.name;
    EXPECT_EQ(p["lower"].get<double>(), spec.lower);
    EXPECT_EQ(p["upper"].get<double>(), spec.upper);
    const bool free = spec.name == "motor.R_ohm" ||
                      (spec.name.rfind("joint.", 0) == 0 && spec.name.size() > 12 &&
                       spec.name.compare(spec.name.size() - 12, 12, ".friction_nm") == 0);
    EXPECT_EQ(p["free"].get<bool>(), free) << spec.name;
  }
  EXPECT_EQ(out["parameters"]["motor.R_ohm"]["unit"], "Ω");
  EXPECT_EQ(out["parameters"]["gear.A.spring_nm_per_rad"]["unit"], "N·m/rad");

  const nlohmann::json& p = out["provenance"];
  EXPECT_EQ(p["config_hash"], "abc123");
  EXPECT_EQ(p["fitness"].get<double>(), 0.0123);
  EXPECT_EQ(p["date"], "2025-01-02T03:04:05Z");
  EXPECT_EQ(p["motoflex_version"], "0.1.0");
  EXPECT_EQ(p["fit"], "fits/test.yaml");
  EXPECT_EQ(p["exported_by"], std::string("motoflex ") + version());

  const auto actuators = export_actuators(*f.input);
  ASSERT_EQ(out["joints"].size(), actuators.size());
  for (const auto& a : actuators) {
    EXPECT_EQ(out["joints"][a.joint]["damping_nm_s_per_rad"].get<double>(), a.damping_nm_s_per_rad);
    EXPECT_EQ(out["joints"][a.joint]["reduction"].get<double>(), a.reduction);
  }
}

TEST(JsonExport, PlainParameterFileHasNoFitProvenance) {
  const auto model = testing::load_robot("servo_pendulum");
  const auto dir = testing::fresh_export_dir("json_plain");
  const std::string path = (dir / "params.json").string();
  std::ofstream(path) << R"({"bench.Kt_nm_per_a": 0.35, "bench.R_ohm": 2.4})";
  ExportInput input{*model, ParameterSet(model->parameters), "bench", {}, 0.001};
  input.provenance = read_fitted_parameters(path, model->name, input.parameters);
  const nlohmann::json out = nlohmann::json::parse(export_json(input));
  EXPECT_EQ(out["parameters"]["bench.Kt_nm_per_a"]["value"].get<double>(), 0.35);
  EXPECT_EQ(out["parameters"]["bench.R_ohm"]["unit"], "Ω");
  EXPECT_TRUE(out["provenance"]["fitness"].is_null());
  EXPECT_TRUE(out["provenance"]["config_hash"].is_null());
  EXPECT_EQ(out["provenance"]["source"], path);
}

TEST(JsonExport, RejectsParametersOfAnotherRobotAndUnknownNames) {
  const auto nao = testing::load_robot("nao");
  const auto pendulum = testing::load_robot("servo_pendulum");
  const auto dir = testing::fresh_export_dir("json_wrong_robot");
  const std::string best = testing::write_best_json(dir, *nao, {});
  ParameterSet set(pendulum->parameters);
  EXPECT_THROW(read_fitted_parameters(best, "servo_pendulum", set), InputError);
  const std::string unknown = (dir / "unknown.json").string();
  std::ofstream(unknown) << R"({"bench.Kt_nm_per_aa": 0.35})";
  EXPECT_THROW(read_fitted_parameters(unknown, "servo_pendulum", set), InputError);
}

}  // namespace
}  // namespace motoflex
