#include "motoflex/core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "motoflex/core/error.hpp"
#include "scratch_dir.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public testing::ScratchFolderTest {
 protected:
  // A test makes its folder read-only: writable again, so that the scratch root can go.
  void TearDown() override { fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add); }

  std::vector<std::string> files_in(const fs::path& folder) const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }
};

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `action`, which must throw InputError for `file` with no line and no field.
std::string expect_write_error(const std::function<void()>& action, const std::string& file) {
  try {
    action();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.line(), 0) << e.what();
    EXPECT_EQ(e.field(), "") << e.what();
    const std::string location = (file.empty() ? std::string("<input>") : file) + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(location, 0), 0u) << e.what();
    return e.message();
  }
  ADD_FAILURE() << "expected InputError for " << file;
  return "";
}

TEST_F(AtomicFileTest, CreatesFileWithContentAndLeavesNoTemporaryFile) {
  const std::string target = path("checkpoint.json");
  write_file_atomically(target, "{\"generation\": 3}\n");
  EXPECT_EQ(read_file(target), "{\"generation\": 3}\n");
  EXPECT_EQ(files_in(dir_), (std::vector<std::string>{"checkpoint.json"}));
}

TEST_F(AtomicFileTest, ReplacesExistingFile) {
  const std::string target = path("data.txt");
  write_file_atomically(target, "a much longer first version\n");
  write_file_atomically(target, "short\n");
  EXPECT_EQ(read_file(target), "short\n");
  write_file_atomically(target, "");
  EXPECT_EQ(read_file(target), "");
  EXPECT_EQ(files_in(dir_), (std::vector<std::string>{"data.txt"}));
}

TEST_F(AtomicFileTest, KeepsBinaryContent) {
  const std::string content("a\0b\r\n\xff", 6);
  write_file_atomically(path("bin"), content);
  EXPECT_EQ(read_file(path("bin")), content);
}

TEST_F(AtomicFileTest, NewFilesGetUmaskPermissions) {
  const mode_t mask = ::umask(022);
  write_file_atomically(path("perm.txt"), "x");
  ::umask(mask);
  struct stat info {};
  ASSERT_EQ(::stat(path("perm.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);
}

TEST_F(AtomicFileTest, RelativePathInCurrentFolder) {
  const fs::path previous = fs::current_path();
  fs::current_path(dir_);
  write_file_atomically("here.txt", "relative");
  fs::current_path(previous);
  EXPECT_EQ(read_file(path("here.txt")), "relative");
  EXPECT_EQ(files_in(dir_), (std::vector<std::string>{"here.txt"}));
}

TEST_F(AtomicFileTest, StreamingWriterHandlesLargeContentInPieces) {
  const std::string target = path("big.csv");
  std::string expected;
  {
    AtomicFileWriter writer(target);
    EXPECT_FALSE(writer.temp_path().empty());
    EXPECT_TRUE(fs::exists(writer.temp_path()));
    EXPECT_FALSE(fs::exists(target));
    for (int i = 0; i < 200000; ++i) {
      const std::string line = std::to_string(i) + ",0.125,-3\n";
      writer.write(line);
      expected += line;
    }
    const std::string block(300000, 'z');  // larger than the internal buffer
    writer.write(block);
    expected += block;
    writer.commit();
    EXPECT_TRUE(writer.temp_path().empty());
    EXPECT_THROW(writer.commit(), std::logic_error);
  }
  EXPECT_EQ(read_file(target), expected);
  EXPECT_EQ(files_in(dir_), (std::vector<std::string>{"big.csv"}));
}

TEST_F(AtomicFileTest, AbandonedWriterRemovesTemporaryAndKeepsOldFile) {
  const std::string target = path("keep.txt");
  write_file_atomically(target, "old");
  {
    AtomicFileWriter writer(target);
    writer.write("new but never committed");
  }
  EXPECT_EQ(read_file(target), "old");
  EXPECT_EQ(files_in(dir_), (std::vector<std::string>{"keep.txt"}));
}

TEST_F(AtomicFileTest, MissingFolderThrowsAndCreatesNothing) {
  const std::string target = path("missing/sub/out.txt");
  const std::string message =
      expect_write_error([&] { write_file_atomically(target, "x"); }, target);
  EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  EXPECT_TRUE(files_in(dir_).empty());
}

TEST_F(AtomicFileTest, ParentIsAFileThrows) {
  write_file_atomically(path("plain"), "x");
  const std::string target = path("plain/out.txt");
  expect_write_error([&] { write_file_atomically(target, "x"); }, target);
  EXPECT_EQ(files_in(dir_), (std::vector<std::string>{"plain"}));
}

TEST_F(AtomicFileTest, TargetIsAFolderThrowsAndRemovesTemporaryFile) {
  // The temporary file is created and written before the rename fails: it must be cleaned up.
  fs::create_directory(path("folder"));
  write_file_atomically(path("folder/inside"), "x");
  const std::string target = path("folder");
  expect_write_error([&] { write_file_atomically(target, "content"); }, target);
  EXPECT_EQ(files_in(dir_), (std::vector<std::string>{"folder"}));
  EXPECT_EQ(files_in(dir_ / "folder"), (std::vector<std::string>{"inside"}));
}

TEST_F(AtomicFileTest, UnwritableFolderThrowsAndLeavesNothing) {
  const fs::path locked = dir_ / "locked";
  fs::create_directory(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  // root ignores directory permissions; then there is nothing to test.
  const std::string probe = (locked / "probe").string();
  if (std::ofstream(probe).good()) {
    fs::remove(probe);
    GTEST_SKIP() << "running with privileges that ignore folder permissions";
  }
  const std::string target = (locked / "out.txt").string();
  const std::string message =
      expect_write_error([&] { write_file_atomically(target, "x"); }, target);
  EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
  EXPECT_TRUE(files_in(locked).empty());
}

TEST_F(AtomicFileTest, EmptyPathIsRejected) {
  expect_write_error([] { write_file_atomically("", "x"); }, "");
  const std::string folder_path = dir_.string() + "/";
  expect_write_error([&] { write_file_atomically(folder_path, "x"); }, folder_path);
}

}  // namespace
}  // namespace motoflex
