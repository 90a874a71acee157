// Parameter declarations, constants and ledger arithmetic of `erosion.pipe` (see hydraulic.hpp).
#include "core/params/hydraulic.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/mutant.hpp"
#include "core/rounding_interval.hpp"

namespace gt {
namespace {

constexpr const char* algorithm_name = "erosion.pipe";

void require(bool condition, const std::string& what) {
  if (!condition) throw InputError(fmt::format("{}: {}", algorithm_name, what));
}

constexpr Choice<SedimentTransport> transport_choices[] = {{"semi_lagrangian", SedimentTransport::semi_lagrangian},
                                                           {"flux", SedimentTransport::flux},
                                                           {"maccormack", SedimentTransport::maccormack}};
constexpr Choice<PipeBoundary> boundary_choices[] = {{"closed", PipeBoundary::closed}, {"open", PipeBoundary::open}};
constexpr Choice<TiltDifferences> tilt_choices[] = {{"central", TiltDifferences::central},
                                                    {"seed001_code", TiltDifferences::seed001_code}};
constexpr Choice<int> pipe_count_choices[] = {{"4", 4}, {"8", 8}};
constexpr Choice<LayerErosion> layer_erosion_choices[] = {{"capacity_above_sediment", LayerErosion::capacity_above_sediment},
                                                          {"as_printed", LayerErosion::as_printed}};

}  // namespace

const char* sediment_transport_name(SedimentTransport transport) { return choice_name(transport_choices, transport); }
const char* pipe_boundary_name(PipeBoundary boundary) { return choice_name(boundary_choices, boundary); }
const char* tilt_differences_name(TiltDifferences differences) { return choice_name(tilt_choices, differences); }
const char* layer_erosion_name(LayerErosion erosion) { return choice_name(layer_erosion_choices, erosion); }

double tilt_span(TiltDifferences differences, int sides, double length) {
  // Mutant erosion.pipe.tilt_unhalved: a central difference divided by l, not 2l (both twins' spans).
  if (differences == TiltDifferences::central && mutant_active("erosion.pipe.tilt_unhalved")) return length;
  return differences == TiltDifferences::central ? sides * length : 1.0;
}

const char* pipe_name(int pipe) {
  static constexpr std::array<const char*, 8> names{"L", "R", "T", "B", "TL", "BR", "TR", "BL"};
  return names.at(static_cast<std::size_t>(pipe));
}

const ParamTable<HydraulicParams>& hydraulic_param_table() {
  using P = HydraulicParams;
  static const ParamTable<P> table = {
      integer_param("steps", &P::steps, 0, 1000000, "count", "time steps of Δt"),
      real_param("time_step", &P::time_step, 1e-6, 3600.0, "s", "Δt"),
      real_param("gravity", &P::gravity, 0.0, 100.0, "m/s²", "g of the pipe acceleration g·Δh/l"),
      real_param("pipe_area", &P::pipe_area, 0.0, 1e8, "m²", "pipe cross-section A; 0 = cell area l_x·l_y"),
      real_param("rain_rate", &P::rain_rate, 0.0, 1.0, "m/s", "uniform rain added as Δt·rate per step"),
      real_param("evaporation_rate", &P::evaporation_rate, 0.0, 1e3, "1/s", "K_e: d ← d·(1 − K_e·Δt); K_e·Δt ≤ 1"),
      real_param("capacity", &P::capacity, 0.0, 1e3, "s", "K_c of the capacity C = K_c·sin α·|v|·l(d)"),
      real_param("min_tilt_sine", &P::min_tilt_sine, 0.0, 1.0, "1", "lower bound of sin α (flat ground still erodes)"),
      choice_param("tilt_differences", &P::tilt_differences, tilt_choices, "",
                   "seed 001 §3.5: sin α from central differences over 2l, or its code's raw |b(x−1) − b(x+1)| (as if "
                   "l = 1, not halved)"),
      real_param("depth_ramp", &P::depth_ramp, 0.0, 1e3, "m",
                 "K_w of the depth ramp l(d) = min(1, d/K_w) (Jákó 2011, seed 001); 0 = no ramp"),
      real_param("dissolving_rate", &P::dissolving_rate, 0.0, 1e3, "1/s",
                 "K_s: a step closes min(1, K_s·Δt) of the gap C − s by erosion"),
      real_param("deposition_rate", &P::deposition_rate, 0.0, 1e3, "1/s",
                 "K_d: a step closes min(1, K_d·Δt) of the gap s − C by deposition"),
      real_param("velocity_depth_floor", &P::velocity_depth_floor, 1e-9, 10.0, "m",
                 "lower bound of the mean depth d̄ that divides the flux into a velocity"),
      choice_param("pipes", &P::pipe_count, pipe_count_choices, "count",
                   "virtual pipes per cell: 4 (L, R, T, B; Mei) or 8 (and the diagonals, length sqrt(l_x² + l_y²))"),
      choice_param("transport", &P::transport, transport_choices, "",
                   "sediment transport: Mei's semi-Lagrangian backtrace (not conservative), with the pipe outflows, or "
                   "MacCormack's correction of the backtrace, limited to the values it read (Selle et al. 2008; not "
                   "conservative)"),

      choice_param("boundary", &P::boundary, boundary_choices, "",
                   "grid border and no-data cells: closed walls or open (water and sediment leave and are counted)"),
      real_param("sediment_diffusion", &P::sediment_diffusion, 0.0, 0.25, "1",
                 "seed 001 §3.8: share w of the sediment (and regolith) sent to each neighbour per step; 0 = off"),
      choice_param("diffusion_weighting", &P::diffusion_weighting, diffusion_weighting_choices, "",
                   "seed 001 §3.8: the thesis's uniform w, or its code's weights by water depth (w only switches it on)"),
      real_param("regolith_depth", &P::regolith_depth, 0.0, 10.0, "m",
                 "seed 001 §3.9: K_r, the largest regolith thickness r_max = min(d, K_r); 0 = no regolith layer"),
      real_param("regolith_dissolving_rate", &P::regolith_dissolving_rate, 0.0, 1e6, "1/s",
                 "K_re: a step closes min(1, K_re·Δt) of the gap r_max − r"),
      real_param("regolith_deposition_rate", &P::regolith_deposition_rate, 0.0, 1e6, "1/s",
                 "K_rd: a step closes min(1, K_rd·Δt) of the gap r − r_max"),
      boolean_param("regolith_diffusion", &P::regolith_diffusion,
                    "seed 001 §3.9: the regolith is diffused like the sediment (the thesis); false = its code (not "
                    "diffused)"),
      boolean_param("thermal_step", &P::thermal_step,
                    "Jákó & Tóth 2011's combined step: one iteration of their thermal erosion after each pipe step"),
      real_param("thermal_talus_angle", &P::thermal_talus_angle, 0.0, 89.0, "degree", "talus angle of the thermal step"),
      real_param("thermal_rate", &P::thermal_rate, 0.0, 1.0, "1", "Jákó's rate Δt·C_t·R of the thermal step"),
      integer_param("layers", &P::layers, 0, max_pipe_layers, "count",
                    "Šťava et al. 2008 (seed 000 §2.5): layers of material on the bedrock, each with its own capacity "
                    "C_k (state fields layer_1 .. layer_N, m; layer N on top takes the deposits); 0 = Mei's single "
                    "material"),
      real_param("layer_capacity_1", element(&P::layer_capacity, 0), 0.0, 1e3, "s",
                 "C_1 of layer 1 (on the bedrock): T_1 = C_1·sin α·|v|·l(d) (eq. 2.28); the bedrock's is K_c"),
      real_param("layer_capacity_2", element(&P::layer_capacity, 1), 0.0, 1e3, "s", "C_2 of layer 2 (eq. 2.28)"),
      real_param("layer_capacity_3", element(&P::layer_capacity, 2), 0.0, 1e3, "s", "C_3 of layer 3 (eq. 2.28)"),
      choice_param("layer_erosion", &P::layer_erosion, layer_erosion_choices, "",
                   "Algorithm 1's condition to erode layer k: T̂_k > s (the prose: capacity left after the layers "
                   "above) or as the thesis prints it, T̂_k < s"),
  };
  return table;
}

const ParamSpecs& hydraulic_param_specs() {
  static const ParamSpecs specs = param_specs(hydraulic_param_table());
  return specs;
}

HydraulicParams hydraulic_params_from_json(const nlohmann::json& resolved) {
  return params_from_json(hydraulic_param_table(), resolved);
}

PipeConstants pipe_constants(const HydraulicParams& params, const Heightmap& terrain) {
  check_param_ranges(algorithm_name, hydraulic_param_table(), params);
  const double evaporated_share = params.evaporation_rate * params.time_step;
  require(evaporated_share <= 1.0,
          fmt::format("evaporation_rate·time_step = {}·{} = {} exceeds 1 (more than all the water per step)",
                      params.evaporation_rate, params.time_step, evaporated_share));
  require(params.layers == 0 || (params.regolith_depth == 0.0 && !params.thermal_step),
          fmt::format("layers = {} with {}: the seeds do not say which layer the regolith loosens or the thermal step "
                      "moves; use layers = 0 or switch those off",
                      params.layers, params.thermal_step ? "the thermal step" : "regolith (regolith_depth > 0)"));
  require(params.layers > 0 || params.layer_erosion == LayerErosion::capacity_above_sediment,
          "layer_erosion = as_printed needs layers >= 1 (Algorithm 1 walks the layers above the bedrock)");
  require(terrain.cell_size_x > 0.0 && terrain.cell_size_y > 0.0,
          fmt::format("cell size {} x {} m must be > 0", terrain.cell_size_x, terrain.cell_size_y));

  PipeConstants constants;
  constants.time_step = params.time_step;
  // Mutant erosion.pipe.gravity_in_cgs: g read in cm/s² (both twins take their constants from here).
  constants.gravity = mutant_active("erosion.pipe.gravity_in_cgs") ? 100.0 * params.gravity : params.gravity;
  constants.length_x = terrain.cell_size_x;
  constants.length_y = terrain.cell_size_y;
  constants.length_diagonal = std::hypot(terrain.cell_size_x, terrain.cell_size_y);
  constants.cell_area = terrain.cell_size_x * terrain.cell_size_y;
  constants.pipe_area = params.pipe_area > 0.0 ? params.pipe_area : constants.cell_area;
  constants.rain_rate = params.rain_rate;
  constants.evaporation_kept = 1.0 - evaporated_share;
  // Mutants (both twins read their constants here): erosion.pipe.capacity_doubled takes 2·K_c; the
  // spec step's calibrated pair takes K_c·(1 + 2^-41) (above its bound) and K_c·(1 + 2^-52) (below).
  constants.capacity = params.capacity;
  if (mutant_active("erosion.pipe.capacity_doubled")) constants.capacity = 2.0 * params.capacity;
  if (mutant_active("erosion.pipe.capacity_off_above_bound")) constants.capacity = params.capacity * (1.0 + 0x1p-41);
  if (mutant_active("erosion.pipe.capacity_off_below_bound")) constants.capacity = params.capacity * (1.0 + 0x1p-52);
  constants.min_tilt_sine = params.min_tilt_sine;
  constants.tilt_differences = params.tilt_differences;
  constants.depth_ramp = params.depth_ramp;
  // Mutant erosion.pipe.rates_swapped: K_s and K_d exchanged (both twins read them here).
  const bool rates_swapped = mutant_active("erosion.pipe.rates_swapped");
  const double dissolving_rate = rates_swapped ? params.deposition_rate : params.dissolving_rate;
  const double deposition_rate = rates_swapped ? params.dissolving_rate : params.deposition_rate;
  constants.dissolving_fraction = std::min(1.0, dissolving_rate * params.time_step);
  constants.deposition_fraction = std::min(1.0, deposition_rate * params.time_step);
  constants.velocity_depth_floor = params.velocity_depth_floor;
  constants.pipe_count = params.pipe_count;
  constants.transport = params.transport;
  constants.boundary = params.boundary;
  constants.sediment_diffusion = params.sediment_diffusion;
  constants.diffusion_weighting = params.diffusion_weighting;
  constants.regolith_depth = params.regolith_depth;
  constants.regolith_dissolving_fraction = std::min(1.0, params.regolith_dissolving_rate * params.time_step);
  constants.regolith_deposition_fraction = std::min(1.0, params.regolith_deposition_rate * params.time_step);
  constants.regolith_diffusion = params.regolith_diffusion;
  constants.thermal_step = params.thermal_step;
  constants.thermal = thermal_jako_constants(
      {.iterations = 1, .talus_angle_deg = params.thermal_talus_angle, .rate = params.thermal_rate}, terrain);
  constants.layer_count = params.layers;
  for (int k = 0; k < params.layers; ++k) constants.layer_capacity[k] = params.layer_capacity[k];
  constants.layer_erosion = params.layer_erosion;
  return constants;
}

template <class Real>
PipeState<Real> dry_pipe_state(const Grid<Real>& terrain, int layers) {
  auto zero_like = [&terrain] {
    Grid<Real> field = terrain;
    std::fill(field.values.begin(), field.values.end(), Real(0));
    return field;
  };
  PipeState<Real> state;
  state.terrain = terrain;
  state.water = zero_like();
  state.sediment = zero_like();
  state.outflow.assign(terrain.size(), std::array<Real, 8>{});
  state.velocity_x = zero_like();
  state.velocity_y = zero_like();
  state.regolith = zero_like();
  for (int k = 0; k < layers; ++k) state.layers.push_back(zero_like());
  return state;
}

template PipeState<float> dry_pipe_state(const Grid<float>&, int);
template PipeState<double> dry_pipe_state(const Grid<double>&, int);

template <class To, class From>
PipeState<To> cast_pipe_state(const PipeState<From>& state) {
  return map_pipe_state<To>(state, [](From value) { return static_cast<To>(value); });
}

template PipeState<float> cast_pipe_state(const PipeState<double>&);
template PipeState<double> cast_pipe_state(const PipeState<float>&);

namespace {

template <class Real>
void require_same_size(const Grid<Real>& field, const Grid<Real>& terrain, const char* name) {
  require(field.width == terrain.width && field.height == terrain.height,
          fmt::format("{} is {}x{}, the terrain {}x{}", name, field.width, field.height, terrain.width, terrain.height));
}

// Finite on valid cells (check_finite names the cell), and not negative where it must not be.
template <class Real>
void require_field(const Grid<Real>& field, const Grid<Real>& terrain, const char* name, bool non_negative) {
  Grid<Real> masked = field;
  masked.valid = terrain.valid;
  check_finite(masked, fmt::format("{}: {}", algorithm_name, name));
  if (!non_negative) return;
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) {
      require(!terrain.is_valid(x, y) || field.at(x, y) >= Real(0),
              fmt::format("the {} at cell (x={}, y={}) is {}; it must be >= 0", name, x, y,
                          static_cast<double>(field.at(x, y))));
    }
  }
}

template <class Real>
void require_fluxes(const PipeState<Real>& state, int pipe_count) {
  const auto& terrain = state.terrain;
  require(state.outflow.size() == terrain.size(),
          fmt::format("the outflow flux has {} cells, the terrain {}", state.outflow.size(), terrain.size()));
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) continue;
    for (int k = 0; k < 8; ++k) {
      const double flux = static_cast<double>(state.outflow[cell][k]);
      require(std::isfinite(flux) && flux >= 0.0,
              fmt::format("outflow flux {} at cell {} must be finite and >= 0", flux, cell));
      require(k < pipe_count || flux == 0.0, fmt::format("outflow flux {} through pipe {} at cell {}: with {} pipes "
                                                         "it must be 0",
                                                         flux, pipe_name(k), cell, pipe_count));
    }
  }
}

// A rate that is finite and >= 0 and stays finite once rounded to Real.
template <class Real>
bool usable_rate(double rate) {
  return std::isfinite(rate) && rate >= 0.0 && std::isfinite(static_cast<double>(static_cast<Real>(rate)));
}

template <class Real>
void require_forcing(const Grid<Real>& terrain, const HydraulicForcing& forcing, const PipeConstants& constants) {
  const auto& rain_map = forcing.rain_map;
  if (!rain_map.values.empty()) {
    require(rain_map.width == terrain.width && rain_map.height == terrain.height,
            fmt::format("the rain map is {}x{}, the terrain {}x{}", rain_map.width, rain_map.height, terrain.width,
                        terrain.height));
    for (std::size_t cell = 0; cell < rain_map.size(); ++cell) {
      require(!terrain.is_valid(cell) || usable_rate<Real>(rain_map.values[cell]),
              fmt::format("the rain map holds {} m/s at cell {}; rain must be finite and >= 0", rain_map.values[cell],
                          cell));
    }
  }
  for (const auto& source : forcing.sources) {
    require(terrain.inside(source.x, source.y) && terrain.is_valid(source.x, source.y),
            fmt::format("point source at cell (x={}, y={}) is off the grid or on a no-data cell", source.x, source.y));
    require(usable_rate<Real>(source.rate) && usable_rate<Real>(source.rate * constants.time_step / constants.cell_area),
            fmt::format("point source at cell (x={}, y={}) has rate {} m³/s; it must be finite and >= 0", source.x,
                        source.y, source.rate));
  }
}

}  // namespace

template <class Real>
void check_pipe_input(const PipeState<Real>& state, const HydraulicForcing& forcing, const PipeConstants& constants) {
  const auto& terrain = state.terrain;
  require(count_valid(terrain) > 0, "the terrain's mask covers every cell");
  require_same_size(state.water, terrain, "the water depth");
  require_same_size(state.sediment, terrain, "the sediment");
  require_same_size(state.velocity_x, terrain, "the x velocity");
  require_same_size(state.velocity_y, terrain, "the y velocity");
  require_same_size(state.regolith, terrain, "the regolith");
  require_field(terrain, terrain, "terrain", false);
  require_field(state.water, terrain, "water depth", true);
  require_field(state.sediment, terrain, "sediment", true);
  require_field(state.regolith, terrain, "regolith", true);
  require_field(state.velocity_x, terrain, "x velocity", false);
  require_field(state.velocity_y, terrain, "y velocity", false);
  require(state.layers.size() == static_cast<std::size_t>(constants.layer_count),
          fmt::format("the state holds {} layers, the parameters ask for {}", state.layers.size(), constants.layer_count));
  for (std::size_t k = 0; k < state.layers.size(); ++k) {
    const std::string name = fmt::format("layer_{}", k + 1);
    require_same_size(state.layers[k], terrain, name.c_str());
    require_field(state.layers[k], terrain, name.c_str(), true);
  }
  require_fluxes(state, constants.pipe_count);
  require_forcing(terrain, forcing, constants);
}

template void check_pipe_input(const PipeState<float>&, const HydraulicForcing&, const PipeConstants&);
template void check_pipe_input(const PipeState<double>&, const HydraulicForcing&, const PipeConstants&);
template void check_pipe_input(const PipeState<RoundingInterval>&, const HydraulicForcing&, const PipeConstants&);

void PipeFlows::write_to(PipeLedgerEntry& entry) const {
  entry.rain_in = rain_in.value();
  entry.source_in = source_in.value();
  entry.water_added = water_added.value();
  entry.evaporated = evaporated.value();
  entry.boundary_out_water = boundary_out_water.value();
  entry.boundary_out_sediment = boundary_out_sediment.value();
  entry.boundary_out_regolith = boundary_out_regolith.value();
}

double water_balance(const PipeLedgerEntry& entry, const PipeLedgerEntry& initial) {
  return (entry.water - initial.water) - entry.water_added +
         (entry.evaporated + entry.boundary_out_water);
}

double rain_rounding(const PipeLedgerEntry& entry) { return (entry.rain_in + entry.source_in) - entry.water_added; }

double material_drift(const PipeLedgerEntry& entry, const PipeLedgerEntry& initial) {
  return ((entry.terrain - initial.terrain) + (entry.sediment - initial.sediment) + (entry.regolith - initial.regolith)) +
         (entry.boundary_out_sediment + entry.boundary_out_regolith);
}

}  // namespace gt
