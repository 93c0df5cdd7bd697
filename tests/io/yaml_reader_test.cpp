#include "motoflex/io/yaml_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "input_error_support.hpp"
#include "motoflex/core/error.hpp"
#include "scratch_dir.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

using YamlReaderTest = testing::ScratchFolderTest;
using testing::expect_input_error;

constexpr const char* kConfig =
    "name: walk test\n"               // 1
    "physics:\n"                      // 2
    "  dt_s: 0.001\n"                 // 3
    "  substeps: 4\n"                 // 4
    "  gravity: [0, 0, -9.81]\n"      // 5
    "  contacts: true\n"              // 6
    "robots:\n"                       // 7
    "  - name: nao\n"                 // 8
    "    urdf: ../robots/nao.urdf\n"  // 9
    "  - name: titan\n"               // 10
    "    urdf: /abs/titan.urdf\n"     // 11
    "tags: [a, \"b c\", 3]\n"         // 12
    "signed: +1.5\n"                  // 13
    "fraction: .5\n"                  // 14
    "exponent: -2.5e-3\n"             // 15
    "negative_int: -7\n";             // 16

TEST_F(YamlReaderTest, ReadsTypedValuesWithFieldsAndLines) {
  const std::string path = write("config.yaml", kConfig);
  const YamlValue root = YamlValue::load_file(path);
  EXPECT_EQ(root.file(), path);
  EXPECT_EQ(root.line(), 1);
  EXPECT_EQ(root.at("name").as_string(), "walk test");

  const YamlValue physics = root.at("physics");
  EXPECT_EQ(physics.field(), "physics");
  EXPECT_EQ(physics.line(), 2);
  const YamlValue dt = physics.at("dt_s");
  EXPECT_EQ(dt.field(), "physics.dt_s");
  EXPECT_EQ(dt.line(), 3);
  EXPECT_EQ(dt.as_double(), 0.001);
  EXPECT_EQ(physics.at("substeps").as_int(), 4);
  EXPECT_EQ(physics.at("gravity").as_double_list(), (std::vector<double>{0, 0, -9.81}));
  EXPECT_TRUE(physics.at("contacts").as_bool());
  EXPECT_EQ(root.at("tags").as_string_list(), (std::vector<std::string>{"a", "b c", "3"}));
  EXPECT_EQ(root.at("signed").as_double(), 1.5);
  EXPECT_EQ(root.at("fraction").as_double(), 0.5);
  EXPECT_EQ(root.at("exponent").as_double(), -2.5e-3);
  EXPECT_EQ(root.at("negative_int").as_int(), -7);
  EXPECT_EQ(root.at("negative_int").as_double(), -7.0);

  const std::vector<YamlValue> robots = root.at("robots").items();
  ASSERT_EQ(robots.size(), 2u);
  EXPECT_EQ(robots[1].field(), "robots[1]");
  EXPECT_EQ(robots[1].line(), 10);
  const YamlValue urdf = robots[1].at("urdf");
  EXPECT_EQ(urdf.field(), "robots[1].urdf");
  EXPECT_EQ(urdf.line(), 11);
}

TEST_F(YamlReaderTest, EntriesKeepDocumentOrder) {
  const YamlValue root = YamlValue::parse("zeta: 1\nalpha: 2\nmid: 3\n", "order.yaml");
  const auto entries = root.entries();
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].first, "zeta");
  EXPECT_EQ(entries[1].first, "alpha");
  EXPECT_EQ(entries[2].first, "mid");
  EXPECT_EQ(entries[2].second.field(), "mid");
  EXPECT_EQ(entries[2].second.line(), 3);
  EXPECT_EQ(entries[1].second.as_int(), 2);
}

TEST_F(YamlReaderTest, FindHasAndDefaults) {
  const YamlValue root = YamlValue::parse("a: 2.5\nflag: false\nn: 3\ns: text\n", "d.yaml");
  EXPECT_TRUE(root.has("a"));
  EXPECT_FALSE(root.has("b"));
  EXPECT_FALSE(root.find("b").has_value());
  EXPECT_EQ(root.get_double("a", 1.0), 2.5);
  EXPECT_EQ(root.get_double("b", 1.0), 1.0);
  EXPECT_EQ(root.get_int("n", 0), 3);
  EXPECT_EQ(root.get_int("m", 9), 9);
  EXPECT_FALSE(root.get_bool("flag", true));
  EXPECT_TRUE(root.get_bool("other", true));
  EXPECT_EQ(root.get_string("s", "x"), "text");
  EXPECT_EQ(root.get_string("t", "x"), "x");
  expect_input_error([&] { root.get_int("a", 0); }, "d.yaml", 1, "a");
}

TEST_F(YamlReaderTest, EmptyValueCountsAsEmptyMappingOrSequence) {
  const YamlValue root = YamlValue::parse("parameters:\nlist:\nafter: 1\n", "e.yaml");
  EXPECT_TRUE(root.at("parameters").entries().empty());
  EXPECT_FALSE(root.at("parameters").has("x"));
  EXPECT_TRUE(root.at("list").items().empty());
  EXPECT_TRUE(root.at("list").as_double_list().empty());
  // ...but it is not a number or a string, and its line is the key's line.
  expect_input_error([&] { root.at("list").as_double(); }, "e.yaml", 2, "list");
  expect_input_error([&] { root.at("list").as_string(); }, "e.yaml", 2, "list");
}

TEST_F(YamlReaderTest, MissingFile) {
  const std::string path = (dir_ / "absent.yaml").string();
  const std::string message = expect_input_error([&] { YamlValue::load_file(path); }, path, 0, "");
  EXPECT_NE(message.find("not found"), std::string::npos);
}

TEST_F(YamlReaderTest, SyntaxErrorCarriesLine) {
  const std::string path = write("bad.yaml", "a: 1\nb: [1, 2\nc: 3\n");
  // yaml-cpp notices the unclosed flow sequence at "c: 3".
  const std::string message = expect_input_error([&] { YamlValue::load_file(path); }, path, 3, "");
  EXPECT_NE(message.find("YAML syntax error"), std::string::npos);

  const std::string tabs = write("tabs.yaml", "a:\n  b: 1\n c: 2\n");
  expect_input_error([&] { YamlValue::load_file(tabs); }, tabs, 3, "");
}

TEST_F(YamlReaderTest, RejectsDuplicateKeysAnywhere) {
  expect_input_error([] { YamlValue::parse("a: 1\nb: 2\na: 3\n", "dup.yaml"); }, "dup.yaml", 3,
                     "a");
  expect_input_error([] { YamlValue::parse("top:\n  list:\n    - {x: 1, x: 2}\n", "dup.yaml"); },
                     "dup.yaml", 3, "top.list[0].x");
}

TEST_F(YamlReaderTest, RejectsMultipleDocumentsAndComplexKeys) {
  // The line of the second document's '---' marker (the documents are counted by an event
  // handler, not by yaml-cpp's LoadAll, which can loop forever on malformed input).
  expect_input_error([] { YamlValue::parse("a: 1\n---\nb: 2\n", "multi.yaml"); }, "multi.yaml", 2,
                     "");
  expect_input_error([] { YamlValue::parse("? [a, b]\n: 1\n", "key.yaml"); }, "key.yaml", 1, "");
}

TEST_F(YamlReaderTest, MissingRequiredKeyNamesDottedField) {
  const YamlValue root = YamlValue::parse("x: 1\nphysics:\n  substeps: 2\n", "m.yaml");
  const std::string message =
      expect_input_error([&] { root.at("physics").at("dt_s"); }, "m.yaml", 2, "physics.dt_s");
  EXPECT_EQ(message, "missing required key");
  expect_input_error([&] { root.at("robot"); }, "m.yaml", 1, "robot");
}

TEST_F(YamlReaderTest, RejectsIllTypedNumbers) {
  const YamlValue root = YamlValue::parse(
      "word: abc\n"        // 1
      "half: 1.5\n"        // 2
      "nan: .nan\n"        // 3
      "inf: .inf\n"        // 4
      "ninf: -.Inf\n"      // 5
      "cnan: nan\n"        // 6
      "cinf: inf\n"        // 7
      "quoted: \"1.5\"\n"  // 8
      "huge: 1e999\n"      // 9
      "big: 3000000000\n"  // 10
      "exp: 1e3\n"         // 11
      "hex: 0x10\n"        // 12
      "map: {a: 1}\n"      // 13
      "seq: [1]\n"         // 14
      "tagged: !!str 5\n"  // 15
      "yes: yes\n"         // 16
      "list: [1, x, 3]\n"  // 17
      "trail: 1.5x\n",     // 18
      "t.yaml");
  const auto check_double = [&](const char* key, int line) {
    expect_input_error([&] { root.at(key).as_double(); }, "t.yaml", line, key);
  };
  const auto check_int = [&](const char* key, int line) {
    expect_input_error([&] { root.at(key).as_int(); }, "t.yaml", line, key);
  };
  check_double("word", 1);
  check_double("nan", 3);
  check_double("inf", 4);
  check_double("ninf", 5);
  check_double("cnan", 6);
  check_double("cinf", 7);
  check_double("quoted", 8);
  check_double("huge", 9);
  check_double("hex", 12);
  check_double("map", 13);
  check_double("seq", 14);
  check_double("tagged", 15);
  check_double("trail", 18);
  check_int("half", 2);
  check_int("big", 10);
  check_int("exp", 11);
  check_int("word", 1);
  EXPECT_EQ(root.at("exp").as_double(), 1000.0);
  EXPECT_EQ(root.at("big").as_double(), 3e9);
  expect_input_error([&] { root.at("yes").as_bool(); }, "t.yaml", 16, "yes");
  expect_input_error([&] { root.at("half").as_bool(); }, "t.yaml", 2, "half");
  expect_input_error([&] { root.at("map").as_string(); }, "t.yaml", 13, "map");
  expect_input_error([&] { root.at("list").as_double_list(); }, "t.yaml", 17, "list[1]");
  expect_input_error([&] { root.at("word").as_double_list(); }, "t.yaml", 1, "word");
  expect_input_error([&] { root.at("seq").entries(); }, "t.yaml", 14, "seq");
  const std::string message =
      expect_input_error([&] { root.at("nan").as_double(); }, "t.yaml", 3, "nan");
  EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
}

TEST_F(YamlReaderTest, UnknownKeySuggestsClosestAllowedKey) {
  const YamlValue root = YamlValue::parse("physics:\n  dt_s: 0.001\n  dtt_s: 2\n", "k.yaml");
  const YamlValue physics = root.at("physics");
  const std::string message = expect_input_error(
      [&] {
        physics.require_keys_within({"dt_s", "substeps"});
      },
      "k.yaml", 3, "physics.dtt_s");
  EXPECT_NE(message.find("unknown key 'dtt_s'"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'dt_s'?"), std::string::npos) << message;
  // Nothing close: list the allowed keys instead of guessing.
  const std::string far = expect_input_error(
      [&] {
        physics.require_keys_within({"substeps", "gravity"});
      },
      "k.yaml", 2, "physics.dt_s");
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
  EXPECT_NE(far.find("allowed: substeps gravity"), std::string::npos) << far;
  physics.require_keys_within({"dt_s", "dtt_s"});
}

TEST_F(YamlReaderTest, UnknownKeyWithoutCloseMatchListsAllowedKeys) {
  const YamlValue root = YamlValue::parse("robot: nao\ncolour: red\n", "c.yaml");
  const std::string message = expect_input_error(
      [&] {
        root.require_keys_within({"robot", "rate_hz"});
      },
      "c.yaml", 2, "colour");
  EXPECT_NE(message.find("allowed: robot rate_hz"), std::string::npos) << message;
}

TEST_F(YamlReaderTest, UnknownKeyMissingItsUnitSuggestsTheUnitKey) {
  const YamlValue root = YamlValue::parse("dt: 0.001\n", "u.yaml");
  const std::string message = expect_input_error(
      [&] {
        root.require_keys_within({"dt_s", "gravity"});
      },
      "u.yaml", 1, "dt");
  EXPECT_NE(message.find("did you mean 'dt_s'?"), std::string::npos) << message;
}

TEST_F(YamlReaderTest, FailUsesValueLocation) {
  const YamlValue root = YamlValue::parse("a:\n  b: -1\n", "f.yaml");
  const std::string message = expect_input_error(
      [&] { root.at("a").at("b").fail("must be positive"); }, "f.yaml", 2, "a.b");
  EXPECT_EQ(message, "must be positive");
}

TEST_F(YamlReaderTest, ResolvesPathsAgainstTheFilesFolder) {
  const YamlValue nested = YamlValue::parse("{}", "/data/scenarios/walk.yaml");
  EXPECT_EQ(nested.resolve_path("../robots/nao.urdf"), "/data/robots/nao.urdf");
  EXPECT_EQ(nested.resolve_path("logs/walk.csv"), "/data/scenarios/logs/walk.csv");
  EXPECT_EQ(nested.resolve_path("/abs/x.csv"), "/abs/x.csv");
  const YamlValue bare = YamlValue::parse("{}", "walk.yaml");
  EXPECT_EQ(bare.resolve_path("logs/walk.csv"), "logs/walk.csv");
  const YamlValue relative = YamlValue::parse("{}", "scenarios/walk.yaml");
  EXPECT_EQ(relative.resolve_path("./a.csv"), "scenarios/a.csv");
}

TEST_F(YamlReaderTest, EmptyFileIsAnEmptyDocument) {
  const std::string path = write("empty.yaml", "");
  const YamlValue root = YamlValue::load_file(path);
  EXPECT_TRUE(root.is_null());
  EXPECT_TRUE(root.entries().empty());
  expect_input_error([&] { root.at("robot"); }, path, 0, "robot");
}

TEST(EditDistance, CountsInsertionsDeletionsSubstitutions) {
  EXPECT_EQ(edit_distance("", ""), 0);
  EXPECT_EQ(edit_distance("abc", ""), 3);
  EXPECT_EQ(edit_distance("dt_s", "dt_s"), 0);
  EXPECT_EQ(edit_distance("dtt_s", "dt_s"), 1);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
  EXPECT_EQ(edit_distance("rate", "rate_hz"), 3);
}

}  // namespace
}  // namespace motoflex
