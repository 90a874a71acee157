// Parameter table of erosion.particle and the kernel and flow-map constants derived from it (see
// particle.hpp).
#include "core/params/particle.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {

int droplet_reach(int lifetime) { return lifetime + 2; }

// Ranges: the upstream UI ranges of §4.4.1 (add-on 1a1a8c9) where it has them, widened where the
// thesis allows more; "must be positive" (§4.4.1) is a lower bound of 1e-6.
const ParamTable<ParticleParams>& particle_param_table() {
  using P = ParticleParams;
  static const ParamTable<P> table = {
      integer_param("iterations", &P::iterations, 0, 1000, "count",
                    "outer iterations of Algorithm 7 (part_iter_num): each releases one droplet per texel in "
                    "spacing² passes"),
      integer_param("lifetime", &P::lifetime, 1, 500, "steps", "steps of one droplet (part_lifetime)"),
      integer_param("spacing", &P::spacing, 1, 1024, "texel",
                    "subdiv: one droplet per spacing x spacing block and pass; disjoint needs spacing > 2·(lifetime "
                    "+ 2)"),
      real_param("acceleration", &P::acceleration, 0.01, 4.0, "1", "a of Algorithm 4 (part_acceleration)"),
      real_param("erosion_strength", &P::erosion_strength, 1e-6, 2.0, "1",
                 "bite (part_fineness); the thesis warns that 0.5 and more oscillates"),
      real_param("deposition_strength", &P::deposition_strength, 1e-6, 1.0, "1",
                 "release (part_deposition x 0.5); the thesis warns that 0.5 and more oscillates"),
      real_param("max_velocity", &P::max_velocity, 1e-3, 100.0, "texel/step", "v_max: the speed is clamped to it"),
      real_param("drag", &P::drag, 0.0, 0.99, "1",
                 "share of the velocity lost per step (part_drag); the kernel multiplies by 1 - drag"),
      real_param("capacity_factor", &P::capacity_factor, 1e-6, 1.0, "height/(texel/step)",
                 "f_c: capacity = f_c·|v| (part_capacity x 1e-2)"),
      real_param("max_jump", &P::max_jump, 1e-6, 1e6, "height",
                 "drop_max: no acceleration towards a neighbour more than this lower (part_maxjump)"),
      boolean_param("interpolate", &P::interpolate,
                    "erosion spread bilinearly over the 4 nearest texel centres (Algorithm 6); "
                    "off: at the droplet's texel"),
      real_param("colour_mixing", &P::colour_mixing, 0.0, 1.0, "1",
                 "f_col (color_mixing): on erosion a droplet's colour becomes f_col·texel + (1 - f_col)·colour (eq. "
                 "4.9); used only when a colour map is transported"),
      boolean_param("interpolate_colour", &P::interpolate_colour,
                    "colour deposited over the 4 nearest texel centres with weights f_col·w (Algorithm 8); "
                    "off: at the droplet's texel with weight f_col; used only when a colour map is transported"),
      choice_param("ordering", &P::ordering, droplet_ordering_choices, "",
                   "droplets of one pass: race (Hydra's dispatch; compared statistically), "
                   "disjoint (spacing keeps them apart; exact), batch (frozen heights and a fixed-point delta; "
                   "bit-exact at any spacing)"),
      real_param("erosion_contrast", &P::erosion_contrast, 0.0, 40.0, "1/height",
                 "c_E of the depth map's picture, min(1, c_E·eroded) (depth_contrast 0.5 x 40); 0: the raw map"),
      real_param("deposition_contrast", &P::deposition_contrast, 0.0, 30.0, "1/height",
                 "c_D of the sediment map's picture, min(1, c_D·deposited) (sed_contrast 0.5 x 30); 0: the raw map"),
      choice_param("colour", &P::colour, {"none", "astronaut", "grass"}, "",
                   "colour map transported by the droplets (§4.5): datasets/real/textures/<name>.png resampled "
                   "bilinearly to the heightmap and sRGB-decoded, or none"),
      boolean_param("flow_map", &P::flow_map,
                    "draw the flow map of the eroded terrain (§4.7): droplet paths as a concentration in [0, 1]"),
      integer_param("flow_spacing", &P::flow_spacing, 1, 1024, "texel",
                    "the flow map's own spacing (flow_subdiv); disjoint needs flow_spacing > 2·(lifetime + 2)"),
      real_param("flow_contrast", &P::flow_contrast, 0.0, 1.0, "1",
                 "contrast of the flow map: f_c = 0.2·exp(-6.61·contrast) of eq. 4.13 in w = w·(1 - f_c) + f_c (eq. "
                 "4.12)"),
      boolean_param("interpolate_flow", &P::interpolate_flow,
                    "concentration left over the 4 nearest texel centres with factors f_c·w; "
                    "off: f_c at the droplet's texel"),
      boolean_param("normalised", &P::normalised,
                    "seed 000's heights (h - min)/(max - min) in [0, 1], in which drop_max and f_c are given; "
                    "off: the input's heights as they are"),
  };
  return table;
}

const ParamSpecs& particle_param_specs() {
  static const ParamSpecs specs = param_specs(particle_param_table());
  return specs;
}

ParticleParams particle_params_from_json(const nlohmann::json& resolved) {
  return params_from_json(particle_param_table(), resolved);
}

ParticleConstants particle_constants(const nlohmann::json& resolved, const Heightmap& heights) {
  const ParticleParams params = particle_params_from_json(resolved);
  ParticleConstants constants;
  constants.iterations = params.iterations;
  constants.lifetime = params.lifetime;
  constants.spacing = params.spacing;
  constants.acceleration = params.acceleration;
  constants.bite = params.erosion_strength;
  constants.release = params.deposition_strength;
  constants.max_velocity = params.max_velocity;
  constants.drag = 1.0 - params.drag;
  constants.capacity_factor = params.capacity_factor;
  constants.max_jump = params.max_jump;
  constants.interpolate = params.interpolate;
  constants.colour_mixing = params.colour_mixing;
  constants.interpolate_colour = params.interpolate_colour;
  constants.ordering = params.ordering;
  if (constants.ordering == DropletOrdering::disjoint && constants.spacing <= 2 * droplet_reach(constants.lifetime)) {
    throw InputError(fmt::format(
        "erosion.particle: ordering `disjoint` needs spacing > 2·(lifetime + 2) = {} so that no two droplets of a "
        "pass meet; spacing is {} (use `race` or `batch`, or a spacing of at least {})",
        2 * droplet_reach(constants.lifetime), constants.spacing, 2 * droplet_reach(constants.lifetime) + 1));
  }
  const auto [low, high] = valid_range(heights);
  constants.quantum = batch_quantum(low > high ? 0.0 : std::max(std::abs(low), std::abs(high)));
  return constants;
}

double flow_contrast_factor(double contrast) { return 0.2 * std::exp(-6.61 * contrast); }

std::array<double, 31> flow_batch_powers(double factor) {
  std::array<double, 31> powers{};
  for (std::size_t i = 0; i < powers.size(); ++i) {
    powers[i] = std::pow(1.0 - factor, std::ldexp(flow_weight_quantum, static_cast<int>(i)));
  }
  return powers;
}

std::optional<FlowConstants> flow_constants(const nlohmann::json& resolved, const ParticleConstants& erosion) {
  const ParticleParams params = particle_params_from_json(resolved);
  if (!params.flow_map) return std::nullopt;
  FlowConstants flow;
  flow.spacing = params.flow_spacing;
  flow.lifetime = erosion.lifetime;
  flow.acceleration = erosion.acceleration;
  flow.max_velocity = erosion.max_velocity;
  flow.drag = erosion.drag;
  flow.factor = flow_contrast_factor(params.flow_contrast);
  flow.interpolate = params.interpolate_flow;
  flow.ordering = erosion.ordering;
  flow.batch_powers = flow_batch_powers(flow.factor);
  if (flow.ordering == DropletOrdering::disjoint && flow.spacing <= 2 * droplet_reach(flow.lifetime)) {
    throw InputError(fmt::format(
        "erosion.particle: ordering `disjoint` draws the flow map with disjoint droplets too, which needs "
        "flow_spacing > 2·(lifetime + 2) = {}; flow_spacing is {} (set flow_spacing to at least {}, or flow_map "
        "false)",
        2 * droplet_reach(flow.lifetime), flow.spacing, 2 * droplet_reach(flow.lifetime) + 1));
  }
  return flow;
}

std::vector<std::string> particle_warnings(const ParticleConstants& constants) {
  std::vector<std::string> warnings;
  if (constants.bite >= 0.5) {
    warnings.push_back(fmt::format("erosion_strength {} is 0.5 or more: the thesis (§4.4.1) warns that the "
                                   "erosion then oscillates; run as asked",
                                   constants.bite));
  }
  if (constants.release >= 0.5) {
    warnings.push_back(fmt::format("deposition_strength {} is 0.5 or more: the thesis (§4.4.1) warns that the "
                                   "deposition then oscillates; run as asked",
                                   constants.release));
  }
  return warnings;
}

}  // namespace gt
