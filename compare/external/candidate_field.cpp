// A user's field file read and checked against the case's grid; see candidate_field.hpp.
#include "compare/external/candidate_field.hpp"

#include <cmath>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/io/heightmap_io.hpp"

namespace gt {
namespace {

// Whether a .npy file's header declares little-endian float64 (its first 256 bytes hold the
// header's dictionary for any array the readers take).
bool npy_holds_doubles(const std::filesystem::path& file) {
  if (file.extension() != ".npy") return false;
  std::ifstream in(file, std::ios::binary);
  std::string header(256, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header.size()));
  header.resize(static_cast<std::size_t>(in.gcount()));
  return header.find("'<f8'") != std::string::npos;
}

}  // namespace

CandidateField load_candidate_field(const std::filesystem::path& file, const Heightmap& grid) {
  const auto extension = file.extension().string();
  if (extension != ".npy" && extension != ".exr") {
    throw InputError(fmt::format("--candidate {}: a field is read from .npy (float32 or float64) or .exr", file.string()));
  }
  CandidateField candidate{.file = std::filesystem::absolute(file), .values = read_heightmap(file).heights};
  if (candidate.values.width != grid.width || candidate.values.height != grid.height) {
    throw InputError(fmt::format("--candidate {}: {} columns × {} rows where the case samples {} × {} (rows down the "
                                 "file's first axis)",
                                 file.string(), candidate.values.width, candidate.values.height, grid.width,
                                 grid.height));
  }
  for (std::size_t cell = 0; cell < candidate.values.size(); ++cell) {
    if (!candidate.values.is_valid(cell) || !std::isfinite(candidate.values.values[cell])) {
      throw InputError(fmt::format("--candidate {}: the value at row {}, column {} is not a finite number (a noise "
                                   "field has one everywhere)",
                                   file.string(), cell / static_cast<std::size_t>(grid.width),
                                   cell % static_cast<std::size_t>(grid.width)));
    }
  }
  candidate.double_precision = npy_holds_doubles(file);
  return candidate;
}

}  // namespace gt
