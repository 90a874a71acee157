// Particle (droplet) hydraulic erosion after Beyer 2015 (seed 000 §2.7, eqs. 2.35-2.45; digest 000
// §3.7 and Appendix B item 6), CPU reference. A droplet has a position p (texels), a unit direction,
// a speed, water and sediment; each step (at most `lifetime`) it
//   1. reads the bilinear height h_old and the gradient g (eq. 2.35) at p;
//   2. turns: dir = dir·c_i - g·(1 - c_i), normalised (eq. 2.36); a zero dir becomes one of the 8
//      compass directions (1,0), (s,s), (0,1), (-s,s), (-1,0), (-s,-s), (0,-1), (s,-s),
//      s = 0.70710678118654752 rounded to Real, picked by random_u32(seed, droplet, step, 0) % 8
//      (a random angle through cos/sin would part the twins);
//   3. moves p_new = p + dir (eq. 2.37); off the map it ends, "left", before eroding anything;
//   4. dh = h(p_new) - h_old (eq. 2.38);
//   5. uphill (dh > 0) deposits min(dh, sediment) at the old position; otherwise with capacity
//      C = c_c·max(-dh, c_min)·v·w (eq. 2.39) it deposits c_d·(s - C) when s > C (eq. 2.40), or
//      erodes min(c_e·(C - s), -dh) (eq. 2.41) with the radius brush of eq. 2.42;
//   6. v = sqrt(max(v² - dh·c_g, 0)) (eq. 2.44 with the physically intended sign; `printed`:
//      v² + dh·c_g as printed); 7. w = w·(1 - c_evap) (eq. 2.45); 8. p = p_new.
// After each outer iteration (every texel has released its droplet) the heights are blended with
// their blur when c_b > 0 (eq. 2.43, reference/erosion/blur_blend.hpp): in place in race and
// disjoint, as quanta through one more batch apply in batch.
// Decisions of this project (digest notes, Appendix B item 6):
//   - heights are samples at integer points; a position's cell is floor(p), its offsets (u, v) =
//     p - cell; a droplet is on the map when the cell's four samples exist and are valid, so reads
//     never leave the map; a droplet starting off it does nothing (a droplet of 0 steps that left);
//   - deposits are bilinear over the old cell's four samples (weights (1-u)(1-v), u(1-v), (1-u)v,
//     uv); erosion uses eq. 2.42's cone centred at the OLD position (Beyer's choice), renormalised
//     over the samples inside the grid and valid;
//   - the sediment a droplet carries when it leaves or its lifetime runs out leaves the terrain.
// Ordering (core/params/droplets.hpp): race and disjoint run the droplets of a pass in row-major
// order of their block (the truth); batch against the pass's frozen heights with integer quanta.
// Batch droplets are blind to each other within a pass: those that converge on a pit all erode its
// rim and refill it, so at small spacings the delta can outgrow int32 (apply() throws, as particle).
// Every operation is spelled out in the shader's order (gpu/shaders/erosion/beyer_droplets.comp);
// max/min are std::max/std::min. Units: texels and steps; heights in the units of the constants.
// Mutants (compare/mutants/beyer.cpp) in both twins: sediment_not_taken_on_erosion (material
// destroyed), uphill_deposit_unbounded (deposits dh uphill and clamps the droplet's sediment at 0:
// material created); the GPU-only ones live in the shader.
#include "reference/erosion/beyer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "core/mutant.hpp"
#include "core/rng.hpp"
#include "reference/erosion/blur_blend.hpp"

namespace gt::reference {
namespace {

template <class Real>
struct Kernel {
  explicit Kernel(const BeyerConstants& c)
      : inertia(static_cast<Real>(c.inertia)),
        gradient_share(Real(1) - inertia),
        capacity_factor(static_cast<Real>(c.capacity_factor)),
        min_slope(static_cast<Real>(c.min_slope)),
        deposition(static_cast<Real>(c.deposition)),
        erosion(static_cast<Real>(c.erosion)),
        gravity(static_cast<Real>(c.gravity)),
        water_kept(Real(1) - static_cast<Real>(c.evaporation)),
        radius(static_cast<Real>(c.radius)),
        initial_speed(static_cast<Real>(c.initial_speed)),
        initial_water(static_cast<Real>(c.initial_water)),
        quantum(static_cast<Real>(c.quantum)),
        inverse_quantum(static_cast<Real>(1.0 / c.quantum)),
        blur_blend(c.blur_blend),
        lifetime(c.lifetime),
        seed(c.seed),
        printed_speed(c.speed_rule == BeyerSpeedRule::printed) {}
  Real inertia;
  Real gradient_share;  // 1 - c_i, computed once in Real
  Real capacity_factor, min_slope, deposition, erosion, gravity;
  Real water_kept;  // 1 - c_evap, computed once in Real
  Real radius, initial_speed, initial_water, quantum, inverse_quantum;
  Real diagonal = static_cast<Real>(0.70710678118654752);  // s of the compass directions
  double blur_blend;  // c_b of eq. 2.43 (blur_blend.cpp rounds its weight)
  int lifetime;
  std::uint32_t seed;
  bool printed_speed;
  // The deliberate bugs of compare/mutants/beyer.cpp that live in both twins.
  bool sediment_not_taken_on_erosion = mutant_active("erosion.beyer.sediment_not_taken_on_erosion");
  bool uphill_deposit_unbounded = mutant_active("erosion.beyer.uphill_deposit_unbounded");
};

struct Texel {
  int x;
  int y;
};

// The bilinear corners in the order they are visited: (0,0), (1,0), (0,1), (1,1).
constexpr Texel corner_offsets[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};

// A sample the droplets may read and change: inside the grid and valid.
template <class Real>
bool holds(const Grid<Real>& heights, Texel t) {
  return heights.inside(t.x, t.y) && heights.is_valid(t.x, t.y);
}

// The heights the droplets of one pass see and change, with what they did to them. Sequential:
// reads and writes go to the heights. Batch: reads see the heights as the pass found them and
// changes collect as quanta in `delta` until apply().
template <class Real>
class PassTerrain {
 public:
  PassTerrain(DropletRun<Real>& run, const Kernel<Real>& kernel, bool batch)
      : run_(run), kernel_(kernel) {
    if (batch) delta_.emplace(run.heights.size(), kernel.quantum, "erosion.beyer");
  }

  const Grid<Real>& heights() const { return run_.heights; }
  bool holds(Texel t) const { return reference::holds(run_.heights, t); }
  Real load(Texel t) const { return run_.heights.at(t.x, t.y); }  // a held sample only
  bool batch() const { return delta_.has_value(); }
  DropletLedger& ledger() { return run_.ledger; }

  long long quanta(Real amount) const {
    return static_cast<long long>(std::nearbyint(amount * kernel_.inverse_quantum));
  }

  // Sequential: the held sample's height becomes `value`.
  void store(Texel t, Real value) { run_.heights.at(t.x, t.y) = value; }
  // Batch: `count` quanta more (negative: fewer) at the held sample when the pass ends.
  void add_quanta(Texel t, long long count) { delta_->add(run_.heights.index(t.x, t.y), count); }

  void mark_side_maps(Texel at, double eroded, double deposited) {
    if (!holds(at)) return;
    run_.eroded_at_droplet.at(at.x, at.y) += eroded;
    run_.deposited_at_droplet.at(at.x, at.y) += deposited;
  }

  // Batch: heights + delta·quantum rounded to Real, as beyer_apply.comp does.
  void apply() {
    if (delta_) delta_->apply(run_.heights, run_.ledger);
  }


 private:
  DropletRun<Real>& run_;
  const Kernel<Real>& kernel_;
  std::optional<BatchDelta<Real>> delta_;  // batch ordering only
};

template <class Real>
struct Droplet {
  Real x, y;                      // position p, texels
  Real dir_x = 0, dir_y = 0;      // unit direction (0 at the start)
  Real speed, water;
  std::uint32_t id;               // RNG counter of its random directions
  Real sediment = 0;              // sequential
  long long sediment_quanta = 0;  // batch
};

// Where a droplet stands: its cell (the (0,0) corner), the offsets inside it and the 4 samples.
template <class Real>
struct Footing {
  Texel cell;
  Real u, v;            // p - cell
  Real rest_u, rest_v;  // 1 - u, 1 - v, computed once
  Real h00, h10, h01, h11;
};

// The footing at (x, y), none when the droplet is off the map (a corner outside or not valid).
template <class Real>
std::optional<Footing<Real>> footing(const PassTerrain<Real>& terrain, Real x, Real y) {
  const Texel cell{static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y))};
  for (const Texel offset : corner_offsets) {
    if (!terrain.holds({cell.x + offset.x, cell.y + offset.y})) return std::nullopt;
  }
  Footing<Real> f{cell, x - static_cast<Real>(cell.x), y - static_cast<Real>(cell.y), 0, 0, 0, 0, 0, 0};
  f.rest_u = Real(1) - f.u;
  f.rest_v = Real(1) - f.v;
  f.h00 = terrain.load(cell);
  f.h10 = terrain.load({cell.x + 1, cell.y});
  f.h01 = terrain.load({cell.x, cell.y + 1});
  f.h11 = terrain.load({cell.x + 1, cell.y + 1});
  return f;
}

// The bilinear height: the bottom row (y = cell.y) and the top row blended along y.
template <class Real>
Real height_at(const Footing<Real>& f) {
  const Real bottom = f.h00 * f.rest_u + f.h10 * f.u;
  const Real top = f.h01 * f.rest_u + f.h11 * f.u;
  return bottom * f.rest_v + top * f.v;
}

template <class Real>
struct Gradient {
  Real x, y;
};

// Eq. 2.35.
template <class Real>
Gradient<Real> gradient_at(const Footing<Real>& f) {
  return {(f.h10 - f.h00) * f.rest_v + (f.h11 - f.h01) * f.v, (f.h01 - f.h00) * f.rest_u + (f.h11 - f.h10) * f.u};
}

// Eq. 2.36: the direction turns towards -g by 1 - c_i and is normalised; a zero direction becomes
// the compass direction random_u32(seed, droplet, age, 0) % 8.
template <class Real>
void turn(Droplet<Real>& drop, Gradient<Real> g, int age, const Kernel<Real>& k) {
  drop.dir_x = drop.dir_x * k.inertia - g.x * k.gradient_share;
  drop.dir_y = drop.dir_y * k.inertia - g.y * k.gradient_share;
  const Real length = std::sqrt(drop.dir_x * drop.dir_x + drop.dir_y * drop.dir_y);
  if (length != 0) {
    drop.dir_x = drop.dir_x / length;
    drop.dir_y = drop.dir_y / length;
    return;
  }
  const Real s = k.diagonal;
  const Real compass[8][2] = {{1, 0}, {s, s}, {0, 1}, {-s, s}, {-1, 0}, {-s, -s}, {0, -1}, {s, -s}};
  const std::uint32_t pick = random_u32(k.seed, drop.id, static_cast<std::uint32_t>(age), 0) % 8u;
  drop.dir_x = compass[pick][0];
  drop.dir_y = compass[pick][1];
}

// The sediment as the model reads it: batch carries it as quanta.
template <class Real>
Real carried(const PassTerrain<Real>& terrain, const Droplet<Real>& drop, const Kernel<Real>& k) {
  return terrain.batch() ? static_cast<Real>(drop.sediment_quanta) * k.quantum : drop.sediment;
}

// Deposits `amount` bilinearly over the four samples of `at` (each gets amount·w_k, rounded to
// quanta separately in batch); the droplet loses what it gave, its sediment clamped at 0 under
// `clamped` (the uphill_deposit_unbounded mutant). Returns what the samples received.
template <class Real>
double deposit(PassTerrain<Real>& terrain, Droplet<Real>& drop, const Footing<Real>& at, Real amount,
               const Kernel<Real>& k, bool clamped = false) {
  const Real weights[4] = {at.rest_u * at.rest_v, at.u * at.rest_v, at.rest_u * at.v, at.u * at.v};
  DropletLedger& ledger = terrain.ledger();
  long long given_quanta = 0;
  double given = 0.0;
  for (int c = 0; c < 4; ++c) {
    const Texel sample{at.cell.x + corner_offsets[c].x, at.cell.y + corner_offsets[c].y};
    const Real share = amount * weights[c];
    if (terrain.batch()) {
      const long long quanta = terrain.quanta(share);
      terrain.add_quanta(sample, quanta);
      given_quanta += quanta;
    } else {
      terrain.store(sample, terrain.load(sample) + share);
      given += static_cast<double>(share);
    }
  }
  if (terrain.batch()) {
    drop.sediment_quanta -= given_quanta;
    if (clamped) drop.sediment_quanta = std::max(drop.sediment_quanta, 0LL);
    ledger.deposited_quanta += given_quanta;
    return static_cast<double>(given_quanta) * static_cast<double>(k.quantum);
  }
  drop.sediment = drop.sediment - amount;
  if (clamped) drop.sediment = std::max(drop.sediment, Real(0));
  ledger.deposited += given;
  return given;
}

// Eq. 2.42's cone at (x, y): calls visit(sample, w) for every sample within the brush's square that
// the droplets may touch, row-major, w = max(radius - distance, 0).
template <class Real, class Visit>
void for_each_brush_sample(const Grid<Real>& heights, Real x, Real y, Real radius, Visit visit) {
  const int first_x = static_cast<int>(std::ceil(x - radius)), last_x = static_cast<int>(std::floor(x + radius));
  const int first_y = static_cast<int>(std::ceil(y - radius)), last_y = static_cast<int>(std::floor(y + radius));
  for (int sy = first_y; sy <= last_y; ++sy) {
    for (int sx = first_x; sx <= last_x; ++sx) {
      if (!holds(heights, {sx, sy})) continue;
      const Real dx = static_cast<Real>(sx) - x;
      const Real dy = static_cast<Real>(sy) - y;
      const Real distance = std::sqrt(dx * dx + dy * dy);
      visit(Texel{sx, sy}, std::max(radius - distance, Real(0)));
    }
  }
}

template <class Real>
Real brush_sum(const Grid<Real>& heights, Real x, Real y, Real radius) {
  Real sum = 0;
  for_each_brush_sample(heights, x, y, radius, [&](Texel, Real weight) { sum = sum + weight; });
  return sum;
}

// Erodes `amount` with the brush at the droplet's (old) position: each sample loses amount·(w/Σw)
// (rounded to quanta separately in batch), the droplet takes it up. Returns what the samples lost.
template <class Real>
double erode(PassTerrain<Real>& terrain, Droplet<Real>& drop, Real amount, const Kernel<Real>& k) {
  const Real sum = brush_sum(terrain.heights(), drop.x, drop.y, k.radius);
  if (sum == 0) return 0.0;
  long long taken_quanta = 0;
  double taken = 0.0;
  for_each_brush_sample(terrain.heights(), drop.x, drop.y, k.radius, [&](Texel sample, Real weight) {
    const Real share = amount * (weight / sum);
    if (terrain.batch()) {
      const long long quanta = terrain.quanta(share);
      terrain.add_quanta(sample, -quanta);
      taken_quanta += quanta;
    } else {
      terrain.store(sample, terrain.load(sample) - share);
      if (!k.sediment_not_taken_on_erosion) drop.sediment = drop.sediment + share;
      taken += static_cast<double>(share);
    }
  });
  DropletLedger& ledger = terrain.ledger();
  if (terrain.batch()) {
    if (!k.sediment_not_taken_on_erosion) drop.sediment_quanta += taken_quanta;
    ledger.eroded_quanta += taken_quanta;
    return static_cast<double>(taken_quanta) * static_cast<double>(k.quantum);
  }
  ledger.eroded += taken;
  return taken;
}

// Step 5: uphill the droplet fills the pit behind it with min(dh, s); downhill it deposits the
// surplus over its capacity (eq. 2.40) or erodes (eq. 2.41). Marks the side maps at the old cell.
template <class Real>
void erode_or_deposit(PassTerrain<Real>& terrain, Droplet<Real>& drop, const Footing<Real>& here, Real dh,
                      const Kernel<Real>& k) {
  const Real sediment = carried(terrain, drop, k);
  if (dh > 0) {
    const Real amount = k.uphill_deposit_unbounded ? dh : std::min(dh, sediment);
    terrain.mark_side_maps(here.cell, 0.0, deposit(terrain, drop, here, amount, k, k.uphill_deposit_unbounded));
    return;
  }
  const Real capacity = k.capacity_factor * std::max(-dh, k.min_slope) * drop.speed * drop.water;
  if (sediment > capacity) {
    const Real amount = k.deposition * (sediment - capacity);
    terrain.mark_side_maps(here.cell, 0.0, deposit(terrain, drop, here, amount, k));
  } else {
    const Real amount = std::min(k.erosion * (capacity - sediment), -dh);
    terrain.mark_side_maps(here.cell, erode(terrain, drop, amount, k), 0.0);
  }
}

// Eq. 2.44, the radicand clamped at 0: physical v² - dh·c_g, printed v² + dh·c_g.
template <class Real>
Real next_speed(Real speed, Real dh, const Kernel<Real>& k) {
  const Real kinetic = speed * speed;
  const Real fall = dh * k.gravity;
  const Real radicand = k.printed_speed ? kinetic + fall : kinetic - fall;
  return std::sqrt(std::max(radicand, Real(0)));
}

enum class StepEnd { moved, left, off_map };  // off_map: the droplet did not stand on the map

// One step of a droplet (steps 1-8 of the header).
template <class Real>
StepEnd step(PassTerrain<Real>& terrain, Droplet<Real>& drop, int age, const Kernel<Real>& k) {
  const std::optional<Footing<Real>> here = footing(terrain, drop.x, drop.y);
  if (!here) return StepEnd::off_map;
  const Real old_height = height_at(*here);
  turn(drop, gradient_at(*here), age, k);
  const Real new_x = drop.x + drop.dir_x;
  const Real new_y = drop.y + drop.dir_y;
  const std::optional<Footing<Real>> there = footing(terrain, new_x, new_y);
  if (!there) return StepEnd::left;
  const Real dh = height_at(*there) - old_height;
  erode_or_deposit(terrain, drop, *here, dh, k);
  drop.speed = next_speed(drop.speed, dh, k);
  drop.water = drop.water * k.water_kept;
  drop.x = new_x;
  drop.y = new_y;
  return StepEnd::moved;
}

template <class Real>
Droplet<Real> start_droplet(Real x, Real y, std::uint32_t id, const Kernel<Real>& k) {
  return Droplet<Real>{x, y, 0, 0, k.initial_speed, k.initial_water, id, 0, 0};
}

// Runs a droplet's life; the sediment it still carries leaves the terrain with it. A step that
// starts on the map counts, the one that carries the droplet off included.
template <class Real>
void run_droplet(PassTerrain<Real>& terrain, Droplet<Real>& drop, const Kernel<Real>& k,
                 BeyerPath<Real>* path = nullptr) {
  DropletLedger& ledger = terrain.ledger();
  ++ledger.droplets;
  bool left = false;
  for (int age = 0; age < k.lifetime && !left; ++age) {
    const StepEnd end = step(terrain, drop, age, k);
    if (end != StepEnd::off_map) ++ledger.steps;
    left = end != StepEnd::moved;
    if (path != nullptr && !left) path->positions.emplace_back(drop.x, drop.y);
  }
  if (left) ++ledger.droplets_left;
  if (terrain.batch()) {
    ledger.sediment_end_quanta += drop.sediment_quanta;
    (left ? ledger.sediment_left : ledger.sediment_at_end) +=
        static_cast<double>(drop.sediment_quanta) * static_cast<double>(k.quantum);
  } else {
    (left ? ledger.sediment_left : ledger.sediment_at_end) += static_cast<double>(drop.sediment);
  }
  if (path != nullptr) path->left = left;
}

// Batch: the ledger's amounts from its exact counts of quanta (sediment_at_end and _left are
// summed per droplet as they end; nothing is taken or dropped off the map).
void express_quanta(DropletLedger& ledger, double quantum) {
  ledger.eroded = static_cast<double>(ledger.eroded_quanta) * quantum;
  ledger.deposited = static_cast<double>(ledger.deposited_quanta) * quantum;
}

// The RNG counter of droplet (i, j) of a pass: (pass_number·blocks_y + j)·blocks_x + i with
// pass_number = iteration·S² + oy·S + ox, all in uint32 arithmetic (wrapping), as the shader
// computes it: unique per droplet of a run (until 2^32 droplets).
std::uint32_t droplet_id(std::uint32_t pass_number, int blocks_x, int blocks_y, int i, int j) {
  return (pass_number * static_cast<std::uint32_t>(blocks_y) + static_cast<std::uint32_t>(j)) *
             static_cast<std::uint32_t>(blocks_x) +
         static_cast<std::uint32_t>(i);
}

// One draw of Algorithm 7: a droplet per block of the ceil(W/S) x ceil(H/S) grid, row-major, the
// droplet of block (i, j) starting at (i·S + ox + 0.5, j·S + oy + 0.5).
template <class Real>
void run_pass(DropletRun<Real>& run, const Kernel<Real>& k, int spacing, Texel offset, std::uint32_t pass_number,
              bool batch) {
  PassTerrain<Real> terrain(run, k, batch);
  const int blocks_x = (run.heights.width + spacing - 1) / spacing;
  const int blocks_y = (run.heights.height + spacing - 1) / spacing;
  for (int j = 0; j < blocks_y; ++j) {
    for (int i = 0; i < blocks_x; ++i) {
      const Real x = static_cast<Real>(i * spacing + offset.x) + Real(0.5);
      const Real y = static_cast<Real>(j * spacing + offset.y) + Real(0.5);
      Droplet<Real> drop = start_droplet(x, y, droplet_id(pass_number, blocks_x, blocks_y, i, j), k);
      run_droplet(terrain, drop, k);
    }
  }
  terrain.apply();
}

// Eq. 2.43 after an outer iteration: in place (sequential) or as one more batch delta, applied and
// booked as the droplets' are (its quanta sum to 0).
template <class Real>
void blend_with_blur(DropletRun<Real>& run, const Kernel<Real>& k, bool batch) {
  if (k.blur_blend == 0.0) return;
  if (!batch) {
    blur_blend(run.heights, k.blur_blend, "erosion.beyer");
    return;
  }
  BatchDelta<Real> delta(run.heights.size(), k.quantum, "erosion.beyer");
  blur_blend_quanta(run.heights, k.blur_blend, k.inverse_quantum, delta, "erosion.beyer");
  delta.apply(run.heights, run.ledger);
}

template <class Real>
DropletRun<Real> empty_run(const Grid<Real>& heights) {
  DropletRun<Real> run{heights, heights.template cast<double>(), heights.template cast<double>(), {}};
  std::fill(run.eroded_at_droplet.values.begin(), run.eroded_at_droplet.values.end(), 0.0);
  std::fill(run.deposited_at_droplet.values.begin(), run.deposited_at_droplet.values.end(), 0.0);
  return run;
}

}  // namespace

template <class Real>
DropletRun<Real> beyer_erosion(const Grid<Real>& heights, const BeyerConstants& constants, int iterations,
                               DropletOrdering ordering, int first_iteration) {
  const Kernel<Real> kernel(constants);
  DropletRun<Real> run = empty_run(heights);
  const bool batch = ordering == DropletOrdering::batch;
  const int spacing = constants.spacing;
  for (int iteration = first_iteration; iteration < first_iteration + iterations; ++iteration) {
    for (int y = 0; y < spacing; ++y) {
      for (int x = 0; x < spacing; ++x) {
        const std::uint32_t pass_number = static_cast<std::uint32_t>(iteration) *
                                              static_cast<std::uint32_t>(spacing * spacing) +
                                          static_cast<std::uint32_t>(y * spacing + x);
        run_pass(run, kernel, spacing, {x, y}, pass_number, batch);
      }
    }
    blend_with_blur(run, kernel, batch);
  }
  if (batch) express_quanta(run.ledger, constants.quantum);
  return run;
}

template <class Real>
Grid<double> beyer_brush_weights(const Grid<Real>& heights, Real x, Real y, Real radius) {
  Grid<double> weights = heights.template cast<double>();
  std::fill(weights.values.begin(), weights.values.end(), 0.0);
  const Real sum = brush_sum(heights, x, y, radius);
  if (sum == 0) return weights;
  for_each_brush_sample(heights, x, y, radius, [&](Texel sample, Real weight) {
    weights.at(sample.x, sample.y) = static_cast<double>(weight / sum);
  });
  return weights;
}

template <class Real>
BeyerPath<Real> beyer_one_droplet(Grid<Real>& heights, const BeyerConstants& constants, Real x, Real y,
                                  std::uint32_t droplet_id) {
  const Kernel<Real> kernel(constants);
  DropletRun<Real> run = empty_run(heights);
  PassTerrain<Real> terrain(run, kernel, false);
  BeyerPath<Real> path;
  Droplet<Real> drop = start_droplet(x, y, droplet_id, kernel);
  path.positions.emplace_back(drop.x, drop.y);
  run_droplet(terrain, drop, kernel, &path);
  path.sediment = drop.sediment;
  path.speed = drop.speed;
  path.water = drop.water;
  heights = run.heights;
  return path;
}

template DropletRun<double> beyer_erosion(const Grid<double>&, const BeyerConstants&, int, DropletOrdering, int);
template DropletRun<float> beyer_erosion(const Grid<float>&, const BeyerConstants&, int, DropletOrdering, int);
template Grid<double> beyer_brush_weights(const Grid<double>&, double, double, double);
template Grid<double> beyer_brush_weights(const Grid<float>&, float, float, float);
template BeyerPath<double> beyer_one_droplet(Grid<double>&, const BeyerConstants&, double, double, std::uint32_t);
template BeyerPath<float> beyer_one_droplet(Grid<float>&, const BeyerConstants&, float, float, std::uint32_t);

}  // namespace gt::reference
