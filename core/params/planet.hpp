// Parameters of seed 002's "Earth-like" planet generator (digest 002_planets.md §4.4, §9) and the
// spec both twins follow, step by step. Shared by reference/planet/*.cpp and gpu/planet/*.cpp; with
// core/planet/cube_sphere.hpp (regions, neighbour table) and core/rng.hpp they are all the twins share.
//
// Random numbers: U(k, step, stream) = uniform01(random_u32(seed, k, step, stream)), a float in
// [0, 1) with 24 bits, identical in C++ and GLSL (core/rng.hpp). The streams of §9.2 are PlanetStream.
// Where the twins must agree bit for bit (plates), every quantity derived from a draw is a float
// computed by the operations written here, in this order.
//
// 1. Jitter (eq. 5.1, §9.3 step 1): offset_axis(i) = 0.5 + (U(i, axis, jitter) − 0.5)·j, axis 0 = a,
//    1 = b; pos(i) = the cube-sphere position of region i at that offset (warped, unit length).
// 2. Plates (§4.4.2, §9.3 step 2).
//    Seeds: plate k (in order 0..P−1) draws region random_u32(seed, k, attempt, plate_seed) % N for
//      attempt = 0, 1, ... until the region is not already a seed; after 64 attempts it takes the
//      first free region in index order. So no plate is empty (the code's duplicate seeds left
//      plates empty, §4.4.2; §9.2 lets us reject them).
//    Rate (erratum 9, the code's formula by default): rate_k = max(lo + (hi − lo)·U(k, 0, rate), 1/256)
//      in float, lo = max(0, 1 − e), hi = 1 + e rounded to float once; rate_formula = thesis takes
//      lo = 1 − e, hi = 1 + e for e < 1 and lo = 0, hi = e for e > 1. The floor of 1/256 keeps every
//      plate growing: a plate of rate 0 would never grow, and could leave regions no plate reaches.
//    Expansions in cycle c (erratum 10, the intended Algorithm 3): whole = floor(rate_k),
//      expansions(k, c) = whole + (U(k, c, expansion) < rate_k − whole ? 1 : 0).
//    Synchronous rule (both twins): cycle c = 0, 1, ... runs sub-steps s = 0 .. max_expansions − 1,
//      max_expansions = floor(hi) + 1. In a sub-step, plate k is active when s < expansions(k, c);
//      every unassigned region takes the lowest active plate index among its valid neighbours'
//      plates as they were before the sub-step (a Jacobi step: assignments made in this sub-step
//      are not seen until the next). Cycles stop when every region has a plate.
//    Legacy rule (CPU only, the seed code): cycle after cycle, plates in index order each run
//      stepExpandPlate as coded: "while rate > 0: expand; rate −= 1", then one more expand (the
//      `random > rate` test after the loop is always true, erratum 10), stopping early when an
//      expand adds nothing; expand() as §4.4.2 (edge list in insertion order, neighbours in table
//      order, first come first served). Stops after a cycle in which no plate grew.
//    Legacy random-driven rule (CPU only, the code's randomDriven): pick t = 0, 1, ... expands plate
//      random_u32(seed, t, 0, random_driven) % P by stepExpandPlate; stops when every plate has
//      finished (an expand that added nothing). `cycles` counts the picks.
// 3. Edge regions: is_edge(i) = some valid neighbour has another plate.
// 4. Plate centre c_k: `mean` (thesis): normalise(Σ pos over members); `edge_sum` (code):
//    normalise(Σ pos over edge members). A zero sum gives c_k = 0. The sum is accumulated well
//    beyond float: in double on the CPU for either Real, in 64-bit fixed point on the GPU (both
//    within N·2^-30 of the exact sum, and order-independent on the GPU), then rounded to Real and
//    normalised. A float running sum over a plate of n regions would be off by up to n·2^-24
//    relative, which the shift would inherit.
// 5. Shift (eq. 5.2): m = 0.5 + 0.5·U(k, 0, shift), α = 2·U(k, 1, shift) − 1, β = 2·U(k, 2, shift) − 1;
//    t_x = c × (1, 0, 0), t_y = c × (0, 1, 0), t = α·t_x + β·t_y; s_k = m·t/|t| (0 when |t| = 0).
// 6. Base elevation: `uniform` (the seed): b_k = e_r·(2·U(k, 0, elevation) − 1), so half the plates are
//    land. `bimodal` (ours, for Earth-like hypsometry: the seed's default gives a land share near
//    0.5 and no second mode, see planet.earth_like.default): plate k is oceanic when
//    U(k, 1, elevation) < ocean_share, with b_k = −e_r·(0.5 + 0.5·U(k, 0, elevation)) in
//    [−e_r, −e_r/2]; otherwise continental, b_k = (0.25·e_r)·U(k, 0, elevation) in [0, e_r/4]
//    (the Earth: ocean floor near −4 km, continents near +0.1 km).
// 7. Noise (§4.4.3 phase 3): E0(i) = b_plate(i) + S·fbm(f·pos(i)), fbm = seed 002's
//    normalizedOctaveNoise3D of improved Perlin noise (reference/noise/fractal.hpp: octaves o,
//    lacunarity 2, gain 0.5) on seeded_permutation(seed) (core/noise/permutation.hpp); without noise
//    E0(i) = b_plate(i).
// 8. Collision (eq. 5.3 as coded, erratum 12–13): an edge region adds C·Σ pressure(i, n) over its valid
//    neighbours n of another plate, in table order; other regions keep E0.
//    `code`:   d = normalise(p_n − p_i), t_i = normalise(p_i + s_A) − p_i, t_n = normalise(p_n + s_B) − p_n,
//              pressure = |s_A|·(t_i·d) + |s_B|·(t_n·(−d)).
//    `thesis`: v = s_A − (s_A·p_i)·p_i, v_n = s_B − (s_B·p_n)·p_n (the plate's motion made tangent at
//              each centroid), pressure = |v|·(v·(p_n − p_i)) + |v_n|·(v_n·(p_i − p_n)).
//    Both are symmetric: pressure(i, n) = pressure(n, i).
// 9. Smoothing (erratum 14): `jacobi` (thesis, both twins): E2(i) = (E1(i) + Σ valid E1(n)) / (1 +
//    valid count), self first, then neighbours in table order; `legacy` (CPU only, the code): in place
//    in index order, e = E1(i), then e = 0.5·(e + E(n)) for each valid neighbour in table order,
//    E(n) already smoothed when n < i; `off`. The code smooths only with collisions on:
//    `smooth_only_with_collisions` (default false, the thesis smooths always).
// Units: elevations in the generator's own units (the palette's sea level is 0, §4.3; e_r = 0.8 puts
// plates in [−0.8, 0.8]); positions on the unit sphere; rates in rings per cycle.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "core/param_table.hpp"
#include "core/planet/cube_sphere.hpp"

namespace gt {

enum class PlateRule { synchronous, legacy, legacy_random };
enum class PlateCentre { mean, edge_sum };
enum class PressureFormula { code, thesis };
// Step 2's rates: the code's U[max(0, 1 − e), 1 + e], or the thesis's (erratum 9) U[1 − e, 1 + e]
// for e < 1 and U[0, e] for e > 1 (undefined at e = 1, refused; a jump there).
enum class RateFormula { code, thesis };
enum class Smoothing { jacobi, legacy, off };
enum class PlateBases { uniform, bimodal };
// The cube-to-sphere warp (seed 002 §2.7): none (the identity, the seed's baseline), the plain
// tangent warp of eq. 3.4 (θ = π/4) or the optimised one of eq. 3.5 (θ = 0.868734829276, the
// code's and the thesis's).
enum class PlanetWarp { none, tangent, optimised };

// The `stream` counters of §9.2.
enum PlanetStream : std::uint32_t {
  planet_stream_jitter = 0x706c0001u,
  planet_stream_plate_seed = 0x706c0002u,
  planet_stream_rate = 0x706c0003u,
  planet_stream_expansion = 0x706c0004u,
  planet_stream_shift = 0x706c0005u,
  planet_stream_elevation = 0x706c0006u,
  planet_stream_random_driven = 0x706c0007u,
};

inline constexpr int plate_seed_attempts = 64;
inline constexpr float minimum_plate_rate = 1.0f / 256.0f;

struct PlanetParams {
  int resolution = 50;          // R: 6R² regions
  std::uint32_t seed = 1;
  double jitter = 1.0;          // j in [0, 1]
  PlanetWarp warp = PlanetWarp::optimised;
  int plates = 50;              // P, at most 6R²
  double expansion_range = 0.5; // e
  RateFormula rate_formula = RateFormula::code;
  PlateRule plate_rule = PlateRule::synchronous;
  PlateCentre centre = PlateCentre::mean;
  double elevation_range = 0.8;     // e_r
  PlateBases plate_bases = PlateBases::uniform;
  double ocean_share = 0.7;         // share of oceanic plates with bimodal bases
  bool collisions = true;
  double collision_strength = 0.5;  // C
  PressureFormula pressure = PressureFormula::code;
  bool noise = true;
  double perlin_frequency = 15.0;   // f
  int perlin_octaves = 1;           // o
  double perlin_strength = 0.2;     // S (the code's; the thesis says 2.0, erratum 15)
  Smoothing smoothing = Smoothing::jacobi;
  bool smooth_only_with_collisions = false;

  int region_count() const { return 6 * resolution * resolution; }
  // Whether step 9 runs.
  bool smooths() const { return smoothing != Smoothing::off && (collisions || !smooth_only_with_collisions); }
};

// The rate bounds of step 2 as the twins use them: lo = max(0, 1 − e), hi = 1 + e (the code's; the
// thesis's lo = 0, hi = e for e > 1), each rounded to float once; max_expansions = floor(hi) + 1
// sub-steps per cycle.
struct PlateRateBounds {
  float low = 0.5f;
  float high = 1.5f;
  int max_expansions = 2;
};
PlateRateBounds plate_rate_bounds(const PlanetParams& params);

// The declarations (core/param_table.hpp), their ParamSpecs, and the struct from resolve_params'
// output, which throws InputError when plates exceed 6R².
const ParamTable<PlanetParams>& planet_param_table();
const ParamSpecs& planet_param_specs();
PlanetParams planet_params_from_json(const nlohmann::json& resolved);

// The warp's θ as the cube sphere takes it (core/planet/cube_sphere.hpp).
CubeWarp cube_warp(PlanetWarp warp);
const char* planet_warp_name(PlanetWarp warp);

const char* plate_rule_name(PlateRule rule);
const char* smoothing_name(Smoothing smoothing);

}  // namespace gt
