// Hydraulic erosion with virtual pipes: Mei, Decaudin, Hu 2007 (digest 000 §3.4, eqs. 2.10-2.25,
// with the fixes of Appendix B items 1-3). Each stage reads the previous stage's fields over the
// whole grid (synchronous, as the GPU passes). Pipes k = 0..3 are L, R, T, B (Mei); with `pipes` = 8
// also the diagonals k = 4..7, TL, BR, TR, BL (gt::pipe_offsets), of length l_d = sqrt(l_x² + l_y²);
// l_k below is l_x, l_y or l_d, and every sum over pipes (Σ) runs over all the pipes in use:
//   1 water    d_A = d + Δt·(r + r_map) + Σ sources·Δt/(l_x·l_y)                 (2.10, with Δt)
//   2 flux     f̂_k = max(0, f_k + Δt·A·g·Δh_k/l_k), Δh_k = (b + d_A) − (b_k + d_A,k)   (2.11, d_A)
//              K = min(1, d_A·l_x·l_y / (Σ f̂·Δt)), f_k = K·f̂_k                 (2.12-2.13)
//   3 depth    d_B = max(0, d_A − Δt·Σf_out/(l_x·l_y)) + Δt·Σf_in/(l_x·l_y)     (2.14-2.17)
//   4 velocity ΔW_X = ½((f^R(x−1) − f^L) + (f^R − f^L(x+1))), u = ΔW_X/(l_y·d̄),
//              d̄ = max(½(d_A + d_B), depth floor); v likewise with T/B and l_x    (2.18-2.19)
//              With 8 pipes ΔW_X = ½ Σ_k dx_k·(l_x/l_k)·(f_k − f_in,k), f_in,k = what neighbour k
//              sends this cell: the axis terms as above plus (l_x/l_d)·Σ_diagonals dx_k·(f_k −
//              f_in,k), the x component of the diagonal pipes' net flux; ΔW_Y with dy_k and l_y/l_d
//   5 erosion  C = K_c·max(sin α, min_tilt_sine)·|v|·l(d_B), l(d) = min(1, d/K_w) (2.20-2.21)
//              C > s: b −= k_s·(C − s), s += k_s·(C − s);  else b += k_d·(s − C), s −= k_d·(s − C)
//              with k = min(1, K·Δt)                                  (2.22, 2.23 with Mei's sign)
//   5' layers  (Šťava et al. 2008, digest 000 §3.5, eqs. 2.27-2.29 and Algorithm 1; only with N =
//              `layers` ≥ 1) layers b_1..b_N on the bedrock, N on top; the tilt, the speed and the ramp
//              of stage 5 give T_k = C_k·max(sin α, T_α)·|v|·l(d_B) for each layer (2.28; C_0 = K_c,
//              the bedrock). Erosion walks the column from the top (Algorithm 1), every comparison
//              with the step's s and the layers' thicknesses at the step's start:
//                above = 0; for k = N .. 0: T̂_k = T_k − above (2.29); stop unless T̂_k > s;
//                  take k_s·(T̂_k − s), at most b_k (the bedrock, k = 0, without limit); stop unless
//                  that took all of b_k (the water did not get through); above += b_k
//              as_printed: the condition T̂_k < s and the amount k_s·(s − T̂_k), the rest alike.
//              Deposition: s > T_N puts k_d·(s − T_N) on the top layer N (2.23; "only into the top
//              layer"). b −= taken − deposited, s += the same. With N = 0 this is stage 5 exactly.
//   5b regolith (seed 001 §3.9, eqs. 2.3-2.7; only when K_r > 0): r_max = min(d_B, K_r);
//              r < r_max: b −= k_re·(r_max − r), r += the same;  r > r_max: b += k_rd·(r − r_max),
//              r −= the same
//   6 sediment semi-Lagrangian: s(x) = s_A(x − (u, v)·Δt), bilinear                 (2.24-2.25)
//              or flux form: each pipe carries s_A·f_k·Δt/(d_A·l_x·l_y), the share of the cell's
//              water it moved (diagonal pipes too); what one cell sends, the neighbour receives as
//              the same number.
//              or MacCormack (Selle et al. 2008): φ̂ the semi-Lagrangian result, φ̌ = φ̂ traced
//              forward, x + (u, v)·Δt, with the same bilinear rule; s = φ̂ + ½(s_A − φ̌), clamped to
//              the least and largest s_A of the cell and its 8 neighbours (the limiter: without it
//              the correction overshoots, below 0 too, which the step check refuses). Decision:
//              Selle clamps to the four corners the backtrace read; which four switches where the
//              displacement crosses a whole cell, so an ulp of velocity there moved the result by the
//              corners' spread and two honest twins disagreed. The 3×3 range holds those corners
//              (the K scaling keeps the displacement within a cell), does not depend on the
//              velocity, and keeps the scheme's result a continuous function of it.
//              The regolith moves with the water the same way (seed 001 §3.9).
//   6b diffusion (seed 001 §3.8; only when w > 0), of s and r from the state after 6 (r only with
//              regolith_diffusion, the thesis; seed 001's code diffuses s alone): each cell
//              sends σ_k·s to each of its 4 axis neighbours k whose pipe is not exterior (with 8
//              pipes too: the seed's 4-neighbour stencil) and keeps s − Σσ_k·s;
//              uniform σ_k = w (the thesis), water σ_k = ½d_k / (d + ½Σd_n) with depths d_B (its
//              code; nothing moves when that sum is 0); what is kept is clamped at 0 (a dry cell
//              sends all of it, and rounding can make the shares' sum exceed it by an ulp)
//   7 evaporation d = d_B·(1 − K_e·Δt)
//   8 thermal (Jákó & Tóth's combined step; only when thermal_step): one iteration of
//              reference/erosion/thermal_jako.hpp on b
// Decisions where the source is vague:
//   - Šťava's layers. The digest's note reads Algorithm 1's printed T̂_k < s as inverted against its
//     prose; the default is the prose (erode while capacity is left), the printed one a variant.
//     Neither the thesis nor the paper gives Erode()'s amount: here the same k_s·gap as Mei's, limited
//     to the layer. T̂_k is compared with the s of the step's start, so with k_s = 1 the water that
//     took all of b_N and part of b_(N−1) holds T_(N−1) exactly: the capacity of the layer it erodes.
//     The walk stops at a layer it did not empty; an empty layer (b_k = 0) passes the water on.
//     Deposition and erosion are separate rules, each from its own condition (the thesis lists them
//     apart): with the prose's condition they never meet (s > T_N stops the walk at the top); as
//     printed both act where s > T_N. The bedrock has no thickness: the terrain b minus Σ b_k is its
//     surface. Regolith and the thermal step are refused with layers (core/params/hydraulic.cpp).
//   - Exterior pipes: a pipe leading off the grid or into a no-data cell (a diagonal pipe too: its
//     diagonal neighbour is off the grid or no data, whatever the axis neighbours are). Closed
//     boundary: its flux is 0 (walls). Open boundary: the exterior is a dry cell at the cell's own
//     terrain height (Δh = d_A), so water drains under its own depth and nothing flows back in;
//     water leaving that way, and the sediment the flux form carries with it, is counted as
//     boundary_out. The semi-Lagrangian mode removes the same sediment share at exterior pipes
//     before backtracing (the axis pipes' shares added in the order L, R, T, B, then the diagonals'
//     (TL + BR) + (TR + BL)).
//     No-data cells hold no water or sediment and get no rain; sources on them are refused.
//   - 8 pipes: every pipe has the cross-section A, so a diagonal conducts l_x/l_d as much per metre
//     of head as an x pipe; the tilt sin α stays the central differences along x and y; diffusion
//     stays on 4 neighbours. With 4 pipes the diagonal fluxes of the state are 0 (a state with
//     others is refused) and every operation is the one of the 4-pipe model, bit for bit: the
//     diagonal terms are added only with 8 pipes.
//   - K's 0/0 (Σ f̂ = 0): K = 1, tested explicitly (the fluxes are 0 anyway).
//   - A cell the K scaling drained (K < 1) keeps exactly 0, its value in exact arithmetic. Elsewhere
//     the remainder d_A − Δt·Σf_out/(l_x·l_y) is clamped at 0: K makes it ≥ 0 in exact arithmetic,
//     the clamp only removes a rounding-sized negative (which the step check would refuse). Setting
//     drained cells to 0 rather than clamping their rounding residual matters in float: the clamp
//     only ever created water (negative residuals cut, positive kept), a bias of about 1e-6 of the
//     water over hundreds of steps; 0 rounds either way. For the same reason fluxes become depths
//     by dividing by l_x·l_y/Δt, the very constant K is formed with: multiplying by Δt/(l_x·l_y),
//     rounded on its own, made every drained cell deliver d_A·(1 + ε) with one fixed ε. The flux form sends at most all of s_A.
//   - Velocity at d → 0: the mean depth is bounded below by velocity_depth_floor (seed 001 uses
//     0.05 m), so thin films cannot produce unbounded speeds; with d̄ = 0 no water moved (K), the
//     flux sums are 0 and so is the velocity — no 0/0.
//   - CFL number: max over cells and axes of Δt·|u|/l_x and Δt·|v|/l_y, the cells the water (and
//     the backtrace) moves per step along each axis; anisotropic cells keep their meaning. The K
//     scaling caps it at 1 where a cell drains completely in one step (frictionless pipes
//     accelerate until that cap: runs on slopes sit at 1).
//   - sin α of the terrain: |∇b|/sqrt(1 + |∇b|²), ∇b by central differences over l_x, l_y; at an
//     exterior neighbour the difference is one-sided, with exterior neighbours on both sides 0.
//     tilt_differences = seed001_code: the same with the raw differences b(x+1) − b(x−1) in place of
//     ∇b (not divided by 2l: its code's get_steepness; its sqrt(q)/sqrt(q + 1) is sqrt(q/(1 + q)) in
//     exact arithmetic); one-sided at an exterior neighbour and not doubled (its code wraps and never
//     meets a border), so on a plane a border cell's q is a quarter of an interior cell's.
//   - Backtrace sampling: a bilinear corner off the grid or on a no-data cell takes the value of
//     the cell being updated (zero gradient at walls, Mei's clamp-to-edge on the grid border). The
//     weights are ceil(p) − p and p − floor(p), so mirrored displacements give mirrored weights
//     bit for bit (1 − w would not); a displacement of whole cells (at rest: 0) reads one cell.
//   - Fixed summation order (L + R) + (T + B) for the four pipes, + ((TL + BR) + (TR + BL)) with
//     eight, so mirror-symmetric inputs give bitwise mirror-symmetric results in both transport
//     modes (along x and y; along the diagonal of a square-celled grid in the flux form — the
//     backtrace's bilinear weights associate x before y).
// Units: metres, seconds, m³/s (see core/params/hydraulic.hpp); the ledger is in m³.
//
// Memory traffic per cell and step (ref<double>, 4 pipes, flux transport; the performance
// table's floor column): 17 passes, 446 B read + 161 B written = 607 B, of which the algorithm's
// 12 passes are 495 B and check_state and the ledger's volumes 112 B. outflow and sent_ are
// double[8] records of which 4 pipes use half: counted in whole cache lines the step moves 863 B.
// Diffusion adds 114 B (3 passes), regolith 193 B (4 passes), 8 pipes make it 863 B.
#include "reference/erosion/pipes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/mutant.hpp"
#include "core/rounding_interval.hpp"
#include "reference/erosion/thermal_jako.hpp"

namespace gt::reference {

// Unqualified, so that a number type of its own (core/rounding_interval.hpp, which the error model of
// the shadow steps instantiates this step with) brings its own by argument-dependent lookup.
using std::ceil;
using std::floor;
using std::isnan;
using std::max;
using std::min;
using std::sqrt;

namespace {

constexpr const char* algorithm_name = "erosion.pipe";

// Pipes as gt::pipe_offsets (core/params/hydraulic.hpp); pipe k and pipe k ^ 1 are opposite.
constexpr int left = 0, right = 1, top = 2, bottom = 3, top_left = 4, bottom_right = 5, top_right = 6, bottom_left = 7;
constexpr int all_pipes = 8;
constexpr int axis_pipes = 4;  // the diffusion's 4 neighbours (seed 001), whatever the pipe count
constexpr int opposite(int pipe) { return pipe ^ 1; }

// drained_'s bits: K < 1 took all of d_A; and (error model) K's interval straddles 1, so another
// implementation may take the other branch.
constexpr unsigned char drained_by_k = 1u, drained_either_way = 2u;

// Error model (Real = RoundingInterval): whether another implementation may hold a > b, some value
// of a's interval above some value of b's; never for float and double (their branch is the one
// they take). Asked where this implementation found a > b false.
template <class Real>
bool may_be_greater(const Real& a, const Real& b) {
  if constexpr (std::is_same_v<Real, RoundingInterval>) {
    return a.high > b.low;
  } else {
    return false;
  }
}

// Error model: `value` joined with what the branch not taken gives (hull, keeping value's value).
template <class Real>
void join_other_branch(Real& value, const Real& other) {
  if constexpr (std::is_same_v<Real, RoundingInterval>) value = hull(value, other);
}

template <class Real>
using PipeValues = std::array<Real, all_pipes>;

template <class Real>
bool is_finite(Real value) {
  return std::isfinite(static_cast<double>(value));
}

// (L + R) + (T + B) and (TL + BR) + (TR + BL): orders that the mirrors along x, y and the diagonal
// map onto themselves (each swaps pipes within a bracket or swaps the brackets), so mirror-
// symmetric inputs give bitwise mirror-symmetric sums.
template <class Real>
Real axis_sum(const PipeValues<Real>& values) {
  return (values[left] + values[right]) + (values[top] + values[bottom]);
}

template <class Real>
Real diagonal_sum(const PipeValues<Real>& values) {
  return (values[top_left] + values[bottom_right]) + (values[top_right] + values[bottom_left]);
}

// The sum over the first `pipe_count` pipes: axis_sum, + diagonal_sum with 8 pipes.
template <class Real>
Real pipe_sum(const PipeValues<Real>& values, int pipe_count) {
  return pipe_count == axis_pipes ? axis_sum(values) : axis_sum(values) + diagonal_sum(values);
}

// The net outflow out − in of a pipe times its step (±1) along one axis, formed as out − in or
// in − out rather than negated, so that a balanced pipe gives +0 either way.
template <class Real>
Real directed_outflow(Real out, Real in, int step) {
  return step > 0 ? out - in : in - out;
}

// diagonal_sum of the diagonal pipes' step along x (along_x) or y times out − in.
template <class Real>
Real diagonal_outflow(const PipeValues<Real>& out, const PipeValues<Real>& in, bool along_x) {
  PipeValues<Real> terms{};
  for (int k = axis_pipes; k < all_pipes; ++k) {
    terms[k] = directed_outflow(out[k], in[k], along_x ? pipe_offsets[k].dx : pipe_offsets[k].dy);
  }
  return diagonal_sum(terms);
}

// A finite value, and not negative where it must not be (the state check after each step).
template <class Real>
bool acceptable(Real value, bool non_negative) {
  return is_finite(value) && !(non_negative && value < Real(0));
}

[[noreturn]] void refuse(const std::string& what) { throw InputError(fmt::format("{}: {}", algorithm_name, what)); }

template <class Real>
void clear_no_data_cells(PipeState<Real>& state) {
  for (std::size_t cell = 0; cell < state.terrain.size(); ++cell) {
    if (state.terrain.is_valid(cell)) continue;
    state.water.values[cell] = state.sediment.values[cell] = state.regolith.values[cell] = Real(0);
    for (auto& layer : state.layers) layer.values[cell] = Real(0);
    state.velocity_x.values[cell] = state.velocity_y.values[cell] = Real(0);
    state.outflow[cell] = {};
  }
}

template <class Real>
std::vector<Real> rain_depths(const Grid<Real>& terrain, const PipeConstants& constants, const Grid<double>& rain_map) {
  const Real time_step = static_cast<Real>(constants.time_step);
  const Real uniform = static_cast<Real>(constants.rain_rate);
  std::vector<Real> depths(terrain.size(), Real(0));
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) continue;
    const Real mapped = rain_map.values.empty() ? Real(0) : static_cast<Real>(rain_map.values[cell]);
    depths[cell] = time_step * (uniform + mapped);
  }
  return depths;
}

template <class Real>
std::vector<std::pair<std::size_t, Real>> source_depths(const Grid<Real>& terrain, const PipeConstants& constants,
                                                        const std::vector<PointSource>& sources) {
  std::vector<std::pair<std::size_t, Real>> depths;
  for (const auto& source : sources) {
    // Mutant erosion.pipe.source_over_length: the volume divided by l_x, not l_x·l_y.
    const double area = mutant_active("erosion.pipe.source_over_length") ? constants.length_x : constants.cell_area;
    depths.emplace_back(terrain.index(source.x, source.y), static_cast<Real>(source.rate * constants.time_step / area));
  }
  return depths;
}

template <class Real>
std::vector<unsigned char> exterior_pipe_bits(const Grid<Real>& terrain) {
  std::vector<unsigned char> bits(terrain.size(), 0);
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      for (int k = 0; k < all_pipes; ++k) {
        const int nx = x + pipe_offsets[k].dx;
        const int ny = y + pipe_offsets[k].dy;
        if (!terrain.inside(nx, ny) || !terrain.is_valid(nx, ny)) bits[terrain.index(x, y)] |= 1u << k;
      }
    }
  }
  return bits;
}

// Σ value·l_x·l_y over valid cells, compensated, in double.
template <class Real>
double volume(const Grid<Real>& field, const Grid<Real>& terrain, double cell_area) {
  CompensatedSum sum;
  for (std::size_t cell = 0; cell < field.size(); ++cell) {
    if (terrain.is_valid(cell)) sum.add(static_cast<double>(field.values[cell]) * cell_area);
  }
  return sum.value();
}

// The displacement of `velocity` over a step in cells of `length`, clamped to ±`reach` cells
// (beyond the grid every corner reads the cell itself).
template <class Real>
Real axis_offset(const Real& velocity, double time_step, double length, const Real& reach) {
  return std::clamp(velocity * static_cast<Real>(time_step / length), -reach, reach);
}

// Linear interpolation along one axis at an offset of `offset` cells, between the cells `low` and
// low + 1 with weights (low + 1) − offset and offset − low, each one rounded operation, so a
// mirrored displacement gives the mirrored weights exactly; an offset of exactly `low` takes its one
// cell. A NaN offset gives NaN weights, which the check after the step reports.
template <class Real>
struct AxisTaps {
  int low = 0;
  Real low_weight = Real(1);
  Real high_weight = Real(0);
};

template <class Real>
bool is_exactly(const Real& offset, int cell) {
  if constexpr (std::is_same_v<Real, RoundingInterval>) {
    return offset.width() == 0.0 && offset.value == cell;
  } else {
    return offset == static_cast<Real>(cell);
  }
}

template <class Real>
AxisTaps<Real> axis_taps(const Real& offset, int low) {
  if (isnan(offset)) return {0, std::numeric_limits<Real>::quiet_NaN(), std::numeric_limits<Real>::quiet_NaN()};
  if (is_exactly(offset, low)) return {low, Real(1), Real(0)};
  return {low, static_cast<Real>(low + 1) - offset, offset - static_cast<Real>(low)};
}

// The lower cell of the bilinear piece at `offset`: floor(offset) (0 for NaN, whose weights are NaN).
template <class Real>
int lower_cell(const Real& offset) {
  return isnan(offset) ? 0 : static_cast<int>(floor(offset));
}

// Every lower cell another implementation may take where this one takes lower_cell (error model,
// Real = RoundingInterval): the floors over the offset's interval, so a displacement within
// rounding of a whole cell (at rest, or a draining cell the K scaling moves exactly one cell a step)
// has the bilinear pieces on both sides of it.
inline std::pair<int, int> lower_cells(const RoundingInterval& offset) {
  if (isnan(offset)) return {0, 0};
  const auto [least, largest] = floor_range(offset);
  return {static_cast<int>(least), static_cast<int>(largest)};
}

// `source` bilinearly between the corners the taps name from (x, y); a corner off the grid or on a
// no-data cell reads the cell (x, y) itself.
template <class Real>
Real bilinear(const Grid<Real>& terrain, const std::vector<Real>& source, int x, int y, const AxisTaps<Real>& taps_x,
              const AxisTaps<Real>& taps_y) {
  const std::size_t cell = terrain.index(x, y);
  auto corner = [&](int dx, int dy) {
    const int cx = x + taps_x.low + dx;
    const int cy = y + taps_y.low + dy;
    return terrain.inside(cx, cy) && terrain.is_valid(cx, cy) ? source[terrain.index(cx, cy)] : source[cell];
  };
  const Real lower_row = taps_x.low_weight * corner(0, 0) + taps_x.high_weight * corner(1, 0);
  const Real upper_row = taps_x.low_weight * corner(0, 1) + taps_x.high_weight * corner(1, 1);
  return taps_y.low_weight * lower_row + taps_y.high_weight * upper_row;
}

}  // namespace

template <class Real>
PipeErosion<Real>::PipeErosion(PipeState<Real> initial, const PipeConstants& constants, HydraulicForcing forcing)
    : state_(std::move(initial)), constants_(constants) {
  check_pipe_input(state_, forcing, constants_);
  clear_no_data_cells(state_);
  rain_depth_ = rain_depths(state_.terrain, constants_, forcing.rain_map);
  source_depths_ = source_depths(state_.terrain, constants_, forcing.sources);
  exterior_pipes_ = exterior_pipe_bits(state_.terrain);
  water_before_flow_.resize(state_.terrain.size());
  scratch_.resize(state_.terrain.size());
  sent_.resize(state_.terrain.size());
  drained_.resize(state_.terrain.size());
  record_ledger();
}

template <class Real>
typename PipeErosion<Real>::Fluxes PipeErosion<Real>::inflows(int x, int y) const {
  const std::size_t cell = state_.terrain.index(x, y);
  Fluxes in{};
  for (int k = 0; k < pipe_count(); ++k) {
    if (!exterior(cell, k)) in[k] = state_.outflow[neighbour(x, y, k)][opposite(k)];
  }
  return in;
}

// The share of the cell's water each pipe moved this step, f_k·Δt/(d_A·l_x·l_y), scaled down to
// sum to 1 where rounding made the total exceed it; 0 for a cell that was dry.
template <class Real>
typename PipeErosion<Real>::Fluxes PipeErosion<Real>::carried_shares(std::size_t cell) const {
  const Real water = water_before_flow_[cell];
  Fluxes shares{};
  if (!(water > Real(0))) return shares;
  const Real volume_to_depth = static_cast<Real>(constants_.time_step / constants_.cell_area);
  for (int k = 0; k < pipe_count(); ++k) shares[k] = state_.outflow[cell][k] * volume_to_depth / water;
  const Real total = pipe_sum(shares, pipe_count());
  if (total > Real(1)) {
    for (auto& share : shares) share = share / total;
  }
  return shares;
}

// The share of the cell's water, and so of what it carries, that left through exterior pipes: the
// exterior axis pipes' shares added in the order L, R, T, B, then with 8 pipes the diagonal_sum of
// the exterior diagonals' shares.
template <class Real>
Real PipeErosion<Real>::exterior_share(std::size_t cell, const Fluxes& shares) const {
  Real leaving = Real(0);
  for (int k = 0; k < axis_pipes; ++k) {
    if (exterior(cell, k)) leaving = leaving + shares[k];
  }
  if (pipe_count() == axis_pipes) return leaving;
  Fluxes exterior_diagonals{};
  for (int k = axis_pipes; k < all_pipes; ++k) {
    if (exterior(cell, k)) exterior_diagonals[k] = shares[k];
  }
  return leaving + diagonal_sum(exterior_diagonals);
}

template <class Real>
Real PipeErosion<Real>::tilt_sine(int x, int y) const {
  const auto& terrain = state_.terrain;
  const std::size_t cell = terrain.index(x, y);
  auto slope = [&](int lower_pipe, int upper_pipe, double length) {
    const int lower = exterior(cell, lower_pipe) ? 0 : 1;
    const int upper = exterior(cell, upper_pipe) ? 0 : 1;
    if (lower + upper == 0) return Real(0);
    const Real low = terrain.at(x + lower * pipe_offsets[lower_pipe].dx, y + lower * pipe_offsets[lower_pipe].dy);
    const Real high = terrain.at(x + upper * pipe_offsets[upper_pipe].dx, y + upper * pipe_offsets[upper_pipe].dy);
    return (high - low) / static_cast<Real>(tilt_span(constants_.tilt_differences, lower + upper, length));
  };
  const Real slope_x = slope(left, right, constants_.length_x);
  const Real slope_y = slope(bottom, top, constants_.length_y);
  const Real squared = slope_x * slope_x + slope_y * slope_y;
  return max(static_cast<Real>(constants_.min_tilt_sine), sqrt(squared / (Real(1) + squared)));
}

template <class Real>
Real PipeErosion<Real>::traced_sediment(const std::vector<Real>& source, int x, int y, int direction) const {
  const auto& terrain = state_.terrain;
  const std::size_t cell = terrain.index(x, y);
  const Real reach = static_cast<Real>(terrain.width + terrain.height);
  const auto offset = [&](const Grid<Real>& velocity, double length) {
    const Real& speed = velocity.values[cell];
    return axis_offset(direction < 0 ? -speed : speed, constants_.time_step, length, reach);
  };
  const Real offset_x = offset(state_.velocity_x, constants_.length_x);
  const Real offset_y = offset(state_.velocity_y, constants_.length_y);
  const auto piece = [&](int low_x, int low_y) {
    return bilinear(terrain, source, x, y, axis_taps(offset_x, low_x), axis_taps(offset_y, low_y));
  };
  const Real traced = piece(lower_cell(offset_x), lower_cell(offset_y));
  if constexpr (std::is_same_v<Real, RoundingInterval>) {
    const auto [first_x, last_x] = lower_cells(offset_x);
    const auto [first_y, last_y] = lower_cells(offset_y);
    // An offset whose interval spans more than two whole cells has lost its displacement to rounding.
    constexpr int most_floors = 3;
    if (last_x - first_x >= most_floors || last_y - first_y >= most_floors) {
      constexpr double infinity = std::numeric_limits<double>::infinity();
      return RoundingInterval::of(traced.value, -infinity, infinity);
    }
    RoundingInterval pieces = traced;
    for (int low_y = first_y; low_y <= last_y; ++low_y) {
      for (int low_x = first_x; low_x <= last_x; ++low_x) pieces = hull(pieces, piece(low_x, low_y));
    }
    return pieces;
  } else {
    return traced;
  }
}

template <class Real>
void PipeErosion<Real>::add_water() {
  auto& water = state_.water.values;
  const double area = constants_.cell_area;
  water_before_flow_ = water;  // d, for what the additions add
  const bool half_rain = mutant_active("erosion.pipe.half_rain");  // mutant: half the rain added
  for (std::size_t cell = 0; cell < water.size(); ++cell) {
    if (!state_.terrain.is_valid(cell)) continue;
    water[cell] = water[cell] + (half_rain ? Real(0.5) * rain_depth_[cell] : rain_depth_[cell]);
    flows_.rain_in.add(static_cast<double>(rain_depth_[cell]) * area);
  }
  for (const auto& [cell, depth] : source_depths_) {
    water[cell] = water[cell] + depth;
    flows_.source_in.add(static_cast<double>(depth) * area);
  }
  for (std::size_t cell = 0; cell < water.size(); ++cell) {
    if (!state_.terrain.is_valid(cell)) continue;
    flows_.water_added.add((static_cast<double>(water[cell]) - static_cast<double>(water_before_flow_[cell])) * area);
  }
  water_before_flow_ = water;
}

template <class Real>
std::size_t PipeErosion<Real>::neighbour(int x, int y, int pipe) const {
  return state_.terrain.index(x + pipe_offsets[pipe].dx, y + pipe_offsets[pipe].dy);
}

template <class Real>
Real PipeErosion<Real>::neighbour_surface(int x, int y, int pipe) const {
  const std::size_t cell = neighbour(x, y, pipe);
  return state_.terrain.values[cell] + state_.water.values[cell];
}

template <class Real>
void PipeErosion<Real>::update_outflow() {
  const auto& terrain = state_.terrain;
  const auto& water = state_.water;
  const bool open = constants_.boundary == PipeBoundary::open;
  const double gain = constants_.time_step * constants_.pipe_area * constants_.gravity;
  const Real diagonal_gain = static_cast<Real>(gain / constants_.length_diagonal);
  const Fluxes flux_gain{static_cast<Real>(gain / constants_.length_x),
                         static_cast<Real>(gain / constants_.length_x),
                         static_cast<Real>(gain / constants_.length_y),
                         static_cast<Real>(gain / constants_.length_y),
                         diagonal_gain, diagonal_gain, diagonal_gain, diagonal_gain};
  const Real area_per_time = static_cast<Real>(constants_.cell_area / constants_.time_step);
  const bool unscaled = mutant_active("erosion.pipe.unscaled_outflow");  // mutant: K = 1 (eq. 2.12 skipped)
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) continue;
      const Real surface = terrain.values[cell] + water.values[cell];
      Fluxes tentative{};
      for (int k = 0; k < pipe_count(); ++k) {
        if (exterior(cell, k) && !open) continue;
        const Real head = exterior(cell, k) ? water.values[cell] : surface - neighbour_surface(x, y, k);
        tentative[k] = max(Real(0), state_.outflow[cell][k] + flux_gain[k] * head);
      }
      const Real total = pipe_sum(tentative, pipe_count());
      const Real scale = total > Real(0) && !unscaled ? min(Real(1), water.values[cell] * area_per_time / total)
                                                      : Real(1);
      for (int k = 0; k < pipe_count(); ++k) state_.outflow[cell][k] = scale * tentative[k];
      drained_[cell] = scale < Real(1) ? drained_by_k : 0;
      if constexpr (std::is_same_v<Real, RoundingInterval>) {
        if (scale.low < 1.0 && scale.high >= 1.0) drained_[cell] |= drained_either_way;
      }
    }
  }
}

template <class Real>
void PipeErosion<Real>::update_water_depth() {
  const auto& terrain = state_.terrain;
  // Fluxes become depths by dividing by the same l_x·l_y/Δt that K used (see update_outflow).
  const Real area_per_time = static_cast<Real>(constants_.cell_area / constants_.time_step);
  const double area = constants_.cell_area;
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) continue;
      const auto& out = state_.outflow[cell];
      const Real kept = max(Real(0), water_before_flow_[cell] - pipe_sum(out, pipe_count()) / area_per_time);
      const bool drained = (drained_[cell] & drained_by_k) != 0;
      Real remaining = drained ? Real(0) : kept;
      // Error model: where K's interval straddles 1 another implementation may take the other
      // branch; both are near 0 (K ≈ 1 sends about all of d_A), but the kept residual is a rounding
      // of d_A, not of the inflow alone.
      if ((drained_[cell] & drained_either_way) != 0) join_other_branch(remaining, drained ? kept : Real(0));
      state_.water.values[cell] = remaining + pipe_sum(inflows(x, y), pipe_count()) / area_per_time;
      for (int k = 0; k < pipe_count(); ++k) {
        if (exterior(cell, k)) {
          flows_.boundary_out_water.add(static_cast<double>(out[k]) / static_cast<double>(area_per_time) * area);
        }
      }
    }
  }
}

template <class Real>
void PipeErosion<Real>::update_velocity() {
  const auto& terrain = state_.terrain;
  const Real half = Real(0.5);
  const Real depth_floor = static_cast<Real>(constants_.velocity_depth_floor);
  const Real length_x = static_cast<Real>(constants_.length_x);
  const Real length_y = static_cast<Real>(constants_.length_y);
  // cos of the diagonal pipes' angle with x and y: their flux's share along each axis
  const Real diagonal_share_x = static_cast<Real>(constants_.length_x / constants_.length_diagonal);
  const Real diagonal_share_y = static_cast<Real>(constants_.length_y / constants_.length_diagonal);
  const bool diagonals = pipe_count() == all_pipes;
  step_max_cfl_ = 0.0;
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) continue;
      const auto& out = state_.outflow[cell];
      const auto in = inflows(x, y);
      Real twice_flow_x = (in[left] - out[left]) + (out[right] - in[right]);
      Real twice_flow_y = (in[bottom] - out[bottom]) + (out[top] - in[top]);
      if (diagonals) {
        twice_flow_x = twice_flow_x + diagonal_share_x * diagonal_outflow(out, in, true);
        twice_flow_y = twice_flow_y + diagonal_share_y * diagonal_outflow(out, in, false);
      }
      const Real flow_x = half * twice_flow_x;
      const Real flow_y = half * twice_flow_y;
      const Real mean_depth = max(depth_floor, half * (water_before_flow_[cell] + state_.water.values[cell]));
      const Real u = flow_x / (length_y * mean_depth);
      const Real v = flow_y / (length_x * mean_depth);
      state_.velocity_x.values[cell] = u;
      state_.velocity_y.values[cell] = v;
      const double cells_x = constants_.time_step * std::abs(static_cast<double>(u)) / constants_.length_x;
      const double cells_y = constants_.time_step * std::abs(static_cast<double>(v)) / constants_.length_y;
      step_max_cfl_ = std::max({step_max_cfl_, cells_x, cells_y});
    }
  }
}

namespace {

// What the cell's water takes from the ground (> 0) or leaves on it (< 0) in one step, Šťava's
// layered law (stage 5' above; with no layers Mei's eqs. 2.22-2.23): `capacities` T_0..T_N of the
// bedrock and the layers, `thickness` b_1..b_N (the cell's, updated), `suspended` s; above_ignored:
// the mutant erosion.pipe.layers_above_ignored (both twins: T̂_k = T_k, eq. 2.29 left out).
// In the error model a comparison another implementation may take the other way joins the branch
// not taken: where a walk stops at T̂_k ≈ s the other may take k_s·gap (gap within rounding of 0),
// and where s ≈ T_N deposit k_d·(s − T_N); so the exchange's bound covers both sides of each
// switch (Mei's law, the walk with N = 0, switches between erosion and deposition at C = s).
template <class Real>
Real layered_exchange(const std::array<Real, max_pipe_layers + 1>& capacities, std::array<Real*, max_pipe_layers> thickness,
                      int layer_count, Real suspended, Real dissolving, Real deposition, LayerErosion condition,
                      bool above_ignored) {
  const bool printed = condition == LayerErosion::as_printed;
  Real taken_total = Real(0);
  Real above = Real(0);  // Σ b_i over the layers above k, at the step's start
  for (int k = layer_count; k >= 0; --k) {
    const Real reach = above_ignored ? capacities[k] : capacities[k] - above;  // T̂_k
    const bool erodes = printed ? reach < suspended : reach > suspended;
    const bool erodes_elsewhere =
        !erodes && (printed ? may_be_greater(suspended, reach) : may_be_greater(reach, suspended));
    const Real gap = printed ? suspended - reach : reach - suspended;
    const Real wanted = dissolving * gap;
    if (k == 0) {
      if (erodes) taken_total = taken_total + wanted;
      if (erodes_elsewhere) join_other_branch(taken_total, taken_total + wanted);
      break;
    }
    Real& layer = *thickness[k - 1];
    const Real held = layer;
    const Real taken = min(wanted, held);
    if (!erodes) {
      if (erodes_elsewhere) {
        join_other_branch(layer, held - taken);
        join_other_branch(taken_total, taken_total + taken);
      }
      break;
    }
    layer = held - taken;
    taken_total = taken_total + taken;
    if (taken < held) break;
    above = above + held;
  }
  const Real top = capacities[layer_count];
  const bool deposits = suspended > top;
  Real deposited = deposits ? deposition * (suspended - top) : Real(0);
  if (!deposits && may_be_greater(suspended, top)) join_other_branch(deposited, deposition * (suspended - top));
  if (layer_count > 0) *thickness[layer_count - 1] = *thickness[layer_count - 1] + deposited;
  return taken_total - deposited;
}

}  // namespace

template <class Real>
void PipeErosion<Real>::erode_and_deposit() {
  const auto& terrain = state_.terrain;
  auto& sediment = state_.sediment.values;
  const Real depth_ramp = static_cast<Real>(constants_.depth_ramp);
  const Real dissolving = static_cast<Real>(constants_.dissolving_fraction);
  const Real deposition = static_cast<Real>(constants_.deposition_fraction);
  const int layer_count = constants_.layer_count;
  std::array<Real, max_pipe_layers + 1> capacity_constants{static_cast<Real>(constants_.capacity)};
  for (int k = 1; k <= layer_count; ++k) capacity_constants[k] = static_cast<Real>(constants_.layer_capacity[k - 1]);
  // Mutant erosion.pipe.sediment_gain_doubled: the sediment gains twice what the bed loses.
  const bool sediment_gain_doubled = mutant_active("erosion.pipe.sediment_gain_doubled");
  const bool above_ignored = mutant_active("erosion.pipe.layers_above_ignored");
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      scratch_[cell] = terrain.values[cell];
      if (!terrain.is_valid(cell)) continue;
      const Real u = state_.velocity_x.values[cell];
      const Real v = state_.velocity_y.values[cell];
      const Real depth = state_.water.values[cell];
      const Real ramp = depth_ramp > Real(0) ? min(Real(1), depth / depth_ramp) : Real(1);
      const Real tilt = tilt_sine(x, y);
      const Real speed = sqrt(u * u + v * v);
      std::array<Real, max_pipe_layers + 1> capacities{};
      for (int k = 0; k <= layer_count; ++k) capacities[k] = capacity_constants[k] * tilt * speed * ramp;
      std::array<Real*, max_pipe_layers> thickness{};
      for (int k = 0; k < layer_count; ++k) thickness[k] = &state_.layers[k].values[cell];
      const Real suspended = sediment[cell];
      const Real moved = layered_exchange(capacities, thickness, layer_count, suspended, dissolving, deposition,
                                          constants_.layer_erosion, above_ignored);
      scratch_[cell] = terrain.values[cell] - moved;
      sediment[cell] = suspended + (sediment_gain_doubled ? Real(2) * moved : moved);
    }
  }
  std::swap(state_.terrain.values, scratch_);
}

template <class Real>
void PipeErosion<Real>::regolith_exchange() {
  const auto& terrain = state_.terrain;
  auto& regolith = state_.regolith.values;
  const Real most = static_cast<Real>(constants_.regolith_depth);
  const Real dissolving = static_cast<Real>(constants_.regolith_dissolving_fraction);
  const Real deposition = static_cast<Real>(constants_.regolith_deposition_fraction);
  // Mutant erosion.pipe.regolith_deepest (both twins): r_max = max(d_B, K_r), the water loosens
  // the bed down to its own depth.
  const bool deepest = mutant_active("erosion.pipe.regolith_deepest");
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) continue;
    const Real depth = state_.water.values[cell];
    const Real loosened = deepest ? max(depth, most) : min(depth, most);
    const Real held = regolith[cell];
    const Real moved = held < loosened ? dissolving * (loosened - held) : -(deposition * (held - loosened));
    state_.terrain.values[cell] = terrain.values[cell] - moved;
    regolith[cell] = held + moved;
  }
}

// The exchange of one step between neighbours through the first `pipes` pipes: `sent[cell][k]`
// leaves the cell through pipe k (exterior pipes: into `boundary_out`), `scratch_` holds what
// stays; afterwards each cell holds what stayed plus what its neighbours sent it.
template <class Real>
void PipeErosion<Real>::gather_sent(std::vector<Real>& field, CompensatedSum& boundary_out, int pipes) {
  const auto& terrain = state_.terrain;
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) continue;
      Fluxes received{};
      for (int k = 0; k < pipes; ++k) {
        if (exterior(cell, k)) {
          boundary_out.add(static_cast<double>(sent_[cell][k]) * constants_.cell_area);
        } else {
          received[k] = sent_[neighbour(x, y, k)][opposite(k)];
        }
      }
      scratch_[cell] = scratch_[cell] + pipe_sum(received, pipes);
    }
  }
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (terrain.is_valid(cell)) field[cell] = scratch_[cell];
  }
}

template <class Real>
void PipeErosion<Real>::transport_with_fluxes(std::vector<Real>& field, CompensatedSum& boundary_out) {
  const auto& terrain = state_.terrain;
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) continue;
    const auto shares = carried_shares(cell);
    for (int k = 0; k < pipe_count(); ++k) sent_[cell][k] = field[cell] * shares[k];
    scratch_[cell] = field[cell] * (Real(1) - min(Real(1), pipe_sum(shares, pipe_count())));
  }
  gather_sent(field, boundary_out, pipe_count());
}

template <class Real>
void PipeErosion<Real>::transport_semi_lagrangian(std::vector<Real>& field, CompensatedSum& boundary_out) {
  const auto& terrain = state_.terrain;
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) continue;
    const Real leaving = exterior_share(cell, carried_shares(cell));
    const Real staying = field[cell] * (Real(1) - min(Real(1), leaving));
    boundary_out.add(static_cast<double>(field[cell] - staying) * constants_.cell_area);
    scratch_[cell] = staying;
  }
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      if (terrain.is_valid(x, y)) field[terrain.index(x, y)] = traced_sediment(scratch_, x, y, -1);
    }
  }
  if (constants_.transport == SedimentTransport::maccormack) maccormack_correction(field);
}

// MacCormack's correction of the semi-Lagrangian step `field` (Selle et al. 2008): the forward
// result φ̂ traced back forward to each cell gives φ̌, and the cell takes φ̂ + ½(φ − φ̌), φ what
// stayed (scratch_); the limiter clamps that to the range of φ over the cell and its 8 neighbours
// (always on: unlimited, it makes negative sediment).
template <class Real>
void PipeErosion<Real>::maccormack_correction(std::vector<Real>& field) {
  const auto& terrain = state_.terrain;
  const bool negated = mutant_active("erosion.pipe.maccormack_correction_negated");
  forward_ = field;
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) continue;
      const Real returned = traced_sediment(forward_, x, y, +1);
      const Real correction = Real(0.5) * (scratch_[cell] - returned);
      // Mutant erosion.pipe.maccormack_correction_negated (both twins): the correction subtracted.
      const Real corrected = negated ? forward_[cell] - correction : forward_[cell] + correction;
      Real lowest = scratch_[cell], highest = scratch_[cell];
      for (int k = 0; k < 8; ++k) {
        const int nx = x + moore_offsets[k].dx, ny = y + moore_offsets[k].dy;
        const Real around = terrain.inside(nx, ny) && terrain.is_valid(nx, ny) ? scratch_[terrain.index(nx, ny)]
                                                                                : scratch_[cell];
        lowest = min(lowest, around);
        highest = max(highest, around);
      }
      field[cell] = max(lowest, min(highest, corrected));
    }
  }
}

template <class Real>
void PipeErosion<Real>::transport(std::vector<Real>& field, CompensatedSum& boundary_out) {
  if (constants_.transport == SedimentTransport::flux) {
    transport_with_fluxes(field, boundary_out);
  } else {
    transport_semi_lagrangian(field, boundary_out);
  }
}

// σ_k of stage 6b for one cell: w for each interior pipe (uniform), or ½d_k/(d + ½Σd_n) (water).
template <class Real>
typename PipeErosion<Real>::Fluxes PipeErosion<Real>::diffusion_shares(int x, int y) const {
  const auto& terrain = state_.terrain;
  const std::size_t cell = terrain.index(x, y);
  Fluxes shares{};
  if (constants_.diffusion_weighting == DiffusionWeighting::uniform) {
    const Real weight = static_cast<Real>(constants_.sediment_diffusion);
    for (int k = 0; k < axis_pipes; ++k) shares[k] = exterior(cell, k) ? Real(0) : weight;
    return shares;
  }
  const Real half = Real(0.5);
  Fluxes neighbour_weights{};
  for (int k = 0; k < axis_pipes; ++k) {
    if (!exterior(cell, k)) neighbour_weights[k] = half * state_.water.values[neighbour(x, y, k)];
  }
  const Real base = state_.water.values[cell] + pipe_sum(neighbour_weights, axis_pipes);
  if (!(base > Real(0))) return shares;
  for (int k = 0; k < axis_pipes; ++k) shares[k] = neighbour_weights[k] / base;
  return shares;
}

template <class Real>
void PipeErosion<Real>::diffuse(std::vector<Real>& field) {
  const auto& terrain = state_.terrain;
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) continue;
      const auto shares = diffusion_shares(x, y);
      for (int k = 0; k < axis_pipes; ++k) sent_[cell][k] = field[cell] * shares[k];
      // Water weighting of a dry cell sends all of it (Σσ = 1): rounding can make Σ sent exceed
      // what the cell holds by an ulp; the clamp removes that (as the water remainder's clamp).
      scratch_[cell] = max(Real(0), field[cell] - pipe_sum(sent_[cell], axis_pipes));
    }
  }
  CompensatedSum nothing_leaves;  // exterior pipes send nothing (σ = 0 there)
  gather_sent(field, nothing_leaves, axis_pipes);
}

template <class Real>
void PipeErosion<Real>::evaporate() {
  // Mutant erosion.pipe.double_evaporation: d·(1 − 2·K_e·Δt).
  const Real kept = static_cast<Real>(mutant_active("erosion.pipe.double_evaporation")
                                          ? 2.0 * constants_.evaporation_kept - 1.0
                                          : constants_.evaporation_kept);
  auto& water = state_.water.values;
  for (std::size_t cell = 0; cell < water.size(); ++cell) {
    if (!state_.terrain.is_valid(cell)) continue;
    const Real before = water[cell];
    water[cell] = before * kept;
    flows_.evaporated.add(static_cast<double>(before - water[cell]) * constants_.cell_area);
  }
}

template <class Real>
void PipeErosion<Real>::check_state() const {
  const auto& terrain = state_.terrain;
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) continue;
      const auto report = [&](const std::string& name, Real value) {
        refuse(fmt::format("step {}, cell (x={}, y={}): {} is {} (Δt = {} s, largest CFL number this step {:.3g}); "
                           "the time step is too large or the input out of range",
                           steps_done_, x, y, name, static_cast<double>(value), constants_.time_step, step_max_cfl_));
      };
      struct Checked {
        const char* name;
        Real value;
        bool non_negative;
      };
      const std::array<Checked, 6> values{{{"terrain height", terrain.values[cell], false},
                                          {"water depth", state_.water.values[cell], true},
                                          {"sediment", state_.sediment.values[cell], true},
                                          {"regolith", state_.regolith.values[cell], true},
                                          {"x velocity", state_.velocity_x.values[cell], false},
                                          {"y velocity", state_.velocity_y.values[cell], false}}};
      for (const auto& [name, value, non_negative] : values) {
        if (!acceptable(value, non_negative)) report(name, value);
      }
      for (int k = 0; k < pipe_count(); ++k) {
        const Real flux = state_.outflow[cell][k];
        if (!acceptable(flux, true)) report(fmt::format("outflow {}", pipe_name(k)), flux);
      }
      for (std::size_t k = 0; k < state_.layers.size(); ++k) {
        const Real thickness = state_.layers[k].values[cell];
        if (!acceptable(thickness, true)) report(fmt::format("layer_{}", k + 1), thickness);
      }
    }
  }
}

template <class Real>
void PipeErosion<Real>::record_ledger() {
  PipeLedgerEntry entry;
  entry.step = steps_done_;
  entry.water = volume(state_.water, state_.terrain, constants_.cell_area);
  entry.terrain = volume(state_.terrain, state_.terrain, constants_.cell_area);
  entry.sediment = volume(state_.sediment, state_.terrain, constants_.cell_area);
  entry.regolith = volume(state_.regolith, state_.terrain, constants_.cell_area);
  flows_.write_to(entry);
  entry.max_cfl = step_max_cfl_;
  ledger_.push_back(entry);
}

template <class Real>
void PipeErosion<Real>::step() {
  add_water();
  update_outflow();
  update_water_depth();
  update_velocity();
  erode_and_deposit();
  const bool regolith = constants_.regolith_depth > 0.0;
  if (regolith) regolith_exchange();
  transport(state_.sediment.values, flows_.boundary_out_sediment);
  if (regolith) transport(state_.regolith.values, flows_.boundary_out_regolith);
  if (constants_.sediment_diffusion > 0.0) {
    diffuse(state_.sediment.values);
    if (regolith && constants_.regolith_diffusion) diffuse(state_.regolith.values);
  }
  evaporate();
  if (constants_.thermal_step) state_.terrain = thermal_jako_erosion(state_.terrain, constants_.thermal, 1);
  ++steps_done_;
  check_state();
  record_ledger();
}

template <class Real>
void PipeErosion<Real>::run(int steps) {
  for (int i = 0; i < steps; ++i) step();
}

template class PipeErosion<float>;
template class PipeErosion<double>;
template class PipeErosion<RoundingInterval>;  // the shadow steps' error model (compare/checks/pipe_error_model.hpp)

}  // namespace gt::reference
