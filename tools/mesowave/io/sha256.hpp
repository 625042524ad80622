#pragma once
// SHA-256 (FIPS 180-4), for content hashes of every file a run reads or writes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace mesowave::io {

/// Incremental SHA-256: update() with any number of chunks, then hex_digest().
class Sha256 {
public:
  Sha256();
  void update(std::span<const std::byte> data);
  void update(std::string_view text);
  /// Finishes the hash; the object must not be updated afterwards.
  std::array<std::uint8_t, 32> digest();
  std::string hex_digest();

private:
  void compress(const std::uint8_t* block);
  std::array<std::uint32_t, 8> state_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t total_bytes_ = 0;
};

/// Lower-case hex SHA-256 of a string.
std::string sha256_hex(std::string_view text);

/// Lower-case hex SHA-256 of a file's content; throws InputError if unreadable.
std::string sha256_file(const std::filesystem::path& path);

}  // namespace mesowave::io
