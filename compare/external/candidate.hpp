// A user's output to grade (`groundtruth run ... --candidate FILE`), for the algorithms that do not
// step: the file stands where the GPU twin's output stands, and gets the GPU twin's checks under
// the name `candidate` (compare/field_twin.hpp, compare/algorithms/cave.cpp, compare/render_case.hpp).
// Which kind of file an algorithm takes is its Algorithm::candidate (compare/algorithm.hpp):
//
//   field  noise.*: .npy of float32/float64 (numpy's own save) or a float EXR. Sampling convention,
//          as the references sample: value (row j, column i) at origin + (i·step, j·step) in noise
//          units (the case's `sampling`), row-major, no cell centring. Values are doubles; a '<f8'
//          .npy is graded as a double implementation.
//   mesh   cave.marching_tetrahedra: .ply, .obj or .off (core/io/mesh_io.hpp), positions in global
//          lattice units, vertices welded (a triangle soup is not watertight), any triangle order.
//   image  render.phong, render.terrain: any format OpenImageIO reads, the case's width × height,
//          RGB or RGBA (alpha ignored, said in a note), row 0 at the top; 8-bit levels, a float or
//          16-bit image rounded to them as the references' images are.
//
// Throws InputError, naming the file, for a file the readers refuse, a size other than the
// case's (both named), a non-finite value or an empty mesh.
#pragma once

#include <filesystem>

#include "compare/field_twin.hpp"
#include "core/grid.hpp"

namespace gt {

CandidateField load_candidate_field(const std::filesystem::path& file, const Heightmap& grid);

CandidateMesh load_candidate_mesh(const std::filesystem::path& file);

CandidateImage load_candidate_image(const std::filesystem::path& file, int width, int height);

}  // namespace gt
