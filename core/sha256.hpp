// SHA-256 digests for provenance (issue 15): a report names the exact shader sources compiled and
// the data files read by their digests, so two reports tell whether they ran the same code on the
// same data. OpenSSL's libcrypto computes them.
//
// Output: 64 lower-case hexadecimal digits.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace gt {

std::string sha256_hex(std::string_view bytes);

// The digest of a file's bytes, read in blocks; throws InputError when it cannot be read.
std::string sha256_file_hex(const std::filesystem::path& file);

}  // namespace gt
