// SHA-256 through OpenSSL's EVP interface; see core/sha256.hpp.
#include "core/sha256.hpp"

#include <array>
#include <fstream>
#include <memory>

#include <fmt/format.h>
#include <openssl/evp.h>

#include "core/errors.hpp"

namespace gt {
namespace {

using DigestContext = std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)>;

DigestContext started_digest() {
  DigestContext context(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!context || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256: libcrypto could not start a digest");
  }
  return context;
}

void add_bytes(EVP_MD_CTX* context, const char* bytes, std::size_t count) {
  if (EVP_DigestUpdate(context, bytes, count) != 1) throw std::runtime_error("SHA-256: libcrypto failed");
}

std::string finished_hex(EVP_MD_CTX* context) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(context, digest.data(), &length) != 1) throw std::runtime_error("SHA-256: libcrypto failed");
  std::string hex;
  for (unsigned int index = 0; index < length; ++index) hex += fmt::format("{:02x}", digest[index]);
  return hex;
}

}  // namespace

std::string sha256_hex(std::string_view bytes) {
  auto context = started_digest();
  add_bytes(context.get(), bytes.data(), bytes.size());
  return finished_hex(context.get());
}

std::string sha256_file_hex(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw InputError(fmt::format("{}: cannot be read to compute its SHA-256", file.string()));
  auto context = started_digest();
  std::array<char, 1 << 16> block{};
  while (stream.read(block.data(), block.size()) || stream.gcount() > 0) {
    add_bytes(context.get(), block.data(), static_cast<std::size_t>(stream.gcount()));
  }
  return finished_hex(context.get());
}

}  // namespace gt
