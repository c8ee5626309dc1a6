// support/atomic_file.hpp: an output is whole or absent. Real write failures, without root:
// - a file-size limit (setrlimit RLIMIT_FSIZE, as `ulimit -f`; SIGXFSZ ignored so that the write
//   fails with EFBIG instead of killing the process) stands for a full disk: a 64 KiB limit and a
//   1 MiB output;
// - /dev/full, where every write fails with ENOSPC (written in place: not a regular file).
// Expected: OutputError naming the file and the system's reason, the previous file byte for byte,
// no `.tmp` left; a failure in the last buffer, seen only by the flush at commit, is caught too.
#include "support/atomic_file.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace impact;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("support_atomic_file_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// RLIMIT_FSIZE lowered to `bytes` while it lives (SIGXFSZ ignored), restored after.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    BOOST_REQUIRE(getrlimit(RLIMIT_FSIZE, &saved_) == 0);
    previous_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit lowered = saved_;
    lowered.rlim_cur = bytes;
    BOOST_REQUIRE(setrlimit(RLIMIT_FSIZE, &lowered) == 0);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_);
  }

 private:
  rlimit saved_{};
  void (*previous_)(int) = nullptr;
};

const std::string kPrevious = "previous complete file\n";

}  // namespace

BOOST_AUTO_TEST_SUITE(atomic_file)

BOOST_AUTO_TEST_CASE(a_complete_write_replaces_the_file_and_leaves_no_temporary) {
  const fs::path dir = scratch("ok");
  write_file_atomically(dir / "a.json", [](std::ostream& o) { o << kPrevious; });
  AtomicFile f(dir / "a.json");
  f.stream() << "new\n";
  f.check();
  BOOST_TEST(read_text(dir / "a.json") == kPrevious);  // not in place before commit
  BOOST_TEST(fs::exists(dir / "a.json.tmp"));
  f.commit();
  BOOST_TEST(read_text(dir / "a.json") == "new\n");
  BOOST_TEST(!fs::exists(dir / "a.json.tmp"));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_write_beyond_the_file_size_limit_keeps_the_previous_file) {
  const fs::path dir = scratch("limit");
  const fs::path file = dir / "out.csv";
  write_file_atomically(file, [](std::ostream& o) { o << kPrevious; });
  const std::string row(1000, 'x');
  std::string message;
  std::size_t rows_written = 0;
  {
    const FileSizeLimit limit(64 * 1024);
    try {
      AtomicFile f(file);
      for (; rows_written < 1000; ++rows_written) {
        f.stream() << row << '\n';
        f.check();
      }
      f.commit();
    } catch (const OutputError& e) {
      message = e.what();
    }
  }
  BOOST_TEST_MESSAGE("rows before the error: " << rows_written << "; " << message);
  BOOST_TEST(contains(message, "cannot write " + file.string() + ": write failed"));
  BOOST_TEST(contains(message, "(File too large)"));
  // Stopped within a buffer or two of the limit (65 rows of 1001 B), not at the end.
  BOOST_TEST(rows_written >= 60u);
  BOOST_TEST(rows_written <= 90u);
  BOOST_TEST(read_text(file) == kPrevious);
  BOOST_TEST(!fs::exists(dir / "out.csv.tmp"));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_failure_seen_only_by_the_final_flush_is_reported) {
  const fs::path dir = scratch("flush");
  const fs::path file = dir / "out.json";
  write_file_atomically(file, [](std::ostream& o) { o << kPrevious; });
  std::string message;
  {
    const FileSizeLimit limit(1000);
    try {
      // 2000 B stay in the stream's buffer until commit() flushes them.
      write_file_atomically(file, [](std::ostream& o) { o << std::string(2000, 'y'); });
    } catch (const OutputError& e) {
      message = e.what();
    }
  }
  BOOST_TEST(contains(message, "cannot write " + file.string()));
  BOOST_TEST(read_text(file) == kPrevious);
  BOOST_TEST(!fs::exists(dir / "out.json.tmp"));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_device_is_written_in_place_and_never_removed) {
  std::string message;
  try {
    AtomicFile f("/dev/full");
    f.stream() << std::string(100000, 'z');
    f.check();
    f.commit();
  } catch (const OutputError& e) {
    message = e.what();
  }
  BOOST_TEST(contains(message, "cannot write /dev/full"));
  BOOST_TEST(contains(message, "(No space left on device)"));
  struct stat st {};
  BOOST_TEST(::stat("/dev/full", &st) == 0);
  BOOST_TEST(S_ISCHR(st.st_mode));
  BOOST_TEST(!fs::exists("/dev/full.tmp"));
  write_file_atomically("/dev/null", [](std::ostream& o) { o << "discarded\n"; });
  BOOST_TEST(::stat("/dev/null", &st) == 0);
  BOOST_TEST(S_ISCHR(st.st_mode));
}

BOOST_AUTO_TEST_CASE(a_writer_that_throws_leaves_the_previous_file) {
  const fs::path dir = scratch("throw");
  const fs::path file = dir / "out.json";
  write_file_atomically(file, [](std::ostream& o) { o << kPrevious; });
  BOOST_CHECK_THROW(write_file_atomically(file,
                                          [](std::ostream& o) {
                                            o << "{\"vers";
                                            throw std::runtime_error("killed");
                                          }),
                    std::runtime_error);
  BOOST_TEST(read_text(file) == kPrevious);
  BOOST_TEST(!fs::exists(dir / "out.json.tmp"));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(an_unwritable_place_names_the_file) {
  BOOST_CHECK_EXCEPTION(AtomicFile("/proc/no_such_dir/x.csv"), OutputError,
                        [](const OutputError& e) {
                          return contains(e.what(),
                                          "cannot write /proc/no_such_dir/x.csv: cannot "
                                          "open /proc/no_such_dir/x.csv.tmp");
                        });
  BOOST_CHECK_EXCEPTION(
      create_output_directory("/proc/x/fit"), OutputError, [](const OutputError& e) {
        return contains(e.what(), "cannot create the output directory /proc/x/fit");
      });
}

BOOST_AUTO_TEST_SUITE_END()
