// The state of seed 001's layered ground (digest 001 §3.1), shared by the CPU reference and the GPU
// twin, stored as flat arrays (structure of arrays) so that each array uploads as one SSBO.
//
// Per column, top down:
//   - 2 soil–rock layers, topsoil (layer 0, at most LayeredParams::topsoil_max thick) and subsoil
//     (layer 1, unbounded), each holding the thickness of its 5 components (org, sand, gravel,
//     stones, boulders); a layer's thickness is the sum of its components, taken in that order;
//   - `bedrock_layer_count` bedrock layers (type, thickness), the same count in every column and
//     fixed for the life of the state: a layer that empties stays, with thickness 0, and is skipped.
//   - surface: the absolute surface height, kept in step with every change of a layer (the layers
//     hang down from it; the bottom of the last bedrock layer is not stored).
//   - vegetation density in [0, 1].
// Units: metres (heights, thicknesses, cell sizes); a volume is thickness·l_x·l_y in m³.
// Cell c = y·width + x. Index of soil component i of layer j: (j·5 + i)·cells + c; of bedrock layer k:
// k·cells + c.
//
// Neighbours (talus and creep, §3.10-3.11): the 8 of gt::pipe_offsets (L, R, T, B, TL, BR, TR, BL;
// k and k^1 opposite) at distances l_x, l_x, l_y, l_y, then sqrt(l_x² + l_y²). Closed borders have no
// neighbour outside the grid; periodic borders wrap (and need at least 3 × 3 cells, so that no cell
// is its own neighbour and no two of a cell's neighbours coincide).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/grid.hpp"
#include "core/params/layered.hpp"

namespace gt {

inline constexpr int soil_layer_count = 2;  // topsoil, subsoil
inline constexpr int layered_neighbour_count = 8;

// Streams of random_u32(seed, cell, step, stream) (core/rng.hpp) that draw rand(0.9, 1): talus per
// neighbour k (thesis eq. 3.3), talus per cell (seed001_code), creep per cell (eq. 3.4).
inline constexpr std::uint32_t talus_neighbour_stream(int k) { return static_cast<std::uint32_t>(k); }
inline constexpr std::uint32_t talus_cell_stream = 8;
inline constexpr std::uint32_t creep_cell_stream = 9;
// rand(0, 1) of vegetation growth (§3.15), one per column and step.
inline constexpr std::uint32_t vegetation_cell_stream = 10;

template <class Real>
struct LayeredGround {
  int width = 0;
  int height = 0;
  double cell_size_x = 1.0;  // l_x, m
  double cell_size_y = 1.0;  // l_y, m
  int bedrock_layer_count = 0;
  std::vector<Real> surface;                // h, m
  std::vector<Real> soil;                   // component thicknesses, m
  std::vector<std::int32_t> bedrock_type;   // index into LayeredParams::bedrock_types
  std::vector<Real> bedrock;                // bedrock layer thicknesses, m
  std::vector<Real> vegetation;             // [0, 1]

  std::size_t cells() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
  std::size_t cell(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  }
  Real& soil_at(int layer, int component, std::size_t c) { return soil[soil_index(layer, component, c)]; }
  Real soil_at(int layer, int component, std::size_t c) const { return soil[soil_index(layer, component, c)]; }
  Real& bedrock_at(int layer, std::size_t c) { return bedrock[bedrock_index(layer, c)]; }
  Real bedrock_at(int layer, std::size_t c) const { return bedrock[bedrock_index(layer, c)]; }
  std::int32_t bedrock_type_at(int layer, std::size_t c) const { return bedrock_type[bedrock_index(layer, c)]; }

  // Sum of the layer's components in the order org, sand, gravel, stones, boulders.
  Real soil_thickness(int layer, std::size_t c) const {
    Real sum = 0;
    for (int component = 0; component < soil_component_count; ++component) sum += soil_at(layer, component, c);
    return sum;
  }

  std::size_t soil_index(int layer, int component, std::size_t c) const {
    return static_cast<std::size_t>(layer * soil_component_count + component) * cells() + c;
  }
  std::size_t bedrock_index(int layer, std::size_t c) const { return static_cast<std::size_t>(layer) * cells() + c; }
};

// What the columns start with (the spatial inputs of seed 001's scenarios): column c gets
// profiles[profile_of[c]] (profiles[0] everywhere when profile_of is empty) and vegetation[c] (one
// value for every column when it holds one). Every profile has the same number of bedrock layers.
struct LayeredColumns {
  std::vector<LayeredProfile> profiles;
  std::vector<std::int32_t> profile_of;  // empty, or one index per cell in [0, profiles.size())
  std::vector<double> vegetation{0.0};   // one value, or one per cell, each in [0, 1]
};

// Every column gets its profile (columns) under the surface height of `surface` (its grid sets the
// size and cell sizes; a mask is refused), and its vegetation. Throws InputError for a bad profile,
// map or surface (validate_layered_profile, check_finite, check_cell_size) and for a grid whose
// state, its step snapshot and outflows do not fit in memory (check_grid_fits):
// validate_layered_inputs. The second form: one profile and one vegetation everywhere.
template <class Real>
LayeredGround<Real> make_layered_ground(const Heightmap& surface, const LayeredColumns& columns,
                                        const LayeredParams& params);
template <class Real>
LayeredGround<Real> make_layered_ground(const Heightmap& surface, const LayeredProfile& profile,
                                        const LayeredParams& params, double vegetation = 0.0);

// make_layered_ground's checks, in its order and with its messages, without making the ground:
// params, profiles (at least one, each valid, all with the same bedrock layer count), the maps'
// sizes, indices and vegetation in [0, 1], no mask, finite surface, cell sizes, and the memory of a
// ground of `real_bytes`-byte reals (sizeof(Real): the default, double, is the larger).
void validate_layered_inputs(const Heightmap& surface, const LayeredColumns& columns, const LayeredParams& params,
                             std::size_t real_bytes = sizeof(double));

// What the processes refuse before a step (InputError, "erosion.layered: ..."): arrays of the
// wrong size, non-finite values, negative thicknesses, a topsoil thicker than the maximum (beyond
// rounding: 1e-6 relative), vegetation outside [0, 1], unknown bedrock types, a periodic border on
// a grid smaller than 3 × 3, cell sizes outside [1e-9, 1e9].
template <class Real>
void check_layered_ground(const LayeredGround<Real>& ground, const LayeredParams& params);

// Neighbour k (gt::pipe_offsets order) of column (x, y), or none outside a closed border.
template <class Real>
std::optional<std::size_t> layered_neighbour(const LayeredGround<Real>& ground, LayeredBorder border, int x, int y,
                                             int k);
// Distance to neighbour k: l_x, l_y or sqrt(l_x² + l_y²), m.
double layered_neighbour_distance(double cell_size_x, double cell_size_y, int k);

// Material volumes, m³, summed over all columns in double with compensated sums.
struct LayeredLedger {
  std::array<double, soil_component_count> components{};  // in the two soil layers
  std::vector<double> bedrock;                              // per bedrock type
  double total() const;
};

// Cumulative conversions between ledger lines, m³:
//   - fragmentation (talus on bedrock, §3.10): `fragmented_from[t]` left bedrock type t,
//     `fragmented_into[i]` entered component i;
//   - weathering of soil (§3.16): `weathered_from[i]` left component i, `weathered_into[i]` entered
//     it (sand → org, gravel → sand, stones → gravel, boulders → stones: org never leaves, boulders
//     never enter);
//   - soil formation (bedrock → subsoil, §3.16): `soil_formed_from[t]` left bedrock type t,
//     `soil_formed_into[i]` entered component i.
// Vegetation growth creates no material (decision: veg is a density, not a volume), so it has no
// line; weathering's sand → org is the only source of organic matter, counted here.
//   - force erosion (§3.12): `broken_from[j]` left component j to be suspended as a smaller size,
//     `broken_into[i]` was suspended as size i from a larger one; `bedrock_eroded_from[t]` left
//     bedrock type t into the water, `bedrock_eroded_into[i]` as size i.
// And what crosses the ledger's edge (the river's sink rows, §3.19; reference/erosion/layered/water.hpp):
// `sunk[i]` of component i (suspended and regolith), `water_added` and `water_sunk` (m³ of water).
// Neither closed nor periodic borders let anything else out: for each component i, with V_i the
// volume in the ground and in the water (layered_water_ledger), V_i(end) − V_i(start) =
// converted_into(i) − converted_from(i) − sunk[i], and for each bedrock type t,
// V_t(end) − V_t(start) = −bedrock_converted(t); the water W(end) − W(start) = water_added − water_sunk.
struct LayeredConversions {
  std::vector<double> fragmented_from;                            // per bedrock type
  std::array<double, soil_component_count> fragmented_into{};     // org stays 0
  std::array<double, soil_component_count> weathered_from{};      // org stays 0
  std::array<double, soil_component_count> weathered_into{};      // boulders stay 0
  std::vector<double> soil_formed_from;                           // per bedrock type
  std::array<double, soil_component_count> soil_formed_into{};
  std::array<double, soil_component_count> broken_from{};         // org stays 0
  std::array<double, soil_component_count> broken_into{};         // org and boulders stay 0
  std::vector<double> bedrock_eroded_from;                         // per bedrock type
  std::array<double, soil_component_count> bedrock_eroded_into{};  // org stays 0
  std::array<double, soil_component_count> sunk{};
  double water_added = 0.0;
  double water_sunk = 0.0;

  // Σ of every conversion into / out of soil component i, and out of bedrock type t (0 past the
  // vectors' ends), m³.
  double converted_into(int component) const;
  double converted_from(int component) const;
  double bedrock_converted(std::size_t type) const;
  // Sizes the per-type vectors for `bedrock_type_count` types (never shrinks them).
  void fit_types(std::size_t bedrock_type_count);
};

template <class Real>
LayeredLedger layered_ledger(const LayeredGround<Real>& ground, std::size_t bedrock_type_count);
LayeredConversions no_conversions(std::size_t bedrock_type_count);

}  // namespace gt
