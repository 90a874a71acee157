// libFuzzer target: read_volume on arbitrary bytes as a .npy file. A malformed file must end in
// InputError; a volume that loads must hold nx·ny·nz samples.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "core/errors.hpp"
#include "core/io/volume_io.hpp"
#include "fuzz/fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = gt::fuzz::write_input(data, size, "input.npy");
  try {
    const gt::Volume<double> volume = gt::read_volume(path);
    const std::size_t expected = static_cast<std::size_t>(volume.nx) * static_cast<std::size_t>(volume.ny) *
                                 static_cast<std::size_t>(volume.nz);
    if (volume.values.size() != expected) std::abort();
  } catch (const gt::InputError&) {
  }
  return 0;
}
