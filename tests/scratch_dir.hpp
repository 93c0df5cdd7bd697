#pragma once
// Scratch folders for tests: every folder a test process writes lives under one root,
// <temp>/motoflex_test_<pid>, which is removed when the process's tests have all passed (and
// kept, with its path printed, when one failed, so the files can be looked at). Before this,
// each `ctest` run left about 100 MB of test folders in /tmp.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace motoflex::testing {

// Where the process's scratch root is (it may not exist yet).
inline std::filesystem::path scratch_root_path() {
  return std::filesystem::temp_directory_path() / ("motoflex_test_" + std::to_string(::getpid()));
}

// The process's scratch root (created on first use).
inline std::filesystem::path scratch_root() {
  auto root = scratch_root_path();
  std::filesystem::create_directories(root);
  return root;
}

// A fresh, empty folder `name` under the scratch root. The process id in the root keeps tests
// that ctest runs at the same time (and test suites of other checkouts) out of each other's
// folders.
inline std::filesystem::path scratch_dir(const std::string& name) {
  auto dir = scratch_root() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A test with a fresh folder of its own, dir_ (under the scratch root, named after the test),
// and a writer for the files it reads back.
class ScratchFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = scratch_dir(std::string(info->test_suite_name()) + "." + info->name());
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Writes `text` byte for byte to dir_/name; returns the path.
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }

  std::filesystem::path dir_;
};

// Removes the scratch root after the last test of the process, unless a test failed.
class ScratchRootCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    const auto root = scratch_root_path();
    std::error_code error;
    if (!std::filesystem::exists(root, error)) return;
    if (::testing::UnitTest::GetInstance()->Passed()) {
      std::filesystem::remove_all(root, error);
    } else {
      std::printf("test files kept in %s\n", root.string().c_str());
    }
  }
};

// Registered once per test binary, before main (gtest owns the environment).
inline ::testing::Environment* const kScratchRootCleanup =
    ::testing::AddGlobalTestEnvironment(new ScratchRootCleanup);

}  // namespace motoflex::testing
