// A user's generated field to grade (`groundtruth run ... --candidate FILE`), for the algorithms that
// sample a function on a grid (noise.*): the file's values stand where the GPU twin's output stands
// (compare/field_twin.hpp). Sampling convention, as the references sample: value (row j, column i)
// at origin + (i·step, j·step) in noise units (the case's `sampling`), row-major, no cell centring.
//
// Inputs:  the file (.npy of float32/float64 — numpy's own save — or a float EXR), the case's grid.
// Outputs: the values as doubles, and whether the file held doubles (a '<f8' .npy).
// Throws:  InputError for a file the heightmap readers refuse, a size other than the grid's (both
//          named), or a value that is not finite.
#pragma once

#include <filesystem>

#include "compare/field_twin.hpp"
#include "core/grid.hpp"

namespace gt {

CandidateField load_candidate_field(const std::filesystem::path& file, const Heightmap& grid);

}  // namespace gt
