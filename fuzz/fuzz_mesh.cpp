// libFuzzer target: read_mesh on arbitrary bytes under the extension GT_FUZZ_EXTENSION (built
// once per format: off, obj, ply, stl). A malformed file must end in InputError; a mesh that
// loads must index only its own vertices.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "core/errors.hpp"
#include "core/io/mesh_io.hpp"
#include "fuzz/fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = gt::fuzz::write_input(data, size, "input" GT_FUZZ_EXTENSION);
  try {
    const gt::MeshFile file = gt::read_mesh(path);
    for (const auto& triangle : file.mesh.triangles)
      for (const auto index : triangle)
      if (index >= file.mesh.positions.size()) std::abort();  // read_mesh promises checked indices
  } catch (const gt::InputError&) {
  }
  return 0;
}
