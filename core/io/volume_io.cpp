// read_volume (volume_io.hpp): a plain .npy file through core/io/npy.hpp's reader, with the
// volume's own shape rules (3-D, 2 to 2^28 samples) and a finiteness check after reading.
//
// The file's size comes from the file system before it is opened for reading, so a header that
// promises more than the file holds is refused before the samples are allocated.
#include "core/io/volume_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/npy.hpp"

namespace gt {
namespace {

using std::filesystem::path;

constexpr long long max_samples = 1LL << 28;

// Samples of an array of this shape, after refusing anything but (nz, ny, nx) with 2 to 2^28
// samples in all and at least 2 per axis.
std::size_t checked_sample_count(const std::vector<long long>& shape, const std::string& where) {
  if (shape.size() != 3) {
    throw InputError(fmt::format("{}: a volume is a 3-D array (nz, ny, nx), this one has shape ({})", where,
                                 fmt::join(shape, ", ")));
  }
  if (std::any_of(shape.begin(), shape.end(), [](long long samples) { return samples < 2; })) {
    throw InputError(fmt::format("{}: empty volume: shape ({}) has an axis of fewer than 2 samples, the least that "
                                 "holds a cube",
                                 where, fmt::join(shape, ", ")));
  }
  long long samples = 1;
  for (const long long axis_samples : shape) {
    if (axis_samples > max_samples / samples) {
      throw InputError(fmt::format("{}: shape ({}) holds more than 2^28 samples, too large for memory", where,
                                   fmt::join(shape, ", ")));
    }
    samples *= axis_samples;
  }
  return static_cast<std::size_t>(samples);
}

void check_finite(const Volume<double>& volume, const std::string& where) {
  const auto first = std::find_if(volume.values.begin(), volume.values.end(),
                                  [](double value) { return !std::isfinite(value); });
  if (first == volume.values.end()) return;
  const auto index = static_cast<std::size_t>(first - volume.values.begin());
  const std::size_t row_samples = static_cast<std::size_t>(volume.nx);
  const std::size_t slice_samples = row_samples * static_cast<std::size_t>(volume.ny);
  throw InputError(fmt::format("{}: sample (x, y, z) = ({}, {}, {}) is {}; a volume must be finite", where,
                               index % row_samples, index % slice_samples / row_samples, index / slice_samples,
                               *first));
}

}  // namespace

Volume<double> read_volume(const path& file) {
  const std::string where = file.string();
  const auto sample_count = [&where](const std::vector<long long>& shape) {
    return checked_sample_count(shape, where);
  };
  detail::NpyArray array = detail::read_npy_file(file, sample_count, "the volume");

  Volume<double> volume;
  volume.nz = static_cast<int>(array.shape[0]);
  volume.ny = static_cast<int>(array.shape[1]);
  volume.nx = static_cast<int>(array.shape[2]);
  volume.values = std::move(array.values);
  check_finite(volume, where);
  return volume;
}

void write_volume(const Volume<double>& volume, const std::filesystem::path& path) {
  const std::size_t samples = static_cast<std::size_t>(std::max(volume.nx, 0)) * static_cast<std::size_t>(std::max(volume.ny, 0)) *
                              static_cast<std::size_t>(std::max(volume.nz, 0));
  if (samples == 0 || volume.values.size() != samples) {
    throw InputError(fmt::format("cannot write {}: volume {}x{}x{} holds {} values", path.string(), volume.nx,
                                 volume.ny, volume.nz, volume.values.size()));
  }
  const std::vector<float> values(volume.values.begin(), volume.values.end());
  write_file_atomically(path, [&](const std::filesystem::path& temporary) {
    detail::write_npy({volume.nz, volume.ny, volume.nx}, values, temporary, path);
  });
}

}  // namespace gt
