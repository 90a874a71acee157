#include "core/io/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <fmt/format.h>
#include <unistd.h>

#include "core/errors.hpp"

namespace gt {

namespace {

[[noreturn]] void refuse_write(const std::filesystem::path& file, int error_number) {
  throw InputError(fmt::format("cannot write {}: {}", file.string(), std::strerror(error_number)));
}

// Writes every byte, then closes; the first failure (errno at that moment) is an InputError.
void write_bytes(const std::filesystem::path& temporary, const std::filesystem::path& file,
                 std::string_view contents) {
  std::FILE* stream = std::fopen(temporary.c_str(), "wb");
  if (stream == nullptr) refuse_write(file, errno);
  const bool written = std::fwrite(contents.data(), 1, contents.size(), stream) == contents.size() &&
                       std::fflush(stream) == 0;
  const int write_error = errno;
  const bool closed = std::fclose(stream) == 0;
  if (!written) refuse_write(file, write_error);
  if (!closed) refuse_write(file, errno);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(const std::filesystem::path& temporary)>& write) {
  const std::filesystem::path temporary =
      file.parent_path() /
      fmt::format(".{}.{}.partial{}", file.filename().string(), getpid(), file.extension().string());
  const auto remove_temporary = [&temporary] {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
  };
  try {
    write(temporary);
  } catch (...) {
    remove_temporary();
    throw;
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) {
    remove_temporary();
    throw InputError(fmt::format("cannot write {}: {}", file.string(), error.message()));
  }
}

void write_file_atomically(const std::filesystem::path& file, std::string_view contents) {
  write_file_atomically(file, [&](const std::filesystem::path& temporary) { write_bytes(temporary, file, contents); });
}

void write_image_atomically(const std::filesystem::path& file, const OIIO::ImageSpec& spec, OIIO::TypeDesc pixel_type,
                            const void* pixels) {
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput in_memory(encoded);
  const auto output = OIIO::ImageOutput::create(file.string());
  if (!output) throw InputError(fmt::format("cannot write {}: {}", file.string(), OIIO::geterror()));
  if (!output->set_ioproxy(&in_memory) || !output->open(file.string(), spec) ||
      !output->write_image(pixel_type, pixels) || !output->close()) {
    throw InputError(fmt::format("cannot write {}: {}", file.string(), output->geterror()));
  }
  write_file_atomically(file, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

}  // namespace gt
