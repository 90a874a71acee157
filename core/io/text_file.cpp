// User-given text files read whole; see core/io/text_file.hpp.
#include "core/io/text_file.hpp"

#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/memory.hpp"

namespace gt {

void require_regular_file(const std::filesystem::path& file, const std::string& what) {
  const std::string named = what.empty() ? file.string() : fmt::format("{} {}", what, file.string());
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) throw InputError(fmt::format("{}: no such file", named));
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError(fmt::format("{}: {}, not a regular file", named,
                                 std::filesystem::is_directory(status) ? "a folder" : "a pipe, socket or device"));
  }
}

std::string read_text_file(const std::filesystem::path& file, const TextFileLimits& limits, const std::string& what) {
  require_regular_file(file, what);
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) throw InputError(fmt::format("{} {}: cannot read: {}", what, file.string(), error.message()));
  if (size > limits.max_bytes) {
    throw InputError(fmt::format("{} {}: {} is larger than the {} such a file may have", what, file.string(),
                                 format_bytes(static_cast<double>(size)), format_bytes(static_cast<double>(limits.max_bytes))));
  }
  require_memory(memory_for(static_cast<double>(size), "bytes", limits.parse_bytes_per_byte),
                 fmt::format("reading {} {}", what, file.string()));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{} {}: cannot be read", what, file.string()));
  // The size that was checked, read once: a file that grows meanwhile is not followed.
  std::string contents(static_cast<std::size_t>(size), '\0');
  in.read(contents.data(), static_cast<std::streamsize>(size));
  if (in.bad()) throw InputError(fmt::format("{} {}: cannot be read", what, file.string()));
  contents.resize(static_cast<std::size_t>(in.gcount()));
  return contents;
}

}  // namespace gt
