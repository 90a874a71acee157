// The flow map of seed 000 (Hydra, §4.7, eqs. 4.12-4.13), CPU reference of gpu/shaders/erosion/
// flow_map_droplets.comp and flow_map_plug.comp, after the digest's notes on upstream's flow.glsl and
// plug.glsl (the thesis gives no algorithm of its own for them):
//   - the motion is the erosion's (reference/erosion/hydra_motion.hpp) without the drop_max limit:
//     Algorithm 4's nested branches, drag, the speed clamped to v_max, a unit step along the
//     velocity; a droplet starts at rest at the centre of texel (i·S + ox, j·S + oy), one per texel
//     over the spacing² passes of one iteration (the map is drawn once: §4.7);
//   - it stops in a pit (h < the lowest neighbour, break), at rest (|v| = 0, break), after lifetime
//     steps, or when a coordinate of its position is <= 0;
//   - eq. 4.12 at each step: F = F·(1 - factor) + factor, factor = f_c·w over erode4's 4 corners
//     (interpolate_flow; the truncated corner's weights leave [0, 1] within half a texel of x = 0 or
//     y = 0, as upstream's) or f_c at the droplet's texel; (1 - factor) rounded once.
// Decisions of this project (the upstream order inside the loop is not in the digest): the
// concentration is left after the velocity is known and before the droplet moves, so a droplet that
// moves marks its start texel and one that never moves marks nothing; the plug pass then fills each
// open texel still 0 (or NaN) with the mean of its 4 neighbours as they were before the pass (off the
// grid and masked: 0), once, as upstream's plug.glsl; masked texels stay 0.
// Batch ordering: each visit's weight as a count of 2^-10 per texel (w rounded to nearest, ties to
// even), and F = 1 - Π (1 - f_c)^(2^i·2^-10) over the count's set bits, ascending (a count below 0,
// possible only at x or y <= 1, gives 0); a count beyond int32 is refused (the GPU's counter).
// Units: positions in texels, velocities in texels per step, the concentration dimensionless.
#include "reference/erosion/flow_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "reference/erosion/hydra_motion.hpp"

namespace gt::reference {
namespace {

template <class Real>
struct FlowKernel {
  explicit FlowKernel(const FlowConstants& c)
      : acceleration(static_cast<Real>(c.acceleration)),
        max_velocity(static_cast<Real>(c.max_velocity)),
        drag(static_cast<Real>(c.drag)),
        factor(static_cast<Real>(c.factor)),
        lifetime(c.lifetime),
        interpolate(c.interpolate),
        batch(c.ordering == DropletOrdering::batch) {
    for (std::size_t i = 0; i < powers.size(); ++i) powers[i] = static_cast<Real>(c.batch_powers[i]);
  }
  Real acceleration, max_velocity, drag, factor;
  int lifetime;
  bool interpolate;
  bool batch;
  std::array<Real, 31> powers{};
};

// The heights the droplets read and the concentration (or, batch, the weight counts) they leave.
template <class Real>
class FlowCanvas {
 public:
  FlowCanvas(const Grid<Real>& heights, const FlowKernel<Real>& kernel)
      : heights_(heights), kernel_(kernel), flow_(heights.size(), Real(0)) {
    if (kernel.batch) counts_.assign(heights.size(), 0);
  }

  bool open(Texel t) const { return heights_.inside(t.x, t.y) && heights_.is_valid(t.x, t.y); }
  Real height(Texel t) const { return open(t) ? heights_.at(t.x, t.y) : Real(0); }

  // Eq. 4.12 with `factor` at the texel (sequential), or its weight `weight` counted (batch).
  void leave(Texel t, Real weight) {
    if (!open(t)) return;
    const std::size_t i = heights_.index(t.x, t.y);
    if (kernel_.batch) {
      counts_[i] += static_cast<long long>(std::nearbyint(weight / static_cast<Real>(flow_weight_quantum)));
      return;
    }
    const Real factor = kernel_.factor * weight;
    const Real rest = Real(1) - factor;
    flow_[i] = flow_[i] * rest + factor;
  }

  // The concentration before the plug pass (batch: from the counts).
  std::vector<Real> concentration() const {
    if (!kernel_.batch) return flow_;
    std::vector<Real> flow(counts_.size(), Real(0));
    for (std::size_t i = 0; i < counts_.size(); ++i) {
      if (counts_[i] > std::numeric_limits<std::int32_t>::max()) {
        throw std::runtime_error(fmt::format(
            "erosion.particle: the batch flow map counts {} weight units in one texel, beyond the GPU's 32-bit "
            "counter; use a shorter lifetime or another ordering",
            counts_[i]));
      }
      flow[i] = counts_[i] <= 0 ? Real(0) : from_count(counts_[i]);
    }
    return flow;
  }

 private:
  Real from_count(long long count) const {
    Real kept = 1;
    for (std::size_t bit = 0; bit < kernel_.powers.size(); ++bit) {
      if ((count >> bit) & 1) kept = kept * kernel_.powers[bit];
    }
    return Real(1) - kept;
  }

  const Grid<Real>& heights_;
  const FlowKernel<Real>& kernel_;
  std::vector<Real> flow_;          // sequential
  std::vector<long long> counts_;   // batch
};

// One droplet's path from the centre of texel `start`.
template <class Real>
void run_droplet(FlowCanvas<Real>& canvas, const FlowKernel<Real>& k, Texel start) {
  Real pos_x = static_cast<Real>(start.x) + Real(0.5), pos_y = static_cast<Real>(start.y) + Real(0.5);
  Texel texel = start;
  Real vel_x = 0, vel_y = 0;
  const Real no_limit = std::numeric_limits<Real>::max();
  for (int age = 0; age < k.lifetime; ++age) {
    const Real below = canvas.height({texel.x, texel.y - 1}), left = canvas.height({texel.x - 1, texel.y});
    const Real right = canvas.height({texel.x + 1, texel.y}), above = canvas.height({texel.x, texel.y + 1});
    const Real lowest = std::min(std::min(below, left), std::min(right, above));
    const Real height = canvas.height(texel);
    vel_x = accelerate_axis(vel_x, height, right, left, k.acceleration, no_limit);
    vel_y = accelerate_axis(vel_y, height, above, below, k.acceleration, no_limit);
    if (height < lowest) break;  // in a pit
    vel_x = vel_x * k.drag;
    vel_y = vel_y * k.drag;
    const Real speed = std::sqrt(vel_x * vel_x + vel_y * vel_y);
    if (speed == 0) break;  // at rest
    const Real norm_x = vel_x / speed, norm_y = vel_y / speed;
    if (speed > k.max_velocity) {
      vel_x = norm_x * k.max_velocity;
      vel_y = norm_y * k.max_velocity;
    }
    if (k.interpolate) {
      const Corners<Real> corners = corners_around(pos_x, pos_y);
      for (int c = 0; c < 4; ++c) canvas.leave(corners.cells[c], corners.weights[c]);
    } else {
      canvas.leave(texel, Real(1));
    }
    pos_x = pos_x + norm_x;
    pos_y = pos_y + norm_y;
    texel = {static_cast<int>(pos_x), static_cast<int>(pos_y)};
    if (pos_x <= 0 || pos_y <= 0) break;
  }
}

// plug.glsl: open texels at 0 or NaN become the mean of their 4 neighbours before the pass.
template <class Real>
std::size_t plug(const Grid<Real>& heights, const std::vector<Real>& before, Grid<Real>& after) {
  const auto value = [&](int x, int y) {
    if (!heights.inside(x, y) || !heights.is_valid(x, y)) return Real(0);
    return before[heights.index(x, y)];
  };
  std::size_t plugged = 0;
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      const std::size_t i = heights.index(x, y);
      if (!heights.is_valid(i)) {
        after.values[i] = 0;
        continue;
      }
      const Real own = before[i];
      if (own == 0 || std::isnan(own)) {
        const Real sum = ((value(x, y - 1) + value(x - 1, y)) + value(x + 1, y)) + value(x, y + 1);
        after.values[i] = sum / Real(4);
        ++plugged;
      } else {
        after.values[i] = own;
      }
    }
  }
  return plugged;
}

}  // namespace

template <class Real>
FlowMapRun<Real> flow_map(const Grid<Real>& heights, const FlowConstants& constants) {
  if (constants.spacing < 1) throw std::invalid_argument("flow_map: spacing must be at least 1");
  const FlowKernel<Real> kernel(constants);
  FlowCanvas<Real> canvas(heights, kernel);
  FlowMapRun<Real> run{heights, 0, 0};
  const int spacing = constants.spacing;
  const int blocks_x = (heights.width + spacing - 1) / spacing, blocks_y = (heights.height + spacing - 1) / spacing;
  for (int offset_y = 0; offset_y < spacing; ++offset_y) {
    for (int offset_x = 0; offset_x < spacing; ++offset_x) {
      for (int j = 0; j < blocks_y; ++j) {
        for (int i = 0; i < blocks_x; ++i) {
          run_droplet(canvas, kernel, {i * spacing + offset_x, j * spacing + offset_y});
          ++run.droplets;
        }
      }
    }
  }
  run.plugged = plug(heights, canvas.concentration(), run.concentration);
  return run;
}

template FlowMapRun<double> flow_map(const Grid<double>&, const FlowConstants&);
template FlowMapRun<float> flow_map(const Grid<float>&, const FlowConstants&);

}  // namespace gt::reference
