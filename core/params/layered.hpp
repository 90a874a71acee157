// Parameters of seed 001's layered ground (digest 001_erosion_terrain.md §3.1, §3.3-3.5, §3.10-3.17,
// §3.19, §5): columns of two soil–rock layers (topsoil, subsoil) of five components over typed
// bedrock, and the constants of its processes. Algorithm family `erosion.layered`. Shared by
// reference/erosion/layered/* and the GPU twin (gpu/erosion/layered/*).
//
// Units: lengths and thicknesses in metres (a component "volume" is its thickness over the cell,
// volume = thickness·l_x·l_y), Δt in seconds, repose angles as tan φ (dimensionless), K_z in m/s.
//
// Where the thesis and its code (commit 496cef1) disagree, the thesis is the default and the code's
// choice a named parameter:
//   - `talus_amount`: thesis eq. 3.3, Δt·Δh·rand(0.9,1)/2 per neighbour, then the availability
//     clamp; `seed001_code`: min(½·max Δh·rand, h_layer) in total (no Δt), split ∝ Δh_i.
//   - `creep_denominator`: thesis, Roering's 1 − (s/S_c)² (singular at S_c); `seed001_code`: the
//     denominator is at least `creep_denominator_floor` (0.1).
//   - `talus_random`, `creep_random`: the thesis draws rand(0.9, 1) in both (eq. 3.3, 3.4); the code
//     only in talus. Off, the factor is 1.
//   - `border`: the thesis states none; closed walls by default, `periodic` is the code's wrap.
//   - The code's depth factor (subsoil × 1.25) is K_depth^j with K_depth = 1.25, not a variant.
//   - The code indexes the bedrock fragment table by layer index instead of type: a bug, not kept.
// Constants the thesis leaves open take the code's values: K_sveg 0.2, K_depth 1.25, topsoil
// maximum 1.5 m, S_c 1.40, K_z 0.01, and the three bedrock types (tan φ 4.0, 1e7, 1e7 — only type 0
// ever falls — with the fragment shares of new_soil_from_bedrock_type). Δt defaults to 0.2 s, not the
// thesis's 0.5 (§3.2, for the single-material 4-neighbour case): eq. 3.3's per-neighbour amounts
// sum over 8 neighbours, so a peak's difference to its neighbours becomes Δh·(1 − 4.5·Δt), which
// overshoots for Δt > 2/9 s and makes a pile oscillate in a checkerboard that never rests. Bedrock hardness has no value in either source: it is a relative
// rank (1, 2, 3) for force erosion (§3.12) and is not read by talus or creep.
//
// Vegetation (§3.15) and weathering (§3.16; reference/erosion/layered/{vegetation,weathering}.hpp):
//   - `vegetation_quality`: thesis, q_s = Σ_i K_v,i·V*_i/min(K_vd, h_soil) over the soil down to the
//     root depth K_vd, and nveg over the 8 neighbours; `seed001_code`: (1 − veg)·q(0.25 m) +
//     veg·q(2.0 m) − vegetation_base, nveg over the 3 × 3 including the centre. K_vorg is a parameter
//     of its own: the thesis's 1 by default, the code uses 1.5 (set it with the variant).
//   - K_veg (the code's spread speed 1), K_eveg 0.8 and K_nveg 0.25: the thesis gives no values.
//   - Weathering: K_conv = 0.01·0.1 m/s (the code's 0.01·organification_speed), [K_org, K_1,0, K_2,1,
//     K_3,2] = [1, 0.2, 0.3, 0.4], reach 4.0 m; per bedrock type the code's soil formation rate
//     (0.01·0.1·[1, 0.3, 0] m/s) and the composition of the soil it forms.
//
// Water (§3.3-3.5, §3.12-3.15, §3.19; reference/erosion/layered/{water,force_erosion,impact_erosion,
// dissolution,wetness}.hpp), thesis by default, the code's choice a parameter:
//   - `slope_form`: sin φ of the true slope (central differences over 2l) or the code's un-halved
//     differences with l = 1; `breakdown_form`: eq. 3.5's a·(x − b) or the code's max(a·x − b, 0);
//     `share_form`: eq. 3.10's min(m·max(K_emin, V_j/V), V_j) or the code's min(V_j, m)·max(...);
//     `velocity_depth_floor`: none (0) or the code's 0.05 m; K_e 0.5 (the code 0.1).
//   - The thesis leaves open and the code gives: K_w 0.45 m, K_c 0.25, organic capacity 0.12,
//     K_wveg 0.2, K_emin 0.1, K_pmin 0.1 m, the bedrock matrices A^rock, B^rock, K_i 0.25, K_dry 0.5,
//     a flood at wetness 1.0; A and B are eq. 3.8-3.9. Rain is a rate here (the code's is one shot).
//   - Sediment diffusion (§3.8, step 8 of §4; reference/erosion/layered/diffusion.hpp): on by default
//     with the thesis's example weight σ = 0.1 to each edge neighbour (`sediment_diffusion`, 0: off);
//     `diffusion_weighting=water` is the code's weighting by water depth; `regolith_diffusion` diffuses
//     the regolith too (the thesis, default; the code does not).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/param_table.hpp"
#include "core/params/diffusion_weighting.hpp"

namespace gt {

// The components of a soil–rock layer (§3.1): organic matter and rock fragments rock0..rock3.
enum class SoilComponent { org, sand, gravel, stones, boulders };
inline constexpr int soil_component_count = 5;
inline constexpr int fragment_size_count = 4;  // sand .. boulders: the sizes bedrock breaks into
// "org", "sand", "gravel", "stones", "boulders".
const char* soil_component_name(int component);

enum class TalusAmount { thesis, seed001_code };
enum class CreepDenominator { singular, seed001_code };
enum class LayeredBorder { closed, periodic };
enum class VegetationQuality { thesis, seed001_code };
enum class SlopeForm { thesis, seed001_code };
enum class BreakdownForm { thesis, seed001_code };
enum class ShareForm { thesis, seed001_code };

// "closed", "periodic": the names of the `border` parameter.
const char* layered_border_name(LayeredBorder border);

using FragmentMatrix = std::array<std::array<double, fragment_size_count>, fragment_size_count>;
// Eq. 3.8 and 3.9: row = source size j, column = result size i (sand .. boulders); lower triangular.
FragmentMatrix thesis_breakdown_slopes();
FragmentMatrix thesis_breakdown_thresholds();

struct BedrockType {
  double repose_tan = 4.0;  // tan φ of the rock face
  // K_rock: shares of sand, gravel, stones, boulders a fallen volume breaks into; each in [0, 1],
  // summing to 1.
  std::array<double, fragment_size_count> fragments{0.0, 0.2, 0.3, 0.5};
  double hardness = 1.0;  // relative, ≥ 0; for force erosion (§3.12)
  // §3.16 bedrock → soil: K_j, thickness turned into subsoil per second at full vegetation (m/s,
  // ≥ 0), and K_j,i, the shares of org, sand, gravel, stones, boulders it becomes (each in [0, 1],
  // summing to 1).
  double soil_rate = 0.001;
  std::array<double, soil_component_count> soil_composition{0.2, 0.0, 0.0, 0.1, 0.7};
  // §3.12 force erosion of bedrock: row t of A^rock and B^rock, the fragments of each size (sand ..
  // boulders) water of strength x breaks off, K_e·max(a·(x − b), 0) m per step (the code's Ab, Bb).
  std::array<double, fragment_size_count> erosion_slopes{0.05, 0.01, 0.004, 0.002};
  std::array<double, fragment_size_count> erosion_thresholds{0.0, 0.25, 0.4, 0.5};
};

// The code's three bedrock types (§3.10 [code]).
std::vector<BedrockType> seed001_bedrock_types();

struct LayeredParams {
  double time_step = 0.2;  // Δt, s
  // tan φ of a pure layer of each component, eq. 3.1: org, sand, gravel, stones, boulders.
  std::array<double, soil_component_count> repose_tan{1.25, 0.7, 0.8, 1.0, 1.0};
  double vegetation_repose = 0.2;  // K_sveg of eq. 3.1, ≥ 0
  double depth_factor = 1.25;      // K_depth: layer j's repose × K_depth^j, in [1, 1.5]
  double topsoil_max = 1.5;        // largest topsoil thickness, m (> 0); the subsoil has none
  std::vector<BedrockType> bedrock_types = seed001_bedrock_types();
  double creep_rate = 0.01;        // K_z of Roering's q = K_z·s/(1 − (s/S_c)²), m/s
  double critical_slope = 1.40;    // S_c, > 0
  CreepDenominator creep_denominator = CreepDenominator::singular;
  double creep_denominator_floor = 0.1;  // the seed001_code variant's least denominator, in (0, 1]
  bool talus = true;               // false switches talus off (creep alone: seed 001 Fig. 5.3)
  TalusAmount talus_amount = TalusAmount::thesis;
  bool talus_random = true;
  bool creep_random = true;
  LayeredBorder border = LayeredBorder::closed;
  std::uint32_t seed = 1;          // key of the counter-based RNG (core/rng.hpp)
  // Vegetation growth (§3.15).
  VegetationQuality vegetation_quality = VegetationQuality::thesis;
  double vegetation_rate = 1.0;         // K_veg, 1/s
  double vegetation_equilibrium = 0.8;  // K_eveg, ≥ 0
  double vegetation_neighbours = 0.25;  // K_nveg, ≥ 0
  // K_v of org (K_vorg: thesis 1, code 1.5), sand (K_vrock0), gravel, stones, boulders; ≥ 0.
  std::array<double, soil_component_count> vegetation_soil_quality{1.0, 0.2, 0.0, 0.0, 0.0};
  double root_depth = 0.25;       // K_vd, m (> 0); the code's shallow sample
  double root_depth_deep = 2.0;   // the code's deep sample, m (> 0; seed001_code only)
  double vegetation_base = 0.2;   // subtracted from the quality (seed001_code only), ≥ 0
  // Weathering (§3.16).
  double weathering_rate = 0.001;  // K_conv, m/s, ≥ 0
  // [K_org (sand → org), K_1,0 (gravel → sand), K_2,1 (stones → gravel), K_3,2 (boulders → stones)], ≥ 0.
  std::array<double, fragment_size_count> weathering_shares{1.0, 0.2, 0.3, 0.4};
  double weathering_reach = 4.0;   // bedrock turns into soil only under less soil than this, m (≥ 0)
  // Water (§3.3-3.5, §3.19): the water processes run only when water is given (initial_water,
  // rain_rate or river; `has_water`).
  double initial_water = 0.0;     // depth on every column at the start, m
  double rain_rate = 0.0;         // added to every column each step, m/s
  int rain_steps = 0;             // rain falls on iterations 0 .. rain_steps − 1 (counted from 0); 0: on every one
  int drain_step = 0;             // at the start of this iteration every column loses its water and what it
                                  // carries (the code's "Drain water", §3.19), booked as sunk; 0: never
  bool river = false;             // the code's river: column (W/2, H/16) set to river_depth each step,
                                  // rows y ≥ 15H/16 emptied (a sink), water and what it carries
  double river_depth = 1.0;       // m
  double gravity = 9.81;          // g, m/s²
  double velocity_depth_floor = 0.0;  // least w̄ of the velocity, m (thesis none; the code 0.05)
  double depth_ramp = 0.45;       // K_w of l(w), m (the code's WATER_MAX_DEPTH_EROSION)
  double slope_floor = 0.05;      // least sin φ
  SlopeForm slope_form = SlopeForm::thesis;
  // Force erosion (§3.12): water strength x = K_c·sin φ·|v|·l(w)/(1 + K_wveg·veg), m.
  double erosion_strength = 0.25;     // K_c, s (the code's erosion_constant)
  double organic_capacity = 0.12;     // C_org = organic_capacity·x (the code's organic_constant)
  double erosion_rate = 0.5;          // K_e (thesis; the code 0.1)
  double deposition_rate = 0.25;      // K_d
  double vegetation_protection = 0.2; // K_wveg
  BreakdownForm breakdown_form = BreakdownForm::thesis;
  ShareForm share_form = ShareForm::thesis;
  double least_share = 0.1;           // K_emin
  double transparency_depth = 0.1;    // K_pmin, m
  FragmentMatrix breakdown_slopes = thesis_breakdown_slopes();          // A (eq. 3.8), 1
  FragmentMatrix breakdown_thresholds = thesis_breakdown_thresholds();  // B (eq. 3.9), m
  // Impact erosion (§3.14): K_i of the impact strength S = K_i·v·A_contact·Δt/(l_x·l_y), m; 0: off.
  double impact_rate = 0.25;          // K_i (the code's inertial_erosion_constant default)
  // Dissolution (§3.13): regolith of org and sand, at most K_r deep.
  double regolith_depth = 0.01;       // K_r, m (0: off)
  double regolith_erosion = 1.0;      // K_re
  double regolith_deposition = 1.0;   // K_rd
  // Sediment diffusion (§3.8): σ, the share of each carried kind sent to each edge neighbour a step,
  // in [0, 1/4] (0: off); with `water` weighting any σ > 0 switches the code's weights on.
  double sediment_diffusion = 0.1;
  DiffusionWeighting diffusion_weighting = DiffusionWeighting::uniform;
  bool regolith_diffusion = true;     // the regolith diffuses like the sediment (thesis) or not (code)
  // Wetness (§3.15, eq. 3.12) and the flood death of vegetation.
  double drying = 0.5;                // K_dry, per second
  double flood_wetness = 1.0;         // vegetation dies above this wetness, m·s
};

// Whether any water is given: initial_water > 0, rain_rate > 0 or the river.
bool has_water(const LayeredParams& params);
// The water schedule (both twins): whether rain falls on iteration `step` (counted from 0), and
// whether every column drains at its start.
bool rains(const LayeredParams& params, std::uint32_t step);
bool drains(const LayeredParams& params, std::uint32_t step);

// Throws InputError ("erosion.layered: ...") naming the first bad value: a scalar outside its
// declared range (check_param_ranges over layered_param_table()), no bedrock type, a bedrock type's
// repose tan ≤ 0 (angle outside (0°, 90°)), its fragment or soil shares outside [0, 1] or not
// summing to 1 (±1e-9), negative hardness or rates, a breakdown matrix with negative entries or
// above its diagonal.
void validate_layered_params(const LayeredParams& params);

// The scalar parameters (everything but the bedrock types and the breakdown matrices): the
// declarations (core/param_table.hpp) and their ParamSpecs.
const ParamTable<LayeredParams>& layered_param_table();
const ParamSpecs& layered_param_specs();
// From resolve_params(..., layered_param_specs(), ...); the bedrock types and matrices keep their
// defaults.
LayeredParams layered_params_from_json(const nlohmann::json& resolved);
// [{"repose_tan": 4.0, "fragments": [0, 0.2, 0.3, 0.5], "hardness": 1}, ...]; validated as above.
// Optional "soil_rate" and "soil_composition" (5 shares; §3.16) default to BedrockType's (type 0's).
std::vector<BedrockType> bedrock_types_from_json(const nlohmann::json& types);

// The initial profile of every column, top down: topsoil and subsoil component thicknesses (m) and
// the bedrock layers (type index into LayeredParams::bedrock_types, thickness m).
struct LayeredProfile {
  std::array<double, soil_component_count> topsoil{};
  std::array<double, soil_component_count> subsoil{};
  struct Bedrock {
    int type = 0;
    double thickness = 0.0;
  };
  std::vector<Bedrock> bedrock;
};

// Throws InputError for a negative or non-finite thickness, a topsoil thicker than the maximum, a
// bedrock type out of range, or a profile without bedrock layers.
void validate_layered_profile(const LayeredProfile& profile, const LayeredParams& params);

}  // namespace gt
