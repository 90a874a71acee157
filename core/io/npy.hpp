// Internal to core/io: one reader and one writer of NumPy's .npy array format, shared by the arrays inside .npz
// archives (dem_formats.cpp, a libzip member) and plain .npy files (volume_io.cpp's volumes,
// dem_formats.cpp's heightmaps).
//
// The reader sees its bytes through a ByteSource, so the header parser, the size check and the
// value conversion exist once whatever holds the array. Supported: format versions 1 to 3, dtypes
// '<i2' '<i4' '<f4' '<f8' (returned as double, which holds all four exactly), C order
// (fortran_order False); anything else is an InputError naming `where` (the caller's name for the
// array: a file, or an archive and member).
//
// Decisions: the caller's ShapeCheck judges the shape (how many axes, how large) and returns the
// element count before anything is allocated; the stored size must then equal what the header
// promises, exactly (short: truncated; long: trailing bytes, a sign of a damaged file either way).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gt::detail {

// Copies up to `bytes` bytes of the stream into `destination` and returns how many it copied
// (fewer only at the end); throws InputError when the stream cannot be read.
using ByteSource = std::function<std::size_t(void* destination, std::size_t bytes)>;

// Returns the element count of an array of this shape, or throws InputError when the caller
// refuses the shape (wrong number of axes, empty, too large).
using ShapeCheck = std::function<std::size_t(const std::vector<long long>& shape)>;

struct NpyArray {
  std::vector<long long> shape;  // NumPy's order: the last axis varies fastest in `values`
  std::vector<double> values;
};

// Reads a whole .npy array from `source`, whose stored size is `stored_bytes`.
NpyArray read_npy(const ByteSource& source, std::uintmax_t stored_bytes, const ShapeCheck& element_count,
                  const std::string& where);

// Reads a plain .npy file; `what` names the array in the messages of a file that cannot be sized
// or opened ("{file}: cannot read {what}: ...", "{file}: cannot open {what}").
NpyArray read_npy_file(const std::filesystem::path& file, const ShapeCheck& element_count, const std::string& what);

// Writes `values` (float32 '<f4' or float64 '<f8' by the vector's type, C order, the last axis
// fastest) of `shape` as a .npy file of format 1.0 at `destination`: the magic, the version, a
// little-endian uint16 header length and a Python dict literal padded with spaces and a newline so
// that the data starts at a multiple of 64 bytes. `target` names the file in the message of a
// failed write (InputError). The host is little-endian (core/io's readers assume it too).
void write_npy(const std::vector<long long>& shape, const std::vector<float>& values,
               const std::filesystem::path& destination, const std::filesystem::path& target);
void write_npy(const std::vector<long long>& shape, const std::vector<double>& values,
               const std::filesystem::path& destination, const std::filesystem::path& target);

}  // namespace gt::detail
