#pragma once

#include <string>

namespace motoflex {

// One owner per run folder: an exclusive flock(2) on `<folder>/.motoflex.lock`, held for the
// object's lifetime (and released by the kernel if the process dies, even by kill -9). The
// file holds the owner's PID so that a second writer can name it. Used by fit, resume and loop.
class FolderLock {
 public:
  // Creates the folder if needed and takes the lock; throws InputError(folder, 0, "out", ...)
  // at once (no waiting) when another process holds it, naming that process's PID, and
  // InputError when the lock file cannot be created.
  explicit FolderLock(const std::string& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  static constexpr const char* kFileName = ".motoflex.lock";

 private:
  int fd_ = -1;
};

// Removes the temporary files write_file_atomically leaves behind when a process is killed
// mid-write (".<name>.tmp-<pid>-..."), in `folder` and its sub-folders (2 levels). Only safe
// while holding the folder's FolderLock. Returns how many it removed.
int remove_stale_temp_files(const std::string& folder);

}  // namespace motoflex
