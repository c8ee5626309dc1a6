// Write to `<name>.tmp`, close, rename over `<name>` (mpm/output/atomic_file.hpp).
#include "mpm/output/atomic_file.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace impact::mpm {

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  namespace fs = std::filesystem;
  fs::path tmp = path;
  tmp += ".tmp";
  const auto fail = [&](const std::string& what) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error("cannot write " + path.string() + ": " + what);
  };
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) fail("cannot open " + tmp.string());
    try {
      write(out);
    } catch (...) {
      std::error_code ignored;
      out.close();
      fs::remove(tmp, ignored);
      throw;
    }
    out.close();
    if (!out) fail("write or close of " + tmp.string() + " failed");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) fail("rename of " + tmp.string() + " failed: " + ec.message());
}

}  // namespace impact::mpm
