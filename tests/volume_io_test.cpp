// Tests of read_volume (core/io/volume_io.hpp) on .npy files written byte by byte here: round trips
// of each dtype with x fastest (shape (nz, ny, nx)), and every refusal, each message naming the
// file and the reason; and of write_volume, read back by read_volume.
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/io/volume_io.hpp"
#include "tests/support/npy_writer.hpp"
#include "tests/support/refusal.hpp"
#include "tests/support/temporary_folder.hpp"

namespace gt {
namespace {

namespace fs = std::filesystem;

using testing::npy_data;
using testing::npy_header;
using testing::refusal;
using testing::TemporaryFolder;

fs::path write_file(const TemporaryFolder& folder, const std::string& name, const std::string& bytes) {
  const fs::path file = folder.path() / name;
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

// value(x, y, z) = 100 z + 10 y + x + 0.25, exact in every dtype tested, in C order of (nz, ny, nx).
template <class T>
std::vector<T> coded_values(int nx, int ny, int nz) {
  std::vector<T> values;
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) values.push_back(static_cast<T>(100 * z + 10 * y + x + 0.25));
    }
  }
  return values;
}

void expect_coded_volume(const Volume<double>& volume, int nx, int ny, int nz, double fraction) {
  ASSERT_EQ(volume.nx, nx);
  ASSERT_EQ(volume.ny, ny);
  ASSERT_EQ(volume.nz, nz);
  ASSERT_EQ(volume.values.size(), static_cast<std::size_t>(nx * ny * nz));
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) EXPECT_EQ(volume.at(x, y, z), 100 * z + 10 * y + x + fraction) << x << y << z;
    }
  }
  EXPECT_EQ(volume.origin, (std::array<double, 3>{0.0, 0.0, 0.0}));
  EXPECT_EQ(volume.spacing, 1.0);
}

TEST(ReadVolume, Float32AndFloat64KeepXFastest) {
  const TemporaryFolder folder;
  const std::string f4 = npy_header("<f4", "(2, 3, 4)") + npy_data(coded_values<float>(4, 3, 2));
  expect_coded_volume(read_volume(write_file(folder, "f4.npy", f4)), 4, 3, 2, 0.25);
  const std::string f8 = npy_header("<f8", "(3, 2, 5)") + npy_data(coded_values<double>(5, 2, 3));
  expect_coded_volume(read_volume(write_file(folder, "f8.npy", f8)), 5, 2, 3, 0.25);
}

TEST(ReadVolume, IntegerDtypesAndFloat32BitsConvertExactly) {
  const TemporaryFolder folder;
  const std::string i2 = npy_header("<i2", "(2, 2, 3)") + npy_data(coded_values<std::int16_t>(3, 2, 2));
  expect_coded_volume(read_volume(write_file(folder, "i2.npy", i2)), 3, 2, 2, 0.0);
  const std::string i4 = npy_header("<i4", "(3, 2, 2)") + npy_data(coded_values<std::int32_t>(2, 2, 3));
  expect_coded_volume(read_volume(write_file(folder, "i4.npy", i4)), 2, 2, 3, 0.0);
  const float smallest = std::numeric_limits<float>::denorm_min();
  std::vector<float> tenths(8, 0.1f);
  tenths[5] = -smallest;  // (1, 0, 1)
  const std::string bits = npy_header("<f4", "(2, 2, 2)") + npy_data(tenths);
  const Volume<double> volume = read_volume(write_file(folder, "tenths.npy", bits));
  EXPECT_EQ(volume.at(0, 0, 0), static_cast<double>(0.1f));
  EXPECT_EQ(volume.at(1, 0, 1), -static_cast<double>(smallest));
}

// Expects read_volume to refuse `file` with a message naming it and containing `reason`.
void expect_refusal(const fs::path& file, const std::string& reason) {
  const std::string message = refusal([&] { read_volume(file); });
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  EXPECT_NE(message.find(reason), std::string::npos) << "expected '" << reason << "' in: " << message;
}

std::string eight_floats() { return npy_data(std::vector<float>(8, 1.0f)); }

// write_volume stores float32: the coded values are exact in float, so they come back exactly, on
// the lattice they were written from; a value beyond float's precision comes back rounded to it.
TEST(WriteVolume, ReadVolumeReadsItBack) {
  const TemporaryFolder folder;
  Volume<double> volume(5, 3, 2);
  volume.values = coded_values<double>(5, 3, 2);
  const fs::path file = folder.path() / "density.npy";
  write_volume(volume, file);
  expect_coded_volume(read_volume(file), 5, 3, 2, 0.25);
  volume.values[0] = 0.1;
  write_volume(volume, file);
  EXPECT_EQ(read_volume(file).values[0], static_cast<double>(0.1f));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder.path()), fs::directory_iterator()), 1)
      << "only the file itself: no temporary left behind";
}

TEST(WriteVolume, RefusesAVolumeShortOfItsSamplesAndAMissingFolder) {
  const TemporaryFolder folder;
  Volume<double> short_volume(4, 4, 4);
  short_volume.values.pop_back();
  EXPECT_NE(refusal([&] { write_volume(short_volume, folder.path() / "short.npy"); }).find("holds 63 values"),
            std::string::npos);
  const Volume<double> volume(2, 2, 2);
  const fs::path missing = folder.path() / "no_such_folder" / "v.npy";
  EXPECT_NE(refusal([&] { write_volume(volume, missing); }).find(missing.string()), std::string::npos);
  EXPECT_TRUE(fs::is_empty(folder.path()));
}

TEST(ReadVolumeRefuses, MissingFileAndAFolder) {
  const TemporaryFolder folder;
  expect_refusal(folder.path() / "absent.npy", "cannot read the volume");
  expect_refusal(folder.path(), "cannot read the volume");
}

TEST(ReadVolumeRefuses, ContentThatIsNotNpy) {
  const TemporaryFolder folder;
  expect_refusal(write_file(folder, "text.npy", "x, y, z\n1, 2, 3\n"), "not a .npy array");
  expect_refusal(write_file(folder, "empty.npy", ""), "not a .npy array");
}

TEST(ReadVolumeRefuses, UnsupportedDtypesAndFortranOrder) {
  const TemporaryFolder folder;
  expect_refusal(write_file(folder, "u1.npy", npy_header("|u1", "(2, 2, 2)") + std::string(8, '\0')),
                 "unsupported .npy dtype '|u1'");
  expect_refusal(write_file(folder, "big_endian.npy", npy_header(">f4", "(2, 2, 2)") + eight_floats()),
                 "unsupported .npy dtype '>f4'");
  expect_refusal(write_file(folder, "fortran.npy", npy_header("<f4", "(2, 2, 2)", true) + eight_floats()),
                 "Fortran-ordered");
}

TEST(ReadVolumeRefuses, ShapesThatAreNot3D) {
  const TemporaryFolder folder;
  expect_refusal(write_file(folder, "plane.npy", npy_header("<f4", "(2, 4)") + eight_floats()),
                 "a volume is a 3-D array (nz, ny, nx), this one has shape (2, 4)");
  const std::string four_d = npy_header("<f4", "(2, 2, 2, 2)") + eight_floats() + eight_floats();
  expect_refusal(write_file(folder, "four_d.npy", four_d), "this one has shape (2, 2, 2, 2)");
}

TEST(ReadVolumeRefuses, AnAxisOfFewerThanTwoSamples) {
  const TemporaryFolder folder;
  expect_refusal(write_file(folder, "one_row.npy", npy_header("<f4", "(4, 1, 2)") + eight_floats()), "empty volume");
  expect_refusal(write_file(folder, "zero.npy", npy_header("<f8", "(0, 2, 2)")), "empty volume");
}

// Refused from the header alone, before any allocation or read of the data.
TEST(ReadVolumeRefuses, MoreThan2To28Samples) {
  const TemporaryFolder folder;
  expect_refusal(write_file(folder, "huge.npy", npy_header("<f8", "(100000, 100000, 100000)")),
                 "more than 2^28 samples");
  expect_refusal(write_file(folder, "just_over.npy", npy_header("<f4", "(1024, 1024, 257)")),
                 "more than 2^28 samples");
}

TEST(ReadVolumeRefuses, SizesTheFileDoesNotHold) {
  const TemporaryFolder folder;
  const std::string short_data = npy_header("<f4", "(4, 4, 4)") + npy_data(std::vector<float>(10, 1.0f));
  expect_refusal(write_file(folder, "truncated.npy", short_data), "truncated");
  // 2^28 doubles promised (2 GiB), three bytes stored: the size check comes before the allocation.
  expect_refusal(write_file(folder, "promised.npy", npy_header("<f8", "(1024, 1024, 256)") + "abc"), "truncated");
  const std::string long_data = npy_header("<f4", "(2, 2, 2)") + eight_floats() + "abcd";
  expect_refusal(write_file(folder, "trailing.npy", long_data), "trailing bytes");
}

TEST(ReadVolumeRefuses, NonFiniteSamplesNamingTheFirst) {
  const TemporaryFolder folder;
  std::vector<double> values(4 * 3 * 2, 0.5);
  values[(1 * 3 + 2) * 4 + 3] = std::numeric_limits<double>::infinity();   // (3, 2, 1), after the NaN
  values[(0 * 3 + 1) * 4 + 2] = std::numeric_limits<double>::quiet_NaN();  // (2, 1, 0)
  const std::string nan = npy_header("<f8", "(2, 3, 4)") + npy_data(values);
  expect_refusal(write_file(folder, "nan.npy", nan), "sample (x, y, z) = (2, 1, 0) is nan");
  std::vector<float> floats(8, 0.5f);
  floats[7] = -std::numeric_limits<float>::infinity();
  const std::string infinite = npy_header("<f4", "(2, 2, 2)") + npy_data(floats);
  expect_refusal(write_file(folder, "infinite.npy", infinite), "sample (x, y, z) = (1, 1, 1) is -inf");
}

}  // namespace
}  // namespace gt
