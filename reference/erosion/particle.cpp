// Particle (droplet) water erosion of seed 000 (Hydra, §4.4.1: Algorithms 4-7, eqs. 4.5-4.6), CPU
// reference, ported from the upstream kernel as digest 000 Appendix A gives it (erosion.frag of
// 1a1a8c9), which the digest names authoritative where the thesis's printed algorithms differ:
//   - acceleration only along the motion, per axis, with nested branches (not Algorithm 4's
//     fall-through); none towards a neighbour more than drop_max lower; a droplet lower than its
//     four neighbours stops (pit stop);
//   - drag multiplies the velocity; the speed is clamped to v_max (not rescaled to it, Algorithm 5
//     as printed); capacity = f_c·|v|; the droplet moves by the unit vector of its velocity;
//   - erosion bounded by the neighbourhood minimum, spread over the 4 texel centres around the
//     droplet with bilinear weights (Algorithm 6), the lower corner taken by truncation
//     (ivec2(pos - 0.5)) as upstream, so a droplet within half a texel of x = 0 or y = 0 gets
//     weights outside [0, 1]; unbilinear erosion stored as max(h - add, 0);
//   - deposition at the droplet's texel only, bounded by the highest neighbour;
//   - the start texel ivec2(fragcoord)·subdiv + off, position + 0.5 (eq. 4.6 read as upstream);
//   - the loop ends when a coordinate of the position is <= 0; nothing checks the far edges:
//     reads outside give 0 and writes there are lost (GLSL images), emulated here, masked cells
//     alike.
//   - colour transport (§4.5, Algorithm 8, eq. 4.9, Appendix A's useColor branches), when a colour
//     map is given: a droplet starts with the colour of its start texel; on erosion (inside
//     h > min_h, after the erosion) col = f_col·C(ipos) + (1 - f_col)·col; on deposition (after the
//     height) colorize4 at the 4 texel centres of erode4 (the same truncated corner and weight
//     products) with factor f_col·w: C = C·(1 - factor) + col·factor, no height condition; without
//     interpolate_colour C(ipos) = C(ipos)·(1 - f_col) + f_col·col. (1 - f_col) and (1 - factor)
//     are rounded once, the operations in this order in both twins.
// Decisions of this project: the droplets of one pass run in row-major order of their
// blocks (the truth), or in batch ordering against the pass's frozen heights with integer quanta
// (core/params/particle.hpp). Units: texels and steps; heights in the units of the constants.
// Batch ordering and colour: the colour is frozen during the pass like the heights (pick-ups read
// the pass's start colour), and a blend being order-dependent, each cell's colour at the pass's end
// is the weighted mean of its start colour (weight 1) and the colours deposited there (weights
// f_col·w_k, or f_col at ipos without interpolation), summed as fixed-point integers of 2^-20
// (ColourDelta in reference/erosion/droplets.hpp): every channel stays within the range of the
// colours involved while the weights are in [0, 1] (up to those quanta). Near x = 0 or y = 0 the
// truncated corner gives weights outside [0, 1] (as erode4's), and the colour may leave that range
// there, in every ordering, as upstream.
// Side maps: what each droplet eroded (erode()'s return: add·Σw, or add) and deposited, at its texel
// ipos when open, summed in Real in droplet order (map = map + amount, the GPU's read-modify-write)
// or, in batch, as counts of the quanta the heights moved (the corners' quanta summed; the deposit's),
// converted when the run ends as Real(count)·quantum. No contrast (Hydra's cE, cD) is applied.
#include "reference/erosion/particle.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "core/mutant.hpp"
#include "reference/erosion/hydra_motion.hpp"

namespace gt::reference {
namespace {

template <class Real>
struct Kernel {
  explicit Kernel(const ParticleConstants& c)
      : acceleration(static_cast<Real>(c.acceleration)),
        bite(static_cast<Real>(c.bite)),
        release(static_cast<Real>(c.release)),
        max_velocity(static_cast<Real>(c.max_velocity)),
        drag(static_cast<Real>(c.drag)),
        capacity_factor(static_cast<Real>(c.capacity_factor)),
        max_jump(static_cast<Real>(c.max_jump)),
        quantum(static_cast<Real>(c.quantum)),
        inverse_quantum(static_cast<Real>(1.0 / c.quantum)),
        colour_mixing(static_cast<Real>(c.colour_mixing)),
        colour_kept(Real(1) - colour_mixing),
        lifetime(c.lifetime),
        interpolate(c.interpolate),
        interpolate_colour(c.interpolate_colour) {}
  Real acceleration, bite, release, max_velocity, drag, capacity_factor, max_jump, quantum, inverse_quantum;
  Real colour_mixing;  // f_col
  Real colour_kept;    // 1 - f_col, rounded once
  int lifetime;
  bool interpolate;
  bool interpolate_colour;
  // The deliberate bugs of compare/mutants/particle.cpp that live in both twins.
  bool rescaled_velocity = mutant_active("erosion.particle.rescaled_velocity");
  bool kept_sediment_on_deposit = mutant_active("erosion.particle.kept_sediment_on_deposit");
  bool unbounded_erosion = mutant_active("erosion.particle.unbounded_erosion");
  bool colour_kept_whole = mutant_active("erosion.particle.colour_kept_whole");
  bool step_by_velocity = mutant_active("erosion.particle.step_by_velocity");
};

template <class Real>
using Colour = std::array<Real, 4>;  // RGBA

// The side maps while a run goes: sequential, Real sums in droplet order; batch, counts of quanta.
template <class Real>
struct SideSums {
  SideSums(std::size_t cells, bool batch) {
    if (batch) {
      eroded_quanta.assign(cells, 0);
      deposited_quanta.assign(cells, 0);
    } else {
      eroded.assign(cells, Real(0));
      deposited.assign(cells, Real(0));
    }
  }
  std::vector<Real> eroded, deposited;
  std::vector<long long> eroded_quanta, deposited_quanta;
};

// What erode() moved: the amount (sequential) or its quanta (batch) the droplet picked up.
template <class Real>
struct Moved {
  Real amount = 0;
  long long quanta = 0;
};

// The heights (and colour, when transported) the droplets of one pass see and change, with what
// they did to them. Sequential: reads and writes go to the run's maps. Batch: reads see the maps as
// the pass found them and changes collect in `delta` (and `colour_delta`) until apply().
template <class Real>
class PassTerrain {
 public:
  PassTerrain(DropletRun<Real>& run, const Kernel<Real>& kernel, bool batch, SideSums<Real>& sides)
      : run_(run), kernel_(kernel), sides_(sides), colour_(run.colour.values.empty() ? nullptr : &run.colour) {
    if (batch) delta_.emplace(run.heights.size(), kernel.quantum, "erosion.particle");
    if (batch && colour_ != nullptr) colour_delta_.emplace(run.heights.size(), "erosion.particle");
  }

  bool holds(Texel t) const { return run_.heights.inside(t.x, t.y) && run_.heights.is_valid(t.x, t.y); }
  Real load(Texel t) const { return holds(t) ? run_.heights.at(t.x, t.y) : Real(0); }
  bool batch() const { return delta_.has_value(); }
  bool colours() const { return colour_ != nullptr; }
  DropletLedger& ledger() { return run_.ledger; }

  long long quanta(Real amount) const {
    return static_cast<long long>(std::nearbyint(amount * kernel_.inverse_quantum));
  }

  // Sequential: the texel's height becomes `value`.
  void store(Texel t, Real value) {
    if (holds(t)) run_.heights.at(t.x, t.y) = value;
  }
  // Batch: `count` quanta more (negative: fewer) at the texel when the pass ends.
  void add_quanta(Texel t, long long count) {
    if (holds(t)) delta_->add(run_.heights.index(t.x, t.y), count);
  }

  // The texel's colour; (0, 0, 0, 0) off the grid and on masked texels.
  Colour<Real> load_colour(Texel t) const { return holds(t) ? colour_->at(t.x, t.y) : Colour<Real>{}; }
  // Sequential: the texel's colour becomes `value`.
  void store_colour(Texel t, const Colour<Real>& value) {
    if (holds(t)) colour_->at(t.x, t.y) = value;
  }
  // Batch: `colour` deposited with weight `factor` at the texel when the pass ends.
  void add_colour(Texel t, Real factor, const Colour<Real>& colour) {
    if (holds(t)) colour_delta_->add(run_.heights.index(t.x, t.y), factor, colour);
  }

  void mark_eroded(Texel at, const Moved<Real>& eroded) {
    if (!holds(at)) return;
    const std::size_t i = run_.heights.index(at.x, at.y);
    if (batch()) {
      sides_.eroded_quanta[i] += eroded.quanta;
    } else {
      sides_.eroded[i] = sides_.eroded[i] + eroded.amount;
    }
  }
  void mark_deposited(Texel at, Real amount, long long quanta) {
    if (!holds(at)) return;
    const std::size_t i = run_.heights.index(at.x, at.y);
    if (batch()) {
      sides_.deposited_quanta[i] += quanta;
    } else {
      sides_.deposited[i] = sides_.deposited[i] + amount;
    }
  }

  // Batch: heights + delta·quantum rounded to Real, then the colours' weighted means, as
  // particle_apply.comp does.
  void apply() {
    if (delta_) delta_->apply(run_.heights, run_.ledger);
    if (colour_delta_) colour_delta_->apply(*colour_);
  }

 private:
  DropletRun<Real>& run_;
  const Kernel<Real>& kernel_;
  SideSums<Real>& sides_;
  ColourMap<Real>* colour_;                         // null when no colour is transported
  std::optional<BatchDelta<Real>> delta_;           // batch ordering only
  std::optional<ColourDelta<Real>> colour_delta_;   // batch ordering with colour only
};

template <class Real>
struct Droplet {
  Real pos_x, pos_y;
  Texel texel;
  Real vel_x = 0, vel_y = 0;
  Real sediment = 0;            // sequential
  long long sediment_quanta = 0;  // batch
  Colour<Real> colour{};        // col, when colour is transported
};

template <class Real>
struct Neighbourhood {
  Real below, left, right, above;  // (0,-1), (-1,0), (+1,0), (0,+1): upstream n0..n3
  Real lowest, highest;
};

template <class Real>
Neighbourhood<Real> neighbourhood(const PassTerrain<Real>& terrain, Texel t) {
  Neighbourhood<Real> n{terrain.load({t.x, t.y - 1}), terrain.load({t.x - 1, t.y}), terrain.load({t.x + 1, t.y}),
                        terrain.load({t.x, t.y + 1}), Real(0), Real(0)};
  n.highest = std::max(std::max(n.below, n.left), std::max(n.right, n.above));
  n.lowest = std::min(std::min(n.below, n.left), std::min(n.right, n.above));
  return n;
}

// Algorithm 6 as upstream's erode4: the amount removed at each corner higher than the
// neighbourhood minimum; returns the weight of the corners eroded and (batch) their quanta.
template <class Real>
std::pair<Real, long long> erode_corners(PassTerrain<Real>& terrain, Droplet<Real>& drop, Real amount, Real lowest) {
  const Corners<Real> corners = corners_around(drop.pos_x, drop.pos_y);
  Real eroded_weight = 0;
  long long eroded_quanta = 0;
  DropletLedger& ledger = terrain.ledger();
  for (int k = 0; k < 4; ++k) {
    const Texel cell = corners.cells[k];
    const Real height = terrain.load(cell);
    if (!(height > lowest)) continue;
    const Real taken = amount * corners.weights[k];
    if (terrain.batch()) {
      const long long quanta = terrain.quanta(taken);
      terrain.add_quanta(cell, -quanta);
      drop.sediment_quanta += quanta;
      eroded_quanta += quanta;
      (terrain.holds(cell) ? ledger.eroded_quanta : ledger.eroded_outside_quanta) += quanta;
    } else {
      terrain.store(cell, height - taken);
      (terrain.holds(cell) ? ledger.eroded : ledger.eroded_outside) += static_cast<double>(taken);
    }
    eroded_weight = eroded_weight + corners.weights[k];
  }
  return {eroded_weight, eroded_quanta};
}

// The erosion branch: `add` bounded by the neighbourhood minimum, spread or at the texel. Returns
// what the droplet picked up (for the side map): the amount, or in batch its quanta.
template <class Real>
Moved<Real> erode(PassTerrain<Real>& terrain, Droplet<Real>& drop, Real height, Real add, Real lowest,
                  const Kernel<Real>& k) {
  DropletLedger& ledger = terrain.ledger();
  if (k.interpolate) {
    const auto [weight, quanta] = erode_corners(terrain, drop, add, lowest);
    const Real picked = add * weight;
    if (!terrain.batch()) drop.sediment = drop.sediment + picked;
    return {picked, quanta};
  }
  const Real removed = height - std::max(height - add, Real(0));
  if (terrain.batch()) {
    const long long removed_quanta = terrain.quanta(removed), added_quanta = terrain.quanta(add);
    terrain.add_quanta(drop.texel, -removed_quanta);
    drop.sediment_quanta += added_quanta;
    (terrain.holds(drop.texel) ? ledger.eroded_quanta : ledger.eroded_outside_quanta) += removed_quanta;
    ledger.clamp_created_quanta += added_quanta - removed_quanta;
    return {add, added_quanta};
  }
  terrain.store(drop.texel, std::max(height - add, Real(0)));
  drop.sediment = drop.sediment + add;
  (terrain.holds(drop.texel) ? ledger.eroded : ledger.eroded_outside) += static_cast<double>(removed);
  ledger.clamp_created += static_cast<double>(add) - static_cast<double>(removed);
  return {add, 0};
}

// The deposition branch, at the droplet's texel only. Returns (batch) the quanta deposited.
template <class Real>
long long deposit(PassTerrain<Real>& terrain, Droplet<Real>& drop, Real height, Real add, const Kernel<Real>& k) {
  DropletLedger& ledger = terrain.ledger();
  if (terrain.batch()) {
    const long long quanta = terrain.quanta(add);
    terrain.add_quanta(drop.texel, quanta);
    if (!k.kept_sediment_on_deposit) drop.sediment_quanta -= quanta;
    (terrain.holds(drop.texel) ? ledger.deposited_quanta : ledger.deposited_outside_quanta) += quanta;
    return quanta;
  }
  terrain.store(drop.texel, height + add);
  if (!k.kept_sediment_on_deposit) drop.sediment = drop.sediment - add;
  (terrain.holds(drop.texel) ? ledger.deposited : ledger.deposited_outside) += static_cast<double>(add);
  return 0;
}

// Eq. 4.9 on erosion: col = f_col·C(ipos) + (1 - f_col)·col (batch: the pass's start colour).
template <class Real>
void pick_up_colour(const PassTerrain<Real>& terrain, Droplet<Real>& drop, const Kernel<Real>& k) {
  const Colour<Real> texel = terrain.load_colour(drop.texel);
  for (int ch = 0; ch < 4; ++ch) drop.colour[ch] = k.colour_mixing * texel[ch] + k.colour_kept * drop.colour[ch];
}

// `factor` of the droplet's colour blended into the texel: C·(1 - factor) + col·factor (sequential),
// or the weighted deposit of the batch ordering.
template <class Real>
void blend_colour(PassTerrain<Real>& terrain, const Droplet<Real>& drop, Texel cell, Real factor,
                  const Kernel<Real>& k) {
  if (terrain.batch()) {
    terrain.add_colour(cell, factor, drop.colour);
    return;
  }
  const Real rest = k.colour_kept_whole ? Real(1) : Real(1) - factor;
  Colour<Real> colour = terrain.load_colour(cell);
  for (int ch = 0; ch < 4; ++ch) colour[ch] = colour[ch] * rest + drop.colour[ch] * factor;
  terrain.store_colour(cell, colour);
}

// The colour deposit after a height deposit: colorize4 (Algorithm 8, factor f_col·w at erode4's 4
// corners, no height condition) or, without interpolation, C(ipos) = C(ipos)·(1 - f_col) + f_col·col.
template <class Real>
void deposit_colour(PassTerrain<Real>& terrain, const Droplet<Real>& drop, const Kernel<Real>& k) {
  if (k.interpolate_colour) {
    const Corners<Real> corners = corners_around(drop.pos_x, drop.pos_y);
    for (int c = 0; c < 4; ++c) blend_colour(terrain, drop, corners.cells[c], k.colour_mixing * corners.weights[c], k);
    return;
  }
  if (terrain.batch()) {
    terrain.add_colour(drop.texel, k.colour_mixing, drop.colour);
    return;
  }
  Colour<Real> colour = terrain.load_colour(drop.texel);
  for (int ch = 0; ch < 4; ++ch) colour[ch] = colour[ch] * k.colour_kept + k.colour_mixing * drop.colour[ch];
  terrain.store_colour(drop.texel, colour);
}

// One step of a droplet (Appendix A's loop body); false when the droplet left across x or y <= 0.
template <class Real>
bool step(PassTerrain<Real>& terrain, Droplet<Real>& drop, const Kernel<Real>& k) {
  const Neighbourhood<Real> n = neighbourhood(terrain, drop.texel);
  Real height = terrain.load(drop.texel);
  drop.vel_x = accelerate_axis(drop.vel_x, height, n.right, n.left, k.acceleration, k.max_jump);
  drop.vel_y = accelerate_axis(drop.vel_y, height, n.above, n.below, k.acceleration, k.max_jump);
  if (height < n.lowest) drop.vel_x = drop.vel_y = 0;  // pit stop
  drop.vel_x = drop.vel_x * k.drag;
  drop.vel_y = drop.vel_y * k.drag;
  Real speed = std::sqrt(drop.vel_x * drop.vel_x + drop.vel_y * drop.vel_y);
  const Real norm_x = speed == 0 ? drop.vel_x : drop.vel_x / speed;
  const Real norm_y = speed == 0 ? drop.vel_y : drop.vel_y / speed;
  if (k.rescaled_velocity ? speed != 0 : speed > k.max_velocity) {
    speed = k.max_velocity;
    drop.vel_x = norm_x * k.max_velocity;
    drop.vel_y = norm_y * k.max_velocity;
  }
  const Real capacity = k.capacity_factor * speed;
  const Real carried = terrain.batch() ? static_cast<Real>(drop.sediment_quanta) * k.quantum : drop.sediment;
  Real difference = capacity - carried;
  height = terrain.load(drop.texel);  // re-read, as upstream
  if (difference > 0) {
    difference = difference * k.bite;
    if (height > n.lowest) {
      const Real add = k.unbounded_erosion ? difference : std::min(difference, height - n.lowest);
      const Moved<Real> eroded = erode(terrain, drop, height, add, n.lowest, k);
      if (terrain.colours()) pick_up_colour(terrain, drop, k);
      terrain.mark_eroded(drop.texel, eroded);
    }
  } else if (height < n.highest) {
    difference = difference * k.release;
    const Real add = std::min(-difference, n.highest - height);
    const long long quanta = deposit(terrain, drop, height, add, k);
    if (terrain.colours()) deposit_colour(terrain, drop, k);
    terrain.mark_deposited(drop.texel, add, quanta);
  }
  drop.pos_x = drop.pos_x + (k.step_by_velocity ? drop.vel_x : norm_x);
  drop.pos_y = drop.pos_y + (k.step_by_velocity ? drop.vel_y : norm_y);
  drop.texel = {static_cast<int>(drop.pos_x), static_cast<int>(drop.pos_y)};
  return !(drop.pos_x <= 0 || drop.pos_y <= 0);
}

// A droplet at rest at the centre of texel `base`, carrying that texel's colour when colour is
// transported.
template <class Real>
Droplet<Real> start_droplet(const PassTerrain<Real>& terrain, int base_x, int base_y) {
  Droplet<Real> drop{static_cast<Real>(base_x) + Real(0.5), static_cast<Real>(base_y) + Real(0.5), {base_x, base_y}};
  if (terrain.colours()) drop.colour = terrain.load_colour(drop.texel);
  return drop;
}

// Runs a droplet's life; the sediment it still carries leaves the terrain with it.
template <class Real>
void run_droplet(PassTerrain<Real>& terrain, Droplet<Real>& drop, const Kernel<Real>& k,
                 std::vector<std::pair<Real, Real>>* path = nullptr) {
  DropletLedger& ledger = terrain.ledger();
  ++ledger.droplets;
  bool left = false;
  for (int s = 0; s < k.lifetime && !left; ++s) {
    left = !step(terrain, drop, k);
    ++ledger.steps;
    if (path != nullptr) path->emplace_back(drop.pos_x, drop.pos_y);
  }
  if (left) ++ledger.droplets_left;
  if (terrain.batch()) {
    ledger.sediment_end_quanta += drop.sediment_quanta;
    (left ? ledger.sediment_left : ledger.sediment_at_end) +=
        static_cast<double>(drop.sediment_quanta) * static_cast<double>(k.quantum);
  } else {
    (left ? ledger.sediment_left : ledger.sediment_at_end) += static_cast<double>(drop.sediment);
  }
}

// Batch: the ledger's amounts from its exact counts of quanta (sediment_at_end and _left are
// summed per droplet as they end).
void express_quanta(DropletLedger& ledger, double quantum) {
  ledger.eroded = static_cast<double>(ledger.eroded_quanta) * quantum;
  ledger.deposited = static_cast<double>(ledger.deposited_quanta) * quantum;
  ledger.eroded_outside = static_cast<double>(ledger.eroded_outside_quanta) * quantum;
  ledger.deposited_outside = static_cast<double>(ledger.deposited_outside_quanta) * quantum;
  ledger.clamp_created = static_cast<double>(ledger.clamp_created_quanta) * quantum;
}

// One draw of Algorithm 7: a droplet per block of the ceil(W/S) x ceil(H/S) grid, row-major.
template <class Real>
void run_pass(DropletRun<Real>& run, const Kernel<Real>& k, SideSums<Real>& sides, int spacing, Texel offset,
              bool batch) {
  PassTerrain<Real> terrain(run, k, batch, sides);
  const int blocks_x = (run.heights.width + spacing - 1) / spacing;
  const int blocks_y = (run.heights.height + spacing - 1) / spacing;
  for (int j = 0; j < blocks_y; ++j) {
    for (int i = 0; i < blocks_x; ++i) {
      Droplet<Real> drop = start_droplet(terrain, i * spacing + offset.x, j * spacing + offset.y);
      run_droplet(terrain, drop, k);
    }
  }
  terrain.apply();
}

// The side maps from their sums: the Real sums as they are, or Real(count)·quantum (the GPU's int32
// counts converted on download; a count beyond int32 is refused).
template <class Real>
void express_side_maps(DropletRun<Real>& run, const SideSums<Real>& sides, const Kernel<Real>& k, bool batch) {
  const auto express = [&](const std::vector<Real>& sums, const std::vector<long long>& counts, Grid<double>& map,
                           const char* name) {
    for (std::size_t i = 0; i < map.size(); ++i) {
      if (!batch) {
        map.values[i] = static_cast<double>(sums[i]);
        continue;
      }
      if (std::llabs(counts[i]) > std::numeric_limits<std::int32_t>::max()) {
        throw std::runtime_error(fmt::format(
            "erosion.particle: the batch side map `{}` holds {} quanta in one cell, beyond the GPU's 32-bit counter; "
            "use fewer iterations",
            name, counts[i]));
      }
      map.values[i] = static_cast<double>(static_cast<Real>(counts[i]) * k.quantum);
    }
  };
  express(sides.eroded, sides.eroded_quanta, run.eroded_at_droplet, "eroded_at_droplet");
  express(sides.deposited, sides.deposited_quanta, run.deposited_at_droplet, "deposited_at_droplet");
}

template <class Real>
DropletRun<Real> empty_run(const Grid<Real>& heights) {
  DropletRun<Real> run{heights, heights.template cast<double>(), heights.template cast<double>(), {}, {}};
  std::fill(run.eroded_at_droplet.values.begin(), run.eroded_at_droplet.values.end(), 0.0);
  std::fill(run.deposited_at_droplet.values.begin(), run.deposited_at_droplet.values.end(), 0.0);
  return run;
}

template <class Real>
void check_colour_size(const Grid<Real>& heights, const ColourMap<Real>& colour, const char* what) {
  if (colour.width != heights.width || colour.height != heights.height || colour.size() != heights.size()) {
    throw std::invalid_argument(fmt::format("{}: the colour map's size differs from the heights'", what));
  }
}

}  // namespace

template <class Real>
DropletRun<Real> particle_erosion(const Grid<Real>& heights, const ParticleConstants& constants, int iterations,
                                   DropletOrdering ordering, const ColourMap<Real>* colour) {
  const Kernel<Real> kernel(constants);
  DropletRun<Real> run = empty_run(heights);
  if (colour != nullptr) {
    check_colour_size(heights, *colour, "particle_erosion");
    run.colour = *colour;
  }
  const bool batch = ordering == DropletOrdering::batch;
  SideSums<Real> sides(heights.size(), batch);
  for (int iteration = 0; iteration < iterations; ++iteration) {
    for (int y = 0; y < constants.spacing; ++y) {
      for (int x = 0; x < constants.spacing; ++x) run_pass(run, kernel, sides, constants.spacing, {x, y}, batch);
    }
  }
  express_side_maps(run, sides, kernel, batch);
  if (batch) express_quanta(run.ledger, constants.quantum);
  return run;
}

template <class Real>
DropletPath<Real> run_one_droplet(Grid<Real>& heights, const ParticleConstants& constants, int base_x, int base_y,
                                  ColourMap<Real>* colour) {
  const Kernel<Real> kernel(constants);
  DropletRun<Real> run = empty_run(heights);
  if (colour != nullptr) {
    check_colour_size(heights, *colour, "run_one_droplet");
    run.colour = *colour;
  }
  SideSums<Real> sides(heights.size(), false);
  PassTerrain<Real> terrain(run, kernel, false, sides);
  DropletPath<Real> path;
  Droplet<Real> drop = start_droplet(terrain, base_x, base_y);
  path.positions.emplace_back(drop.pos_x, drop.pos_y);
  run_droplet(terrain, drop, kernel, &path.positions);
  path.sediment = drop.sediment;
  heights = run.heights;
  if (colour != nullptr) *colour = run.colour;
  return path;
}

template DropletRun<double> particle_erosion(const Grid<double>&, const ParticleConstants&, int, DropletOrdering,
                                             const ColourMap<double>*);
template DropletRun<float> particle_erosion(const Grid<float>&, const ParticleConstants&, int, DropletOrdering,
                                            const ColourMap<float>*);
template DropletPath<double> run_one_droplet(Grid<double>&, const ParticleConstants&, int, int, ColourMap<double>*);
template DropletPath<float> run_one_droplet(Grid<float>&, const ParticleConstants&, int, int, ColourMap<float>*);

}  // namespace gt::reference
