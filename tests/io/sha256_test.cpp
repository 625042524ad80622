// SHA-256 against the FIPS 180-4 example vectors (NIST CSRC "SHA256.pdf").
#include <gtest/gtest.h>

#include <string>

#include "mesowave/io/sha256.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;

TEST(Sha256, NistVectors) {
  EXPECT_EQ(io::sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(io::sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(io::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(io::sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, ChunkingDoesNotMatter) {
  std::string text;
  for (int i = 0; i < 1000; ++i) text += char('a' + i % 26);
  io::Sha256 pieces;
  for (std::size_t at = 0; at < text.size(); at += 7) pieces.update(std::string_view(text).substr(at, 7));
  EXPECT_EQ(pieces.hex_digest(), io::sha256_hex(text));
}

TEST(Sha256, FileHashEqualsTextHash) {
  test::TempDir dir;
  test::write_file(dir / "f.txt", "abc");
  EXPECT_EQ(io::sha256_file(dir / "f.txt"), io::sha256_hex("abc"));
}
