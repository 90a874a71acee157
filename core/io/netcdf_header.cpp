// The classic netCDF header walked with its counts bounded; see core/io/netcdf_header.hpp.
#include "core/io/netcdf_header.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt::detail {
namespace {

constexpr std::uint64_t max_header_bytes = std::uint64_t{16} << 20;
constexpr std::uint32_t dimension_tag = 0x0A, variable_tag = 0x0B, attribute_tag = 0x0C;

// Bytes per value of an nc_type (NC_BYTE 1 ... NC_UINT64 11; 7-11 are CDF-5's); 0 when unknown.
std::uint64_t type_bytes(std::uint32_t type, int version) {
  static constexpr std::uint64_t sizes[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
  const std::uint32_t largest = version == 5 ? 11 : 6;
  return type >= 1 && type <= largest ? sizes[type] : 0;
}

std::uint64_t padded(std::uint64_t bytes) { return (bytes + 3) / 4 * 4; }

class Header {
 public:
  Header(std::string bytes, std::uint64_t file_bytes, int version, const std::filesystem::path& file)
      : bytes_(std::move(bytes)), file_bytes_(file_bytes), version_(version), file_(file) {}

  int version() const { return version_; }
  std::uint64_t file_bytes() const { return file_bytes_; }

  std::uint32_t u32() {
    need(4, "a number");
    std::uint32_t value = 0;
    for (int k = 0; k < 4; ++k) value = value << 8 | static_cast<unsigned char>(bytes_[position_++]);
    return value;
  }
  std::uint64_t u64() {
    const std::uint64_t high = u32();
    return high << 32 | u32();
  }
  // nelems, a dimension's length, a variable's vsize: 8 bytes in CDF-5, else 4.
  std::uint64_t count() { return version_ == 5 ? u64() : u32(); }
  // A variable's begin: 4 bytes in CDF-1, else 8.
  std::uint64_t offset() { return version_ == 1 ? u32() : u64(); }
  void skip(std::uint64_t bytes, const std::string& what) {
    need(bytes, what);
    position_ += bytes;
  }
  std::string name() {
    const std::uint64_t length = count();
    need(padded(length), fmt::format("a name of {} characters", length));
    std::string text = bytes_.substr(position_, std::min<std::uint64_t>(length, 120));
    position_ += padded(length);
    return text;
  }
  // Refuses `count` items of at least `each` bytes that the rest of the file cannot hold.
  void check_count(std::uint64_t count, std::uint64_t each, const std::string& what) {
    const std::uint64_t rest = file_bytes_ - position_;
    if (count > rest / each) {
      throw refusal(fmt::format("declares {} {}, more than the {} bytes after them can hold", count, what, rest));
    }
  }
  InputError refusal(const std::string& why) const {
    return InputError(fmt::format("{}: not a netCDF file groundtruth reads: its header {}", file_.string(), why));
  }

 private:
  void need(std::uint64_t bytes, const std::string& what) {
    if (bytes <= bytes_.size() - position_) return;
    if (file_bytes_ > bytes_.size()) throw refusal(fmt::format("is larger than {} MiB", max_header_bytes >> 20));
    throw refusal(fmt::format("ends inside {} (at byte {} of {})", what, position_, file_bytes_));
  }

  std::string bytes_;
  std::uint64_t file_bytes_;
  int version_;
  std::filesystem::path file_;
  std::uint64_t position_ = 4;  // after the magic number
};

// A list's tag and element count: 0 for ABSENT (two zeros), else the count after `tag`.
std::uint64_t list_count(Header& header, std::uint32_t tag, const char* list) {
  const std::uint32_t found = header.u32();
  const std::uint64_t count = header.count();
  if (found == 0 && count == 0) return 0;
  if (found != tag) throw header.refusal(fmt::format("has tag {:#x} where the {} list belongs", found, list));
  return count;
}

void skip_attributes(Header& header) {
  const std::uint64_t attributes = list_count(header, attribute_tag, "attribute");
  const std::uint64_t smallest = header.version() == 5 ? 20 : 12;  // an empty name, a type, no values
  header.check_count(attributes, smallest, "attributes");
  for (std::uint64_t index = 0; index < attributes; ++index) {
    const std::string name = header.name();
    const std::uint32_t type = header.u32();
    const std::uint64_t each = type_bytes(type, header.version());
    if (each == 0) throw header.refusal(fmt::format("gives attribute {} the unknown type {}", name, type));
    const std::uint64_t values = header.count();
    header.check_count(values, each, fmt::format("values of attribute {}", name));
    header.skip(padded(values * each), fmt::format("the values of attribute {}", name));
  }
}

}  // namespace

void check_netcdf_header(const std::filesystem::path& file) {
  std::error_code error;
  const std::uint64_t file_bytes = std::filesystem::file_size(file, error);
  if (error) return;  // libnetcdf names what is wrong with it
  std::ifstream in(file, std::ios::binary);
  std::string bytes(static_cast<std::size_t>(std::min(file_bytes, max_header_bytes)), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (bytes.size() < 4 || bytes.compare(0, 3, "CDF") != 0) return;  // netCDF-4 (HDF5) or not netCDF
  const int version = bytes[3];
  if (version != 1 && version != 2 && version != 5) return;  // libnetcdf refuses it
  Header header(std::move(bytes), file_bytes, version, file);
  header.count();  // numrecs (or STREAMING)

  const std::uint64_t dimension_count = list_count(header, dimension_tag, "dimension");
  header.check_count(dimension_count, version == 5 ? 16 : 8, "dimensions");
  std::vector<std::uint64_t> lengths;
  for (std::uint64_t index = 0; index < dimension_count; ++index) {
    header.name();
    lengths.push_back(header.count());
  }
  skip_attributes(header);  // the global attributes

  const std::uint64_t variables = list_count(header, variable_tag, "variable");
  header.check_count(variables, version == 1 ? 28 : version == 2 ? 32 : 48, "variables");
  for (std::uint64_t index = 0; index < variables; ++index) {
    const std::string name = header.name();
    const std::uint64_t rank = header.count();
    header.check_count(rank, version == 5 ? 8 : 4, fmt::format("dimensions of variable {}", name));
    std::vector<std::uint64_t> dimensions;
    for (std::uint64_t k = 0; k < rank; ++k) dimensions.push_back(header.count());
    skip_attributes(header);
    const std::uint32_t type = header.u32();
    const std::uint64_t each = type_bytes(type, version);
    if (each == 0) throw header.refusal(fmt::format("gives variable {} the unknown type {}", name, type));
    header.count();  // vsize: recomputed below, since it saturates for large variables
    const std::uint64_t begin = header.offset();
    double data_bytes = static_cast<double>(each);
    bool record_variable = false;
    for (const std::uint64_t dimension : dimensions) {
      if (dimension >= lengths.size()) {
        throw header.refusal(fmt::format("gives variable {} dimension id {} of {}", name, dimension, lengths.size()));
      }
      record_variable = record_variable || lengths[dimension] == 0;  // the unlimited dimension
      data_bytes *= static_cast<double>(lengths[dimension]);
    }
    if (!record_variable && static_cast<double>(begin) + data_bytes > static_cast<double>(file_bytes)) {
      throw InputError(fmt::format("{}: truncated: variable {}'s data ends at byte {:.0f}, but the file has {} bytes",
                                   file.string(), name, static_cast<double>(begin) + data_bytes, file_bytes));
    }
  }
}

}  // namespace gt::detail
