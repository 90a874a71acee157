// The fault-line planet's parameters, normals and positions (see fault_planet.hpp).
#include "core/params/fault_planet.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/planet/cube_sphere.hpp"
#include "core/rng.hpp"

namespace gt {

const ParamTable<FaultPlanetParams>& fault_planet_param_table() {
  using P = FaultPlanetParams;
  static const ParamTable<FaultPlanetParams> table = {
      integer_param("resolution", &P::resolution, 1, max_cube_sphere_resolution, "count",
                    "R: cells along a cube face's edge; 6R² regions, each at its cell's centre"),
      integer_param("faults", &P::faults, 1, 1000000, "count",
                    "N: random planes through the centre, each raising one side by step and lowering the other"),
      real_param("step", &P::step, 1e-9, 1e6, "generator units",
                 "Δ: the change of one fault (the thesis gives none; 0.04 keeps 1000 faults within the §4.3 palette)"),
      integer_param("seed", &P::seed, 0, 4294967295.0, "1", "counter-RNG seed of the fault normals"),
  };
  return table;
}

const ParamSpecs& fault_planet_param_specs() {
  static const ParamSpecs specs = param_specs(fault_planet_param_table());
  return specs;
}

FaultPlanetParams fault_planet_params_from_json(const nlohmann::json& resolved) {
  const FaultPlanetParams params = params_from_json(fault_planet_param_table(), resolved);
  const double products = 6.0 * params.resolution * params.resolution * double(params.faults);
  if (products > max_fault_dot_products) {
    throw InputError(fmt::format("planet.fault_lines: R = {} ({} regions) and {} faults make {:.3g} dot products per "
                                 "twin, beyond the {:.3g} a case may take: lower faults or resolution",
                                 params.resolution, 6 * params.resolution * params.resolution, params.faults, products,
                                 max_fault_dot_products));
  }
  return params;
}

std::vector<std::array<double, 3>> fault_normals(const FaultPlanetParams& params) {
  std::vector<std::array<double, 3>> normals;
  normals.reserve(static_cast<std::size_t>(params.faults));
  for (int fault = 0; fault < params.faults; ++fault) {
    const auto draw = [&](std::uint32_t step) {
      return double(uniform01(random_u32(params.seed, static_cast<std::uint32_t>(fault), step, fault_stream)));
    };
    const double z = 2.0 * draw(0) - 1.0;
    const double angle = 2.0 * std::numbers::pi * draw(1);
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    normals.push_back({radius * std::cos(angle), radius * std::sin(angle), z});
  }
  return normals;
}

std::vector<double> fault_planet_positions(int resolution) {
  const CubeSphere sphere(resolution);
  std::vector<double> positions;
  positions.reserve(3 * sphere.region_count());
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    const Vec3 position = sphere_position(sphere.local_position(region));
    positions.insert(positions.end(), position.begin(), position.end());
  }
  return positions;
}

}  // namespace gt
