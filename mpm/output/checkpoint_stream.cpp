#include "mpm/output/checkpoint_stream.hpp"

namespace impact::mpm {

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= b[i];
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

void CheckpointWriter::bytes(const void* data, std::size_t size) {
  size_ += size;
  if (out_ == nullptr) return;
  hash_ = fnv1a(data, size, hash_);
  out_->write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
}

void CheckpointWriter::text(const std::string& s) {
  value(static_cast<std::uint64_t>(s.size()));
  bytes(s.data(), s.size());
}

void CheckpointWriter::section(const std::string& tag, std::uint64_t count,
                               std::uint32_t element_size) {
  text(tag);
  value(count);
  value(element_size);
}

void CheckpointWriter::finish() {
  const std::uint64_t h = hash_;
  size_ += sizeof h;
  if (out_ != nullptr) out_->write(reinterpret_cast<const char*>(&h), sizeof h);
}

void CheckpointReader::fail(const std::string& why) const {
  throw CheckpointError(file_ + ": " + why);
}

void CheckpointReader::bytes(void* data, std::size_t size) {
  if (!in_.read(static_cast<char*>(data), static_cast<std::streamsize>(size)))
    fail("truncated (corrupt checkpoint)");
  hash_ = fnv1a(data, size, hash_);
}

std::string CheckpointReader::text() {
  const auto n = value<std::uint64_t>();
  if (n > (1u << 20)) fail("corrupt checkpoint (a text of " + std::to_string(n) + " bytes)");
  std::string s(n, '\0');
  bytes(s.data(), n);
  return s;
}

std::uint64_t CheckpointReader::section(const std::string& tag, std::uint32_t element_size,
                                        std::uint64_t expected_count) {
  const std::string got = text();
  if (got != tag)
    fail("section \"" + got + "\" where \"" + tag + "\" belongs (corrupt checkpoint)");
  const auto count = value<std::uint64_t>();
  const auto size = value<std::uint32_t>();
  if (size != element_size) {
    fail("section \"" + tag + "\": elements of " + std::to_string(size) + " bytes, expected " +
         std::to_string(element_size));
  }
  if (expected_count != npos && count != expected_count) {
    fail("section \"" + tag + "\": " + std::to_string(count) + " elements, expected " +
         std::to_string(expected_count));
  }
  return count;
}

void CheckpointReader::finish() {
  const std::uint64_t computed = hash_;
  std::uint64_t stored = 0;
  if (!in_.read(reinterpret_cast<char*>(&stored), sizeof stored))
    fail("truncated (no trailer: corrupt checkpoint)");
  if (stored != computed) fail("checksum mismatch (corrupt checkpoint)");
  if (in_.peek() != std::char_traits<char>::eof()) fail("bytes after the trailer");
}

}  // namespace impact::mpm
