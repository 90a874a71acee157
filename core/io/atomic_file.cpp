#include "core/io/atomic_file.hpp"

#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

#include "core/errors.hpp"

namespace gt::detail {

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

}  // namespace gt::detail
