// Every parameter table (core/param_table.hpp) is sound: names unique, defaults within their ranges
// and equal to the struct's, and each row bound to a member of its own — a value given for one
// parameter lands there and changes no other row — the member its name says (checked by name for a
// few rows of each table). The declarations the algorithms register are their tables'.
#include <set>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/refusal.hpp"

#include "compare/algorithm.hpp"
#include "compare/algorithms/cave.hpp"
#include "compare/algorithms/pipes.hpp"
#include "compare/algorithms/render_heightmap.hpp"
#include "compare/algorithms/render_phong.hpp"
#include "compare/algorithms/render_terrain.hpp"
#include "compare/layered_case.hpp"
#include "core/errors.hpp"
#include "core/param_table.hpp"
#include "core/params/beyer.hpp"
#include "core/params/cave.hpp"
#include "core/params/dissolution.hpp"
#include "core/params/hydraulic.hpp"
#include "core/params/layered.hpp"
#include "core/params/noise.hpp"
#include "core/params/particle.hpp"
#include "core/params/planet.hpp"
#include "core/params/thermal.hpp"

namespace {

using gt::testing::refusal;
using nlohmann::json;
using ::testing::HasSubstr;

// A valid value of `spec` other than its default.
json other_value(const gt::ParamSpec& spec) {
  const json& fallback = spec.default_value;
  switch (spec.kind) {
    case gt::ParamKind::boolean: return !fallback.get<bool>();
    case gt::ParamKind::choice:
      for (const auto& choice : spec.choices) {
        if (choice != fallback) return choice;
      }
      break;
    case gt::ParamKind::integer: {
      const auto number = fallback.get<long long>();
      return number < spec.max ? number + 1 : number - 1;
    }
    case gt::ParamKind::real: {
      const double middle = 0.5 * (spec.min + spec.max);
      return middle != fallback.get<double>() ? middle : 0.5 * (fallback.get<double>() + spec.max);
    }
  }
  return fallback;
}

json as_json(const gt::ParamSpecs& specs) {
  json out = json::array();
  for (const auto& spec : specs) out.push_back(gt::to_json(spec));
  return out;
}

template <class Params>
void expect_sound(const std::string& algorithm, const gt::ParamTable<Params>& table, const Params& defaults = Params{}) {
  SCOPED_TRACE(algorithm);
  const gt::ParamSpecs specs = gt::param_specs(table, defaults);
  std::set<std::string> names;
  for (const auto& spec : specs) EXPECT_TRUE(names.insert(spec.name).second) << spec.name << " is declared twice";
  const json resolved = gt::resolve_params(algorithm, specs, {});
  EXPECT_NO_THROW(gt::resolve_params(algorithm, specs, resolved)) << "a default lies outside its range or choices";
  const json default_values = gt::params_to_json(table, defaults);
  EXPECT_EQ(gt::params_to_json(table, gt::params_from_json(table, resolved)), default_values);
  for (const auto& spec : specs) {
    const json value = other_value(spec);
    ASSERT_NE(value, spec.default_value) << spec.name;
    json expected = default_values;
    expected[spec.name] = value;
    const Params read = gt::params_from_json(table, gt::resolve_params(algorithm, specs, {{spec.name, value}}));
    EXPECT_EQ(gt::params_to_json(table, read), expected) << spec.name << " = " << value.dump();
  }
}

void expect_registered(const std::string& algorithm, const gt::ParamSpecs& specs) {
  EXPECT_EQ(as_json(*gt::find_algorithm(algorithm).params), as_json(specs)) << algorithm;
}

template <class Params>
Params read(const gt::ParamTable<Params>& table, const json& given) {
  return gt::params_from_json(table, gt::resolve_params("test", gt::param_specs(table), given));
}

TEST(ParamTables, EveryRegisteredAlgorithmDeclaresUniqueNamesWithDefaultsInRange) {
  for (const auto& algorithm : gt::algorithms()) {
    SCOPED_TRACE(algorithm.name);
    std::set<std::string> names;
    for (const auto& spec : *algorithm.params) EXPECT_TRUE(names.insert(spec.name).second) << spec.name;
    const json resolved = gt::resolve_params(algorithm.name, *algorithm.params, {});
    EXPECT_NO_THROW(gt::resolve_params(algorithm.name, *algorithm.params, resolved));
  }
}

TEST(ParamTables, ErosionTablesAreSound) {
  expect_sound("erosion.thermal", gt::thermal_param_table());
  expect_sound("erosion.thermal_jako", gt::thermal_jako_param_table());
  expect_sound("erosion.dissolution", gt::dissolution_param_table());
  expect_sound("erosion.pipe", gt::hydraulic_param_table());
  expect_sound("erosion.pipe", gt::pipe_case_param_table());
  expect_sound("erosion.layered", gt::layered_param_table());
  expect_sound("erosion.layered", gt::layered_case_param_table());
  expect_sound("erosion.particle", gt::particle_param_table());
  expect_sound("erosion.beyer", gt::beyer_param_table());
  expect_registered("erosion.thermal", gt::thermal_param_specs());
  expect_registered("erosion.thermal_jako", gt::thermal_jako_param_specs());
  expect_registered("erosion.dissolution", gt::dissolution_param_specs());
  expect_registered("erosion.pipe", gt::param_specs(gt::pipe_case_param_table()));
  expect_registered("erosion.layered", gt::layered_case_param_specs());
  expect_registered("erosion.particle", gt::particle_param_specs());
  expect_registered("erosion.beyer", gt::beyer_param_specs());
}

TEST(ParamTables, NoisePlanetAndCaveTablesAreSound) {
  using gt::Fractal;
  using gt::NoiseBasis;
  for (const auto& [name, basis] : {std::pair{"noise.simplex2", NoiseBasis::simplex2},
                                    std::pair{"noise.simplex3", NoiseBasis::simplex3},
                                    std::pair{"noise.simplex4", NoiseBasis::simplex4},
                                    std::pair{"noise.perlin3", NoiseBasis::perlin3},
                                    std::pair{"noise.perlin3_texture", NoiseBasis::perlin3_texture}}) {
    expect_sound(name, gt::noise_param_table(basis, Fractal::none), gt::noise_defaults(basis, Fractal::none));
    expect_registered(name, gt::noise_param_specs(basis));
  }
  for (const auto& [name, fractal] : {std::pair{"noise.fbm", Fractal::fbm}, std::pair{"noise.ridged", Fractal::ridged},
                                      std::pair{"noise.hetero_terrain", Fractal::hetero_terrain}}) {
    expect_sound(name, gt::noise_param_table(NoiseBasis::perlin3, fractal), gt::noise_defaults(NoiseBasis::perlin3, fractal));
    expect_registered(name, gt::fractal_param_specs(fractal));
  }
  expect_sound("planet.earth_like", gt::planet_param_table());
  expect_registered("planet.earth_like", gt::planet_param_specs());
  expect_sound("cave", gt::cave_param_table());
  expect_sound("cave.marching_tetrahedra", gt::cave_mesh_param_table());
  expect_sound("cave.marching_cubes", gt::cave_mesh_param_table(), gt::cave_mesh_defaults_for_cubes());
  expect_sound("cave.endless", gt::cave_endless_param_table());
  expect_registered("cave.marching_tetrahedra", gt::param_specs(gt::cave_mesh_param_table()));
  expect_registered("cave.marching_cubes", gt::param_specs(gt::cave_mesh_param_table(), gt::cave_mesh_defaults_for_cubes()));
  expect_registered("cave.endless", gt::param_specs(gt::cave_endless_param_table()));
}

TEST(ParamTables, RenderTablesAreSound) {
  expect_sound("render.heightmap_from_mesh", gt::heightmap_render_param_table());
  expect_sound("render.phong", gt::phong_render_param_table());
  expect_sound("render.terrain", gt::terrain_render_param_table());
  expect_registered("render.heightmap_from_mesh", gt::param_specs(gt::heightmap_render_param_table()));
  expect_registered("render.phong", gt::param_specs(gt::phong_render_param_table()));
  expect_registered("render.terrain", gt::param_specs(gt::terrain_render_param_table()));
}

// The round trip above cannot tell a row bound to the wrong member that no other row binds; these
// name the member.
TEST(ParamTables, RowsBindTheMembersTheirNamesSay) {
  const auto thermal = read(gt::thermal_param_table(), {{"iterations", 7}, {"talus_angle", 30.0}, {"strength", 1.5},
                                                        {"neighbourhood", "diagonal"}, {"normalised", true},
                                                        {"vertical_aspect", 2.0}});
  EXPECT_EQ(thermal.iterations, 7);
  EXPECT_EQ(thermal.talus_angle_deg, 30.0);
  EXPECT_EQ(thermal.strength, 1.5);
  EXPECT_EQ(thermal.neighbourhood, gt::Neighbourhood::diagonal);
  EXPECT_TRUE(thermal.normalised);
  EXPECT_EQ(thermal.vertical_aspect, 2.0);
  const auto pipe = read(gt::pipe_case_param_table(), {{"pipes", "8"}, {"thermal_talus_angle", 20.0}, {"checkpoints", 3},
                                                       {"rain_map", "orographic"}});
  EXPECT_EQ(pipe.hydraulic.pipe_count, 8);
  EXPECT_EQ(pipe.hydraulic.thermal_talus_angle, 20.0);
  EXPECT_EQ(pipe.checkpoints, 3);
  EXPECT_EQ(pipe.rain_map, gt::RainMap::orographic);
  const auto layered = read(gt::layered_case_param_table(), {{"repose_sand", 0.9}, {"weathering_stones", 0.5},
                                                             {"creep_rate", 0.5}, {"soil", "scree"}});
  EXPECT_EQ(layered.layered.repose_tan[1], 0.9);
  EXPECT_EQ(layered.layered.weathering_shares[3], 0.5);
  EXPECT_EQ(layered.layered.creep_rate, 0.5);
  EXPECT_EQ(layered.soil, "scree");
  const auto particle = read(gt::particle_param_table(), {{"drag", 0.5}, {"erosion_strength", 0.1}, {"ordering", "race"}});
  EXPECT_EQ(particle.drag, 0.5);
  EXPECT_EQ(particle.erosion_strength, 0.1);
  EXPECT_EQ(particle.ordering, gt::DropletOrdering::race);
  const auto beyer = read(gt::beyer_param_table(), {{"erosion", 0.7}, {"speed_rule", "physical"}, {"normalised", false}});
  EXPECT_EQ(beyer.kernel.erosion, 0.7);
  EXPECT_EQ(beyer.kernel.speed_rule, gt::BeyerSpeedRule::physical);
  EXPECT_FALSE(beyer.normalised);
  const auto noise = read(gt::noise_param_table(gt::NoiseBasis::perlin3, gt::Fractal::ridged),
                          {{"origin_y", 3.0}, {"step", 0.25}, {"octaves", 4.5}, {"gain", 1.5}, {"basis", "simplex3"}});
  EXPECT_EQ(noise.sampling.origin[1], 3.0);
  EXPECT_EQ(noise.sampling.step, 0.25);
  EXPECT_EQ(noise.fractal_params.octaves, 4.5);
  EXPECT_EQ(noise.fractal_params.gain, 1.5);
  EXPECT_EQ(noise.basis, gt::NoiseBasis::simplex3);
  const auto endless = read(gt::cave_endless_param_table(), {{"origin_z", -5}, {"size_y", 7}, {"direction", "-y"}});
  EXPECT_EQ(endless.big_cube.origin[2], -5);
  EXPECT_EQ(endless.big_cube.size[1], 7);
  EXPECT_EQ(endless.direction, "-y");
  const auto phong = read(gt::phong_render_param_table(), {{"target_y", 2.0}, {"moss", 0.5}, {"up_axis", "z"},
                                                           {"block_size_x", 9}, {"camera", "fixed"}});
  EXPECT_EQ(phong.target[1], 2.0);
  EXPECT_EQ(phong.cave.moss, 0.5);
  EXPECT_EQ(phong.up, (gt::reference::Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(phong.block_size[0], 9);
  EXPECT_TRUE(phong.fixed_camera);
  const auto terrain = read(gt::terrain_render_param_table(), {{"thermal_talus_angle", 12.0}, {"layered_steps", 3},
                                                               {"pipe_time_step", 0.5}});
  EXPECT_EQ(terrain.thermal.talus_angle_deg, 12.0);
  EXPECT_EQ(terrain.layered.steps, 3);
  EXPECT_EQ(terrain.pipe.time_step, 0.5);
}

// A struct built in code is checked against the same declarations, with the same refusal.
TEST(ParamTables, StructsBuiltInCodeAreCheckedAgainstTheDeclaredRanges) {
  gt::ThermalParams thermal;
  EXPECT_NO_THROW(gt::check_param_ranges("erosion.thermal", gt::thermal_param_table(), thermal));
  thermal.talus_angle_deg = 95.0;
  EXPECT_THAT(refusal([&] { gt::check_param_ranges("erosion.thermal", gt::thermal_param_table(), thermal); }),
              HasSubstr("erosion.thermal: parameter talus_angle = 95.0 is out of range; expected real in [0, 85] degree"));
  gt::HydraulicParams pipe;
  pipe.pipe_count = 6;
  EXPECT_THAT(refusal([&] { gt::check_param_ranges("erosion.pipe", gt::hydraulic_param_table(), pipe); }),
              HasSubstr("pipes = \"6\" is unknown; expected one of 4, 8"));
  gt::LayeredParams layered;
  layered.depth_factor = 2.0;
  EXPECT_THAT(refusal([&] { gt::validate_layered_params(layered); }),
              HasSubstr("parameter depth_factor = 2.0 is out of range; expected real in [1, 1.5]"));
}

}  // namespace
