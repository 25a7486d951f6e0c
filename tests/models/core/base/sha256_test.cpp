#include "models/core/base/sha256.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "models/core/base/error.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

// The examples of NIST's "SHA-256" example document (FIPS 180-4 test vectors).
const char* const kAbc = "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad";
const char* const kEmpty = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855";
const char* const kTwoBlock = "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1";
const char* const kMillionA = "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0";
const char* const kTwoBlockMessage = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";

TEST(Sha256, NistVectors) {
  EXPECT_EQ(sha256_hex("abc"), kAbc);
  EXPECT_EQ(sha256_hex(""), kEmpty);
  EXPECT_EQ(sha256_hex(kTwoBlockMessage), kTwoBlock);
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), kMillionA);
}

// Feeding the message in pieces of every size across the 64-byte block
// boundary gives the same hash as feeding it at once.
TEST(Sha256, IncrementalUpdatesMatchOneShot) {
  const std::string message(1000, 'a');
  const std::string whole = sha256_hex(message);
  for (std::size_t piece : {1u, 3u, 55u, 56u, 63u, 64u, 65u, 127u, 999u}) {
    Sha256 hash;
    for (std::size_t at = 0; at < message.size(); at += piece) {
      hash.update(std::string_view(message).substr(at, piece));
    }
    EXPECT_EQ(hash.hex_digest(), whole) << piece;
  }
}

// Lengths around the padding boundary (55, 56, 64 bytes) must differ from each other.
TEST(Sha256, PaddingBoundariesGiveDistinctHashes) {
  EXPECT_NE(sha256_hex(std::string(55, 'a')), sha256_hex(std::string(56, 'a')));
  EXPECT_NE(sha256_hex(std::string(63, 'a')), sha256_hex(std::string(64, 'a')));
  EXPECT_NE(sha256_hex(std::string(1, '\0')), sha256_hex(""));
}

TEST(Sha256, FileIsHashedLikeItsContents) {
  const test_support::TempDir dir;
  const fs::path path = dir.path / "million_a.bin";
  {
    std::ofstream out(path, std::ios::binary);
    // a million 'a' spans many 64 KiB read chunks
    out << std::string(1000000, 'a');
  }
  EXPECT_EQ(sha256_hex_of_file(path.string()), kMillionA);
}

TEST(Sha256, MissingFileOrDirectoryIsAnInputError) {
  EXPECT_THROW(sha256_hex_of_file("/nonexistent/repose/file"), InputError);
  EXPECT_THROW(sha256_hex_of_file(fs::temp_directory_path().string()), InputError);
}

}  // namespace
}  // namespace repose
