// Parameter table and validation of `erosion.layered` (see layered.hpp).
#include "core/params/layered.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {
namespace {

constexpr const char* algorithm_name = "erosion.layered";
constexpr double fragment_sum_tolerance = 1e-9;

void require(bool condition, const std::string& what) {
  if (!condition) throw InputError(fmt::format("{}: {}", algorithm_name, what));
}

void require_finite(double value, const std::string& name) {
  require(std::isfinite(value), fmt::format("{} = {} must be finite", name, value));
}

void require_at_least(double value, double low, const std::string& name) {
  require_finite(value, name);
  require(value >= low, fmt::format("{} = {} must be >= {}", name, value, low));
}

void require_repose(double tan_phi, const std::string& name) {
  require(std::isfinite(tan_phi) && tan_phi > 0.0,
          fmt::format("{} = {} is not the tangent of an angle of repose in (0°, 90°): it must be finite and > 0",
                      name, tan_phi));
}

void validate_bedrock_type(const BedrockType& type, std::size_t index) {
  const std::string name = fmt::format("bedrock type {}", index);
  require_repose(type.repose_tan, name + " repose_tan");
  double sum = 0.0;
  for (int size = 0; size < fragment_size_count; ++size) {
    const double share = type.fragments[static_cast<std::size_t>(size)];
    const std::string share_name = fmt::format("{} fragment share of {}", name, soil_component_name(size + 1));
    require_at_least(share, 0.0, share_name);
    require(share <= 1.0, fmt::format("{} = {} must be <= 1", share_name, share));
    sum += share;
  }
  require(std::abs(sum - 1.0) <= fragment_sum_tolerance,
          fmt::format("{} fragment shares K_rock sum to {}, not 1", name, sum));
  require_at_least(type.hardness, 0.0, name + " hardness");
  require_at_least(type.soil_rate, 0.0, name + " soil_rate");
  double composition = 0.0;
  for (int component = 0; component < soil_component_count; ++component) {
    const double share = type.soil_composition[static_cast<std::size_t>(component)];
    const std::string share_name = fmt::format("{} soil_composition share of {}", name, soil_component_name(component));
    require_at_least(share, 0.0, share_name);
    require(share <= 1.0, fmt::format("{} = {} must be <= 1", share_name, share));
    composition += share;
  }
  require(std::abs(composition - 1.0) <= fragment_sum_tolerance,
          fmt::format("{} soil_composition shares K_j,i sum to {}, not 1", name, composition));
  for (std::size_t size = 0; size < fragment_size_count; ++size) {
    require_at_least(type.erosion_slopes[size], 0.0, fmt::format("{} erosion slope {}", name, size));
    require_at_least(type.erosion_thresholds[size], 0.0, fmt::format("{} erosion threshold {}", name, size));
  }
}

void validate_fragment_matrix(const FragmentMatrix& matrix, const char* name) {
  for (std::size_t j = 0; j < fragment_size_count; ++j) {
    for (std::size_t i = 0; i < fragment_size_count; ++i) {
      require_at_least(matrix[j][i], 0.0, fmt::format("{}[{}][{}]", name, j, i));
      require(i <= j || matrix[j][i] == 0.0,
              fmt::format("{}[{}][{}] = {}: fragments cannot grow, the matrix is lower triangular", name, j, i,
                          matrix[j][i]));
    }
  }
}

constexpr Choice<TalusAmount> talus_amount_choices[] = {{"thesis", TalusAmount::thesis},
                                                        {"seed001_code", TalusAmount::seed001_code}};
constexpr Choice<CreepDenominator> creep_denominator_choices[] = {{"singular", CreepDenominator::singular},
                                                                  {"seed001_code", CreepDenominator::seed001_code}};
constexpr Choice<LayeredBorder> border_choices[] = {{"closed", LayeredBorder::closed},
                                                    {"periodic", LayeredBorder::periodic}};
constexpr Choice<VegetationQuality> vegetation_quality_choices[] = {{"thesis", VegetationQuality::thesis},
                                                                    {"seed001_code", VegetationQuality::seed001_code}};
constexpr Choice<SlopeForm> slope_form_choices[] = {{"thesis", SlopeForm::thesis},
                                                    {"seed001_code", SlopeForm::seed001_code}};
constexpr Choice<BreakdownForm> breakdown_form_choices[] = {{"thesis", BreakdownForm::thesis},
                                                            {"seed001_code", BreakdownForm::seed001_code}};
constexpr Choice<ShareForm> share_form_choices[] = {{"thesis", ShareForm::thesis},
                                                    {"seed001_code", ShareForm::seed001_code}};

}  // namespace

const char* soil_component_name(int component) {
  static constexpr std::array<const char*, soil_component_count> names{"org", "sand", "gravel", "stones",
                                                                       "boulders"};
  return names.at(static_cast<std::size_t>(component));
}

const char* layered_border_name(LayeredBorder border) { return choice_name(border_choices, border); }

FragmentMatrix thesis_breakdown_slopes() {
  return {{{0.3, 0.0, 0.0, 0.0}, {0.02, 0.08, 0.0, 0.0}, {0.02, 0.01, 0.04, 0.0}, {0.02, 0.01, 0.01, 0.02}}};
}

FragmentMatrix thesis_breakdown_thresholds() {
  return {{{0.0, 0.0, 0.0, 0.0}, {0.01, 0.1, 0.0, 0.0}, {0.02, 0.2, 0.3, 0.0}, {0.03, 0.25, 0.4, 0.5}}};
}

bool has_water(const LayeredParams& params) {
  return params.initial_water > 0.0 || params.rain_rate > 0.0 || params.river;
}

bool rains(const LayeredParams& params, std::uint32_t step) {
  return params.rain_steps == 0 || step < static_cast<std::uint32_t>(params.rain_steps);
}

bool drains(const LayeredParams& params, std::uint32_t step) {
  return params.drain_step > 0 && step == static_cast<std::uint32_t>(params.drain_step);
}

// Type 2 ("granite") forms no soil in the code (rate 0); its composition, never used, is all boulders.
std::vector<BedrockType> seed001_bedrock_types() {
  // The code's Ab and Bb rows (§3.12 [code]; Bb stored negated there).
  return {{4.0, {0.0, 0.2, 0.3, 0.5}, 1.0, 0.001, {0.2, 0.0, 0.0, 0.1, 0.7}, {0.05, 0.01, 0.004, 0.002},
           {0.0, 0.25, 0.4, 0.5}},
          {1e7, {0.0, 0.1, 0.2, 0.7}, 2.0, 0.0003, {0.2, 0.0, 0.0, 0.0, 0.8}, {0.02, 0.005, 0.001, 0.0001},
           {0.0, 0.3, 0.5, 0.7}},
          {1e7, {0.0, 0.05, 0.15, 0.8}, 3.0, 0.0, {0.0, 0.0, 0.0, 0.0, 1.0}, {0.002, 0.0005, 0.0, 0.0},
           {0.0, 0.5, 0.0, 0.0}}};
}

void validate_layered_params(const LayeredParams& params) {
  check_param_ranges(algorithm_name, layered_param_table(), params);
  require(!params.bedrock_types.empty(), "at least one bedrock type is needed");
  for (std::size_t i = 0; i < params.bedrock_types.size(); ++i) validate_bedrock_type(params.bedrock_types[i], i);
  validate_fragment_matrix(params.breakdown_slopes, "breakdown_slopes");
  validate_fragment_matrix(params.breakdown_thresholds, "breakdown_thresholds");
}

const ParamTable<LayeredParams>& layered_param_table() {
  using P = LayeredParams;
  static const ParamTable<P> table = {
      real_param("time_step", &P::time_step, 1e-6, 10.0, "s",
                 "Δt of talus (eq. 3.3) and creep (eq. 3.4); talus overshoots (never rests) above 2/9"),
      real_param("repose_org", element(&P::repose_tan, 0), 1e-6, 1e7, "1", "tan φ of pure organic matter (eq. 3.1)"),
      real_param("repose_sand", element(&P::repose_tan, 1), 1e-6, 1e7, "1", "tan φ of pure sand (rock0)"),
      real_param("repose_gravel", element(&P::repose_tan, 2), 1e-6, 1e7, "1", "tan φ of pure gravel (rock1)"),
      real_param("repose_stones", element(&P::repose_tan, 3), 1e-6, 1e7, "1", "tan φ of pure stones (rock2)"),
      real_param("repose_boulders", element(&P::repose_tan, 4), 1e-6, 1e7, "1", "tan φ of pure boulders (rock3)"),
      real_param("vegetation_repose", &P::vegetation_repose, 0.0, 10.0, "1", "K_sveg: repose × (1 + K_sveg·veg)"),
      real_param("depth_factor", &P::depth_factor, 1.0, 1.5, "1", "K_depth: soil layer j's repose × K_depth^j"),
      real_param("topsoil_max", &P::topsoil_max, 1e-6, 1e3, "m", "largest topsoil thickness; overflow goes down"),
      real_param("creep_rate", &P::creep_rate, 0.0, 10.0, "m/s", "K_z of Roering's creep flux"),
      real_param("critical_slope", &P::critical_slope, 1e-3, 100.0, "1", "S_c, where the creep flux diverges"),
      choice_param("creep_denominator", &P::creep_denominator, creep_denominator_choices, "",
                   "the thesis's 1 − (s/S_c)², or its code's max(1 − (s/S_c)², creep_denominator_floor)"),
      real_param("creep_denominator_floor", &P::creep_denominator_floor, 1e-6, 1.0, "1",
                 "least creep denominator of the seed001_code variant"),
      choice_param("talus_amount", &P::talus_amount, talus_amount_choices, "",
                   "eq. 3.3 per neighbour then clamped, or the code's min(½·maxΔh·rand, h_layer) split ∝ Δh"),
      boolean_param("talus", &P::talus, "talus collapse runs (off: creep alone, as the seed's Fig. 5.3)"),
      boolean_param("talus_random", &P::talus_random, "talus amounts × rand(0.9, 1) (thesis and code)"),
      boolean_param("creep_random", &P::creep_random, "creep amounts × rand(0.9, 1) (thesis; the code: off)"),
      choice_param("border", &P::border, border_choices, "",
                   "closed walls, or the code's periodic wrap (grids of at least 3 × 3)"),
      integer_param("seed", &P::seed, 0, 4294967295.0, "count", "key of the counter-based random numbers"),
      choice_param("vegetation_quality", &P::vegetation_quality, vegetation_quality_choices, "",
                   "soil quality of vegetation growth (§3.15): one sample to root_depth, nveg over 8 neighbours; or "
                   "the code's blend of root_depth and root_depth_deep samples by veg, minus vegetation_base, nveg "
                   "over the 3 × 3"),
      real_param("vegetation_rate", &P::vegetation_rate, 0.0, 10.0, "1/s", "K_veg: vegetation spread rate (code: 1)"),
      real_param("vegetation_equilibrium", &P::vegetation_equilibrium, 0.0, 10.0, "1",
                 "K_eveg: veg' ∝ q_s − K_eveg·veg (code)"),
      real_param("vegetation_neighbours", &P::vegetation_neighbours, 0.0, 10.0, "1",
                 "K_nveg: weight of the neighbours' veg (code)"),
      real_param("vegetation_quality_org", element(&P::vegetation_soil_quality, 0), 0.0, 100.0, "1",
                 "K_vorg (thesis 1; the code 1.5)"),
      real_param("vegetation_quality_sand", element(&P::vegetation_soil_quality, 1), 0.0, 100.0, "1",
                 "K_vrock0 (thesis and code 0.2)"),
      real_param("vegetation_quality_gravel", element(&P::vegetation_soil_quality, 2), 0.0, 100.0, "1", "K_vrock1"),
      real_param("vegetation_quality_stones", element(&P::vegetation_soil_quality, 3), 0.0, 100.0, "1", "K_vrock2"),
      real_param("vegetation_quality_boulders", element(&P::vegetation_soil_quality, 4), 0.0, 100.0, "1", "K_vrock3"),
      real_param("root_depth", &P::root_depth, 1e-6, 1e3, "m", "K_vd, depth of the soil sample (code's shallow one)"),
      real_param("root_depth_deep", &P::root_depth_deep, 1e-6, 1e3, "m", "the code's deep sample (seed001_code)"),
      real_param("vegetation_base", &P::vegetation_base, 0.0, 2.0, "1", "subtracted from the quality (seed001_code)"),
      real_param("weathering_rate", &P::weathering_rate, 0.0, 1.0, "m/s",
                 "K_conv: rock broken by roots per second at veg 1 (code: 0.01 × rock breakdown speed 0.1)"),
      real_param("weathering_org", element(&P::weathering_shares, 0), 0.0, 100.0, "1", "K_org: sand → organic matter"),
      real_param("weathering_sand", element(&P::weathering_shares, 1), 0.0, 100.0, "1", "K_1,0: gravel → sand"),
      real_param("weathering_gravel", element(&P::weathering_shares, 2), 0.0, 100.0, "1", "K_2,1: stones → gravel"),
      real_param("weathering_stones", element(&P::weathering_shares, 3), 0.0, 100.0, "1", "K_3,2: boulders → stones"),
      real_param("weathering_reach", &P::weathering_reach, 0.0, 1e3, "m",
                 "bedrock turns into subsoil only under less soil than this (code: 4.0)"),
      real_param("initial_water", &P::initial_water, 0.0, 1e3, "m", "water on every column at the start (code: 0.2)"),
      real_param("rain_rate", &P::rain_rate, 0.0, 10.0, "m/s", "water added to every column each step"),
      integer_param("rain_steps", &P::rain_steps, 0, 1e9, "count",
                    "rain falls on the first this many iterations only (0: on every one)"),
      integer_param("drain_step", &P::drain_step, 0, 1e9, "count",
                    "at the start of this iteration (counted from 0) every column's water and what it carries is "
                    "removed, the code's \"Drain water\" (0: never)"),
      boolean_param("river", &P::river,
                    "the code's river: column (W/2, H/16) held at river_depth, rows y >= 15H/16 a sink"),
      real_param("river_depth", &P::river_depth, 0.0, 20.0, "m", "water depth of the river's source column"),
      real_param("gravity", &P::gravity, 1e-3, 100.0, "m/s^2", "g of the pipe model (§3.3)"),
      real_param("velocity_depth_floor", &P::velocity_depth_floor, 0.0, 10.0, "m",
                 "least mean depth w̄ of the velocity (thesis none; the code 0.05)"),
      real_param("depth_ramp", &P::depth_ramp, 1e-6, 100.0, "m", "K_w: capacity rises with depth up to it"),
      real_param("slope_floor", &P::slope_floor, 0.0, 1.0, "1", "least sin φ of the capacity"),
      choice_param("slope_form", &P::slope_form, slope_form_choices, "",
                   "sin φ of the true slope (central differences over 2l), or the code's un-halved differences with "
                   "l = 1"),
      real_param("erosion_strength", &P::erosion_strength, 0.0, 10.0, "s",
                 "K_c: water strength x = K_c·sin φ·|v|·l(w)"),
      real_param("organic_capacity", &P::organic_capacity, 0.0, 10.0, "1", "C_org = organic_capacity·x (code 0.12)"),
      real_param("erosion_rate", &P::erosion_rate, 0.0, 1.0, "1", "K_e (thesis 0.5; the code 0.1)"),
      real_param("deposition_rate", &P::deposition_rate, 0.0, 1.0, "1", "K_d (thesis and code 0.25)"),
      real_param("vegetation_protection", &P::vegetation_protection, 0.0, 100.0, "1", "K_wveg: x/(1 + K_wveg·veg)"),
      choice_param("breakdown_form", &P::breakdown_form, breakdown_form_choices, "",
                   "eq. 3.5's a·(x − b), or the code's max(a·x − b, 0)"),
      choice_param("share_form", &P::share_form, share_form_choices, "",
                   "eq. 3.10's min(m·max(K_emin, V_j/V), V_j), or the code's min(V_j, m)·max(K_emin, V_j/V)"),
      real_param("least_share", &P::least_share, 0.0, 1.0, "1", "K_emin of the surface-only factor"),
      real_param("transparency_depth", &P::transparency_depth, 1e-6, 100.0, "m",
                 "K_pmin: erosion reaches below thinner layers"),
      real_param("impact_rate", &P::impact_rate, 0.0, 100.0, "1",
                 "K_i: impact strength S = K_i·v·A_contact·Δt/(l_x·l_y) of water hitting a neighbour's layers "
                 "(§3.14); 0 off"),
      real_param("regolith_depth", &P::regolith_depth, 0.0, 2.0, "m", "K_r: regolith depth (§3.13); 0 switches it off"),
      real_param("regolith_erosion", &P::regolith_erosion, 0.0, 1.0, "1", "K_re"),
      real_param("regolith_deposition", &P::regolith_deposition, 0.0, 1.0, "1", "K_rd"),
      real_param("sediment_diffusion", &P::sediment_diffusion, 0.0, 0.25, "1",
                 "σ: share of the suspended sediment sent to each edge neighbour a step (§3.8; thesis e.g. 0.1; 0: off)"),
      choice_param("diffusion_weighting", &P::diffusion_weighting, diffusion_weighting_choices, "",
                   "uniform σ (thesis) or the code's weights by water depth, ½·w_n/(w + Σ ½·w_n)"),
      boolean_param("regolith_diffusion", &P::regolith_diffusion,
                    "the regolith diffuses like the sediment (thesis) or stays (the code)"),
      real_param("drying", &P::drying, 0.0, 1.0, "1/s", "K_dry: a dry column's wetness × K_dry^Δt"),
      real_param("flood_wetness", &P::flood_wetness, 0.0, 1e6, "m·s", "vegetation dies above this wetness (code 1.0)"),
  };
  return table;
}

const ParamSpecs& layered_param_specs() {
  static const ParamSpecs specs = param_specs(layered_param_table());
  return specs;
}

LayeredParams layered_params_from_json(const nlohmann::json& resolved) {
  return params_from_json(layered_param_table(), resolved);
}

std::vector<BedrockType> bedrock_types_from_json(const nlohmann::json& types) {
  require(types.is_array(), "bedrock_types must be an array of {repose_tan, fragments, hardness}");
  std::vector<BedrockType> out;
  for (const auto& entry : types) {
    require(entry.is_object() && entry.contains("repose_tan") && entry.contains("fragments") &&
                entry.at("fragments").is_array() && entry.at("fragments").size() == fragment_size_count,
            fmt::format("bedrock type {} needs repose_tan, fragments (4 shares) and hardness", out.size()));
    BedrockType type;
    type.repose_tan = entry.at("repose_tan").get<double>();
    for (int size = 0; size < fragment_size_count; ++size) {
      type.fragments[static_cast<std::size_t>(size)] = entry.at("fragments").at(static_cast<std::size_t>(size)).get<double>();
    }
    type.hardness = entry.value("hardness", 1.0);
    if (entry.contains("soil_rate")) type.soil_rate = entry.at("soil_rate").get<double>();
    if (entry.contains("soil_composition")) {
      require(entry.at("soil_composition").is_array() && entry.at("soil_composition").size() == soil_component_count,
              fmt::format("bedrock type {} soil_composition needs 5 shares", out.size()));
      for (int component = 0; component < soil_component_count; ++component) {
        type.soil_composition[static_cast<std::size_t>(component)] =
            entry.at("soil_composition").at(static_cast<std::size_t>(component)).get<double>();
      }
    }
    validate_bedrock_type(type, out.size());
    out.push_back(type);
  }
  require(!out.empty(), "at least one bedrock type is needed");
  return out;
}

void validate_layered_profile(const LayeredProfile& profile, const LayeredParams& params) {
  double topsoil = 0.0;
  for (int component = 0; component < soil_component_count; ++component) {
    const auto c = static_cast<std::size_t>(component);
    require_at_least(profile.topsoil[c], 0.0, fmt::format("profile topsoil {}", soil_component_name(component)));
    require_at_least(profile.subsoil[c], 0.0, fmt::format("profile subsoil {}", soil_component_name(component)));
    topsoil += profile.topsoil[c];
  }
  require(topsoil <= params.topsoil_max,
          fmt::format("profile topsoil is {} m thick, more than topsoil_max = {} m", topsoil, params.topsoil_max));
  require(!profile.bedrock.empty(), "the profile needs at least one bedrock layer");
  for (std::size_t layer = 0; layer < profile.bedrock.size(); ++layer) {
    const auto& bedrock = profile.bedrock[layer];
    require(bedrock.type >= 0 && static_cast<std::size_t>(bedrock.type) < params.bedrock_types.size(),
            fmt::format("profile bedrock layer {} has type {}, but only {} types are defined", layer, bedrock.type,
                        params.bedrock_types.size()));
    require_at_least(bedrock.thickness, 0.0, fmt::format("profile bedrock layer {} thickness", layer));
  }
}

}  // namespace gt
