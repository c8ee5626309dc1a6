// The byte stream of a checkpoint (format in mpm/run/checkpoint.hpp): values and tagged arrays
// written as stored, every byte hashed (FNV-1a), and read back with the section, its element size
// and count checked. The Simulation writes its part through it (mpm/simulation/
// simulation_checkpoint.cpp), the run loop the header and its own state (mpm/run/checkpoint.cpp).
#pragma once

#include <cstdint>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace impact::mpm {

/// 64-bit FNV-1a of a byte string (scene.json fingerprint, checkpoint trailer).
inline constexpr std::uint64_t kHashSeed = 0xcbf29ce484222325ULL;  ///< FNV-1a offset basis
std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = kHashSeed);

/// Writes values and tagged arrays, hashing every byte; counting() only counts them (a
/// checkpoint's header states its length, so that a file cut short reads as truncated).
class CheckpointWriter {
 public:
  explicit CheckpointWriter(std::ostream& out) : out_(&out) {}
  /// A writer that writes and hashes nothing, only counts the bytes.
  static CheckpointWriter counting() { return CheckpointWriter(); }
  /// Bytes written (or counted) so far, the trailer included once finish() is called.
  std::uint64_t size() const { return size_; }
  void bytes(const void* data, std::size_t size);
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  void text(const std::string& s);
  /// Tag, count, element size, elements (T trivially copyable, written as stored).
  template <class T>
  void array(const std::string& tag, const std::vector<T>& v) {
    section(tag, v.size(), sizeof(T));
    bytes(v.data(), v.size() * sizeof(T));
  }
  void section(const std::string& tag, std::uint64_t count, std::uint32_t element_size);
  /// The trailer: the hash of everything written so far.
  void finish();

 private:
  CheckpointWriter() = default;
  std::ostream* out_ = nullptr;  ///< null: counting only
  std::uint64_t hash_ = kHashSeed;
  std::uint64_t size_ = 0;
};

/// Reads what CheckpointWriter wrote; throws CheckpointError naming the file and the section.
class CheckpointReader {
 public:
  CheckpointReader(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}
  void bytes(void* data, std::size_t size);
  template <class T>
  T value() {
    T v;
    bytes(&v, sizeof v);
    return v;
  }
  std::string text();
  /// Reads a section written by array(): the tag must match and the element size be sizeof(T);
  /// `expected_count` (if not npos) must match too.
  template <class T>
  void array(const std::string& tag, std::vector<T>& v, std::uint64_t expected_count = npos) {
    v.resize(section(tag, sizeof(T), expected_count));
    bytes(v.data(), v.size() * sizeof(T));
  }
  std::uint64_t section(const std::string& tag, std::uint32_t element_size,
                        std::uint64_t expected_count = npos);
  /// Checks the trailer hash and that nothing follows it.
  void finish();
  [[noreturn]] void fail(const std::string& why) const;
  const std::string& file() const { return file_; }

  static constexpr std::uint64_t npos = ~std::uint64_t(0);

 private:
  std::istream& in_;
  std::string file_;
  std::uint64_t hash_ = kHashSeed;
};

/// A checkpoint that cannot be used (missing, another version, corrupt, another scene).
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace impact::mpm
