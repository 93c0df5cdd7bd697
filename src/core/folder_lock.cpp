#include "motoflex/core/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

std::string read_owner(int fd) {
  char buffer[32] = {};
  const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
  std::string text = n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : "";
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "unknown" : text;
}

bool is_temp_name(const std::string& name) {
  return name.size() > 1 && name[0] == '.' && name.find(".tmp-") != std::string::npos;
}

}  // namespace

FolderLock::FolderLock(const std::string& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw InputError(folder, 0, "out", "cannot create the folder: " + error.message());
  const std::string path = (fs::path(folder) / kFileName).string();
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    throw InputError(
        folder, 0, "out",
        "cannot create the lock file " + std::string(kFileName) + ": " + std::strerror(errno));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int lock_error = errno;
    const std::string owner = read_owner(fd_);
    ::close(fd_);
    fd_ = -1;
    if (lock_error == EWOULDBLOCK) {
      throw InputError(folder, 0, "out",
                       "in use by another motoflex process (pid " + owner +
                           "); wait for it to finish or choose another --out");
    }
    throw InputError(folder, 0, "out", std::string("cannot lock: ") + std::strerror(lock_error));
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
    // The lock holds regardless; only the PID in messages would be missing.
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the flock
}

int remove_stale_temp_files(const std::string& folder) {
  int removed = 0;
  std::error_code error;
  auto it = fs::recursive_directory_iterator(folder, error);
  if (error) return 0;
  for (; it != fs::recursive_directory_iterator(); it.increment(error)) {
    if (error) break;
    if (it.depth() >= 2) it.disable_recursion_pending();
    const std::string name = it->path().filename().string();
    if (it->is_regular_file(error) && is_temp_name(name) && fs::remove(it->path(), error)) {
      ++removed;
    }
  }
  return removed;
}

}  // namespace motoflex
