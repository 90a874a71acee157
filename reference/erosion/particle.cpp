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
// Decisions of this project (issue 12): the droplets of one pass run in row-major order of their
// blocks (the truth), or in batch ordering against the pass's frozen heights with integer quanta
// (core/params/particle.hpp). Units: texels and steps; heights in the units of the constants.
#include "reference/erosion/particle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "core/mutant.hpp"

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
        lifetime(c.lifetime),
        interpolate(c.interpolate) {}
  Real acceleration, bite, release, max_velocity, drag, capacity_factor, max_jump, quantum, inverse_quantum;
  int lifetime;
  bool interpolate;
  // The deliberate bugs of compare/mutants/particle.cpp that live in both twins.
  bool rescaled_velocity = mutant_active("erosion.particle.rescaled_velocity");
  bool kept_sediment_on_deposit = mutant_active("erosion.particle.kept_sediment_on_deposit");
  bool unbounded_erosion = mutant_active("erosion.particle.unbounded_erosion");
};

struct Texel {
  int x;
  int y;
};

// The heights the droplets of one pass see and change, with what they did to them. Sequential:
// reads and writes go to the heights. Batch: reads see the heights as the pass found them and
// changes collect as quanta in `delta` until apply().
template <class Real>
class PassTerrain {
 public:
  PassTerrain(DropletRun<Real>& run, const Kernel<Real>& kernel, bool batch)
      : run_(run), kernel_(kernel) {
    if (batch) delta_.emplace(run.heights.size(), kernel.quantum, "erosion.particle");
  }

  bool holds(Texel t) const { return run_.heights.inside(t.x, t.y) && run_.heights.is_valid(t.x, t.y); }
  Real load(Texel t) const { return holds(t) ? run_.heights.at(t.x, t.y) : Real(0); }
  bool batch() const { return delta_.has_value(); }
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

  void mark_side_maps(Texel at, double eroded, double deposited) {
    if (!holds(at)) return;
    run_.eroded_at_droplet.at(at.x, at.y) += eroded;
    run_.deposited_at_droplet.at(at.x, at.y) += deposited;
  }

  // Batch: heights + delta·quantum rounded to Real, as particle_apply.comp does.
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
  Real pos_x, pos_y;
  Texel texel;
  Real vel_x = 0, vel_y = 0;
  Real sediment = 0;            // sequential
  long long sediment_quanta = 0;  // batch
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

// Algorithm 4 as upstream nests it: per axis, towards the lower side along the motion (from rest
// the negative side), not when the drop exceeds drop_max.
template <class Real>
Real accelerate_axis(Real velocity, Real height, Real ahead, Real behind, const Kernel<Real>& k) {
  if (velocity > 0) {
    const Real drop = height - ahead;
    if (drop <= k.max_jump) velocity = velocity + k.acceleration * drop;
  } else {
    const Real drop = height - behind;
    if (drop <= k.max_jump) velocity = velocity - k.acceleration * drop;
  }
  return velocity;
}

// Algorithm 6 as upstream's erode4: the amount removed at each corner higher than the
// neighbourhood minimum; returns the weight of the corners eroded (sequential ordering).
template <class Real>
Real erode_corners(PassTerrain<Real>& terrain, Droplet<Real>& drop, Real amount, Real lowest) {
  const Real corner_x = drop.pos_x - Real(0.5), corner_y = drop.pos_y - Real(0.5);
  const Texel corner{static_cast<int>(corner_x), static_cast<int>(corner_y)};  // truncation, as ivec2()
  const Real fx = corner_x - static_cast<Real>(corner.x), fy = corner_y - static_cast<Real>(corner.y);
  const Real gx = Real(1) - fx, gy = Real(1) - fy;
  const Texel cells[4] = {corner, {corner.x + 1, corner.y}, {corner.x, corner.y + 1}, {corner.x + 1, corner.y + 1}};
  const Real weights[4] = {gx * gy, fx * gy, gx * fy, fx * fy};
  Real eroded_weight = 0;
  DropletLedger& ledger = terrain.ledger();
  for (int k = 0; k < 4; ++k) {
    const Real height = terrain.load(cells[k]);
    if (!(height > lowest)) continue;
    const Real taken = amount * weights[k];
    if (terrain.batch()) {
      const long long quanta = terrain.quanta(taken);
      terrain.add_quanta(cells[k], -quanta);
      drop.sediment_quanta += quanta;
      (terrain.holds(cells[k]) ? ledger.eroded_quanta : ledger.eroded_outside_quanta) += quanta;
    } else {
      terrain.store(cells[k], height - taken);
      (terrain.holds(cells[k]) ? ledger.eroded : ledger.eroded_outside) += static_cast<double>(taken);
    }
    eroded_weight = eroded_weight + weights[k];
  }
  return eroded_weight;
}

// The erosion branch: `add` bounded by the neighbourhood minimum, spread or at the texel. Returns
// what the droplet picked up (for the side map).
template <class Real>
Real erode(PassTerrain<Real>& terrain, Droplet<Real>& drop, Real height, Real add, Real lowest,
           const Kernel<Real>& k) {
  DropletLedger& ledger = terrain.ledger();
  if (k.interpolate) {
    const Real weight = erode_corners(terrain, drop, add, lowest);
    const Real picked = add * weight;
    if (!terrain.batch()) drop.sediment = drop.sediment + picked;
    return picked;
  }
  const Real removed = height - std::max(height - add, Real(0));
  if (terrain.batch()) {
    const long long removed_quanta = terrain.quanta(removed), added_quanta = terrain.quanta(add);
    terrain.add_quanta(drop.texel, -removed_quanta);
    drop.sediment_quanta += added_quanta;
    (terrain.holds(drop.texel) ? ledger.eroded_quanta : ledger.eroded_outside_quanta) += removed_quanta;
    ledger.clamp_created_quanta += added_quanta - removed_quanta;
  } else {
    terrain.store(drop.texel, std::max(height - add, Real(0)));
    drop.sediment = drop.sediment + add;
    (terrain.holds(drop.texel) ? ledger.eroded : ledger.eroded_outside) += static_cast<double>(removed);
    ledger.clamp_created += static_cast<double>(add) - static_cast<double>(removed);
  }
  return add;
}

// The deposition branch, at the droplet's texel only.
template <class Real>
void deposit(PassTerrain<Real>& terrain, Droplet<Real>& drop, Real height, Real add, const Kernel<Real>& k) {
  DropletLedger& ledger = terrain.ledger();
  if (terrain.batch()) {
    const long long quanta = terrain.quanta(add);
    terrain.add_quanta(drop.texel, quanta);
    if (!k.kept_sediment_on_deposit) drop.sediment_quanta -= quanta;
    (terrain.holds(drop.texel) ? ledger.deposited_quanta : ledger.deposited_outside_quanta) += quanta;
  } else {
    terrain.store(drop.texel, height + add);
    if (!k.kept_sediment_on_deposit) drop.sediment = drop.sediment - add;
    (terrain.holds(drop.texel) ? ledger.deposited : ledger.deposited_outside) += static_cast<double>(add);
  }
}

// One step of a droplet (Appendix A's loop body); false when the droplet left across x or y <= 0.
template <class Real>
bool step(PassTerrain<Real>& terrain, Droplet<Real>& drop, const Kernel<Real>& k) {
  const Neighbourhood<Real> n = neighbourhood(terrain, drop.texel);
  Real height = terrain.load(drop.texel);
  drop.vel_x = accelerate_axis(drop.vel_x, height, n.right, n.left, k);
  drop.vel_y = accelerate_axis(drop.vel_y, height, n.above, n.below, k);
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
      terrain.mark_side_maps(drop.texel, static_cast<double>(erode(terrain, drop, height, add, n.lowest, k)), 0.0);
    }
  } else if (height < n.highest) {
    difference = difference * k.release;
    const Real add = std::min(-difference, n.highest - height);
    deposit(terrain, drop, height, add, k);
    terrain.mark_side_maps(drop.texel, 0.0, static_cast<double>(add));
  }
  drop.pos_x = drop.pos_x + norm_x;
  drop.pos_y = drop.pos_y + norm_y;
  drop.texel = {static_cast<int>(drop.pos_x), static_cast<int>(drop.pos_y)};
  return !(drop.pos_x <= 0 || drop.pos_y <= 0);
}

template <class Real>
Droplet<Real> start_droplet(int base_x, int base_y) {
  return Droplet<Real>{static_cast<Real>(base_x) + Real(0.5), static_cast<Real>(base_y) + Real(0.5), {base_x, base_y}};
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
void run_pass(DropletRun<Real>& run, const Kernel<Real>& k, int spacing, Texel offset, bool batch) {
  PassTerrain<Real> terrain(run, k, batch);
  const int blocks_x = (run.heights.width + spacing - 1) / spacing;
  const int blocks_y = (run.heights.height + spacing - 1) / spacing;
  for (int j = 0; j < blocks_y; ++j) {
    for (int i = 0; i < blocks_x; ++i) {
      Droplet<Real> drop = start_droplet<Real>(i * spacing + offset.x, j * spacing + offset.y);
      run_droplet(terrain, drop, k);
    }
  }
  terrain.apply();
}

}  // namespace

template <class Real>
DropletRun<Real> particle_erosion(const Grid<Real>& heights, const ParticleConstants& constants, int iterations,
                                   DropletOrdering ordering) {
  const Kernel<Real> kernel(constants);
  DropletRun<Real> run{heights, heights.template cast<double>(), heights.template cast<double>(), {}};
  std::fill(run.eroded_at_droplet.values.begin(), run.eroded_at_droplet.values.end(), 0.0);
  std::fill(run.deposited_at_droplet.values.begin(), run.deposited_at_droplet.values.end(), 0.0);
  const bool batch = ordering == DropletOrdering::batch;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    for (int y = 0; y < constants.spacing; ++y) {
      for (int x = 0; x < constants.spacing; ++x) run_pass(run, kernel, constants.spacing, {x, y}, batch);
    }
  }
  if (batch) express_quanta(run.ledger, constants.quantum);
  return run;
}

template <class Real>
DropletPath<Real> run_one_droplet(Grid<Real>& heights, const ParticleConstants& constants, int base_x, int base_y) {
  const Kernel<Real> kernel(constants);
  DropletRun<Real> run{heights, heights.template cast<double>(), heights.template cast<double>(), {}};
  PassTerrain<Real> terrain(run, kernel, false);
  DropletPath<Real> path;
  Droplet<Real> drop = start_droplet<Real>(base_x, base_y);
  path.positions.emplace_back(drop.pos_x, drop.pos_y);
  run_droplet(terrain, drop, kernel, &path.positions);
  path.sediment = drop.sediment;
  heights = run.heights;
  return path;
}

template DropletRun<double> particle_erosion(const Grid<double>&, const ParticleConstants&, int, DropletOrdering);
template DropletRun<float> particle_erosion(const Grid<float>&, const ParticleConstants&, int, DropletOrdering);
template DropletPath<double> run_one_droplet(Grid<double>&, const ParticleConstants&, int, int);
template DropletPath<float> run_one_droplet(Grid<float>&, const ParticleConstants&, int, int);

}  // namespace gt::reference
