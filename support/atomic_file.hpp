// Outputs that are whole or absent, shared by the programs (mpm, pointdriver, material_check; the
// libraries' public headers do not include it). A file is written to `<name>.tmp` in its own
// directory and renamed over `<name>` only after every write, the flush and the close succeeded,
// so a full disk, a file-size limit, a kill or a crash leaves the previous complete file (or
// none), never a truncated one: rename within one directory is atomic on POSIX file systems. A
// failed write (ENOSPC, EFBIG, EIO) is an OutputError naming the file and the system's reason,
// and the temporary is removed. A target that exists and is not a regular file (/dev/null, a
// FIFO, /dev/stdout) is written in place with the same checks, and never removed.
#pragma once

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

namespace impact {

/// An output that could not be written in full (the programs exit 3).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class AtomicFile {
 public:
  /// Opens `<path>.tmp` for writing (`path` itself when it is an existing non-regular file; a
  /// symbolic link's target). Throws OutputError naming `path` when it cannot.
  explicit AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path target = path_;
    if (fs::is_symlink(target, ec)) target = fs::weakly_canonical(target, ec);
    if (ec) target = path_;
    const fs::file_status status = fs::status(target, ec);
    in_place_ = !ec && fs::exists(status) && !fs::is_regular_file(status);
    if (in_place_) {
      written_ = target;
    } else {
      target_ = target;
      written_ = target;
      written_ += ".tmp";
    }
    errno = 0;
    out_.open(written_, std::ios::binary | std::ios::trunc);
    if (!out_) fail("cannot open " + written_.string());
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Without commit(): the temporary is removed, the previous file stays.
  ~AtomicFile() { discard(); }

  std::ostream& stream() { return out_; }
  const std::filesystem::path& path() const { return path_; }

  /// Throws OutputError when a write so far failed. A long output calls it after each record,
  /// so that a full disk stops the work at once rather than at the end.
  void check() {
    if (!out_) fail("write failed");
  }

  /// Flushes, closes, checks and renames into place; OutputError on any failure.
  void commit() {
    if (done_) return;
    check();
    out_.flush();
    check();
    out_.close();
    if (out_.fail()) fail("close failed");
    if (!in_place_) {
      std::error_code ec;
      std::filesystem::rename(written_, target_, ec);
      if (ec) fail("rename of " + written_.string() + " failed: " + ec.message());
    }
    done_ = true;
  }

  /// Abandons the output: the temporary is removed (nothing happens after commit()).
  void discard() noexcept {
    if (done_) return;
    done_ = true;
    if (out_.is_open()) out_.close();
    if (in_place_) return;
    std::error_code ignored;
    std::filesystem::remove(written_, ignored);
  }

 private:
  [[noreturn]] void fail(const std::string& what) {
    const int error = errno;  // set by the failing system call (write, close, open)
    discard();
    std::string message = "cannot write " + path_.string() + ": " + what;
    if (error != 0) message += " (" + std::string(std::strerror(error)) + ")";
    throw OutputError(message);
  }

  std::filesystem::path path_, target_, written_;
  bool in_place_ = false, done_ = false;
  std::ofstream out_;
};

/// Creates `dir` and its parents; OutputError naming it when it cannot (/proc/x, a file in the
/// way, a read-only file system).
inline void create_output_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    throw OutputError("cannot create the output directory " + dir.string() + ": " + ec.message());
  }
}

/// Writes `path` through `write` as one AtomicFile. OutputError naming the file when it cannot
/// be opened, written, closed or renamed; when `write` throws, its exception goes on and the
/// previous file stays.
inline void write_file_atomically(const std::filesystem::path& path,
                                  const std::function<void(std::ostream&)>& write) {
  AtomicFile file(path);
  write(file.stream());
  file.commit();
}

}  // namespace impact
