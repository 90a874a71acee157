// `render.terrain`: a heightmap (any case input: a DEM file, a generator, cropped or not), eroded
// first when `erode` asks for it, meshed as a closed solid (reference/render/terrain_solid.hpp:
// surface, skirts and a base; x east, y up, z south, metres) and Phong-shaded through the orbit
// camera of reference/render/phong.hpp by both twins (compare/render_case.hpp: the same image
// checks, timings and pictures as render.phong).
//
// Erosion (reference only, in double, before meshing; both twins then draw the same solid, so the
// images compare rendering alone and a pair of cases shows the terrain before and after):
//   erode = none      the input as it is
//   erode = thermal   seed 000's two-pass thermal erosion (reference/erosion/thermal.hpp) with the
//                     thermal_* parameters (erosion.thermal's, in physical heights: T = tan α)
//   erode = pipe      Mei's virtual-pipe erosion (reference/erosion/pipes.hpp) from a dry start
//                     with the pipe_* parameters (erosion.pipe's hydraulic ones; rain brings water)
//   erode = layered   seed 001's layered ground (compare/layered_case.hpp: ref<double> for
//                     layered_steps iterations) with the layered_* parameters (erosion.layered's
//                     and its profile's: layered_soil, layered_vegetation, layered_rain_rate, ...);
//                     the heights meshed are the ground's surface after the run. The input must
//                     have no no-data cells (crop it): the layered ground holds none.
// Another erosion is one more choice, a member of TerrainRenderParams with its rows prefixed likewise
// (append_prefixed), and one more branch in eroded().
//
// Base: base_depth, or 0 for terrain_solid's automatic depth; for an eroded terrain the automatic
// base is the un-eroded terrain's, so that a before/after pair shares its base and skirt bottoms.
// Look: terrain (reference/render/phong.hpp's height ramp and rock by slope) with the ramp over the
// input's heights before erosion, or plain.
// Drape (terrain look only): drape = astronaut | grass reads datasets/real/textures/<name>.png (fetched by
// datasets/fetch.sh; the folder is the build's GT_DATASET_DIR) and lays it over the solid's xz
// bounding box, west to east and north to south (the surface's extent: the skirts and the base lie
// within it), image row 0 at the north edge; its colour replaces the height ramp, the rock blend
// stays. A gray image gives r = g = b, an alpha channel is dropped. A missing or unreadable file is
// an InputError naming the path; drape = none renders the ramp exactly as before drapes existed.
// drape = material (erode = layered only; otherwise an InputError naming the remedy) builds the
// drape in memory instead of reading a file: one texel per cell, row 0 the grid's first (north)
// row, laid so that texel centre (i + 0.5)/W falls on sample i's vertex (the extent is the solid's
// xz box widened by half a cell on every side). Its colour is layered_surface_colour of the ground
// after the run (compare/layered_look.hpp: the top non-empty layer's material, greened by the
// vegetation), turned toward water blue (0.10, 0.30, 0.62) where the run leaves water:
//   t = clamp((w - 0.05 m) / (1 m - 0.05 m), 0, 1), colour = (1 - t)·material + t·blue
// (w the water depth of the cell; the rain's running film, a few cm on the flanks, does not show,
// ponds a metre deep and more are all water), each channel rounded to round(255·c) bytes like the layered pictures' PNGs. The texture
// reaches both twins as any drape does (TerrainLook::drape; render_phong.cpp hands the same bytes
// to the GL twin), so the image checks compare the same picture.
// Checks: those of run_phong_twins (image.*, determinism.gpu) and the mesh checks of the solid
// (compare/checks/mesh.hpp, backend "cpu", closed expected): the solid must be watertight,
// manifold, outward and free of self-intersections; genus, components and volume are informative.
#include "compare/algorithms/render_terrain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <OpenImageIO/imagebuf.h>

#include "compare/algorithm.hpp"
#include "compare/checks/image.hpp"
#include "compare/checks/mesh.hpp"
#include "compare/layered_case.hpp"
#include "compare/layered_look.hpp"
#include "compare/render_case.hpp"
#include "core/errors.hpp"
#include "core/params/hydraulic.hpp"
#include "core/params/thermal.hpp"
#include "reference/erosion/pipes.hpp"
#include "reference/erosion/thermal.hpp"
#include "reference/render/phong.hpp"
#include "reference/render/terrain_solid.hpp"

namespace gt {
namespace {

constexpr Choice<reference::Look> look_choices[] = {{"terrain", reference::Look::terrain},
                                                    {"plain", reference::Look::plain}};

const ParamSpecs& terrain_specs() {
  static const ParamSpecs specs = param_specs(terrain_render_param_table());
  return specs;
}

struct Eroded {
  Heightmap heights;
  std::string description;               // "" when not eroded
  std::optional<LayeredOutcome> layered;  // the ground (and water) after erode = layered
};

double largest_change(const Heightmap& before, const Heightmap& after) {
  double moved = 0.0;
  for (std::size_t k = 0; k < before.size(); ++k) {
    if (before.is_valid(k)) moved = std::max(moved, std::abs(after.values[k] - before.values[k]));
  }
  return moved;
}

// Physical heights (T = tan α, lengths the cell sizes).
Eroded thermally_eroded(const Heightmap& input, const ThermalParams& params) {
  const ThermalConstants constants = thermal_constants(params, input);
  Eroded out{reference::thermal_erosion(input, constants, params.iterations, params.neighbourhood), ""};
  out.description = fmt::format("thermal erosion (reference, double): {} iterations, talus {}°, strength {}, {}; "
                                "largest height change {:.3g} {}",
                                params.iterations, params.talus_angle_deg, params.strength,
                                neighbourhood_name(params.neighbourhood), largest_change(input, out.heights),
                                input.vertical_unit);
  return out;
}

// Mei's pipes from a dry start (erosion.pipe's parameters; rain_rate brings the water).
Eroded pipe_eroded(const Heightmap& input, const HydraulicParams& params) {
  reference::PipeErosion<double> erosion(dry_pipe_state(input), pipe_constants(params, input));
  erosion.run(params.steps);
  Eroded out{erosion.state().terrain, ""};
  out.description = fmt::format("pipe erosion (reference, double): {} steps of {} s, rain {} m/s, K_c {} s, {} "
                                "transport; largest height change {:.3g} {}",
                                params.steps, params.time_step, params.rain_rate, params.capacity,
                                sediment_transport_name(params.transport), largest_change(input, out.heights),
                                input.vertical_unit);
  return out;
}

// Seed 001's layered ground (erosion.layered's case setup), ref<double>; the heights are its surface.
Eroded layered_eroded(const Heightmap& input, const LayeredCaseParams& params) {
  LayeredSetup setup;
  try {
    setup = layered_setup(params, input);
  } catch (const InputError& refused) {
    throw InputError(fmt::format("render.terrain, erode = layered: {}", refused.what()));
  }
  Eroded out{input, "", run_layered_reference(setup)};
  const LayeredGround<double>& ground = out.layered->ground;
  for (std::size_t c = 0; c < ground.cells(); ++c) out.heights.values[c] = ground.surface[c];
  out.description = fmt::format("layered ground (reference, double): {} steps of {} s, {} soil, vegetation {}, rain {} "
                                "m/s{}; largest height change {:.3g} {}",
                                setup.steps, setup.params.time_step, setup.soils[0], setup.columns.vegetation[0],
                                setup.params.rain_rate, out.layered->water ? "" : " (no water)",
                                largest_change(input, out.heights), input.vertical_unit);
  return out;
}

Eroded eroded(const Heightmap& input, const TerrainRenderParams& params) {
  if (params.erode == "thermal") return thermally_eroded(input, params.thermal);
  if (params.erode == "pipe") return pipe_eroded(input, params.pipe);
  if (params.erode == "layered") return layered_eroded(input, params.layered);
  return {input, "", {}};
}

// The base below the eroded terrain lies where the un-eroded terrain's automatic base would (the
// pair of cases then differs only in the surface), unless base_depth is given or the erosion dug
// below that level (then the automatic depth of the eroded terrain).
double base_depth(const Heightmap& input, const Heightmap& eroded, const TerrainRenderParams& params) {
  if (params.base_depth > 0.0 || params.erode == "none") return params.base_depth;
  const double vertical_scale = params.vertical_scale;
  const double original_base = reference::terrain_solid(input, {.vertical_scale = vertical_scale}).base_y;
  const reference::TerrainSolid automatic = reference::terrain_solid(eroded, {.vertical_scale = vertical_scale});
  const double depth = automatic.base_y + automatic.base_depth - original_base;  // from the lowest kept vertex
  return depth > 0.0 ? depth : 0.0;
}

// The RGB8 texels of an image file: gray replicated to r = g = b, channels beyond the third dropped.
reference::TerrainDrape drape_texels(const std::filesystem::path& file) {
  const OIIO::ImageBuf image = read_image(file);
  const OIIO::ImageSpec& spec = image.spec();
  std::vector<std::uint8_t> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
  if (!image.get_pixels(image.roi(), OIIO::TypeDesc::UINT8, pixels.data())) {
    throw InputError(fmt::format("cannot read the pixels of {}: {}", file.string(), image.geterror()));
  }
  reference::TerrainDrape drape{.width = spec.width, .height = spec.height, .rgb = {}};
  drape.rgb.reserve(3 * pixels.size() / std::size_t(spec.nchannels));
  for (std::size_t first = 0; first < pixels.size(); first += std::size_t(spec.nchannels)) {
    for (int channel = 0; channel < 3; ++channel) {
      drape.rgb.push_back(pixels[first + std::size_t(spec.nchannels >= 3 ? channel : 0)]);
    }
  }
  return drape;
}

// datasets/real/textures/<name>.png over the solid's xz bounding box.
reference::TerrainDrape terrain_drape(const std::string& name, const Mesh& solid) {
  const auto file = std::filesystem::path(GT_DATASET_DIR) / "real" / "textures" / (name + ".png");
  if (!std::filesystem::is_regular_file(file)) {
    throw InputError(fmt::format("render.terrain: the drape {} is missing (datasets/fetch.sh fetches it)", file.string()));
  }
  reference::TerrainDrape drape = drape_texels(file);
  const auto [low, high] = bounding_box(solid);
  drape.x_west = low[0];
  drape.x_east = high[0];
  drape.z_north = low[2];
  drape.z_south = high[2];
  return drape;
}

// drape = material: the layered ground's surface colour a texel a cell, blued where water stands
// (the header's rule), texel centres on the samples' vertices of terrain_solid(heights).
constexpr double shallowest_water_shown = 0.05;  // m
constexpr double water_fully_shown = 1.0;        // m
constexpr LayeredColour water_blue{0.10f, 0.30f, 0.62f};

reference::TerrainDrape material_drape(const LayeredOutcome& outcome, const Heightmap& heights, std::size_t& watery) {
  const LayeredGround<double>& ground = outcome.ground;
  reference::TerrainDrape drape{.width = ground.width,
                                .height = ground.height,
                                .rgb = {},
                                .x_west = -0.5 * ground.width * heights.cell_size_x,
                                .x_east = 0.5 * ground.width * heights.cell_size_x,
                                .z_north = -0.5 * ground.height * heights.cell_size_y,
                                .z_south = 0.5 * ground.height * heights.cell_size_y};
  drape.rgb.reserve(3 * ground.cells());
  watery = 0;
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    LayeredColour colour = layered_surface_colour(ground, c);
    const double depth = outcome.water ? outcome.water->water[c] : 0.0;
    const double t =
        std::clamp((depth - shallowest_water_shown) / (water_fully_shown - shallowest_water_shown), 0.0, 1.0);
    if (t > 0.0) ++watery;
    for (int channel = 0; channel < 3; ++channel) {
      const double value = (1.0 - t) * colour[channel] + t * water_blue[channel];
      drape.rgb.push_back(std::uint8_t(std::lround(255.0 * std::clamp(value, 0.0, 1.0))));
    }
  }
  return drape;
}

struct TerrainCase {
  reference::TerrainSolid solid;
  reference::PhongScene scene;
  int subpixel_bits = 8;
  double min_covered_share = 0.0;
  std::string input;
  std::vector<std::string> notes;
};

void run_terrain(const TerrainCase& terrain, const RunOptions& options, CaseResult& result) {
  result.notes.insert(result.notes.end(), terrain.notes.begin(), terrain.notes.end());
  if (options.progress) options.progress->stage("mesh checks of the solid");
  const MeshReport report = check_mesh(terrain.solid.mesh);
  for (Check& check : mesh_checks(report, "cpu", true)) result.checks.push_back(std::move(check));
  run_phong_twins(terrain.scene, terrain.subpixel_bits, terrain.min_covered_share, terrain.input, options,
                  result);
}

PreparedTwin prepare_terrain(const nlohmann::json& resolved, const LoadedInput& input) {
  if (input.heights.size() == 0) {
    throw InputError("render.terrain meshes a heightmap: give the case a heightmap input ({\"file\": ...})");
  }
  const auto params = params_from_json(terrain_render_param_table(), resolved);
  const std::string& drape = params.drape;
  if (drape == "material" && params.erode != "layered") {
    throw InputError("render.terrain: drape = material colours the surface by the layered ground's material, which "
                     "only erode = layered makes: set erode = layered, or choose another drape");
  }
  Eroded terrain_heights = eroded(input.heights, params);
  const double vertical_scale = params.vertical_scale;
  const reference::TerrainSolid solid = reference::terrain_solid(
      terrain_heights.heights,
      {.vertical_scale = vertical_scale, .base_depth = base_depth(input.heights, terrain_heights.heights, params)});
  const reference::Camera camera = reference::orbit_camera(solid.mesh, params.azimuth_deg, params.elevation_deg,
                                                           params.fov_deg, params.width, params.height);
  const bool terrain_look = params.look == reference::Look::terrain;
  TerrainCase terrain{solid, reference::phong_scene(solid.mesh, camera, params.look), params.subpixel_bits,
                      params.min_covered_share, "", {}};
  // The ramp spans the input's heights before erosion (not the base's): an eroded terrain, whose
  // heights stay within that range (erosion moves material), keeps the colours of its original.
  if (terrain_look) {
    const auto [low, high] = valid_range(input.heights);
    if (high > low) {
      terrain.scene.terrain.height_low = vertical_scale * low;
      terrain.scene.terrain.height_high = vertical_scale * high;
    }
  }
  if (drape != "none") {
    if (!terrain_look) throw InputError("render.terrain: a drape needs look = terrain");
    std::size_t watery = 0;
    terrain.scene.terrain.drape = drape == "material"
                                      ? material_drape(*terrain_heights.layered, terrain_heights.heights, watery)
                                      : terrain_drape(drape, solid.mesh);
    const reference::TerrainDrape& placed = *terrain.scene.terrain.drape;
    terrain.notes.push_back(fmt::format("drape {}, {}x{} texels over x [{:.4g}, {:.4g}] m, z [{:.4g}, {:.4g}] m{}",
                                        drape == "material" ? "material (the layered ground's surface)" : drape + ".png",
                                        placed.width, placed.height, placed.x_west, placed.x_east, placed.z_north,
                                        placed.z_south,
                                        drape == "material" ? fmt::format("; water shown on {} of {} cells", watery,
                                                                          terrain_heights.heights.size())
                                                            : ""));
  }
  if (!terrain_heights.description.empty()) terrain.notes.push_back(terrain_heights.description);
  terrain.notes.push_back(fmt::format(
      "terrain solid: {} quads ({} dropped where two met only at a corner), {} triangles ({} surface, {} base, {} "
      "skirt), base at y = {:.4g} m ({:.4g} m below the lowest height), vertical scale {}",
      solid.kept_quads, solid.dropped_quads, solid.mesh.triangles.size(), solid.surface_triangles,
      solid.base_triangles, solid.skirt_triangles, solid.base_y, solid.base_depth, nlohmann::json(vertical_scale).dump()));
  const std::string& erode = params.erode;
  terrain.input = fmt::format("{}{}, solid of {} triangles", input.description,
                              erode == "none" ? "" : ", after " + erode + " erosion", solid.mesh.triangles.size());
  PreparedTwin prepared;
  prepared.kind = CaseRun([terrain = std::move(terrain)](const nlohmann::json&, const RunOptions& options, CaseResult& result) {
    run_terrain(terrain, options, result);
  });
  return prepared;
}

// Another algorithm's rows under "<prefix>_<name>", so that several erosions can sit side by side;
// `left_out` names the ones this algorithm fixes (at the struct's defaults).
template <class Erosion>
void append_prefixed(ParamTable<TerrainRenderParams>& rows, Erosion TerrainRenderParams::*member,
                     const ParamTable<Erosion>& from, const std::string& prefix,
                     const std::vector<std::string>& left_out) {
  for (ParamRow<TerrainRenderParams> row : nested(member, from)) {
    if (std::find(left_out.begin(), left_out.end(), row.spec.name) != left_out.end()) continue;
    row.spec.name = prefix + "_" + row.spec.name;
    row.spec.description = fmt::format("erode = {}: {}", prefix, row.spec.description);
    rows.push_back(std::move(row));
  }
}

}  // namespace

const ParamTable<TerrainRenderParams>& terrain_render_param_table() {
  using P = TerrainRenderParams;
  static const ParamTable<P> table = [] {
    ParamTable<P> rows = {
        integer_param("width", &P::width, 1, 4096, "pixel", "image columns"),
        integer_param("height", &P::height, 1, 4096, "pixel", "image rows"),
        real_param("fov_deg", &P::fov_deg, 1.0, 150.0, "degree",
                   "vertical field of view (37°: at 4:3 the horizontal one holds the bounding sphere)"),
        real_param("azimuth_deg", &P::azimuth_deg, -360.0, 360.0, "degree",
                   "camera direction around +y (up) from the box centre, from +z (south) towards +x (east)"),
        real_param("elevation_deg", &P::elevation_deg, -89.0, 89.0, "degree",
                   "camera direction above the ground plane"),
        integer_param("subpixel_bits", &P::subpixel_bits, 0, 16, "bit",
                      "GL_SUBPIXEL_BITS the reference snaps vertices to (8: llvmpipe and NVIDIA)"),
        real_param("vertical_scale", &P::vertical_scale, 0.01, 100.0, "1", "vertical exaggeration of the heights"),
        real_param("base_depth", &P::base_depth, 0.0, 1e5, "m",
                   "depth of the solid's base below the lowest height; 0: a fifth of the relief (at least 2 % of the "
                   "extent)"),
        choice_param("look", &P::look, look_choices, "1",
                     "terrain: height ramp from the lowest to the highest input height (before erosion, "
                     "so that a before/after pair shares its colours), rock by slope (skirts and base are rock); "
                     "plain: seed 004's one albedo"),
        choice_param("drape", &P::drape, {"none", "astronaut", "grass", "material"}, "1",
                     "terrain look: colour image draped over the surface in plan view "
                     "(datasets/real/textures/<name>.png, west to east, north at the top), "
                     "replacing the height ramp; material (erode = layered only): the layered ground's surface "
                     "material after the run, a texel a cell, water deeper than 5 cm blued by depth; none: the ramp"),
        real_param("min_covered_share", &P::min_covered_share, 0.0, 1.0, "1",
                   "least share of pixels the solid must cover in the reference image (0: not checked)"),
        choice_param("erode", &P::erode, {"none", "thermal", "pipe", "layered"}, "",
                     "erosion applied to the heightmap (reference, double) before meshing"),
    };
    append_prefixed(rows, &P::thermal, thermal_param_table(), "thermal", {"normalised", "vertical_aspect"});
    append_prefixed(rows, &P::pipe, hydraulic_param_table(), "pipe", {});
    append_prefixed(rows, &P::layered, layered_case_param_table(), "layered", {});
    return rows;
  }();
  return table;
}

Algorithm render_terrain_algorithm() {
  return {.name = "render.terrain",
          .summary = "heightmap (optionally eroded) as a closed solid, Phong-shaded: reference rasterizer vs the GL pipeline",
          .source = "issue 6 (terrain look before/after erosion); seed 004 §2.9 shading; seed 000 §4.4.3 thermal erosion; seed 001's layered ground and its surface material (erode = layered, drape = material)",
          .params = &terrain_specs(),
          .prepare = prepare_terrain,
          .kind = CaseKind::custom,
          .ad_hoc_input = AdHocInput::heightmap,
          .candidate = CandidateOutput::image,
          // Measured 2316 B a height cell (1024² vs 256² input: the closed solid, two triangles a
          // cell, and its checks) and 16 B a pixel (1024² vs 256² image).
          .memory = [](const nlohmann::json& resolved, const LoadedInput& input) {
            const auto params = params_from_json(terrain_render_param_table(), resolved);
            const double pixels = double(params.width) * params.height;
            // erode = layered adds its ground and water in double (erosion.layered's 1000 B a cell).
            const double cell_bytes = params.erode == "layered" ? 3600 : 2600;
            return memory_for(static_cast<double>(input.heights.size()), "cells", cell_bytes) +
                   memory_for(pixels, "pixels", 120);
          }};
}

}  // namespace gt
