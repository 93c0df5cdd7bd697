// FolderLock: one owner per run folder. A second lock on the same folder fails at once with a
// message naming the holder's PID; released locks can be taken again; stale temporary files of
// an atomic write are removed, other files are kept.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>

#include "motoflex/core/error.hpp"
#include "motoflex/core/folder_lock.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("motoflex_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  return dir;
}

TEST(FolderLock, SecondOwnerFailsNamingTheFirst) {
  const fs::path dir = fresh("folder_lock");
  std::optional<FolderLock> first;
  first.emplace(dir.string());  // creates the folder
  EXPECT_TRUE(fs::exists(dir / FolderLock::kFileName));
  // flock(2) locks belong to an open file description: a second open, even in this process,
  // conflicts exactly as another process would.
  try {
    FolderLock second(dir.string());
    FAIL() << "two owners of one folder";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "out");
    EXPECT_NE(error.message().find("pid " + std::to_string(::getpid())), std::string::npos)
        << error.message();
  }
  first.reset();
  EXPECT_NO_THROW(FolderLock again(dir.string()));
  fs::remove_all(dir);
}

TEST(FolderLock, RemovesStaleTempFilesOnly) {
  const fs::path dir = fresh("folder_lock_tmp");
  fs::create_directories(dir / "best" / "validation");
  for (const fs::path& p :
       {dir / ".checkpoint.json.tmp-123-0-42", dir / "best" / ".best.json.tmp-9-1-7",
        dir / "best" / "validation" / ".kick.csv.tmp-5-0-1", dir / "checkpoint.json",
        dir / "notes.tmp-1", dir / ".hidden"}) {
    std::ofstream(p) << "x";
  }
  EXPECT_EQ(remove_stale_temp_files(dir.string()), 3);
  EXPECT_TRUE(fs::exists(dir / "checkpoint.json"));
  EXPECT_TRUE(fs::exists(dir / "notes.tmp-1"));
  EXPECT_TRUE(fs::exists(dir / ".hidden"));
  EXPECT_FALSE(fs::exists(dir / "best" / ".best.json.tmp-9-1-7"));
  EXPECT_EQ(remove_stale_temp_files((dir / "missing").string()), 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motoflex
