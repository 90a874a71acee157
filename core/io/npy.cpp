// The .npy reader of npy.hpp: preamble and header dict, the caller's shape check, the size check,
// then the values converted to double.
//
// The header is a Python dict literal, e.g. {'descr': '<i2', 'fortran_order': False, 'shape': (344, 403), }
// and is read with three regular expressions (keys in any order, spaces free) rather than a
// Python-literal parser: the format fixes its three keys and their value syntax. Data is copied
// as it is stored, which is right for the little-endian dtypes accepted on a little-endian host.
#include "core/io/npy.hpp"

#include <bit>
#include <charconv>
#include <fstream>
#include <limits>
#include <regex>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"

namespace gt::detail {
namespace {

static_assert(std::endian::native == std::endian::little, "the .npy reader copies little-endian data as is");

constexpr std::uint32_t max_header_length = 1u << 20;

struct NpyHeader {
  std::string descr;
  std::vector<long long> shape;
  std::size_t bytes = 0;  // magic, version, length field and header text: where the data starts
};

void read_exact(const ByteSource& source, void* destination, std::size_t bytes, const std::string& where) {
  const std::size_t read = source(destination, bytes);
  if (read != bytes) throw InputError(fmt::format("{}: truncated ({} of {} bytes)", where, read, bytes));
}

std::vector<long long> parse_shape(const std::string& tuple, const std::string& where) {
  std::vector<long long> shape;
  static const std::regex dimension_pattern(R"(\s*([^,\s]+)\s*(,|$))");
  for (auto it = std::sregex_iterator(tuple.begin(), tuple.end(), dimension_pattern); it != std::sregex_iterator();
       ++it) {
    const std::string text = (*it)[1];
    long long dimension = -1;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), dimension);
    if (error != std::errc{} || end != text.data() + text.size() || dimension < 0) {
      throw InputError(fmt::format("{}: bad .npy shape ({})", where, tuple));
    }
    shape.push_back(dimension);
  }
  return shape;
}

std::string header_field(const std::string& header, const std::regex& pattern, const char* key,
                         const std::string& where) {
  std::smatch match;
  if (!std::regex_search(header, match, pattern)) {
    throw InputError(fmt::format("{}: .npy header has no valid '{}': {}", where, key, header));
  }
  return match[1];
}

NpyHeader read_header(const ByteSource& source, const std::string& where) {
  char preamble[8];  // magic "\x93NUMPY", major and minor version
  const std::size_t read = source(preamble, sizeof preamble);
  if (read != sizeof preamble || std::string_view(preamble, 6) != "\x93NUMPY") {
    throw InputError(fmt::format("{}: not a .npy array (no \\x93NUMPY magic)", where));
  }
  const int major_version = static_cast<unsigned char>(preamble[6]);
  if (major_version < 1 || major_version > 3) {
    throw InputError(fmt::format("{}: unsupported .npy format version {}", where, major_version));
  }
  std::uint32_t header_length = 0;  // little-endian uint16 in version 1, uint32 in versions 2 and 3
  const std::size_t length_bytes = major_version == 1 ? 2 : 4;
  read_exact(source, &header_length, length_bytes, where);
  if (header_length > max_header_length) {
    throw InputError(fmt::format("{}: .npy header of {} bytes", where, header_length));
  }

  std::string header(header_length, '\0');
  read_exact(source, header.data(), header.size(), where);
  static const std::regex descr_pattern(R"('descr'\s*:\s*'([^']*)')");
  static const std::regex fortran_pattern(R"('fortran_order'\s*:\s*(True|False))");
  static const std::regex shape_pattern(R"('shape'\s*:\s*\(([^)]*)\))");
  if (header_field(header, fortran_pattern, "fortran_order", where) != "False") {
    throw InputError(fmt::format("{}: Fortran-ordered .npy arrays are not supported", where));
  }
  return {header_field(header, descr_pattern, "descr", where),
          parse_shape(header_field(header, shape_pattern, "shape", where), where),
          sizeof preamble + length_bytes + header_length};
}

std::size_t item_size(const std::string& descr, const std::string& where) {
  if (descr == "<i2") return 2;
  if (descr == "<i4" || descr == "<f4") return 4;
  if (descr == "<f8") return 8;
  throw InputError(fmt::format("{}: unsupported .npy dtype '{}' (supported: <i2 <i4 <f4 <f8)", where, descr));
}

// Throws unless `stored_bytes` is exactly the header plus `count` items.
void check_stored_size(const NpyHeader& header, std::size_t count, std::size_t item_bytes, std::uintmax_t stored_bytes,
                       const std::string& where) {
  const std::uintmax_t data_bytes_max = std::numeric_limits<std::uintmax_t>::max() - header.bytes;
  if (count > data_bytes_max / item_bytes) {
    throw InputError(fmt::format("{}: .npy shape of {} elements overflows a byte count", where, count));
  }
  const std::uintmax_t promised = header.bytes + std::uintmax_t{count} * item_bytes;
  if (stored_bytes < promised) {
    throw InputError(fmt::format("{}: truncated: holds {} bytes, its header promises {}", where, stored_bytes,
                                 promised));
  }
  if (stored_bytes > promised) {
    throw InputError(fmt::format("{}: holds {} bytes, its header promises {} (trailing bytes)", where, stored_bytes,
                                 promised));
  }
}

template <class T>
std::vector<double> read_values(const ByteSource& source, std::size_t count, const std::string& where) {
  if constexpr (std::is_same_v<T, double>) {
    std::vector<double> values(count);
    read_exact(source, values.data(), count * sizeof(double), where);
    return values;
  } else {
    std::vector<T> stored(count);
    read_exact(source, stored.data(), count * sizeof(T), where);
    return {stored.begin(), stored.end()};
  }
}

std::vector<double> read_data(const ByteSource& source, const std::string& descr, std::size_t count,
                              const std::string& where) {
  if (descr == "<i2") return read_values<std::int16_t>(source, count, where);
  if (descr == "<i4") return read_values<std::int32_t>(source, count, where);
  if (descr == "<f4") return read_values<float>(source, count, where);
  return read_values<double>(source, count, where);
}

}  // namespace

NpyArray read_npy(const ByteSource& source, std::uintmax_t stored_bytes, const ShapeCheck& element_count,
                  const std::string& where) {
  const NpyHeader header = read_header(source, where);
  const std::size_t item_bytes = item_size(header.descr, where);
  const std::size_t count = element_count(header.shape);
  check_stored_size(header, count, item_bytes, stored_bytes, where);
  return {header.shape, read_data(source, header.descr, count, where)};
}

NpyArray read_npy_file(const std::filesystem::path& file, const ShapeCheck& element_count, const std::string& what) {
  const std::string where = file.string();
  std::error_code error;
  const std::uintmax_t stored_bytes = std::filesystem::file_size(file, error);
  if (error) throw InputError(fmt::format("{}: cannot read {}: {}", where, what, error.message()));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open {}", where, what));
  const ByteSource source = [&in, &where](void* destination, std::size_t bytes) {
    in.read(static_cast<char*>(destination), static_cast<std::streamsize>(bytes));
    if (in.bad()) throw InputError(fmt::format("{}: read error", where));
    return static_cast<std::size_t>(in.gcount());
  };
  return read_npy(source, stored_bytes, element_count, where);
}

namespace {

// The magic, the version, the header and `bytes` of data with NumPy's type string `descr`.
void write_npy_bytes(const std::vector<long long>& shape, const char* descr, const void* data, std::size_t bytes,
                     const std::filesystem::path& destination, const std::filesystem::path& target) {
  // A 1-tuple needs its comma: (5,).
  const std::string dimensions = shape.size() == 1 ? fmt::format("{},", shape[0]) : fmt::format("{}", fmt::join(shape, ", "));
  std::string header = fmt::format("{{'descr': '{}', 'fortran_order': False, 'shape': ({}), }}", descr, dimensions);
  const std::size_t preamble = 10;  // magic (6), version (2), header length (2)
  header.append(63 - (preamble + header.size()) % 64, ' ');
  header.push_back('\n');
  std::ofstream out(destination, std::ios::binary);
  const auto length = static_cast<std::uint16_t>(header.size());
  const char lead[preamble] = {'\x93', 'N', 'U', 'M', 'P', 'Y', '\x01', '\x00', static_cast<char>(length & 0xff),
                               static_cast<char>(length >> 8)};
  out.write(lead, preamble);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
  out.close();
  if (!out) throw InputError(fmt::format("cannot write {}", target.string()));
}

}  // namespace

void write_npy(const std::vector<long long>& shape, const std::vector<float>& values,
               const std::filesystem::path& destination, const std::filesystem::path& target) {
  write_npy_bytes(shape, "<f4", values.data(), values.size() * sizeof(float), destination, target);
}

void write_npy(const std::vector<long long>& shape, const std::vector<double>& values,
               const std::filesystem::path& destination, const std::filesystem::path& target) {
  write_npy_bytes(shape, "<f8", values.data(), values.size() * sizeof(double), destination, target);
}

}  // namespace gt::detail
