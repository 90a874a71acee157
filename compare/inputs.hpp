// Inputs of cases: a heightmap file (any format of core/io/heightmap_io.hpp) or a generated field.
//
// {"file": "real/volcano.json"}   relative paths are under datasets/; optional "cell_size" (m)
//                                 and "vertical_scale" (m per unit of 8/16-bit images).
// Files and generators take "cell_size_y" (m) beside "cell_size" for rectangular cells:
// "cell_size" is then the columns' spacing (x), "cell_size_y" the rows' (y); alone it is refused.
// {"generator": NAME, ...}        fields made here, deterministic (noise from the counter RNG):
//   cone          "width", "height" (cells, default 128), "cell_size" (m, 1), "peak" (m, 100),
//                 "radius" (share of the shorter side, 0.4): a right circular cone on a plane.
//   step          "width", "height", "cell_size", "peak": a cliff of height `peak` at x = width/2.
//   slope         "width", "height", "cell_size", "base" (m, 0), "gradient" (m/m, 0.05), "axis" ("x"
//                 or "y"; x): a plane base + gradient·x (or ·y) rising along +x (+y), x and y in
//                 metres from the first column (row).
//   flat          "width", "height", "cell_size": zeros; the sampling grid of generated fields (noise).
//   terrain       "width", "height", "cell_size", "algorithm" (a noise.* algorithm), "params": the
//                 terrain that algorithm's double reference synthesises (see terrain.* cases).
//   example_3x3   seed 000's 3×3 test field: centre 1, other cells 0, cell size 1.
//   strips        "width", "height", "cell_size", "count" (2), "axis" (x), "peak" (1): `count` equal
//                 strips across the axis, strip i holding peak·i (a category map: 0, 1, 2, ...).
//   hills         "width", "height", "cell_size", "count" (4), "peak" (m, 10), "radius" (share of a
//                 strip's width, 0.45): a row of cones along x, one centred in each of `count` strips.
//   box           "width", "height", "cell_size", "x", "y", "box_width", "box_height" (cells; 0, 0, 1,
//                 1), "peak" (1): `peak` on that block of cells, 0 elsewhere.
//   cone, step, slope, strips, hills, box and flat take "noise" (m, default 0) and "seed" (default 1): uniform noise in
//   [0, noise) added to every cell from random_u32(seed, cell, 0, 0).
// A file or generator heightmap may carry input fields beside it (seed 001's spatial inputs: which
// soil profile in which column, a vegetation map): "fields": {NAME: a file or generator as above},
// at most 8. A field generator without "width" takes the heightmap's grid; each field is cropped
// as the heightmap and must then have its size, finite values and no no-data cells. Which names
// an algorithm reads is its Algorithm::input_fields (the driver refuses the others).
// {"mesh": "real/meshes/cow.off"}   a triangle mesh (OFF, OBJ, PLY, STL; core/io/mesh_io.hpp).
// {"volume": "sdf.npy"}            a scalar volume, a 3-D .npy array (core/io/volume_io.hpp): the
//                                  cave's density when it is not the seed's noise.
// {"global_grid": "real/etopo60.cdf", "variable": "ROSE"}   a global latitude-longitude elevation
//                                  grid (netCDF, core/io/global_grid.hpp; "variable" optional): what
//                                  a generated planet is set beside (planet.earth_like).
// {} (no input)                    an empty LoadedInput: the algorithm makes its own field (cave).
// "crop": [x, y, width, height] cuts a window out of the input (InputError if it does not fit).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/grid.hpp"
#include "core/io/global_grid.hpp"
#include "core/mesh.hpp"
#include "core/volume.hpp"

namespace gt {

// An input field an algorithm reads beside its heightmap ("fields" above).
struct InputFieldSpec {
  std::string name;
  std::string unit;         // "1", "index", "m"
  std::string description;  // what it sets, in a line
};

struct LoadedInput {
  Heightmap heights;
  std::string description;          // e.g. "volcano.json, 87x61 cells of 10 m"
  std::vector<std::string> notes;   // what the reader decided
  std::optional<Mesh> mesh;         // for {"mesh": path}
  std::optional<Volume<double>> volume;  // for {"volume": path}
  std::optional<GlobalGrid> global_grid;  // for {"global_grid": path}
  std::filesystem::path source;     // the file read, empty for generated fields (provenance digests it)
  std::map<std::string, Heightmap> fields;  // the heightmap's input fields, by name
};

LoadedInput load_input(const nlohmann::json& input, const nlohmann::json& crop,
                       const std::filesystem::path& dataset_dir);

}  // namespace gt
