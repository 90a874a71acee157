// Text files a user gives (report.json, case files, expectations, sweep sets, BMI configs, volcano
// JSON) read whole, with their size and kind checked before a byte is read.
//
//   std::string read_text_file(file, limits, what)
//     Inputs: the path; the largest size accepted; the bytes of memory the caller's parse needs per
//     byte of the file (nlohmann::json holds about 37 B per byte of a report.json: a 115 MB report
//     took 4.25 GB to parse); `what` names the file's role in messages ("--expectations").
//     Output: the file's contents.
//     Throws InputError "WHAT FILE: ..." when the path does not exist, is not a regular file (a
//     FIFO would block forever, a device such as /dev/zero never ends, a folder reads as empty),
//     is larger than `limits.max_bytes`, when its parse would need more memory than this process
//     may use (core/memory.hpp), or when it cannot be read.
//
//   void require_regular_file(file, what)
//     The kind check alone, for every reader of a user's file (heightmaps, meshes, images, netCDF):
//     InputError "WHAT FILE: no such file", "...: a folder, not a regular file" or "...: a pipe,
//     socket or device, not a regular file" (`what` may be empty).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace gt {

struct TextFileLimits {
  std::uintmax_t max_bytes = 0;
  double parse_bytes_per_byte = 0.0;
};

// A JSON document parsed into nlohmann::json: up to 1 GiB, 40 B of memory per byte.
inline constexpr TextFileLimits json_document_limits{std::uintmax_t{1} << 30, 40.0};
// A file a person writes by hand (expectations, a BMI config): up to 16 MiB.
inline constexpr TextFileLimits hand_written_limits{std::uintmax_t{16} << 20, 40.0};

std::string read_text_file(const std::filesystem::path& file, const TextFileLimits& limits, const std::string& what);

void require_regular_file(const std::filesystem::path& file, const std::string& what);

}  // namespace gt
