// One pipe step on the host (see pipe_spec.hpp). Written from digest 000 §3.4's equations, stage by
// stage over whole grids (each stage reads the previous one's fields, as Mei's passes do):
//   2.10        d_A = d + Δt·(r + r_map) + Σ_sources rate·Δt/(l_x·l_y)
//   2.11-2.13   f̂_k = max(0, f_k + Δt·A·g·Δh_k/l_k), Δh_k = (b + d_A) − (b_k + d_A,k);
//               K = min(1, d_A·l_x·l_y/(Δt·Σf̂)), 1 when Σf̂ = 0; f_k = K·f̂_k
//   2.14-2.17   d_B = max(0, d_A − Δt·Σf_out/(l_x·l_y)) + Δt·Σf_in/(l_x·l_y)
//   2.18-2.19   u = ½((f_in,L − f_L) + (f_R − f_in,R))/(l_y·d̄), v likewise along y with l_x,
//               d̄ = max(depth floor, ½(d_A + d_B))
//   2.20-2.23   C = K_c·max(sin α, T_α)·|(u, v)|·min(1, d_B/K_w); sin α = |∇b|/√(1 + |∇b|²), ∇b by
//               central differences over 2l (one-sided over l beside an exterior pipe, 0 with both
//               sides exterior); C > s: b −= k_s·(C − s), s += the same; else b += k_d·(s − C),
//               s −= the same; k = min(1, K·Δt)
//               with seed 001's code's tilt: the raw differences b(x+1) − b(x−1) in place of ∇b
//   layers      (Šťava et al. 2008, eqs. 2.27-2.29, Algorithm 1; layers = N ≥ 1) T_k = C_k·(the same
//               tilt, speed and ramp), C_0 = K_c for the bedrock; from the top layer down, while the
//               capacity left after the layers above (T_k − Σ_{i>k} b_i, start thicknesses) exceeds s
//               (as printed: falls below it): k_s times that gap comes out of layer k, which the water
//               gets through only by emptying it; the bedrock gives without limit. s > T_N: k_d·(s − T_N)
//               settles on layer N. b and s change by the total, as Mei's
//   regolith    (seed 001 §3.9, K_r > 0) r_max = min(d_B, K_r); r < r_max: b −= k_re·(r_max − r),
//               r += the same; else b += k_rd·(r − r_max), r −= the same
//   8 pipes     the diagonals TL, BR, TR, BL of length l_d = √(l_x² + l_y²), the same A; the net flux
//               along x adds (l_x/l_d)·dx_k·(f_k − f_in,k) of each diagonal (y likewise); the tilt
//               and the diffusion stay on the axes
//   semi-Lagr.  (2.24-2.25) what left through exterior pipes is gone; each cell takes the bilinear
//               value at x − (u, v)·Δt of what stayed, corners off the grid or on no data reading
//               the cell itself
//   MacCormack  (Selle et al. 2008) that value φ̂ sampled the same way at x + (u, v)·Δt (φ̌); the
//               cell takes φ̂ + ½(φ − φ̌), φ what stayed, clamped to the range of φ over the cell
//               and its 8 neighbours
//   flux form   each pipe carries the share f_k·Δt/(d_A·l_x·l_y) of the eroded s (and of r: what the
//               cell's water moved); a cell keeps s·(1 − min(1, Σ shares)) and gains its neighbours'
//   diffusion   (seed 001 §3.8, w > 0) s (and r with regolith_diffusion) to the 4 axis neighbours
//               that take part, σ = w or ½d_k/(d + ½Σd_n) with depths d_B; kept: max(0, s − Σσ·s)
//   evaporation d = d_B·(1 − K_e·Δt)
//   thermal     (Jákó & Tóth's combined step) one iteration of their thermal erosion on b
// Exterior pipes (off the grid or into no data): walls with closed borders; with open borders a dry
// neighbour at the cell's own height (Δh = d_A) that sends nothing back.
#include "compare/algorithms/pipe_spec.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "compare/algorithms/thermal_specs.hpp"
#include "core/rounding_interval.hpp"

namespace gt {

namespace {

// Unqualified, so that RoundingInterval brings its own.
using std::max;
using std::min;
using std::floor;
using std::sqrt;

// The pipes in pipe_offsets' order, L, R, T (+y), B, then the diagonals TL, BR, TR, BL; pipe k's
// opposite is k ^ 1. Diffusion uses the 4 axis pipes whatever the count.
constexpr int axis_pipes = 4;
constexpr int left = 0, right = 1, top = 2, bottom = 3;
constexpr int towards_cell(int pipe) { return pipe ^ 1; }

template <class Real>
using Fluxes = std::array<Real, 8>;

// What one stage needs of the grid: sizes, which cells take part, where pipe k leads, how many
// pipes there are.
template <class Real>
struct Cells {
  const Grid<Real>& terrain;
  int pipes = axis_pipes;

  bool wet(int x, int y) const { return terrain.inside(x, y) && terrain.is_valid(x, y); }
  // Pipe k of (x, y) leads to a cell that takes part.
  bool interior(int x, int y, int pipe) const { return wet(x + pipe_offsets[pipe].dx, y + pipe_offsets[pipe].dy); }
  std::size_t neighbour(int x, int y, int pipe) const {
    return terrain.index(x + pipe_offsets[pipe].dx, y + pipe_offsets[pipe].dy);
  }
  template <class Visit>
  void each(Visit visit) const {
    for (int y = 0; y < terrain.height; ++y) {
      for (int x = 0; x < terrain.width; ++x) {
        if (terrain.is_valid(x, y)) visit(x, y, terrain.index(x, y));
      }
    }
  }
};

// The sum over the first `count` pipes.
template <class Real>
Real total(const Fluxes<Real>& fluxes, int count) {
  Real sum = Real(0);
  for (int k = 0; k < count; ++k) sum = sum + fluxes[k];
  return sum;
}

// What the neighbours send into (x, y): pipe k's neighbour sends through its opposite pipe.
template <class Real>
Fluxes<Real> arriving(const Cells<Real>& cells, const std::vector<Fluxes<Real>>& sent, int x, int y) {
  Fluxes<Real> in{};
  for (int k = 0; k < cells.pipes; ++k) {
    if (cells.interior(x, y, k)) in[k] = sent[cells.neighbour(x, y, k)][towards_cell(k)];
  }
  return in;
}

// eq. 2.10: the depth after rain, the rain map and the sources.
template <class Real>
std::vector<Real> water_after_additions(const Cells<Real>& cells, const Grid<Real>& water, const HydraulicParams& params,
                                        const HydraulicForcing& forcing) {
  std::vector<Real> depth(water.size(), Real(0));
  const Real time_step(params.time_step);
  cells.each([&](int, int, std::size_t cell) {
    const double mapped = forcing.rain_map.values.empty() ? 0.0 : forcing.rain_map.values[cell];
    depth[cell] = water.values[cell] + time_step * (Real(params.rain_rate) + Real(mapped));
  });
  const double cell_area = cells.terrain.cell_size_x * cells.terrain.cell_size_y;
  for (const PointSource& source : forcing.sources) {
    const std::size_t cell = cells.terrain.index(source.x, source.y);
    depth[cell] = depth[cell] + Real(source.rate) * Real(params.time_step / cell_area);
  }
  return depth;
}

// eqs. 2.11-2.13: the outflows after the head accelerated them, scaled by K.
template <class Real>
std::vector<Fluxes<Real>> scaled_outflows(const Cells<Real>& cells, const std::vector<Fluxes<Real>>& flux,
                                          const std::vector<Real>& depth, const HydraulicParams& params) {
  const auto& terrain = cells.terrain;
  const double cell_area = terrain.cell_size_x * terrain.cell_size_y;
  const double cross_section = params.pipe_area > 0.0 ? params.pipe_area : cell_area;
  const double diagonal = std::hypot(terrain.cell_size_x, terrain.cell_size_y);
  const double pipe_length[8] = {terrain.cell_size_x, terrain.cell_size_x, terrain.cell_size_y, terrain.cell_size_y,
                                 diagonal,            diagonal,            diagonal,            diagonal};
  const bool open = params.boundary == PipeBoundary::open;
  std::vector<Fluxes<Real>> scaled(flux.size(), Fluxes<Real>{});
  cells.each([&](int x, int y, std::size_t cell) {
    const Real surface = terrain.values[cell] + depth[cell];
    Fluxes<Real> accelerated{};
    for (int k = 0; k < cells.pipes; ++k) {
      const bool inside = cells.interior(x, y, k);
      if (!inside && !open) continue;
      const std::size_t other = inside ? cells.neighbour(x, y, k) : cell;
      const Real head = inside ? surface - (terrain.values[other] + depth[other]) : depth[cell];
      const Real acceleration(params.time_step * cross_section * params.gravity / pipe_length[k]);
      accelerated[k] = max(Real(0), flux[cell][k] + acceleration * head);
    }
    const Real asked = total(accelerated, cells.pipes) * Real(params.time_step);
    const Real held = depth[cell] * Real(cell_area);
    const Real factor = asked > Real(0) ? min(Real(1), held / asked) : Real(1);
    for (int k = 0; k < cells.pipes; ++k) scaled[cell][k] = factor * accelerated[k];
  });
  return scaled;
}

// The terrain's tilt sin α at (x, y) (eq. 2.20's α): from the slope by central differences over 2l
// (one-sided over l beside an exterior pipe, 0 with both sides exterior), or, with seed 001's code,
// from the raw height differences (its get_steepness: as if l were 1 and the difference not halved).
template <class Real>
Real tilt_sine(const Cells<Real>& cells, TiltDifferences differences, int x, int y) {
  const auto& terrain = cells.terrain;
  const auto slope = [&](int down, int up, double length) {
    const bool has_down = cells.interior(x, y, down);
    const bool has_up = cells.interior(x, y, up);
    if (!has_down && !has_up) return Real(0);
    const Real lower = has_down ? terrain.values[cells.neighbour(x, y, down)] : terrain.at(x, y);
    const Real upper = has_up ? terrain.values[cells.neighbour(x, y, up)] : terrain.at(x, y);
    if (differences == TiltDifferences::seed001_code) return upper - lower;
    return (upper - lower) / Real((has_down && has_up ? 2.0 : 1.0) * length);
  };
  const Real along_x = slope(left, right, terrain.cell_size_x);
  const Real along_y = slope(bottom, top, terrain.cell_size_y);
  const Real squared = along_x * along_x + along_y * along_y;
  return sqrt(squared / (Real(1) + squared));
}

// The share of the cell's water d_A each pipe moved, f_k·Δt/(d_A·l_x·l_y); none for a dry cell.
template <class Real>
Fluxes<Real> water_shares(const Cells<Real>& cells, const Fluxes<Real>& outflow, const Real& added,
                          const Real& volume_to_depth) {
  Fluxes<Real> shares{};
  if (added > Real(0)) {
    for (int k = 0; k < cells.pipes; ++k) shares[k] = outflow[k] * volume_to_depth / added;
  }
  return shares;
}

// The flux form: `field` goes where the water went, in the shares of the cell's d_A its pipes
// moved; a cell keeps field·(1 − min(1, Σ shares)) and gains what its neighbours send.
template <class Real>
std::vector<Real> carried_with_water(const Cells<Real>& cells, const std::vector<Real>& field,
                                     const std::vector<Fluxes<Real>>& outflow, const std::vector<Real>& added,
                                     const Real& volume_to_depth) {
  std::vector<Fluxes<Real>> sent(field.size(), Fluxes<Real>{});
  std::vector<Real> kept(field.size(), Real(0));
  cells.each([&](int, int, std::size_t cell) {
    const Fluxes<Real> shares = water_shares(cells, outflow[cell], added[cell], volume_to_depth);
    for (int k = 0; k < cells.pipes; ++k) sent[cell][k] = field[cell] * shares[k];
    kept[cell] = field[cell] * (Real(1) - min(Real(1), total(shares, cells.pipes)));
  });
  std::vector<Real> moved = field;
  cells.each([&](int x, int y, std::size_t cell) {
    moved[cell] = kept[cell] + total(arriving(cells, sent, x, y), cells.pipes);
  });
  return moved;
}

// Mei's semi-Lagrangian transport (eqs. 2.24-2.25): the share that left through exterior pipes
// is gone; then each cell takes the bilinear value of what stayed at x − (u, v)·Δt (in cells; at
// most the grid's width + height away), a corner off the grid or on no data reading the cell
// itself. With MacCormack's correction (Selle et al. 2008) that value φ̂ is traced forward, to
// x + (u, v)·Δt, by the same rule (φ̌), and the cell takes φ̂ + ½(φ − φ̌), φ what stayed,
// clamped to the least and largest φ of the cell and its 8 neighbours (no data: the cell's own).
template <class Real>
std::vector<Real> backtraced(const Cells<Real>& cells, const std::vector<Real>& field,
                             const std::vector<Fluxes<Real>>& outflow, const std::vector<Real>& added,
                             const PipeState<Real>& flowing, const HydraulicParams& params,
                             const Real& volume_to_depth) {
  const auto& terrain = cells.terrain;
  std::vector<Real> staying = field;
  cells.each([&](int x, int y, std::size_t cell) {
    const Fluxes<Real> shares = water_shares(cells, outflow[cell], added[cell], volume_to_depth);
    Real leaving = Real(0);
    for (int k = 0; k < cells.pipes; ++k) {
      if (!cells.interior(x, y, k)) leaving = leaving + shares[k];
    }
    staying[cell] = field[cell] * (Real(1) - min(Real(1), leaving));
  });
  const Real reach(terrain.width + terrain.height);
  const auto bracket = [&](const Real& displacement) {
    const Real offset = min(reach, max(-reach, displacement));
    const Real below = floor(offset);
    return std::pair{below, offset - below};  // the lower cell and the weight of the upper one
  };
  // `source` bilinearly at the cell moved by `towards`·(u, v)·Δt (−1 back, +1 forward).
  const auto sample = [&](const std::vector<Real>& source, int x, int y, std::size_t cell, int towards) {
    const auto along = [towards](const Real& velocity) { return towards < 0 ? -velocity : velocity; };
    const auto [below_x, upper_x] =
        bracket(along(flowing.velocity_x.values[cell]) * Real(params.time_step / terrain.cell_size_x));
    const auto [below_y, upper_y] =
        bracket(along(flowing.velocity_y.values[cell]) * Real(params.time_step / terrain.cell_size_y));
    const int corner_x = x + static_cast<int>(below_x), corner_y = y + static_cast<int>(below_y);
    const auto at = [&](int dx, int dy) {
      const int cx = corner_x + dx, cy = corner_y + dy;
      return cells.wet(cx, cy) ? source[terrain.index(cx, cy)] : source[cell];
    };
    const Real lower_row = (Real(1) - upper_x) * at(0, 0) + upper_x * at(1, 0);
    const Real upper_row = (Real(1) - upper_x) * at(0, 1) + upper_x * at(1, 1);
    return (Real(1) - upper_y) * lower_row + upper_y * upper_row;
  };
  std::vector<Real> moved = field;
  cells.each([&](int x, int y, std::size_t cell) { moved[cell] = sample(staying, x, y, cell, -1); });
  if (params.transport != SedimentTransport::maccormack) return moved;
  std::vector<Real> corrected = moved;
  cells.each([&](int x, int y, std::size_t cell) {
    const Real returned = sample(moved, x, y, cell, +1);
    Real lowest = staying[cell], highest = staying[cell];
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const Real around = cells.wet(x + dx, y + dy) ? staying[terrain.index(x + dx, y + dy)] : staying[cell];
        lowest = min(lowest, around);
        highest = max(highest, around);
      }
    }
    corrected[cell] = max(lowest, min(highest, moved[cell] + Real(0.5) * (staying[cell] - returned)));
  });
  return corrected;
}

// Seed 001 §3.8's diffusion to the 4 axis neighbours that take part: each gets σ_k of the cell's
// value, σ_k = w (the thesis) or ½d_k/(d + ½Σd_n) over depths `water` (its code; nothing moves
// where that sum is 0); the cell keeps the rest, at least 0.
template <class Real>
std::vector<Real> diffused(const Cells<Real>& cells, const std::vector<Real>& field, const std::vector<Real>& water,
                           const HydraulicParams& params) {
  std::vector<Fluxes<Real>> sent(field.size(), Fluxes<Real>{});
  std::vector<Real> kept(field.size(), Real(0));
  cells.each([&](int x, int y, std::size_t cell) {
    Fluxes<Real> shares{};
    if (params.diffusion_weighting == DiffusionWeighting::uniform) {
      for (int k = 0; k < axis_pipes; ++k) shares[k] = cells.interior(x, y, k) ? Real(params.sediment_diffusion) : Real(0);
    } else {
      Fluxes<Real> halves{};
      for (int k = 0; k < axis_pipes; ++k) {
        if (cells.interior(x, y, k)) halves[k] = Real(0.5) * water[cells.neighbour(x, y, k)];
      }
      const Real weight = water[cell] + total(halves, axis_pipes);
      if (weight > Real(0)) {
        for (int k = 0; k < axis_pipes; ++k) shares[k] = halves[k] / weight;
      }
    }
    for (int k = 0; k < axis_pipes; ++k) sent[cell][k] = field[cell] * shares[k];
    kept[cell] = max(Real(0), field[cell] - total(sent[cell], axis_pipes));
  });
  const Cells<Real> axis{cells.terrain, axis_pipes};
  std::vector<Real> spread = field;
  cells.each([&](int x, int y, std::size_t cell) {
    spread[cell] = kept[cell] + total(arriving(axis, sent, x, y), axis_pipes);
  });
  return spread;
}

}  // namespace

// Šťava's layers at one cell (see the top): the layers of `state` at `cell` (the start's thicknesses)
// lose what the walk takes and the top one gains the deposit; returns taken − deposited.
template <class Real, class CapacityOf>
Real layers_exchange(PipeState<Real>& state, std::size_t cell, const CapacityOf& capacity_of, const Real& suspended,
                     const Real& dissolving, const Real& depositing, const HydraulicParams& params) {
  const bool as_printed = params.layer_erosion == LayerErosion::as_printed;
  const auto constant_of = [&](int layer) { return layer == 0 ? params.capacity : params.layer_capacity[layer - 1]; };
  // The gap that drives erosion of a layer whose capacity left is `left`, 0 where it does not erode.
  const auto erosion_gap = [&](const Real& left) {
    if (as_printed) return left < suspended ? suspended - left : Real(0);
    return left > suspended ? left - suspended : Real(0);
  };
  Real taken(0.0);
  Real buried_above(0.0);
  bool through = true;  // the water got through every layer above
  for (int layer = params.layers; layer >= 1 && through; --layer) {
    Real& thickness = state.layers[static_cast<std::size_t>(layer - 1)].values[cell];
    const Real gap = erosion_gap(capacity_of(constant_of(layer)) - buried_above);
    if (!(gap > Real(0.0))) {
      through = false;
    } else if (dissolving * gap < thickness) {
      thickness = thickness - dissolving * gap;
      taken = taken + dissolving * gap;
      through = false;
    } else {
      taken = taken + thickness;
      buried_above = buried_above + thickness;
      thickness = Real(0.0);
    }
  }
  if (through) taken = taken + dissolving * erosion_gap(capacity_of(params.capacity) - buried_above);
  const Real top_capacity = capacity_of(constant_of(params.layers));
  if (suspended > top_capacity) {
    Real& top = state.layers[static_cast<std::size_t>(params.layers - 1)].values[cell];
    const Real settled = depositing * (suspended - top_capacity);
    top = top + settled;
    taken = taken - settled;
  }
  return taken;
}

template <class Real>
PipeState<Real> pipe_spec_step(const PipeState<Real>& start, const HydraulicParams& params,
                               const HydraulicForcing& forcing) {
  const Cells<Real> cells{start.terrain, params.pipe_count};
  const double cell_area = start.terrain.cell_size_x * start.terrain.cell_size_y;
  const Real volume_to_depth(params.time_step / cell_area);
  PipeState<Real> next = start;

  const std::vector<Real> added = water_after_additions(cells, start.water, params, forcing);
  const std::vector<Fluxes<Real>> outflow = scaled_outflows(cells, start.outflow, added, params);

  // eqs. 2.14-2.19: depth after the flow, and the velocity from the net flux through the cell.
  const double diagonal = std::hypot(start.terrain.cell_size_x, start.terrain.cell_size_y);
  std::vector<Real> flowed(added.size(), Real(0));
  cells.each([&](int x, int y, std::size_t cell) {
    const Fluxes<Real>& out = outflow[cell];
    const Fluxes<Real> in = arriving(cells, outflow, x, y);
    flowed[cell] = max(Real(0), added[cell] - volume_to_depth * total(out, cells.pipes)) +
                   volume_to_depth * total(in, cells.pipes);
    const Real mean_depth = max(Real(params.velocity_depth_floor), Real(0.5) * (added[cell] + flowed[cell]));
    // The net flux along x: each pipe's (out − in) times its x direction and the share of its
    // length along x (1 for L and R, l_x/l_d for a diagonal); along y likewise.
    Real net_x = Real(0), net_y = Real(0);
    for (int k = 0; k < cells.pipes; ++k) {
      const double along_x = k < axis_pipes ? 1.0 : start.terrain.cell_size_x / diagonal;
      const double along_y = k < axis_pipes ? 1.0 : start.terrain.cell_size_y / diagonal;
      const Real net = out[k] - in[k];
      if (pipe_offsets[k].dx != 0) net_x = net_x + Real(pipe_offsets[k].dx * along_x) * net;
      if (pipe_offsets[k].dy != 0) net_y = net_y + Real(pipe_offsets[k].dy * along_y) * net;
    }
    net_x = Real(0.5) * net_x;
    net_y = Real(0.5) * net_y;
    next.velocity_x.values[cell] = net_x / (Real(start.terrain.cell_size_y) * mean_depth);
    next.velocity_y.values[cell] = net_y / (Real(start.terrain.cell_size_x) * mean_depth);
  });

  // eqs. 2.20-2.23: erosion towards the capacity, deposition above it; then seed 001 §3.9's
  // regolith: the water loosens the bed up to r_max = min(d_B, K_r) and lets it settle above.
  const Real dissolving(std::min(1.0, params.dissolving_rate * params.time_step));
  const Real depositing(std::min(1.0, params.deposition_rate * params.time_step));
  const Real loosening(std::min(1.0, params.regolith_dissolving_rate * params.time_step));
  const Real settling(std::min(1.0, params.regolith_deposition_rate * params.time_step));
  const bool regolith = params.regolith_depth > 0.0;
  std::vector<Real> sediment(added.size(), Real(0));
  std::vector<Real> loose(added.size(), Real(0));
  cells.each([&](int x, int y, std::size_t cell) {
    const Real u = next.velocity_x.values[cell];
    const Real v = next.velocity_y.values[cell];
    const Real ramp = params.depth_ramp > 0.0 ? min(Real(1), flowed[cell] / Real(params.depth_ramp)) : Real(1);
    const Real tilt = max(Real(params.min_tilt_sine), tilt_sine(cells, params.tilt_differences, x, y));
    const Real speed = sqrt(u * u + v * v);
    const auto capacity_of = [&](double constant) { return Real(constant) * tilt * speed * ramp; };
    const Real suspended = start.sediment.values[cell];
    const Real capacity = capacity_of(params.capacity);
    const Real taken = params.layers == 0 ? (capacity > suspended ? dissolving * (capacity - suspended)
                                                                  : -(depositing * (suspended - capacity)))
                                          : layers_exchange(next, cell, capacity_of, suspended, dissolving, depositing,
                                                            params);
    Real bed = start.terrain.values[cell] - taken;
    sediment[cell] = suspended + taken;
    if (regolith) {
      const Real most = min(flowed[cell], Real(params.regolith_depth));
      const Real held = start.regolith.values[cell];
      const Real loosened = held < most ? loosening * (most - held) : -(settling * (held - most));
      bed = bed - loosened;
      loose[cell] = held + loosened;
    }
    next.terrain.values[cell] = bed;
  });

  // What the water carries goes with it, then spreads (seed 001 §3.8, the regolith too with
  // regolith_diffusion); the water evaporates (2.25's K_e).
  const auto transported = [&](const std::vector<Real>& field) {
    return params.transport == SedimentTransport::flux
               ? carried_with_water(cells, field, outflow, added, volume_to_depth)
               : backtraced(cells, field, outflow, added, next, params, volume_to_depth);
  };
  sediment = transported(sediment);
  if (regolith) loose = transported(loose);
  if (params.sediment_diffusion > 0.0) {
    sediment = diffused(cells, sediment, flowed, params);
    if (regolith && params.regolith_diffusion) loose = diffused(cells, loose, flowed, params);
  }
  const Real evaporation_kept(1.0 - params.evaporation_rate * params.time_step);
  cells.each([&](int, int, std::size_t cell) {
    next.sediment.values[cell] = sediment[cell];
    if (regolith) next.regolith.values[cell] = loose[cell];
    next.water.values[cell] = flowed[cell] * evaporation_kept;
    for (int k = 0; k < cells.pipes; ++k) next.outflow[cell][k] = outflow[cell][k];
  });
  // Jákó & Tóth's combined step: one iteration of their thermal erosion on the bed, from the
  // thermal spec (compare/algorithms/thermal_specs.hpp).
  if (params.thermal_step) {
    ThermalConstants thermal;
    thermal.talus_slope = std::tan(params.thermal_talus_angle * std::numbers::pi / 180.0);
    thermal.length_x = start.terrain.cell_size_x;
    thermal.length_y = start.terrain.cell_size_y;
    thermal.length_diagonal = std::hypot(thermal.length_x, thermal.length_y);
    thermal.request_factor = params.thermal_rate;
    next.terrain = jako_first_iteration(next.terrain, thermal);
  }
  return next;
}

template PipeState<double> pipe_spec_step(const PipeState<double>&, const HydraulicParams&, const HydraulicForcing&);
template PipeState<RoundingInterval> pipe_spec_step(const PipeState<RoundingInterval>&, const HydraulicParams&,
                                                    const HydraulicForcing&);

}  // namespace gt
