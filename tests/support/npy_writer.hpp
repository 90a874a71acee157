// The bytes of NumPy .npy files, written by hand so tests need no NumPy: a version-1 header and
// little-endian data (the machines are little-endian, as the readers assume).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace gt::testing {

// A version-1 .npy header for this dtype, order and shape (Python tuple text), padded as numpy pads
// it: spaces and a newline up to a multiple of 64 bytes.
inline std::string npy_header(const std::string& descr, const std::string& shape, bool fortran_order = false) {
  std::string dict = fmt::format("{{'descr': '{}', 'fortran_order': {}, 'shape': {}, }}", descr,
                                 fortran_order ? "True" : "False", shape);
  const std::size_t preamble = 10;  // magic, version, uint16 length
  dict.append(63 - (preamble + dict.size()) % 64, ' ');
  dict.push_back('\n');
  const auto length = static_cast<std::uint16_t>(dict.size());
  std::string header("\x93NUMPY\x01\x00", 8);
  header.append(reinterpret_cast<const char*>(&length), sizeof length);
  return header + dict;
}

template <class T>
std::string npy_data(const std::vector<T>& values) {
  return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)};
}

}  // namespace gt::testing
