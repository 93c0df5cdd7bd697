#pragma once

#include <string>
#include <string_view>

namespace motoflex {

// Replaces the file at `path` with `content` so that a reader (or a crash) sees either the old
// file or the complete new one, never a torn write: the content goes to a temporary file in the
// same folder, which is fsync'ed, renamed over `path`, and then the folder is fsync'ed so the
// rename itself is durable. On any failure the temporary file is removed and InputError(path, 0,
// "", reason) is thrown (for example a missing or unwritable folder, or `path` naming a
// folder). New files get the usual permissions (0666 minus the umask).
void write_file_atomically(const std::string& path, std::string_view content);

// The streaming form of write_file_atomically, for content too large to build in memory:
//   AtomicFileWriter out(path);   // creates the temporary file
//   out.write(...); ...           // buffered appends
//   out.commit();                 // fsync, rename over `path`, fsync the folder
// If commit() is never reached (an exception, an early return) the destructor removes the
// temporary file and `path` is left untouched. Every failure throws InputError(path, 0, "", ...)
// and removes the temporary file.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(std::string path);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void write(std::string_view data);
  void commit();

  const std::string& path() const { return path_; }
  // Where the content goes until commit(); empty once committed or abandoned.
  const std::string& temp_path() const { return temp_path_; }

 private:
  void flush_buffer();
  // Removes the temporary file and throws InputError with `reason` and strerror(error_number).
  [[noreturn]] void fail(const std::string& reason, int error_number);
  void discard() noexcept;

  std::string path_;
  std::string folder_;
  std::string temp_path_;
  std::string buffer_;
  int fd_ = -1;
};

}  // namespace motoflex
