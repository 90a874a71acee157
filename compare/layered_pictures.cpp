// The pictures of the layered ground after a run (see layered_pictures.hpp).
#include "compare/layered_pictures.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "compare/field_files.hpp"
#include "compare/layered_look.hpp"
#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "reference/erosion/layered/material_masks.hpp"

namespace gt {
namespace {

using Colour = LayeredColour;

// The middle row: above, the surface's elevation (grey ground under white air, its range stretched
// to the panel); below, a dark rule, then the layers from the surface down to 1.2 times the deepest
// soil plus soft rock of the row, true to scale in depth.
void write_cross_section(const LayeredGround<double>& ground, const std::filesystem::path& png, double& depth_shown) {
  constexpr int elevation_rows = 120, rule_rows = 3, layer_rows = 240;
  const int row = ground.height / 2;
  const int scale = std::max(1, 720 / ground.width);
  const int width = ground.width * scale;
  double low = std::numeric_limits<double>::infinity(), high = -low, deepest = 0.0;
  for (int x = 0; x < ground.width; ++x) {
    const std::size_t c = ground.cell(x, row);
    low = std::min(low, ground.surface[c]);
    high = std::max(high, ground.surface[c]);
    double soft = ground.soil_thickness(0, c) + ground.soil_thickness(1, c);
    if (ground.bedrock_layer_count > 0) soft += ground.bedrock_at(0, c);
    deepest = std::max(deepest, soft);
  }
  depth_shown = std::max(1.2 * deepest, 1.0);
  const double span = std::max(high - low, 1e-9);
  std::vector<Colour> pixels(std::size_t(width) * (elevation_rows + rule_rows + layer_rows));
  for (int px = 0; px < width; ++px) {
    const std::size_t c = ground.cell(px / scale, row);
    const double ground_rows = 8.0 + (elevation_rows - 16.0) * (ground.surface[c] - low) / span;
    for (int py = 0; py < elevation_rows; ++py) {
      const bool below = elevation_rows - py <= ground_rows;
      pixels[std::size_t(py) * width + px] = below ? layered_surface_colour(ground, c) : Colour{1, 1, 1};
    }
    for (int py = elevation_rows; py < elevation_rows + rule_rows; ++py) pixels[std::size_t(py) * width + px] = {0.1f, 0.1f, 0.1f};
    for (int py = 0; py < layer_rows; ++py) {
      const double depth = (py + 0.5) / layer_rows * depth_shown;
      pixels[std::size_t(elevation_rows + rule_rows + py) * width + px] = layered_colour_at_depth(ground, c, depth);
    }
  }
  write_colour_image(width, elevation_rows + rule_rows + layer_rows, pixels, png);
}

// The same row with axes in metres (the picture above has no room for text): the surface's
// elevation along the row, and beside it the base of each layer below the surface, true depth,
// with a legend: the depth scale and the legend the colour picture cannot carry.
void plot_cross_section(const LayeredGround<double>& ground, const RunOptions& options, CaseResult& result) {
  const int row = ground.height / 2;
  SeriesPlot surface{fmt::format("surface along row {}", row), "distance along the row (m)", "elevation (m)"};
  SeriesPlot layers{"the layers' bases under the surface", "distance along the row (m)",
                    "depth below the surface (m, negative down)"};
  Series elevation{"surface"};
  std::vector<Series> bases{{"base of the topsoil"}, {"base of the subsoil"}};
  for (int layer = 0; layer + 1 < ground.bedrock_layer_count; ++layer) {
    bases.push_back({fmt::format("base of bedrock layer {}", layer + 1)});
  }
  for (int x = 0; x < ground.width; ++x) {
    const std::size_t c = ground.cell(x, row);
    const double distance = (x + 0.5) * ground.cell_size_x;
    elevation.x.push_back(distance);
    elevation.y.push_back(ground.surface[c]);
    double depth = 0.0;
    for (std::size_t base = 0; base < bases.size(); ++base) {
      depth += base < 2 ? ground.soil_thickness(int(base), c) : ground.bedrock_at(int(base) - 2, c);
      bases[base].x.push_back(distance);
      bases[base].y.push_back(-depth);
    }
  }
  surface.series.push_back(std::move(elevation));
  layers.series = std::move(bases);
  attach_plot({surface, layers}, options, "cross_section_axes.png",
              fmt::format("cross-section along row {} in metres: the surface's elevation, and the base of each layer "
                          "below the surface (the last bedrock layer's base is not stored)",
                          row),
              result);
}

// The material masks (§3.17, reference/erosion/layered/material_masks.hpp) as fields `mask_<material>`
// and a picture each, named in its caption: from black (0) to the material's colour at the mask's
// largest share, so that a material showing on a few per cent of a cell is still visible; the
// colour bar gives the share.
void write_material_masks(const LayeredGround<double>& ground, const LayeredParams& params, const RunOptions& options,
                          CaseResult& result) {
  const std::size_t materials = soil_component_count + params.bedrock_types.size();
  std::vector<Grid<double>> masks(materials, Grid<double>(ground.width, ground.height));
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    const auto column = reference::material_masks(ground, params, c);
    for (std::size_t m = 0; m < materials; ++m) masks[m].values[c] = column[m];
  }
  const int scale = std::max(1, 240 / std::max(ground.width, ground.height));
  const auto folder = options.report_dir / result.name;
  for (std::size_t m = 0; m < materials; ++m) {
    auto& mask = masks[m];
    mask.cell_size_x = ground.cell_size_x;
    mask.cell_size_y = ground.cell_size_y;
    const Colour colour = m < soil_component_count ? layered_component_colour(int(m))
                                                   : layered_bedrock_colour(int(m - soil_component_count));
    const double largest = *std::max_element(mask.values.begin(), mask.values.end());
    const auto shade = [&](double share) {
      const auto strength = static_cast<float>(largest > 0.0 ? std::clamp(share / largest, 0.0, 1.0) : 0.0);
      return Colour{strength * colour[0], strength * colour[1], strength * colour[2]};
    };
    std::vector<Colour> pixels;
    for (int py = 0; py < ground.height * scale; ++py) {
      for (int px = 0; px < ground.width * scale; ++px) pixels.push_back(shade(mask.values[ground.cell(px / scale, py / scale)]));
    }
    const std::string name = layered_material_name(m);
    std::string key = "mask_" + name;
    std::replace(key.begin(), key.end(), ' ', '_');
    write_colour_image(ground.width * scale, ground.height * scale, pixels, folder / (key + ".png"));
    add_picture(result, key + ".png",
                fmt::format("{}: its share of the surface after the run, with the thesis's transparency (§3.17: a "
                            "layer thinner than K_pmin lets the one below show)",
                            name),
                sampled_scale("black to " + name, 0.0, largest, "1", shade),
                map_width_m(ground.width, ground.cell_size_x));
    write_field_files(mask, {key, key, "cpu", "1", fmt::format("share of the surface showing {} (§3.17), ref<double>", name)},
                      options, result);
  }
}

}  // namespace

std::string layered_material_name(std::size_t material) {
  return material < soil_component_count ? soil_component_name(int(material))
                                         : fmt::format("bedrock type {}", material - soil_component_count);
}

void write_layered_pictures(const LayeredGround<double>& ground, const LayeredParams& params, const RunOptions& options,
                            CaseResult& result) {
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  std::vector<Colour> surface;
  for (std::size_t c = 0; c < ground.cells(); ++c) surface.push_back(layered_surface_colour(ground, c));
  // Each cell a square of pixels, so a small grid is still readable.
  const int scale = std::max(1, 512 / ground.width);
  std::vector<Colour> pixels;
  for (int py = 0; py < ground.height * scale; ++py) {
    for (int px = 0; px < ground.width * scale; ++px) pixels.push_back(surface[ground.cell(px / scale, py / scale)]);
  }
  write_colour_image(ground.width * scale, ground.height * scale, pixels, folder / "surface_material.png");
  add_picture(result, "surface_material.png",
              "surface material after the run, ref<double> (a cell a square of pixels): the top non-empty layer's mixture (organic "
                              "dark brown, sand pale yellow, gravel light grey, stones grey, boulders slate; bedrock: "
                              "soft rock red, hard rock dark grey), greened by 35 % of the vegetation density",
              std::nullopt, map_width_m(ground.width, ground.cell_size_x));
  write_material_masks(ground, params, options, result);
  double depth_shown = 0.0;
  write_cross_section(ground, folder / "cross_section.png", depth_shown);
  add_picture(result, "cross_section.png",
              fmt::format("cross-section along row {} after the run: above, the surface (elevation stretched to the panel); "
                   "below, the layers from the surface down to {:.3g} m, true to scale in depth (topsoil, the subsoil "
                   "darker, soft rock red, hard rock grey; colours as the surface material); the same row with "
                   "axes in metres: cross_section_axes.png",
                   ground.height / 2, depth_shown));
  plot_cross_section(ground, options, result);
}

}  // namespace gt
