#include "fuzz/fuzz_file.hpp"

#include "core/memory.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace gt::fuzz {
namespace {

struct PrivateFolder {
  std::filesystem::path path;
  PrivateFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "gt-fuzz-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("fuzz: cannot make a temporary folder");
    path = pattern;
  }
  ~PrivateFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

}  // namespace

std::filesystem::path write_input(const std::uint8_t* data, std::size_t size, const std::string& name) {
  static PrivateFolder folder;
  const std::filesystem::path path = folder.path / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) throw std::runtime_error("fuzz: cannot write " + path.string());
  return path;
}

}  // namespace gt::fuzz

// libFuzzer calls this once before the first input: the loaders' memory estimates are held to
// 1 GiB, below the 2 GB at which scripts/fuzz.sh has libFuzzer report an allocation as a bug, so
// that an input declaring a large but honest grid is refused by its estimate, as for a user.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  gt::set_memory_limit(1024.0 * 1024.0 * 1024.0);
  return 0;
}
