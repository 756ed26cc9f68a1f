#pragma once
// SHA-256 checksums (OpenSSL EVP), so a hierarchy records exactly which input produced it.
#include <filesystem>
#include <span>
#include <string>

namespace molmesh {

// Lower-case hex digest of a file's bytes. Throws InputError when it cannot be read.
std::string sha256_file(const std::filesystem::path& path);

// Lower-case hex digest of a byte buffer.
std::string sha256_bytes(std::span<const unsigned char> bytes);

}  // namespace molmesh
