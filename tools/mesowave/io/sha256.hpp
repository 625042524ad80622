#pragma once
// SHA-256 (FIPS 180-4), for content hashes of every file a run reads or writes.
// The hash itself is OpenSSL's (libcrypto, the EVP digest interface): a maintained,
// validated implementation, not one of ours; this header only fits it to the
// library's types (byte spans, strings, files) and to InputError.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>

// OpenSSL's context type, declared as <openssl/types.h> does, so that users of
// this header do not include OpenSSL.
struct evp_md_ctx_st;

namespace mesowave::io {

/// Incremental SHA-256: update() with any number of chunks, then hex_digest().
class Sha256 {
public:
  Sha256();
  ~Sha256();
  Sha256(Sha256&&) noexcept;
  Sha256& operator=(Sha256&&) noexcept;
  void update(std::span<const std::byte> data);
  void update(std::string_view text);
  /// Finishes the hash; the object must not be updated afterwards.
  std::array<std::uint8_t, 32> digest();
  std::string hex_digest();

private:
  struct FreeContext {
    void operator()(evp_md_ctx_st* context) const;
  };
  std::unique_ptr<evp_md_ctx_st, FreeContext> context_;
};

/// Lower-case hex SHA-256 of a string.
std::string sha256_hex(std::string_view text);

/// Lower-case hex SHA-256 of a file's content; throws InputError if unreadable.
std::string sha256_file(const std::filesystem::path& path);

}  // namespace mesowave::io
