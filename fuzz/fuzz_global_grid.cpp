// libFuzzer target: read_global_grid (a planet's netCDF elevation grid) on arbitrary bytes, the
// classic header pre-scan (core/io/netcdf_header.hpp) first, then libnetcdf. A malformed file must
// end in InputError; a crash, a sanitizer report or a blown memory limit is a bug (issue 40: a
// 96-byte header declaring 2^31 variables crashed inside nc_open).
#include <cstddef>
#include <cstdint>

#include "core/errors.hpp"
#include "core/io/global_grid.hpp"
#include "fuzz/fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = gt::fuzz::write_input(data, size, "grid.nc");
  try {
    const gt::GlobalGrid grid = gt::read_global_grid(path.string());
    double sum = 0.0;  // touch every value so a wrong size surfaces under AddressSanitizer
    for (const double height : grid.elevation.values) sum += height;
    (void)sum;
  } catch (const gt::InputError&) {
  }
  return 0;
}
