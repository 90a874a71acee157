// The .npy reader of npy.hpp: preamble and header dict, the caller's shape check, the size check,
// then the values converted to double.
//
// The header is a Python dict literal, e.g. {'descr': '<i2', 'fortran_order': False, 'shape': (344, 403), }
// and is read by finding its three keys (in any order, spaces free around the colon) and scanning
// their values, each in one linear pass without recursion (std::regex recursed once a character:
// a 100 KB header overflowed the stack), rather than with a Python-literal parser: the format fixes
// its three keys and their value syntax. Headers over numpy's own 10,000-byte default are refused
// before they are read. Data is copied
// as it is stored, which is right for the little-endian dtypes accepted on a little-endian host.
#include "core/io/npy.hpp"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"
#include "core/io/text_file.hpp"

namespace gt::detail {
namespace {

static_assert(std::endian::native == std::endian::little, "the .npy reader copies little-endian data as is");

// numpy.load's own default limit (max_header_size): a header of the four dtypes read here needs
// under 200 bytes; a longer one is hostile or not one of ours.
constexpr std::uint32_t max_header_length = 10000;

struct NpyHeader {
  std::string descr;
  std::vector<long long> shape;
  std::size_t bytes = 0;  // magic, version, length field and header text: where the data starts
};

void read_exact(const ByteSource& source, void* destination, std::size_t bytes, const std::string& where) {
  const std::size_t read = source(destination, bytes);
  if (read != bytes) throw InputError(fmt::format("{}: truncated ({} of {} bytes)", where, read, bytes));
}

// The header dict's text after `'key':` (spaces free around the colon), or nullopt without the key.
std::optional<std::string_view> after_key(std::string_view header, std::string_view key) {
  const std::string quoted = fmt::format("'{}'", key);
  const std::size_t found = header.find(quoted);
  if (found == std::string_view::npos) return std::nullopt;
  const auto skip_spaces = [](std::string_view text) {
    const std::size_t first = text.find_first_not_of(" \t");
    return first == std::string_view::npos ? std::string_view() : text.substr(first);
  };
  const std::string_view rest = skip_spaces(header.substr(found + quoted.size()));
  if (rest.empty() || rest.front() != ':') return std::nullopt;
  return skip_spaces(rest.substr(1));
}

// Text as quoted in a message: its first 120 characters.
std::string quoted_text(std::string_view text) {
  return text.size() <= 120 ? std::string(text) : fmt::format("{}... ({} bytes)", text.substr(0, 120), text.size());
}

[[noreturn]] void bad_field(std::string_view header, const char* key, const std::string& where) {
  throw InputError(fmt::format("{}: .npy header has no valid '{}': {}", where, key, quoted_text(header)));
}

// 'descr': '<text>'
std::string descr_of(std::string_view header, const std::string& where) {
  const auto value = after_key(header, "descr");
  if (!value || value->empty() || value->front() != '\'') bad_field(header, "descr", where);
  const std::size_t close = value->find('\'', 1);
  if (close == std::string_view::npos) bad_field(header, "descr", where);
  return std::string(value->substr(1, close - 1));
}

// 'fortran_order': True|False
bool fortran_order_of(std::string_view header, const std::string& where) {
  const auto value = after_key(header, "fortran_order");
  if (value && value->starts_with("True")) return true;
  if (value && value->starts_with("False")) return false;
  bad_field(header, "fortran_order", where);
}

// One dimension of a shape tuple, spaces around it free.
long long dimension_of(std::string_view text, std::string_view tuple, const std::string& where) {
  const std::size_t first = text.find_first_not_of(" \t");
  const std::size_t last = text.find_last_not_of(" \t");
  if (first != std::string_view::npos) text = text.substr(first, last - first + 1);
  long long dimension = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), dimension);
  if (first == std::string_view::npos || error != std::errc{} || end != text.data() + text.size() || dimension < 0) {
    throw InputError(fmt::format("{}: bad .npy shape ({})", where, quoted_text(tuple)));
  }
  return dimension;
}

// 'shape': (d0, d1, ...) with an optional trailing comma; () is a scalar's.
std::vector<long long> shape_of(std::string_view header, const std::string& where) {
  const auto value = after_key(header, "shape");
  if (!value || value->empty() || value->front() != '(') bad_field(header, "shape", where);
  const std::size_t close = value->find(')');
  if (close == std::string_view::npos) bad_field(header, "shape", where);
  const std::string_view tuple = value->substr(1, close - 1);
  std::vector<long long> shape;
  std::size_t start = 0;
  while (start < tuple.size()) {
    const std::size_t comma = std::min(tuple.find(',', start), tuple.size());
    const std::string_view text = tuple.substr(start, comma - start);
    const bool trailing = comma == tuple.size() && text.find_first_not_of(" \t") == std::string_view::npos;
    if (!trailing) shape.push_back(dimension_of(text, tuple, where));
    start = comma + 1;
  }
  return shape;
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
    throw InputError(fmt::format("{}: .npy header of {} bytes, over the {} numpy.load reads by default", where,
                                 header_length, max_header_length));
  }

  std::string header(header_length, '\0');
  read_exact(source, header.data(), header.size(), where);
  if (fortran_order_of(header, where)) {
    throw InputError(fmt::format("{}: Fortran-ordered .npy arrays are not supported", where));
  }
  return {descr_of(header, where), shape_of(header, where), sizeof preamble + length_bytes + header_length};
}

std::size_t item_size(const std::string& descr, const std::string& where) {
  if (descr == "<i2") return 2;
  if (descr == "<i4" || descr == "<f4") return 4;
  if (descr == "<f8") return 8;
  throw InputError(
      fmt::format("{}: unsupported .npy dtype '{}' (supported: <i2 <i4 <f4 <f8)", where, quoted_text(descr)));
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
  require_regular_file(file, fmt::format("cannot read {}", what));
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
  if (!out) throw InputError(fmt::format("cannot write {}: {}", target.string(), std::strerror(errno)));
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
