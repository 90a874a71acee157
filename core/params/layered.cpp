// Parameter declarations and validation of `erosion.layered` (see layered.hpp).
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

void require_positive(double value, const std::string& name) {
  require_finite(value, name);
  require(value > 0.0, fmt::format("{} = {} must be > 0", name, value));
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

template <class Enum>
Enum choice_from_json(const nlohmann::json& resolved, const char* key, std::initializer_list<Enum> options,
                      const char* (*name_of)(Enum)) {
  const auto text = resolved.at(key).get<std::string>();
  for (Enum option : options) {
    if (text == name_of(option)) return option;
  }
  throw InputError(fmt::format("{}: unknown {} '{}'", algorithm_name, key, text));
}

constexpr std::array<const char*, soil_component_count> repose_keys{"repose_org", "repose_sand", "repose_gravel",
                                                                    "repose_stones", "repose_boulders"};
constexpr std::array<const char*, soil_component_count> quality_keys{
    "vegetation_quality_org", "vegetation_quality_sand", "vegetation_quality_gravel", "vegetation_quality_stones",
    "vegetation_quality_boulders"};
constexpr std::array<const char*, fragment_size_count> weathering_keys{"weathering_org", "weathering_sand",
                                                                       "weathering_gravel", "weathering_stones"};

}  // namespace

const char* soil_component_name(int component) {
  static constexpr std::array<const char*, soil_component_count> names{"org", "sand", "gravel", "stones",
                                                                       "boulders"};
  return names.at(static_cast<std::size_t>(component));
}

const char* talus_amount_name(TalusAmount amount) {
  return amount == TalusAmount::thesis ? "thesis" : "seed001_code";
}

const char* creep_denominator_name(CreepDenominator denominator) {
  return denominator == CreepDenominator::singular ? "singular" : "seed001_code";
}

const char* layered_border_name(LayeredBorder border) {
  return border == LayeredBorder::closed ? "closed" : "periodic";
}

const char* vegetation_quality_name(VegetationQuality quality) {
  return quality == VegetationQuality::thesis ? "thesis" : "seed001_code";
}

const char* slope_form_name(SlopeForm form) { return form == SlopeForm::thesis ? "thesis" : "seed001_code"; }
const char* breakdown_form_name(BreakdownForm form) {
  return form == BreakdownForm::thesis ? "thesis" : "seed001_code";
}
const char* share_form_name(ShareForm form) { return form == ShareForm::thesis ? "thesis" : "seed001_code"; }

FragmentMatrix thesis_breakdown_slopes() {
  return {{{0.3, 0.0, 0.0, 0.0}, {0.02, 0.08, 0.0, 0.0}, {0.02, 0.01, 0.04, 0.0}, {0.02, 0.01, 0.01, 0.02}}};
}

FragmentMatrix thesis_breakdown_thresholds() {
  return {{{0.0, 0.0, 0.0, 0.0}, {0.01, 0.1, 0.0, 0.0}, {0.02, 0.2, 0.3, 0.0}, {0.03, 0.25, 0.4, 0.5}}};
}

bool has_water(const LayeredParams& params) {
  return params.initial_water > 0.0 || params.rain_rate > 0.0 || params.river;
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
  require_positive(params.time_step, "time_step");
  for (int component = 0; component < soil_component_count; ++component) {
    require_repose(params.repose_tan[static_cast<std::size_t>(component)], repose_keys[static_cast<std::size_t>(component)]);
  }
  require_at_least(params.vegetation_repose, 0.0, "vegetation_repose");
  require_at_least(params.depth_factor, 1.0, "depth_factor");
  require(params.depth_factor <= 1.5, fmt::format("depth_factor = {} must be <= 1.5", params.depth_factor));
  require_positive(params.topsoil_max, "topsoil_max");
  require(!params.bedrock_types.empty(), "at least one bedrock type is needed");
  for (std::size_t i = 0; i < params.bedrock_types.size(); ++i) validate_bedrock_type(params.bedrock_types[i], i);
  require_at_least(params.creep_rate, 0.0, "creep_rate");
  require_positive(params.critical_slope, "critical_slope");
  require_positive(params.creep_denominator_floor, "creep_denominator_floor");
  require(params.creep_denominator_floor <= 1.0,
          fmt::format("creep_denominator_floor = {} must be <= 1", params.creep_denominator_floor));
  require_at_least(params.vegetation_rate, 0.0, "vegetation_rate");
  require_at_least(params.vegetation_equilibrium, 0.0, "vegetation_equilibrium");
  require_at_least(params.vegetation_neighbours, 0.0, "vegetation_neighbours");
  for (std::size_t i = 0; i < quality_keys.size(); ++i) {
    require_at_least(params.vegetation_soil_quality[i], 0.0, quality_keys[i]);
  }
  require_positive(params.root_depth, "root_depth");
  require_positive(params.root_depth_deep, "root_depth_deep");
  require_at_least(params.vegetation_base, 0.0, "vegetation_base");
  require_at_least(params.weathering_rate, 0.0, "weathering_rate");
  for (std::size_t i = 0; i < weathering_keys.size(); ++i) {
    require_at_least(params.weathering_shares[i], 0.0, weathering_keys[i]);
  }
  require_at_least(params.weathering_reach, 0.0, "weathering_reach");
  require_at_least(params.initial_water, 0.0, "initial_water");
  require_at_least(params.rain_rate, 0.0, "rain_rate");
  require_at_least(params.river_depth, 0.0, "river_depth");
  require_positive(params.gravity, "gravity");
  require_at_least(params.velocity_depth_floor, 0.0, "velocity_depth_floor");
  require_positive(params.depth_ramp, "depth_ramp");
  require_at_least(params.slope_floor, 0.0, "slope_floor");
  require(params.slope_floor <= 1.0, fmt::format("slope_floor = {} must be <= 1", params.slope_floor));
  require_at_least(params.erosion_strength, 0.0, "erosion_strength");
  require_at_least(params.organic_capacity, 0.0, "organic_capacity");
  for (const auto& [rate, name] : {std::pair{params.erosion_rate, "erosion_rate"},
                                   std::pair{params.deposition_rate, "deposition_rate"},
                                   std::pair{params.regolith_erosion, "regolith_erosion"},
                                   std::pair{params.regolith_deposition, "regolith_deposition"},
                                   std::pair{params.least_share, "least_share"}}) {
    require_at_least(rate, 0.0, name);
    require(rate <= 1.0, fmt::format("{} = {} is a fraction of the gap closed per step and must be <= 1", name, rate));
  }
  require_at_least(params.vegetation_protection, 0.0, "vegetation_protection");
  require_positive(params.transparency_depth, "transparency_depth");
  validate_fragment_matrix(params.breakdown_slopes, "breakdown_slopes");
  validate_fragment_matrix(params.breakdown_thresholds, "breakdown_thresholds");
  require_at_least(params.impact_rate, 0.0, "impact_rate");
  require_at_least(params.regolith_depth, 0.0, "regolith_depth");
  require_at_least(params.drying, 0.0, "drying");
  require(params.drying <= 1.0, fmt::format("drying = {} must be <= 1", params.drying));
  require_at_least(params.flood_wetness, 0.0, "flood_wetness");
}

const ParamSpecs& layered_param_specs() {
  static const ParamSpecs specs = {
      {"time_step", ParamKind::real, 0.2, 1e-6, 10.0, {}, "s",
       "Δt of talus (eq. 3.3) and creep (eq. 3.4); talus overshoots (never rests) above 2/9"},
      {"repose_org", ParamKind::real, 1.25, 1e-6, 1e7, {}, "1", "tan φ of pure organic matter (eq. 3.1)"},
      {"repose_sand", ParamKind::real, 0.7, 1e-6, 1e7, {}, "1", "tan φ of pure sand (rock0)"},
      {"repose_gravel", ParamKind::real, 0.8, 1e-6, 1e7, {}, "1", "tan φ of pure gravel (rock1)"},
      {"repose_stones", ParamKind::real, 1.0, 1e-6, 1e7, {}, "1", "tan φ of pure stones (rock2)"},
      {"repose_boulders", ParamKind::real, 1.0, 1e-6, 1e7, {}, "1", "tan φ of pure boulders (rock3)"},
      {"vegetation_repose", ParamKind::real, 0.2, 0.0, 10.0, {}, "1", "K_sveg: repose × (1 + K_sveg·veg)"},
      {"depth_factor", ParamKind::real, 1.25, 1.0, 1.5, {}, "1", "K_depth: soil layer j's repose × K_depth^j"},
      {"topsoil_max", ParamKind::real, 1.5, 1e-6, 1e3, {}, "m", "largest topsoil thickness; overflow goes down"},
      {"creep_rate", ParamKind::real, 0.01, 0.0, 10.0, {}, "m/s", "K_z of Roering's creep flux"},
      {"critical_slope", ParamKind::real, 1.40, 1e-3, 100.0, {}, "1", "S_c, where the creep flux diverges"},
      {"creep_denominator", ParamKind::choice, "singular", 0, 0, {"singular", "seed001_code"}, "",
       "the thesis's 1 − (s/S_c)², or its code's max(1 − (s/S_c)², creep_denominator_floor)"},
      {"creep_denominator_floor", ParamKind::real, 0.1, 1e-6, 1.0, {}, "1",
       "least creep denominator of the seed001_code variant"},
      {"talus_amount", ParamKind::choice, "thesis", 0, 0, {"thesis", "seed001_code"}, "",
       "eq. 3.3 per neighbour then clamped, or the code's min(½·maxΔh·rand, h_layer) split ∝ Δh"},
      {"talus_random", ParamKind::boolean, true, 0, 0, {}, "", "talus amounts × rand(0.9, 1) (thesis and code)"},
      {"creep_random", ParamKind::boolean, true, 0, 0, {}, "", "creep amounts × rand(0.9, 1) (thesis; the code: off)"},
      {"border", ParamKind::choice, "closed", 0, 0, {"closed", "periodic"}, "",
       "closed walls, or the code's periodic wrap (grids of at least 3 × 3)"},
      {"seed", ParamKind::integer, 1, 0, 4294967295.0, {}, "count", "key of the counter-based random numbers"},
      {"vegetation_quality", ParamKind::choice, "thesis", 0, 0, {"thesis", "seed001_code"}, "",
       "soil quality of vegetation growth (§3.15): one sample to root_depth, nveg over 8 neighbours; or the code's "
       "blend of root_depth and root_depth_deep samples by veg, minus vegetation_base, nveg over the 3 × 3"},
      {"vegetation_rate", ParamKind::real, 1.0, 0.0, 10.0, {}, "1/s", "K_veg: vegetation spread rate (code: 1)"},
      {"vegetation_equilibrium", ParamKind::real, 0.8, 0.0, 10.0, {}, "1", "K_eveg: veg' ∝ q_s − K_eveg·veg (code)"},
      {"vegetation_neighbours", ParamKind::real, 0.25, 0.0, 10.0, {}, "1", "K_nveg: weight of the neighbours' veg (code)"},
      {"vegetation_quality_org", ParamKind::real, 1.0, 0.0, 100.0, {}, "1", "K_vorg (thesis 1; the code 1.5)"},
      {"vegetation_quality_sand", ParamKind::real, 0.2, 0.0, 100.0, {}, "1", "K_vrock0 (thesis and code 0.2)"},
      {"vegetation_quality_gravel", ParamKind::real, 0.0, 0.0, 100.0, {}, "1", "K_vrock1"},
      {"vegetation_quality_stones", ParamKind::real, 0.0, 0.0, 100.0, {}, "1", "K_vrock2"},
      {"vegetation_quality_boulders", ParamKind::real, 0.0, 0.0, 100.0, {}, "1", "K_vrock3"},
      {"root_depth", ParamKind::real, 0.25, 1e-6, 1e3, {}, "m", "K_vd, depth of the soil sample (code's shallow one)"},
      {"root_depth_deep", ParamKind::real, 2.0, 1e-6, 1e3, {}, "m", "the code's deep sample (seed001_code)"},
      {"vegetation_base", ParamKind::real, 0.2, 0.0, 2.0, {}, "1", "subtracted from the quality (seed001_code)"},
      {"weathering_rate", ParamKind::real, 0.001, 0.0, 1.0, {}, "m/s",
       "K_conv: rock broken by roots per second at veg 1 (code: 0.01 × rock breakdown speed 0.1)"},
      {"weathering_org", ParamKind::real, 1.0, 0.0, 100.0, {}, "1", "K_org: sand → organic matter"},
      {"weathering_sand", ParamKind::real, 0.2, 0.0, 100.0, {}, "1", "K_1,0: gravel → sand"},
      {"weathering_gravel", ParamKind::real, 0.3, 0.0, 100.0, {}, "1", "K_2,1: stones → gravel"},
      {"weathering_stones", ParamKind::real, 0.4, 0.0, 100.0, {}, "1", "K_3,2: boulders → stones"},
      {"weathering_reach", ParamKind::real, 4.0, 0.0, 1e3, {}, "m",
       "bedrock turns into subsoil only under less soil than this (code: 4.0)"},
      {"initial_water", ParamKind::real, 0.0, 0.0, 1e3, {}, "m", "water on every column at the start (code: 0.2)"},
      {"rain_rate", ParamKind::real, 0.0, 0.0, 10.0, {}, "m/s", "water added to every column each step"},
      {"river", ParamKind::boolean, false, 0, 0, {}, "",
       "the code's river: column (W/2, H/16) held at river_depth, rows y >= 15H/16 a sink"},
      {"river_depth", ParamKind::real, 1.0, 0.0, 20.0, {}, "m", "water depth of the river's source column"},
      {"gravity", ParamKind::real, 9.81, 1e-3, 100.0, {}, "m/s^2", "g of the pipe model (§3.3)"},
      {"velocity_depth_floor", ParamKind::real, 0.0, 0.0, 10.0, {}, "m",
       "least mean depth w̄ of the velocity (thesis none; the code 0.05)"},
      {"depth_ramp", ParamKind::real, 0.45, 1e-6, 100.0, {}, "m", "K_w: capacity rises with depth up to it"},
      {"slope_floor", ParamKind::real, 0.05, 0.0, 1.0, {}, "1", "least sin φ of the capacity"},
      {"slope_form", ParamKind::choice, "thesis", 0, 0, {"thesis", "seed001_code"}, "",
       "sin φ of the true slope (central differences over 2l), or the code's un-halved differences with l = 1"},
      {"erosion_strength", ParamKind::real, 0.25, 0.0, 10.0, {}, "s", "K_c: water strength x = K_c·sin φ·|v|·l(w)"},
      {"organic_capacity", ParamKind::real, 0.12, 0.0, 10.0, {}, "1", "C_org = organic_capacity·x (code 0.12)"},
      {"erosion_rate", ParamKind::real, 0.5, 0.0, 1.0, {}, "1", "K_e (thesis 0.5; the code 0.1)"},
      {"deposition_rate", ParamKind::real, 0.25, 0.0, 1.0, {}, "1", "K_d (thesis and code 0.25)"},
      {"vegetation_protection", ParamKind::real, 0.2, 0.0, 100.0, {}, "1", "K_wveg: x/(1 + K_wveg·veg)"},
      {"breakdown_form", ParamKind::choice, "thesis", 0, 0, {"thesis", "seed001_code"}, "",
       "eq. 3.5's a·(x − b), or the code's max(a·x − b, 0)"},
      {"share_form", ParamKind::choice, "thesis", 0, 0, {"thesis", "seed001_code"}, "",
       "eq. 3.10's min(m·max(K_emin, V_j/V), V_j), or the code's min(V_j, m)·max(K_emin, V_j/V)"},
      {"least_share", ParamKind::real, 0.1, 0.0, 1.0, {}, "1", "K_emin of the surface-only factor"},
      {"transparency_depth", ParamKind::real, 0.1, 1e-6, 100.0, {}, "m", "K_pmin: erosion reaches below thinner layers"},
      {"impact_rate", ParamKind::real, 0.25, 0.0, 100.0, {}, "1",
       "K_i: impact strength S = K_i·v·A_contact·Δt/(l_x·l_y) of water hitting a neighbour's layers (§3.14); 0 off"},
      {"regolith_depth", ParamKind::real, 0.01, 0.0, 2.0, {}, "m", "K_r: regolith depth (§3.13); 0 switches it off"},
      {"regolith_erosion", ParamKind::real, 1.0, 0.0, 1.0, {}, "1", "K_re"},
      {"regolith_deposition", ParamKind::real, 1.0, 0.0, 1.0, {}, "1", "K_rd"},
      {"drying", ParamKind::real, 0.5, 0.0, 1.0, {}, "1/s", "K_dry: a dry column's wetness × K_dry^Δt"},
      {"flood_wetness", ParamKind::real, 1.0, 0.0, 1e6, {}, "m·s", "vegetation dies above this wetness (code 1.0)"},
  };
  return specs;
}

LayeredParams layered_params_from_json(const nlohmann::json& resolved) {
  LayeredParams params;
  params.time_step = resolved.at("time_step").get<double>();
  for (std::size_t component = 0; component < repose_keys.size(); ++component) {
    params.repose_tan[component] = resolved.at(repose_keys[component]).get<double>();
  }
  params.vegetation_repose = resolved.at("vegetation_repose").get<double>();
  params.depth_factor = resolved.at("depth_factor").get<double>();
  params.topsoil_max = resolved.at("topsoil_max").get<double>();
  params.creep_rate = resolved.at("creep_rate").get<double>();
  params.critical_slope = resolved.at("critical_slope").get<double>();
  params.creep_denominator = choice_from_json(resolved, "creep_denominator",
                                              {CreepDenominator::singular, CreepDenominator::seed001_code},
                                              creep_denominator_name);
  params.creep_denominator_floor = resolved.at("creep_denominator_floor").get<double>();
  params.talus_amount = choice_from_json(resolved, "talus_amount", {TalusAmount::thesis, TalusAmount::seed001_code},
                                         talus_amount_name);
  params.talus_random = resolved.at("talus_random").get<bool>();
  params.creep_random = resolved.at("creep_random").get<bool>();
  params.border = choice_from_json(resolved, "border", {LayeredBorder::closed, LayeredBorder::periodic},
                                   layered_border_name);
  params.seed = resolved.at("seed").get<std::uint32_t>();
  params.vegetation_quality = choice_from_json(resolved, "vegetation_quality",
                                               {VegetationQuality::thesis, VegetationQuality::seed001_code},
                                               vegetation_quality_name);
  params.vegetation_rate = resolved.at("vegetation_rate").get<double>();
  params.vegetation_equilibrium = resolved.at("vegetation_equilibrium").get<double>();
  params.vegetation_neighbours = resolved.at("vegetation_neighbours").get<double>();
  for (std::size_t i = 0; i < quality_keys.size(); ++i) {
    params.vegetation_soil_quality[i] = resolved.at(quality_keys[i]).get<double>();
  }
  params.root_depth = resolved.at("root_depth").get<double>();
  params.root_depth_deep = resolved.at("root_depth_deep").get<double>();
  params.vegetation_base = resolved.at("vegetation_base").get<double>();
  params.weathering_rate = resolved.at("weathering_rate").get<double>();
  for (std::size_t i = 0; i < weathering_keys.size(); ++i) {
    params.weathering_shares[i] = resolved.at(weathering_keys[i]).get<double>();
  }
  params.weathering_reach = resolved.at("weathering_reach").get<double>();
  for (auto [key, value] : {std::pair{"initial_water", &params.initial_water}, std::pair{"rain_rate", &params.rain_rate},
                            std::pair{"river_depth", &params.river_depth}, std::pair{"gravity", &params.gravity},
                            std::pair{"velocity_depth_floor", &params.velocity_depth_floor},
                            std::pair{"depth_ramp", &params.depth_ramp}, std::pair{"slope_floor", &params.slope_floor},
                            std::pair{"erosion_strength", &params.erosion_strength},
                            std::pair{"organic_capacity", &params.organic_capacity},
                            std::pair{"erosion_rate", &params.erosion_rate},
                            std::pair{"deposition_rate", &params.deposition_rate},
                            std::pair{"vegetation_protection", &params.vegetation_protection},
                            std::pair{"least_share", &params.least_share},
                            std::pair{"transparency_depth", &params.transparency_depth},
                            std::pair{"impact_rate", &params.impact_rate},
                            std::pair{"regolith_depth", &params.regolith_depth},
                            std::pair{"regolith_erosion", &params.regolith_erosion},
                            std::pair{"regolith_deposition", &params.regolith_deposition},
                            std::pair{"drying", &params.drying}, std::pair{"flood_wetness", &params.flood_wetness}}) {
    *value = resolved.at(key).get<double>();
  }
  params.river = resolved.at("river").get<bool>();
  params.slope_form = choice_from_json(resolved, "slope_form", {SlopeForm::thesis, SlopeForm::seed001_code},
                                       slope_form_name);
  params.breakdown_form = choice_from_json(resolved, "breakdown_form",
                                           {BreakdownForm::thesis, BreakdownForm::seed001_code}, breakdown_form_name);
  params.share_form = choice_from_json(resolved, "share_form", {ShareForm::thesis, ShareForm::seed001_code},
                                       share_form_name);
  validate_layered_params(params);
  return params;
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
