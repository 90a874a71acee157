// Host side of the virtual-pipe erosion (Mei 2007) on the GPU: validation, upload, the std140
// parameter block, the dispatches of a step and the ledger. The algorithm, its stages and every
// decision where Mei is vague (exterior pipes, 0/0, clamps, the velocity's depth floor, the tilt,
// backtrace sampling, the summation order) are those of reference/erosion/pipes.cpp; the shaders
// repeat its float operations in the same order (`precise`, no fused multiply-add).
//
// Passes per step (gpu/shaders/erosion/):
//   pipes_water.comp     stage 1   d_A = d + Δt·(r + r_map)
//   pipes_sources.comp   stage 1   + point sources (only when there are any; one invocation per cell)
//   pipes_outflow.comp   stage 2   fluxes of the 4 or 8 pipes, in place (reads the neighbours' d_A)
//   pipes_flow.comp      3, 4, 5, 5b, 6a  d_B, velocity, erosion/deposition, regolith exchange,
//                        what leaves each cell
//   pipes_sediment.comp  6, 7      transport (gather or backtrace) of s and r, and evaporation
//   pipes_maccormack.comp 6        MacCormack's correction of the backtrace (only with that
//                                  transport), written to a buffer swapped with s (and r)
//   pipes_diffusion.comp 6b        diffusion of s and r (seed 001 §3.8; only when w > 0; r only with
//                                  regolith_diffusion)
//   pipes_thermal_outflow.comp, pipes_thermal_gather.comp
//                        8         Jákó & Tóth's thermal iteration on b0 + Δb (only with thermal_step)
// Buffers: per-cell constants {b0, rain depth, flags}, Δb (two, ping-pong: the tilt reads the
// neighbours' old Δb), water {d, d_A, d_B}, outflow {f_L, f_R, f_T, f_B} (+ {f_TL, f_BR, f_TR, f_BL}
// with 8 pipes), velocity, s, the sediment a cell keeps before transport (also the diffusion's
// output, swapped with s), what it sends down each pipe (one or two vec4 as the outflow), and the
// same three for the regolith r (allocated only when K_r > 0). Variants are compiled in with
// defines: PIPES_8, TRANSPORT_FLUX, REGOLITH, REGOLITH_DIFFUSION (r diffused too: the thesis, not
// seed 001's code), DIFFUSION_WATER, LAYERS=N (Šťava's layers, 0 without: their thicknesses, N
// floats a cell, are read and written in place by pipes_flow.comp) and LAYERS_AS_PRINTED. Seed
// 001's code tilt (tilt_differences) needs no define: it is the spans of the tilt's differences in
// the parameter block, 1 instead of l and 2l.
//
// The float trap and its solution. ref<float> stores b as a float: an erosion amount a
// below half the float spacing of b (2^-15 m = 3.05e-5 m between floats at 500 m, so a < 1.5e-5 m)
// leaves b unchanged while s gains a, so material is created (and destroyed by deposition). Here
// the terrain is
//   b = b0 + Δb,  b0 = the initial height as a float (never written), Δb = float, starting at 0;
// erosion writes Δb − a and deposition Δb + a (the regolith exchange and the thermal step
// likewise), so a lands in a number of the size of the changes, and every height difference is
// formed as (b0_a − b0_b) + (Δb_a − Δb_b) (+ water), the first difference exact at a high base
// (Sterbenz), so heads and slopes keep the precision of the relief and the water, not of the
// base. The ledger's terrain volume is Σ b0 (the stored floats, in double, summed once) + Σ Δb,
// and state() returns b0 + Δb in double. Material conservation is then limited by the rounding
// of Δb and s only. Measured on 256x256 cells on a 500 m slope, 500 steps of rain, flux transport
// (tests/pipes_gpu_test.cpp, FluxTransportConservesMaterialAt500Metres): material drift 9.5e-6 m³
// = 2.9e-13 of the material on the GPU, 60 m³ = 1.8e-6 in ref<float>.
// Against ref<float> this storage is the one intended source of disagreement (besides GLSL's
// licensed 2.5-ulp division and square root, exact on llvmpipe): one step from the same state,
// where both form every head exactly, gives every field but the terrain bit for bit, and the
// terrain differs by at most the roundings ref<float> makes of b (half an ulp of |b| per write).
//
// The ledger (keep_ledger): after each step the state is downloaded and the reference's ledger is
// rebuilt from the same float quantities in the same order: rain and source depths as uploaded,
// Δt·f_k through exterior pipes, the sediment (and regolith) sent through exterior pipes (flux
// form) or removed at exterior pipes (semi-Lagrangian, written by the shader), d_B − d for
// evaporation (a float subtraction, as the reference), Σ d, Σ s, Σ r, Σ b0 + Σ Δb, the CFL number.
//
// Memory traffic per cell and step (4 pipes, flux transport; the performance table's floor
// column): 4 dispatches, 192 B read + 116 B written = 308 B counting whole elements (the cells'
// 16-B constants read by all 4, the water vec4 read by all 4 and one component written by each,
// outflow vec4 read twice and written once, sent vec4 written then read, delta f32, velocity
// vec2, sediment and staying f32); 180 B counting the components touched. Diffusion adds 24 B
// (1 dispatch), regolith 48 B, 8 pipes make it 388 B.
#include "gpu/erosion/pipes.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/mutant.hpp"

namespace gt::gpu {
namespace {

constexpr const char* algorithm_name = "erosion.pipe";
constexpr int local_size = 16;          // local_size_x/y of the 2-D passes
constexpr int source_local_size = 64;   // local_size_x of pipes_sources.comp
constexpr unsigned valid_flag = 256u;   // bit 8 of CellConstants::flags (bits 0-7: exterior pipes)

// Bindings of gpu/shaders/erosion/pipes_block.glsl and pipes_sources.comp.
enum Binding : GLuint {
  block_binding = 0,
  cells_binding = 1,
  delta_binding = 2,
  delta_next_binding = 3,
  water_binding = 4,
  outflow_binding = 5,
  velocity_binding = 6,
  sediment_binding = 7,
  staying_binding = 8,
  sent_binding = 9,
  source_cells_binding = 10,
  source_depths_binding = 11,
  regolith_binding = 12,
  regolith_staying_binding = 13,
  regolith_sent_binding = 14,
  thermal_outflows_binding = 15,
  corrected_binding = 16,
  regolith_corrected_binding = 17,
  layers_binding = 18,
};

// Mirror of `PipeBlock` in gpu/shaders/erosion/pipes_block.glsl (std140).
struct PipeBlock {
  float flux_gain[8];
  float slope_span_x[2];
  float slope_span_y[2];
  std::int32_t grid_size[2];
  float area_per_time;
  float volume_to_depth;
  float depth_floor;
  float length_x;
  float length_y;
  float capacity_constant;
  float depth_ramp;
  float dissolving;
  float deposition;
  float min_tilt_sine;
  float backtrace_x;
  float backtrace_y;
  float reach;
  float evaporation_kept;
  std::uint32_t boundary_open;
  std::uint32_t source_cell_count;
  float regolith_depth;
  float regolith_dissolving;
  float regolith_deposition;
  float diffusion_weight;
  float diagonal_share[2];
  float talus_limit_cardinal[4];
  float talus_limit_diagonal[4];
  float thermal_rate;
  std::uint32_t padding[3];
  float layer_capacity[4];
};

// Mirror of `CellConstants` (std430).
struct CellConstants {
  float base;
  float rain;
  std::uint32_t flags;
  std::uint32_t unused;
};

// A program of pipes_block.glsl, its PipeBlock and its Cells records checked against the mirrors.
ComputeProgram pipe_program(const char* shader, const std::vector<std::string>& defines = {}) {
  ComputeProgram program = ComputeProgram::load(shader, defines);
  program.check_block("PipeBlock", sizeof(PipeBlock),
                      {{"flux_gain", offsetof(PipeBlock, flux_gain)},
                       {"slope_span_x", offsetof(PipeBlock, slope_span_x)},
                       {"slope_span_y", offsetof(PipeBlock, slope_span_y)},
                       {"grid_size", offsetof(PipeBlock, grid_size)},
                       {"area_per_time", offsetof(PipeBlock, area_per_time)},
                       {"volume_to_depth", offsetof(PipeBlock, volume_to_depth)},
                       {"depth_floor", offsetof(PipeBlock, depth_floor)},
                       {"length_x", offsetof(PipeBlock, length_x)},
                       {"length_y", offsetof(PipeBlock, length_y)},
                       {"capacity_constant", offsetof(PipeBlock, capacity_constant)},
                       {"depth_ramp", offsetof(PipeBlock, depth_ramp)},
                       {"dissolving", offsetof(PipeBlock, dissolving)},
                       {"deposition", offsetof(PipeBlock, deposition)},
                       {"min_tilt_sine", offsetof(PipeBlock, min_tilt_sine)},
                       {"backtrace_x", offsetof(PipeBlock, backtrace_x)},
                       {"backtrace_y", offsetof(PipeBlock, backtrace_y)},
                       {"reach", offsetof(PipeBlock, reach)},
                       {"evaporation_kept", offsetof(PipeBlock, evaporation_kept)},
                       {"boundary_open", offsetof(PipeBlock, boundary_open)},
                       {"source_cell_count", offsetof(PipeBlock, source_cell_count)},
                       {"regolith_depth", offsetof(PipeBlock, regolith_depth)},
                       {"regolith_dissolving", offsetof(PipeBlock, regolith_dissolving)},
                       {"regolith_deposition", offsetof(PipeBlock, regolith_deposition)},
                       {"diffusion_weight", offsetof(PipeBlock, diffusion_weight)},
                       {"diagonal_share", offsetof(PipeBlock, diagonal_share)},
                       {"talus_limit_cardinal", offsetof(PipeBlock, talus_limit_cardinal)},
                       {"talus_limit_diagonal", offsetof(PipeBlock, talus_limit_diagonal)},
                       {"thermal_rate", offsetof(PipeBlock, thermal_rate)},
                       {"layer_capacity", offsetof(PipeBlock, layer_capacity)}});
  program.check_block("Cells", sizeof(CellConstants),
                      {{"cells[0].base", offsetof(CellConstants, base)},
                       {"cells[0].rain", offsetof(CellConstants, rain)},
                       {"cells[0].flags", offsetof(CellConstants, flags)},
                       {"cells[0].unused", offsetof(CellConstants, unused)}});
  return program;
}

[[noreturn]] void refuse(const std::string& what) { throw InputError(fmt::format("{}: {}", algorithm_name, what)); }

// Δt·(r + r_map) per cell in float, as ref<float> computes it; 0 on no-data cells.
std::vector<float> rain_depths(const Grid<double>& terrain, const PipeConstants& constants,
                               const Grid<double>& rain_map) {
  const float time_step = static_cast<float>(constants.time_step);
  const float uniform = static_cast<float>(constants.rain_rate);
  std::vector<float> depths(terrain.size(), 0.0f);
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) continue;
    const float mapped = rain_map.values.empty() ? 0.0f : static_cast<float>(rain_map.values[cell]);
    depths[cell] = time_step * (uniform + mapped);
  }
  return depths;
}

// Cell and depth rate·Δt/(l_x·l_y) (rounded once to float) of each source, in the order given.
std::vector<std::pair<std::size_t, float>> source_depths(const Grid<double>& terrain, const PipeConstants& constants,
                                                         const std::vector<PointSource>& sources) {
  std::vector<std::pair<std::size_t, float>> depths;
  for (const auto& source : sources) {
    // Mutant erosion.pipe.source_over_length: the volume divided by l_x, not l_x·l_y.
    const double area = mutant_active("erosion.pipe.source_over_length") ? constants.length_x : constants.cell_area;
    const double depth = source.rate * constants.time_step / area;
    depths.emplace_back(terrain.index(source.x, source.y), static_cast<float>(depth));
  }
  return depths;
}

std::vector<std::uint32_t> cell_flags(const Grid<double>& terrain) {
  std::vector<std::uint32_t> flags(terrain.size(), 0);
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      auto& cell = flags[terrain.index(x, y)];
      if (terrain.is_valid(x, y)) cell |= valid_flag;
      for (int k = 0; k < 8; ++k) {
        const int nx = x + pipe_offsets[k].dx;
        const int ny = y + pipe_offsets[k].dy;
        if (!terrain.inside(nx, ny) || !terrain.is_valid(nx, ny)) cell |= 1u << k;
      }
    }
  }
  return flags;
}

// Every constant rounded once from double, as ref<float> rounds it.
PipeBlock block_for(const PipeConstants& constants, int width, int height, std::size_t source_cells) {
  PipeBlock block{};
  const double gain = constants.time_step * constants.pipe_area * constants.gravity;
  block.flux_gain[0] = block.flux_gain[1] = static_cast<float>(gain / constants.length_x);
  block.flux_gain[2] = block.flux_gain[3] = static_cast<float>(gain / constants.length_y);
  for (int k = 4; k < 8; ++k) block.flux_gain[k] = static_cast<float>(gain / constants.length_diagonal);
  const auto differences = constants.tilt_differences;
  for (int sides = 1; sides <= 2; ++sides) {
    block.slope_span_x[sides - 1] = static_cast<float>(tilt_span(differences, sides, constants.length_x));
    block.slope_span_y[sides - 1] = static_cast<float>(tilt_span(differences, sides, constants.length_y));
  }
  block.grid_size[0] = width;
  block.grid_size[1] = height;
  block.area_per_time = static_cast<float>(constants.cell_area / constants.time_step);
  block.volume_to_depth = static_cast<float>(constants.time_step / constants.cell_area);
  block.depth_floor = static_cast<float>(constants.velocity_depth_floor);
  block.length_x = static_cast<float>(constants.length_x);
  block.length_y = static_cast<float>(constants.length_y);
  block.capacity_constant = static_cast<float>(constants.capacity);
  block.depth_ramp = static_cast<float>(constants.depth_ramp);
  block.dissolving = static_cast<float>(constants.dissolving_fraction);
  block.deposition = static_cast<float>(constants.deposition_fraction);
  block.min_tilt_sine = static_cast<float>(constants.min_tilt_sine);
  block.backtrace_x = static_cast<float>(constants.time_step / constants.length_x);
  block.backtrace_y = static_cast<float>(constants.time_step / constants.length_y);
  block.reach = static_cast<float>(width + height);
  block.evaporation_kept = static_cast<float>(constants.evaporation_kept);
  block.boundary_open = constants.boundary == PipeBoundary::open ? 1u : 0u;
  block.source_cell_count = static_cast<std::uint32_t>(source_cells);
  block.regolith_depth = static_cast<float>(constants.regolith_depth);
  block.regolith_dissolving = static_cast<float>(constants.regolith_dissolving_fraction);
  block.regolith_deposition = static_cast<float>(constants.regolith_deposition_fraction);
  block.diffusion_weight = static_cast<float>(constants.sediment_diffusion);
  block.diagonal_share[0] = static_cast<float>(constants.length_x / constants.length_diagonal);
  block.diagonal_share[1] = static_cast<float>(constants.length_y / constants.length_diagonal);
  // T·l per pipe, rounded once from double as reference/erosion/thermal_jako.cpp does.
  const auto& thermal = constants.thermal;
  const float limit_x = static_cast<float>(thermal.talus_slope * thermal.length_x);
  const float limit_y = static_cast<float>(thermal.talus_slope * thermal.length_y);
  for (int k = 0; k < 4; ++k) {
    block.talus_limit_cardinal[k] = k % 2 == 0 ? limit_x : limit_y;
    block.talus_limit_diagonal[k] = static_cast<float>(thermal.talus_slope * thermal.length_diagonal);
  }
  block.thermal_rate = static_cast<float>(thermal.request_factor);
  for (int k = 0; k < constants.layer_count; ++k) block.layer_capacity[k] = static_cast<float>(constants.layer_capacity[k]);
  return block;
}

bool has_regolith(const PipeConstants& constants) { return constants.regolith_depth > 0.0; }
bool has_diffusion(const PipeConstants& constants) { return constants.sediment_diffusion > 0.0; }
bool diffuses_regolith(const PipeConstants& constants) {
  return has_regolith(constants) && has_diffusion(constants) && constants.regolith_diffusion;
}

// The define of the pipe count alone (the outflow pass needs no other), and those of every variant.
std::vector<std::string> pipe_defines(const PipeConstants& constants) {
  return constants.pipe_count == 8 ? std::vector<std::string>{"PIPES_8"} : std::vector<std::string>{};
}

std::vector<std::string> stage_defines(const PipeConstants& constants) {
  std::vector<std::string> defines = pipe_defines(constants);
  if (constants.transport == SedimentTransport::flux) defines.push_back("TRANSPORT_FLUX");
  if (has_regolith(constants)) defines.push_back("REGOLITH");
  if (diffuses_regolith(constants)) defines.push_back("REGOLITH_DIFFUSION");
  if (constants.diffusion_weighting == DiffusionWeighting::water) defines.push_back("DIFFUSION_WATER");
  defines.push_back(fmt::format("LAYERS={}", constants.layer_count));
  if (constants.layer_erosion == LayerErosion::as_printed) defines.push_back("LAYERS_AS_PRINTED");
  return defines;
}

template <class T>
StorageBuffer buffer_of(const std::vector<T>& values) {
  return values.empty() ? StorageBuffer(16) : StorageBuffer::from(values);
}

std::vector<float> floats_of(const Grid<double>& field, const Grid<double>& terrain) {
  std::vector<float> values(field.size(), 0.0f);
  for (std::size_t cell = 0; cell < field.size(); ++cell) {
    if (terrain.is_valid(cell)) values[cell] = static_cast<float>(field.values[cell]);
  }
  return values;
}

// The CFL number of the reference: max over valid cells and axes of Δt·|u|/l_x and Δt·|v|/l_y,
// in double.
double max_cfl_of(const std::vector<float>& velocity, const std::vector<std::uint32_t>& flags,
                  const PipeConstants& constants) {
  double largest = 0.0;
  for (std::size_t cell = 0; cell < flags.size(); ++cell) {
    if ((flags[cell] & valid_flag) == 0) continue;
    const double cells_x = constants.time_step * std::abs(static_cast<double>(velocity[2 * cell])) / constants.length_x;
    const double cells_y =
        constants.time_step * std::abs(static_cast<double>(velocity[2 * cell + 1])) / constants.length_y;
    largest = std::max({largest, cells_x, cells_y});
  }
  return largest;
}

// The reference's refusals, on the state as given and as the float the GPU stores.
const PipeState<double>& checked(const PipeState<double>& state, const HydraulicForcing& forcing,
                                 const PipeConstants& constants) {
  check_pipe_input(state, forcing, constants);
  try {
    check_pipe_input(cast_pipe_state<float>(state), forcing, constants);
  } catch (const InputError& error) {
    throw InputError(fmt::format("{} (rounded to the float the GPU stores)", error.what()));
  }
  return state;
}

}  // namespace

// The fields a step leaves on the GPU, downloaded.
struct PipeErosion::Download {
  std::vector<float> delta;          // Δb
  std::vector<float> water;          // d, d_A, d_B, unused per cell
  std::vector<float> outflow;        // f per pipe, 4 per cell (+ 4 diagonals with 8 pipes)
  std::vector<float> velocity;       // u, v per cell
  std::vector<float> sediment;       // s
  std::vector<float> regolith;       // r
  std::vector<float> sent;           // flux form: sent per pipe (as outflow); semi-Lagrangian: [0] = left the grid
  std::vector<float> regolith_sent;  // the same for r (empty without the regolith stage)
  std::vector<float> layers;         // Šťava's b_1..b_N per cell (empty without layers)
};

PipeErosion::PipeErosion(const PipeState<double>& initial, const PipeConstants& constants,
                         const HydraulicForcing& forcing, bool keep_ledger)
    : width_(checked(initial, forcing, constants).terrain.width),
      height_(initial.terrain.height),
      constants_(constants),
      forcing_(forcing),
      keep_ledger_(keep_ledger),
      rain_depth_(rain_depths(initial.terrain, constants, forcing.rain_map)),
      source_depths_(source_depths(initial.terrain, constants, forcing.sources)),
      water_program_(pipe_program("erosion/pipes_water.comp")),
      outflow_program_(pipe_program("erosion/pipes_outflow.comp", pipe_defines(constants))),
      flow_program_(pipe_program("erosion/pipes_flow.comp", stage_defines(constants))),
      sediment_program_(pipe_program("erosion/pipes_sediment.comp", stage_defines(constants))),
      block_(sizeof(PipeBlock)),
      cells_(16),
      delta_(16),
      delta_next_(16),
      water_(16),
      outflow_(16),
      velocity_(16),
      sediment_(16),
      staying_(16),
      sent_(16),
      regolith_(16),
      regolith_staying_(16),
      regolith_sent_(16),
      thermal_outflows_(16),
      corrected_(16),
      regolith_corrected_(16),
      source_cells_(16),
      source_list_(16),
      layers_(16) {
  const auto& terrain = initial.terrain;
  flags_ = cell_flags(terrain);
  layout_ = terrain;
  layout_.values.clear();
  if (has_diffusion(constants_)) {
    diffusion_program_.emplace(pipe_program("erosion/pipes_diffusion.comp", stage_defines(constants_)));
  }
  if (constants_.transport == SedimentTransport::maccormack) {
    maccormack_program_.emplace(pipe_program("erosion/pipes_maccormack.comp", stage_defines(constants_)));
  }
  if (constants_.thermal_step) {
    thermal_outflow_program_.emplace(pipe_program("erosion/pipes_thermal_outflow.comp"));
    thermal_gather_program_.emplace(pipe_program("erosion/pipes_thermal_gather.comp"));
  }

  // Sources grouped by cell, each cell's in the order given: {cell, first, count, 0}.
  std::map<std::size_t, std::vector<float>> by_cell;
  for (const auto& [cell, depth] : source_depths_) by_cell[cell].push_back(depth);
  std::vector<std::uint32_t> source_cells;
  std::vector<float> grouped_depths;
  for (const auto& [cell, depths] : by_cell) {
    source_cells.insert(source_cells.end(), {static_cast<std::uint32_t>(cell),
                                             static_cast<std::uint32_t>(grouped_depths.size()),
                                             static_cast<std::uint32_t>(depths.size()), 0u});
    grouped_depths.insert(grouped_depths.end(), depths.begin(), depths.end());
  }
  source_cell_count_ = by_cell.size();
  if (source_cell_count_ > 0) sources_program_.emplace(pipe_program("erosion/pipes_sources.comp"));
  block_.upload(block_for(constants_, width_, height_, source_cell_count_));
  source_cells_ = buffer_of(source_cells);
  source_list_ = buffer_of(grouped_depths);
  upload(initial);
}

void PipeErosion::upload(const PipeState<double>& state) {
  checked(state, forcing_, constants_);
  const auto& terrain = state.terrain;
  if (terrain.width != layout_.width || terrain.height != layout_.height || terrain.valid != layout_.valid ||
      terrain.cell_size_x != layout_.cell_size_x || terrain.cell_size_y != layout_.cell_size_y) {
    refuse("a state uploaded into a running twin must have the grid and mask it was constructed with");
  }
  const std::size_t cells = terrain.size();
  base_.assign(cells, 0.0f);
  std::vector<CellConstants> constants_per_cell(cells);
  CompensatedSum base_volume;
  for (std::size_t cell = 0; cell < cells; ++cell) {
    base_[cell] = static_cast<float>(terrain.values[cell]);
    constants_per_cell[cell] = {base_[cell], rain_depth_[cell], flags_[cell], 0u};
    if (terrain.is_valid(cell)) base_volume.add(static_cast<double>(base_[cell]) * constants_.cell_area);
  }
  base_volume_ = base_volume.value();

  const std::size_t per_cell = pipe_values_per_cell();
  std::vector<float> water(4 * cells, 0.0f), outflow(per_cell * cells, 0.0f), velocity(2 * cells, 0.0f);
  water_before_.assign(cells, 0.0f);
  for (std::size_t cell = 0; cell < cells; ++cell) {
    if (!terrain.is_valid(cell)) continue;
    water[4 * cell] = static_cast<float>(state.water.values[cell]);
    water_before_[cell] = water[4 * cell];
    for (int k = 0; k < constants_.pipe_count; ++k) {
      outflow[per_cell * cell + k] = static_cast<float>(state.outflow[cell][k]);
    }
    velocity[2 * cell] = static_cast<float>(state.velocity_x.values[cell]);
    velocity[2 * cell + 1] = static_cast<float>(state.velocity_y.values[cell]);
  }
  const std::vector<float> zeros(cells, 0.0f), zero_vectors(per_cell * cells, 0.0f);
  cells_ = StorageBuffer::from(constants_per_cell);
  delta_ = StorageBuffer::from(zeros);
  delta_next_ = StorageBuffer::from(zeros);
  water_ = StorageBuffer::from(water);
  outflow_ = StorageBuffer::from(outflow);
  velocity_ = StorageBuffer::from(velocity);
  sediment_ = StorageBuffer::from(floats_of(state.sediment, terrain));
  staying_ = StorageBuffer::from(zeros);
  sent_ = StorageBuffer::from(zero_vectors);
  regolith_ = StorageBuffer::from(floats_of(state.regolith, terrain));
  if (has_regolith(constants_)) {
    regolith_staying_ = StorageBuffer::from(zeros);
    regolith_sent_ = StorageBuffer::from(zero_vectors);
  }
  if (constants_.thermal_step) thermal_outflows_ = StorageBuffer::from(std::vector<float>(8 * cells, 0.0f));
  const std::size_t layer_count = layer_values_per_cell();
  if (layer_count > 0) {
    std::vector<float> thicknesses(layer_count * cells, 0.0f);
    for (std::size_t cell = 0; cell < cells; ++cell) {
      if (!terrain.is_valid(cell)) continue;
      for (std::size_t k = 0; k < layer_count; ++k) {
        thicknesses[layer_count * cell + k] = static_cast<float>(state.layers[k].values[cell]);
      }
    }
    layers_ = StorageBuffer::from(thicknesses);
  }
  if (maccormack_program_) {
    corrected_ = StorageBuffer::from(zeros);
    if (has_regolith(constants_)) regolith_corrected_ = StorageBuffer::from(zeros);
  }
  flows_ = PipeFlows{};
  steps_done_ = 0;
  ledger_.clear();
  record_ledger(download());
}

std::size_t PipeErosion::pipe_values_per_cell() const { return static_cast<std::size_t>(constants_.pipe_count); }
std::size_t PipeErosion::layer_values_per_cell() const { return static_cast<std::size_t>(constants_.layer_count); }

int PipeErosion::passes_per_step() const {
  return 4 + (sources_program_ ? 1 : 0) + (maccormack_program_ ? 1 : 0) + (diffusion_program_ ? 1 : 0) +
         (thermal_outflow_program_ ? 2 : 0);
}

void PipeErosion::bind() const {
  block_.bind(block_binding);
  cells_.bind(cells_binding);
  delta_.bind(delta_binding);
  delta_next_.bind(delta_next_binding);
  water_.bind(water_binding);
  outflow_.bind(outflow_binding);
  velocity_.bind(velocity_binding);
  sediment_.bind(sediment_binding);
  staying_.bind(staying_binding);
  sent_.bind(sent_binding);
  source_cells_.bind(source_cells_binding);
  source_list_.bind(source_depths_binding);
  regolith_.bind(regolith_binding);
  regolith_staying_.bind(regolith_staying_binding);
  regolith_sent_.bind(regolith_sent_binding);
  thermal_outflows_.bind(thermal_outflows_binding);
  corrected_.bind(corrected_binding);
  regolith_corrected_.bind(regolith_corrected_binding);
  layers_.bind(layers_binding);
}

void PipeErosion::step() {
  auto pass = [this](const ComputeProgram& program) {
    program.dispatch(width_, height_, local_size, local_size);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  };
  bind();
  pass(water_program_);
  if (sources_program_) {
    sources_program_->dispatch(static_cast<int>(source_cell_count_), 1, source_local_size, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  pass(outflow_program_);
  pass(flow_program_);
  std::swap(delta_, delta_next_);
  pass(sediment_program_);
  if (maccormack_program_) {
    pass(*maccormack_program_);
    std::swap(sediment_, corrected_);
    if (has_regolith(constants_)) std::swap(regolith_, regolith_corrected_);
    bind();
  }
  if (diffusion_program_) {
    pass(*diffusion_program_);
    std::swap(sediment_, staying_);
    if (diffuses_regolith(constants_)) std::swap(regolith_, regolith_staying_);
  }
  if (thermal_outflow_program_) {
    delta_.bind(delta_binding);
    delta_next_.bind(delta_next_binding);
    pass(*thermal_outflow_program_);
    pass(*thermal_gather_program_);
    std::swap(delta_, delta_next_);
  }
  ++steps_done_;
  if (keep_ledger_) record_step();
}

void PipeErosion::run(int steps) {
  for (int i = 0; i < steps; ++i) step();
}

PipeErosion::Download PipeErosion::download() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::size_t cells = base_.size();
  const std::size_t per_cell = pipe_values_per_cell();
  Download fields{delta_.download<float>(cells),             water_.download<float>(4 * cells),
                  outflow_.download<float>(per_cell * cells), velocity_.download<float>(2 * cells),
                  sediment_.download<float>(cells),          regolith_.download<float>(cells),
                  sent_.download<float>(per_cell * cells),    {}};
  if (has_regolith(constants_)) fields.regolith_sent = regolith_sent_.download<float>(per_cell * cells);
  const std::size_t layer_count = layer_values_per_cell();
  if (layer_count > 0) fields.layers = layers_.download<float>(layer_count * cells);
  return fields;
}

PipeState<double> PipeErosion::state() const {
  const auto fields = download();
  auto field_of = [this](auto value) {
    Grid<double> grid = layout_;
    grid.values.resize(base_.size());
    for (std::size_t cell = 0; cell < base_.size(); ++cell) grid.values[cell] = value(cell);
    return grid;
  };
  auto from = [&](const std::vector<float>& values, std::size_t stride, std::size_t offset) {
    return field_of([&](std::size_t cell) { return static_cast<double>(values[stride * cell + offset]); });
  };
  PipeState<double> state;
  state.terrain = field_of([&](std::size_t cell) {
    return static_cast<double>(base_[cell]) + static_cast<double>(fields.delta[cell]);
  });
  state.water = from(fields.water, 4, 0);
  state.sediment = from(fields.sediment, 1, 0);
  state.velocity_x = from(fields.velocity, 2, 0);
  state.velocity_y = from(fields.velocity, 2, 1);
  state.regolith = from(fields.regolith, 1, 0);
  const std::size_t layer_count = layer_values_per_cell();
  for (std::size_t k = 0; k < layer_count; ++k) state.layers.push_back(from(fields.layers, layer_count, k));
  const std::size_t per_cell = pipe_values_per_cell();
  state.outflow.resize(base_.size());
  for (std::size_t cell = 0; cell < base_.size(); ++cell) {
    for (int k = 0; k < constants_.pipe_count; ++k) {
      state.outflow[cell][k] = static_cast<double>(fields.outflow[per_cell * cell + k]);
    }
  }
  return state;
}

// The flows of one step, accumulated in the reference's order: rain (row-major), sources (as
// given), water through exterior pipes, sediment and regolith leaving, evaporation.
void PipeErosion::record_step() {
  const auto fields = download();
  const double area = constants_.cell_area;
  // The float l_x·l_y/Δt the shaders divide fluxes by (pipes_flow.comp, stage 3).
  const double area_per_time = static_cast<float>(constants_.cell_area / constants_.time_step);
  const std::size_t cells = base_.size();
  const std::size_t per_cell = pipe_values_per_cell();
  const int pipes = constants_.pipe_count;
  auto exterior = [this](std::size_t cell, int k) { return ((flags_[cell] >> k) & 1u) != 0; };
  auto valid = [this](std::size_t cell) { return (flags_[cell] & valid_flag) != 0; };
  for (std::size_t cell = 0; cell < cells; ++cell) {
    if (valid(cell)) flows_.rain_in.add(static_cast<double>(rain_depth_[cell]) * area);
  }
  for (const auto& source : source_depths_) flows_.source_in.add(static_cast<double>(source.second) * area);
  // What the additions added, d_A − d, in the reference's order (d: the last step's final depth).
  for (std::size_t cell = 0; cell < cells; ++cell) {
    if (!valid(cell)) continue;
    const double added = static_cast<double>(fields.water[4 * cell + 1]) - static_cast<double>(water_before_[cell]);
    flows_.water_added.add(added * area);
  }
  for (std::size_t cell = 0; cell < cells; ++cell) {
    if (!valid(cell)) continue;
    for (int k = 0; k < pipes; ++k) {
      if (exterior(cell, k)) {
        const double depth = static_cast<double>(fields.outflow[per_cell * cell + k]) / area_per_time;
        flows_.boundary_out_water.add(depth * area);
      }
    }
  }
  // Flux form: what was sent down exterior pipes; semi-Lagrangian: the shader's s_A − staying.
  const bool flux = constants_.transport == SedimentTransport::flux;
  auto add_leaving = [&](const std::vector<float>& sent, CompensatedSum& boundary_out) {
    for (std::size_t cell = 0; cell < cells; ++cell) {
      if (!valid(cell)) continue;
      for (int k = 0; k < (flux ? pipes : 1); ++k) {
        if (!flux || exterior(cell, k)) boundary_out.add(static_cast<double>(sent[per_cell * cell + k]) * area);
      }
    }
  };
  add_leaving(fields.sent, flows_.boundary_out_sediment);
  if (has_regolith(constants_)) add_leaving(fields.regolith_sent, flows_.boundary_out_regolith);
  for (std::size_t cell = 0; cell < cells; ++cell) {
    if (!valid(cell)) continue;
    const float before = fields.water[4 * cell + 2];
    const float after = fields.water[4 * cell];
    flows_.evaporated.add(static_cast<double>(before - after) * area);
  }
  check_state(fields);
  record_ledger(fields);
  for (std::size_t cell = 0; cell < cells; ++cell) water_before_[cell] = fields.water[4 * cell];
}

void PipeErosion::check_state(const Download& fields) const {
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const std::size_t cell = layout_.index(x, y);
      if ((flags_[cell] & valid_flag) == 0) continue;
      struct Checked {
        const char* name;
        double value;
        bool non_negative;
      };
      const auto report = [&](const std::string& name, double value) {
        refuse(fmt::format("step {}, cell (x={}, y={}): {} is {} (Δt = {} s, largest CFL number this step {:.3g}); "
                           "the time step is too large or the input out of range",
                           steps_done_, x, y, name, value, constants_.time_step,
                           max_cfl_of(fields.velocity, flags_, constants_)));
      };
      auto acceptable = [](double value, bool non_negative) {
        return std::isfinite(value) && !(non_negative && value < 0.0);
      };
      const Checked values[] = {
          {"terrain height", static_cast<double>(base_[cell]) + static_cast<double>(fields.delta[cell]), false},
          {"water depth", fields.water[4 * cell], true},
          {"sediment", fields.sediment[cell], true},
          {"regolith", fields.regolith[cell], true},
          {"x velocity", fields.velocity[2 * cell], false},
          {"y velocity", fields.velocity[2 * cell + 1], false}};
      for (const auto& [name, value, non_negative] : values) {
        if (!acceptable(value, non_negative)) report(name, value);
      }
      for (int k = 0; k < constants_.pipe_count; ++k) {
        const double flux = fields.outflow[pipe_values_per_cell() * cell + k];
        if (!acceptable(flux, true)) report(fmt::format("outflow {}", pipe_name(k)), flux);
      }
      const std::size_t layer_count = layer_values_per_cell();
      for (std::size_t k = 0; k < layer_count; ++k) {
        const double thickness = fields.layers[layer_count * cell + k];
        if (!acceptable(thickness, true)) report(fmt::format("layer_{}", k + 1), thickness);
      }
    }
  }
}

void PipeErosion::record_ledger(const Download& fields) {
  const double area = constants_.cell_area;
  CompensatedSum water, delta, sediment, regolith;
  for (std::size_t cell = 0; cell < base_.size(); ++cell) {
    if ((flags_[cell] & valid_flag) == 0) continue;
    water.add(static_cast<double>(fields.water[4 * cell]) * area);
    delta.add(static_cast<double>(fields.delta[cell]) * area);
    sediment.add(static_cast<double>(fields.sediment[cell]) * area);
    regolith.add(static_cast<double>(fields.regolith[cell]) * area);
  }
  PipeLedgerEntry entry;
  entry.step = steps_done_;
  entry.water = water.value();
  entry.terrain = base_volume_ + delta.value();
  entry.sediment = sediment.value();
  entry.regolith = regolith.value();
  flows_.write_to(entry);
  entry.max_cfl = steps_done_ == 0 ? 0.0 : max_cfl_of(fields.velocity, flags_, constants_);
  ledger_.push_back(entry);
}

}  // namespace gt::gpu
