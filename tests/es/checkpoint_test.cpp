#include "motoflex_es/checkpoint.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "motoflex_es/cma_es.hpp"
#include "motoflex_es/mu_plus_lambda.hpp"
#include "motoflex_es/random.hpp"
#include "test_problems.hpp"

namespace motoflex_es {
namespace {

namespace fs = std::filesystem;

class EsCheckpointTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("motoflex_es_checkpoint_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  std::string path(const std::string& name) const { return (folder_ / name).string(); }

  static std::string read(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  static void write(const std::string& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
  }

  // A MuPlusLambda a few generations into a run, and its checkpoint at `file`.
  static MuPlusLambdaOptions options() {
    MuPlusLambdaOptions o;
    o.mu = 4;
    o.lambda = 20;
    o.seed = 8;
    return o;
  }
  static Bounds bounds() {
    return Bounds{std::vector<double>(3, -5.0), std::vector<double>(3, 5.0)};
  }
  void write_run_checkpoint(const std::string& file, const std::string& hash) {
    MuPlusLambda es(bounds(), options());
    for (int g = 0; g < 5; ++g) {
      const auto xs = es.ask();
      std::vector<double> fitness;
      for (const auto& x : xs) fitness.push_back(testing::benchmark(testing::Function::kSphere, x));
      es.tell(fitness);
    }
    Checkpoint checkpoint;
    checkpoint.config_hash = hash;
    checkpoint.strategy_state = es.save_state();
    checkpoint.extra = {{"rows_written", 5}};
    write_checkpoint(file, checkpoint);
  }

  // The CheckpointError message of reading `file`; fails the test if nothing is thrown.
  static std::string error_of(const std::string& file, const std::string& hash) {
    try {
      read_checkpoint(file, hash);
    } catch (const CheckpointError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
      return message;
    }
    ADD_FAILURE() << "no CheckpointError for " << file;
    return {};
  }

  fs::path folder_;
};

TEST_F(EsCheckpointTest, NlohmannWritesDoublesThatReadBackBitExactly) {
  std::vector<double> values = {0.1,
                                1.0 / 3.0,
                                M_PI,
                                -0.0,
                                5e-324,  // smallest subnormal
                                2.2250738585072009e-308,
                                DBL_MIN,
                                DBL_MAX,
                                -DBL_MAX,
                                1e23,
                                9007199254740993.0,
                                std::nextafter(1.0, 2.0)};
  motoflex::RandomStream bits = es_stream(1, 0, 0, Purpose::kTest);
  while (values.size() < 20000) {
    const std::uint64_t pattern = bits.next_u64();
    double value;
    std::memcpy(&value, &pattern, sizeof value);
    if (std::isfinite(value)) values.push_back(value);
  }
  for (double value : values) {
    const double back = nlohmann::json::parse(nlohmann::json(value).dump()).get<double>();
    ASSERT_EQ(std::memcmp(&back, &value, sizeof value), 0) << nlohmann::json(value).dump();
  }
}

TEST_F(EsCheckpointTest, RoundTripRestoresTheStrategyExactly) {
  write_run_checkpoint(path("run.ckpt"), "abc123");
  const Checkpoint loaded = read_checkpoint(path("run.ckpt"), "abc123");
  EXPECT_EQ(loaded.config_hash, "abc123");
  EXPECT_EQ(loaded.extra.at("rows_written"), 5);
  MuPlusLambda resumed(bounds(), options());
  resumed.load_state(loaded.strategy_state);
  EXPECT_EQ(resumed.save_state(), loaded.strategy_state);
  EXPECT_EQ(resumed.generation(), 5u);
  // The state of a fresh strategy holds +inf (best fitness); it survives as "inf".
  MuPlusLambda fresh(bounds(), options());
  Checkpoint initial;
  initial.config_hash = "h";
  initial.strategy_state = fresh.save_state();
  write_checkpoint(path("fresh.ckpt"), initial);
  MuPlusLambda reloaded(bounds(), options());
  reloaded.load_state(read_checkpoint(path("fresh.ckpt"), "h").strategy_state);
  EXPECT_EQ(reloaded.best_fitness(), std::numeric_limits<double>::infinity());
}

TEST_F(EsCheckpointTest, WritingLeavesNoTemporaryFilesAndReplacesTheOldOne) {
  write_run_checkpoint(path("run.ckpt"), "first");
  write_run_checkpoint(path("run.ckpt"), "second");
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder_)) {
    names.push_back(entry.path().filename().string());
  }
  EXPECT_EQ(names, std::vector<std::string>{"run.ckpt"});
  EXPECT_NO_THROW(read_checkpoint(path("run.ckpt"), "second"));
  EXPECT_THROW(write_checkpoint(path("missing_folder/run.ckpt"), Checkpoint{}), CheckpointError);
}

TEST_F(EsCheckpointTest, TruncatedCheckpointIsRejected) {
  write_run_checkpoint(path("run.ckpt"), "h");
  const std::string text = read(path("run.ckpt"));
  write(path("run.ckpt"), text.substr(0, text.size() / 2));
  EXPECT_NE(error_of(path("run.ckpt"), "h").find("truncated or corrupt"), std::string::npos);
  write(path("empty.ckpt"), "");
  EXPECT_NE(error_of(path("empty.ckpt"), "h").find("not valid JSON"), std::string::npos);
}

TEST_F(EsCheckpointTest, CorruptedPayloadIsRejected) {
  write_run_checkpoint(path("run.ckpt"), "h");
  std::string text = read(path("run.ckpt"));
  // Change one digit of a number in the population: still valid JSON, but not what was written.
  const std::size_t at = text.find("\"fitness\":");
  ASSERT_NE(at, std::string::npos);
  std::size_t digit = text.find_first_of("0123456789", at);
  text[digit] = text[digit] == '7' ? '8' : '7';
  write(path("run.ckpt"), text);
  EXPECT_NE(error_of(path("run.ckpt"), "h").find("payload is corrupt"), std::string::npos);
}

TEST_F(EsCheckpointTest, ConfigHashMismatchIsRejected) {
  write_run_checkpoint(path("run.ckpt"), config_hash({{"mu", 4}}));
  const std::string message = error_of(path("run.ckpt"), config_hash({{"mu", 5}}));
  EXPECT_NE(message.find("written for config"), std::string::npos) << message;
  EXPECT_EQ(message.rfind(path("run.ckpt"), 0), 0u) << "starts with the file: " << message;
  EXPECT_EQ(config_hash({{"a", 1}, {"b", 2}}), config_hash({{"b", 2}, {"a", 1}}));
  EXPECT_EQ(motoflex::hash_text("").size(), 16u);
}

TEST_F(EsCheckpointTest, OtherFormatVersionIsRejected) {
  write_run_checkpoint(path("run.ckpt"), "h");
  nlohmann::json document = nlohmann::json::parse(read(path("run.ckpt")));
  document["format_version"] = kCheckpointFormatVersion + 1;
  write(path("run.ckpt"), document.dump());
  EXPECT_NE(error_of(path("run.ckpt"), "h").find("format version"), std::string::npos);
  write(path("other.json"), R"({"hello": "world"})");
  EXPECT_NE(error_of(path("other.json"), "h").find("not a checkpoint"), std::string::npos);
  EXPECT_NE(error_of(path("absent.ckpt"), "h").find("cannot open"), std::string::npos);
}

TEST_F(EsCheckpointTest, StateOfAnotherStrategyOrOtherOptionsIsRejected) {
  write_run_checkpoint(path("run.ckpt"), "h");
  const nlohmann::json state = read_checkpoint(path("run.ckpt"), "h").strategy_state;
  CmaEs cma(bounds(), CmaEsOptions{});
  EXPECT_THROW(cma.load_state(state), CheckpointError);
  MuPlusLambdaOptions other = options();
  other.mu = 5;
  MuPlusLambda different(bounds(), other);
  try {
    different.load_state(state);
    FAIL() << "no CheckpointError";
  } catch (const CheckpointError& error) {
    EXPECT_NE(std::string(error.what()).find("mu"), std::string::npos) << error.what();
  }
  nlohmann::json damaged = state;
  damaged["population"][0].erase("step");
  MuPlusLambda same(bounds(), options());
  EXPECT_THROW(same.load_state(damaged), CheckpointError);
  damaged = state;
  damaged["common"]["generation"] = 5.0;  // an integer written as a float
  EXPECT_THROW(same.load_state(damaged), CheckpointError);
}

}  // namespace
}  // namespace motoflex_es
