// libFuzzer target: read_heightmap on arbitrary bytes under the extension GT_FUZZ_EXTENSION
// (built once per format: png, tif, exr, npz, json, npy). A malformed file must end in InputError;
// anything else (a crash, a sanitizer report, another exception, a blown memory limit) is a bug.
#include <cstddef>
#include <cstdint>

#include "core/errors.hpp"
#include "core/io/heightmap_io.hpp"
#include "fuzz/fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = gt::fuzz::write_input(data, size, "input" GT_FUZZ_EXTENSION);
  try {
    const gt::HeightmapFile file = gt::read_heightmap(path);
    // Touch every value so a wrong size surfaces under AddressSanitizer.
    double sum = 0.0;
    for (const double height : file.heights.values) sum += height;
    (void)sum;
  } catch (const gt::InputError&) {
  }
  return 0;
}
