// Shared by the libFuzzer targets: the loaders read paths, so each input is written to a file
// with the extension the loader picks its reader by, in a private temporary folder that the
// process removes at exit. Linking this also caps the loaders' memory estimates at 1 GiB
// (LLVMFuzzerInitialize).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace gt::fuzz {

// Writes `size` bytes to `<private folder>/<name>` (replacing the previous input) and returns the path.
std::filesystem::path write_input(const std::uint8_t* data, std::size_t size, const std::string& name);

}  // namespace gt::fuzz
