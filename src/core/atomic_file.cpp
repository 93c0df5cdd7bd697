#include "motoflex/core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

constexpr std::size_t kBufferBytes = 1 << 16;

// Writes everything or returns the errno of the failing write.
int write_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t written = ::write(fd, data.data(), data.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data.remove_prefix(static_cast<std::size_t>(written));
  }
  return 0;
}

// Unique within the process by the counter, across processes by the pid, and across hosts
// sharing a folder (and pid reuse) by the clock; O_EXCL catches whatever still collides.
std::string temp_name_for(const std::string& file_name) {
  static std::atomic<unsigned long long> counter{0};
  const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  return "." + file_name + ".tmp-" + std::to_string(::getpid()) + "-" +
         std::to_string(counter.fetch_add(1)) + "-" + std::to_string(ticks % 1000000007);
}

}  // namespace

AtomicFileWriter::AtomicFileWriter(std::string path) : path_(std::move(path)) {
  const std::filesystem::path target(path_);
  if (path_.empty() || !target.has_filename()) {
    throw InputError(path_, 0, "", "not a file path");
  }
  folder_ = target.has_parent_path() ? target.parent_path().string() : std::string(".");
  const std::string file_name = target.filename().string();
  int open_error = 0;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string candidate = (std::filesystem::path(folder_) / temp_name_for(file_name));
    fd_ = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      temp_path_ = candidate;
      return;
    }
    open_error = errno;
    if (open_error != EEXIST) break;
  }
  fail("cannot create a temporary file in '" + folder_ + "'", open_error);
}

AtomicFileWriter::~AtomicFileWriter() {
  discard();
}

void AtomicFileWriter::write(std::string_view data) {
  if (fd_ < 0) throw std::logic_error("AtomicFileWriter::write after commit or failure");
  if (buffer_.size() + data.size() < kBufferBytes) {
    buffer_.append(data);
    return;
  }
  flush_buffer();
  if (const int error = write_all(fd_, data)) fail("cannot write", error);
}

void AtomicFileWriter::flush_buffer() {
  if (buffer_.empty()) return;
  if (const int error = write_all(fd_, buffer_)) fail("cannot write", error);
  buffer_.clear();
}

void AtomicFileWriter::commit() {
  if (fd_ < 0) throw std::logic_error("AtomicFileWriter::commit after commit or failure");
  flush_buffer();
  if (::fsync(fd_) != 0) {
    const int sync_error = errno;
    fail("cannot fsync", sync_error);
  }
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) {
    const int close_error = errno;
    fail("cannot close", close_error);
  }
  if (::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const int rename_error = errno;
    fail("cannot rename the temporary file over it", rename_error);
  }
  temp_path_.clear();

  // Without this the rename may be lost in a crash even though the content was synced.
  const int folder_fd = ::open(folder_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder_fd < 0) {
    const int open_folder_error = errno;
    fail("cannot open folder '" + folder_ + "' to fsync it", open_folder_error);
  }
  const int sync_result = ::fsync(folder_fd);
  const int sync_error = errno;
  ::close(folder_fd);
  // Some file systems cannot fsync a folder; the rename is then as durable as they allow.
  if (sync_result != 0 && sync_error != EINVAL && sync_error != ENOTSUP) {
    fail("cannot fsync folder '" + folder_ + "'", sync_error);
  }
}

void AtomicFileWriter::fail(const std::string& reason, int error_number) {
  discard();
  const std::string message = reason + ": " + std::strerror(error_number);
  // A path that names no folder (or a folder) is the user's input; anything else (a full
  // disk, a read-only file system, no permission) is the machine's.
  if (error_number == ENOENT || error_number == ENOTDIR || error_number == EISDIR) {
    throw InputError(path_, 0, "", message);
  }
  throw IoError(path_, 0, "", message);
}

void AtomicFileWriter::discard() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temp_path_.empty()) {
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
  }
  buffer_.clear();
}

void write_file_atomically(const std::string& path, std::string_view content) {
  AtomicFileWriter writer(path);
  writer.write(content);
  writer.commit();
}

}  // namespace motoflex
