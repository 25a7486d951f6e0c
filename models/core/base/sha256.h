#pragma once
// SHA-256 (FIPS 180-4), for the hashes a manifest records (scene files,
// inputs) and for cache keys. Results are 64 lower-case hex digits.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace repose {

// Incremental hashing: update() any number of times, then hex_digest() once.
class Sha256 {
 public:
  Sha256();
  void update(std::string_view bytes);
  // Finishes the hash; the object must not be updated afterwards.
  std::string hex_digest();

 private:
  void compress(const std::uint8_t* block);

  std::array<std::uint32_t, 8> state_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t total_bytes_ = 0;
  bool finished_ = false;
};

std::string sha256_hex(std::string_view bytes);
// Streams the file; throws InputError naming the file when it cannot be read.
std::string sha256_hex_of_file(const std::string& path);

}  // namespace repose
