// A user's output files read and checked against the case; see candidate.hpp.
#include "compare/external/candidate.hpp"

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "compare/checks/image.hpp"
#include "core/io/heightmap_io.hpp"
#include "core/io/mesh_io.hpp"

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

CandidateMesh load_candidate_mesh(const std::filesystem::path& file) {
  MeshFile read = read_mesh(file);  // refuses a file without faces
  return {.file = std::filesystem::absolute(file), .mesh = std::move(read.mesh), .notes = std::move(read.notes)};
}

CandidateImage load_candidate_image(const std::filesystem::path& file, int width, int height) {
  const OIIO::ImageBuf image = read_image(file);
  const OIIO::ImageSpec& spec = image.spec();
  if (spec.width != width || spec.height != height || spec.depth > 1) {
    throw InputError(fmt::format("--candidate {}: {} × {} pixels where the case renders {} × {}", file.string(),
                                 spec.width, spec.height, width, height));
  }
  if (spec.nchannels != 3 && spec.nchannels != 4) {
    throw InputError(fmt::format("--candidate {}: {} channels; a rendered image is RGB or RGBA", file.string(),
                                 spec.nchannels));
  }
  CandidateImage candidate{.file = std::filesystem::absolute(file), .width = width, .height = height};
  candidate.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  // OpenImageIO converts any pixel type to 8-bit levels, rounding and clamping to [0, 1].
  if (!image.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8, candidate.rgb.data())) {
    throw InputError(fmt::format("--candidate {}: cannot read its pixels as 8-bit RGB: {}", file.string(),
                                 image.geterror()));
  }
  if (spec.format != OIIO::TypeDesc::UINT8) {
    candidate.notes.push_back(fmt::format("{} pixels rounded to 8-bit levels, as the references' images are",
                                          spec.format.c_str()));
  }
  if (spec.nchannels == 4) candidate.notes.push_back("its alpha channel is ignored");
  return candidate;
}

}  // namespace gt
