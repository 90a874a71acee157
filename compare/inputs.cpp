// Case inputs: files through core/io, generated fields here; see compare/inputs.hpp.
#include "compare/inputs.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>
#include <variant>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "core/errors.hpp"
#include "core/io/heightmap_io.hpp"
#include "core/json_keys.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/volume_io.hpp"
#include "core/rng.hpp"

namespace gt {
namespace {

// Sides beyond 2^20 cells are refused here already; check_grid_fits then weighs the memory.
constexpr long long largest_generated_side = 1 << 20;

int grid_side(const nlohmann::json& input, const char* key) {
  return static_cast<int>(json_integer(input, key, 128, 1, largest_generated_side, "input generator"));
}

// "cell_size" (the columns' spacing, x) and "cell_size_y" (the rows', when it differs) in metres;
// `unset` when "cell_size" is absent, and "cell_size_y" alone is refused.
std::pair<double, double> json_cell_sizes(const nlohmann::json& input, double unset, const char* what) {
  if (input.contains("cell_size_y") && !input.contains("cell_size")) {
    throw InputError(fmt::format("{}: cell_size_y (the rows' spacing) needs cell_size (the columns') too", what));
  }
  const double minimum = unset > 0.0 ? 1e-9 : 0.0;
  const double x = json_number(input, "cell_size", unset, minimum, 1e9, what);
  return {x, json_number(input, "cell_size_y", x, 1e-9, 1e9, what)};
}

Heightmap blank_field(const nlohmann::json& input) {
  const int width = grid_side(input, "width");
  const int height = grid_side(input, "height");
  check_grid_fits(width, height, 64, "generated input");
  Heightmap field(width, height, 0.0);
  std::tie(field.cell_size_x, field.cell_size_y) = json_cell_sizes(input, 1.0, "input generator");
  return field;
}

void add_noise(Heightmap& field, const nlohmann::json& input) {
  const double amplitude = json_number(input, "noise", 0.0, 0.0, 1e6, "input generator");
  const auto seed = static_cast<std::uint32_t>(json_integer(input, "seed", 1, 0, 0xffffffffLL, "input generator"));
  if (amplitude == 0.0) return;
  for (std::size_t i = 0; i < field.size(); ++i) {
    field.values[i] += amplitude * uniform01(random_u32(seed, static_cast<std::uint32_t>(i), 0, 0));
  }
}

Heightmap cone(const nlohmann::json& input) {
  Heightmap field = blank_field(input);
  const double peak = json_number(input, "peak", 100.0, -1e6, 1e6, "input generator cone");
  const double radius = json_number(input, "radius", 0.4, 1e-6, 1e3, "input generator cone") * std::min(field.width * field.cell_size_x,
                                                               field.height * field.cell_size_y);
  const double centre_x = 0.5 * field.width * field.cell_size_x;
  const double centre_y = 0.5 * field.height * field.cell_size_y;
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) {
      const double distance = std::hypot((x + 0.5) * field.cell_size_x - centre_x, (y + 0.5) * field.cell_size_y - centre_y);
      field.at(x, y) = peak * std::max(0.0, 1.0 - distance / radius);
    }
  }
  return field;
}

Heightmap step(const nlohmann::json& input) {
  Heightmap field = blank_field(input);
  const double peak = json_number(input, "peak", 100.0, -1e6, 1e6, "input generator step");
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) field.at(x, y) = x < field.width / 2 ? 0.0 : peak;
  }
  return field;
}

// `count` strips across the axis, strip i holding peak·i: a category map (which profile in which
// column) or stepped levels.
Heightmap strips(const nlohmann::json& input) {
  Heightmap field = blank_field(input);
  const auto count = json_integer(input, "count", 2, 1, 64, "input generator strips");
  const double peak = json_number(input, "peak", 1.0, -1e6, 1e6, "input generator strips");
  const std::string axis = input.value("axis", std::string("x"));
  if (axis != "x" && axis != "y") throw InputError(fmt::format("input generator strips: axis '{}' is neither x nor y", axis));
  const long long side = axis == "x" ? field.width : field.height;
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) field.at(x, y) = peak * double(count * (axis == "x" ? x : y) / side);
  }
  return field;
}

// `count` cones in a row along x, one centred in each of `count` equal strips and on the middle
// row, each `peak` high with a base radius of `radius` times the strip's width (seed 001's Fig. 5.1
// hills of four materials).
Heightmap hills(const nlohmann::json& input) {
  Heightmap field = blank_field(input);
  const auto count = json_integer(input, "count", 4, 1, 64, "input generator hills");
  const double peak = json_number(input, "peak", 10.0, -1e6, 1e6, "input generator hills");
  const double strip = field.width * field.cell_size_x / double(count);
  const double radius = json_number(input, "radius", 0.45, 1e-6, 1e3, "input generator hills") * strip;
  const double centre_y = 0.5 * field.height * field.cell_size_y;
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) {
      const double position = (x + 0.5) * field.cell_size_x;
      const double centre_x = (std::floor(position / strip) + 0.5) * strip;
      const double distance = std::hypot(position - centre_x, (y + 0.5) * field.cell_size_y - centre_y);
      field.at(x, y) = peak * std::max(0.0, 1.0 - distance / radius);
    }
  }
  return field;
}

// A block of height `peak` on the cells x .. x + box_width − 1, y .. y + box_height − 1 (an obstacle
// to raise a surface by, or a category map: 1 inside, 0 outside), 0 elsewhere.
Heightmap box(const nlohmann::json& input) {
  Heightmap field = blank_field(input);
  const char* what = "input generator box";
  const auto x0 = json_integer(input, "x", 0, 0, field.width - 1, what);
  const auto y0 = json_integer(input, "y", 0, 0, field.height - 1, what);
  const auto box_width = json_integer(input, "box_width", 1, 1, field.width - x0, what);
  const auto box_height = json_integer(input, "box_height", 1, 1, field.height - y0, what);
  const double peak = json_number(input, "peak", 1.0, -1e6, 1e6, what);
  for (long long y = y0; y < y0 + box_height; ++y) {
    for (long long x = x0; x < x0 + box_width; ++x) field.at(int(x), int(y)) = peak;
  }
  return field;
}

// A plane rising along +x: base + gradient·x (x in metres from the first column's centre).
Heightmap slope(const nlohmann::json& input) {
  Heightmap field = blank_field(input);
  const double base = json_number(input, "base", 0.0, -1e6, 1e6, "input generator slope");
  const double gradient = json_number(input, "gradient", 0.05, -1e3, 1e3, "input generator slope");
  const std::string axis = input.value("axis", std::string("x"));
  if (axis != "x" && axis != "y") throw InputError(fmt::format("input generator slope: axis '{}' is neither x nor y", axis));
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) {
      field.at(x, y) = base + gradient * (axis == "x" ? x * field.cell_size_x : y * field.cell_size_y);
    }
  }
  return field;
}

// A terrain synthesised by a noise algorithm's double reference (terrain.* cases make the same
// field and report on it): {"generator": "terrain", "algorithm": "noise.hetero_terrain",
// "params": {...}, "width", "height", "cell_size"}.
Heightmap noise_terrain(const nlohmann::json& input) {
  const Heightmap grid = blank_field(input);
  const auto& algorithm = find_algorithm(input.value("algorithm", std::string("noise.hetero_terrain")));
  if (algorithm.kind != CaseKind::generated) {
    throw InputError(fmt::format("input generator terrain: {} is not a noise algorithm (`groundtruth list` names them: "
                                 "noise.*)",
                                 algorithm.name));
  }
  const auto resolved = resolve_params(algorithm.name, *algorithm.params, input.value("params", nlohmann::json::object()));
  LoadedInput sampling_grid;
  sampling_grid.heights = grid;
  const PreparedTwin prepared = algorithm.prepare(resolved, sampling_grid);
  const auto& generated = std::get<GeneratedCase>(prepared.kind);
  return generated.twin.reference_double(generated.grid);
}

Heightmap example_3x3() {
  Heightmap field(3, 3, 0.0);
  field.at(1, 1) = 1.0;
  field.vertical_unit = "1";
  field.horizontal_unit = "cell";
  return field;
}

// The keys each generator reads (compare/inputs.hpp); any other is a typo.
const std::vector<std::string>& generator_keys(const std::string& name) {
  static const std::vector<std::string> grid = {"generator", "width", "height", "cell_size", "cell_size_y", "noise", "seed"};
  static const std::map<std::string, std::vector<std::string>> keys = [] {
    const auto with = [](std::vector<std::string> extra) {
      extra.insert(extra.begin(), grid.begin(), grid.end());
      return extra;
    };
    return std::map<std::string, std::vector<std::string>>{
        {"cone", with({"peak", "radius"})},
        {"step", with({"peak"})},
        {"slope", with({"base", "gradient", "axis"})},
        {"strips", with({"count", "peak", "axis"})},
        {"hills", with({"count", "peak", "radius"})},
        {"box", with({"x", "y", "box_width", "box_height", "peak"})},
        {"flat", grid},
        {"terrain", {"generator", "width", "height", "cell_size", "cell_size_y", "algorithm", "params"}},
        {"example_3x3", {"generator"}}};
  }();
  const auto found = keys.find(name);
  if (found == keys.end()) {
    throw InputError(fmt::format("unknown input generator '{}'; known: cone, step, slope, strips, hills, box, flat, terrain, example_3x3", name));
  }
  return found->second;
}

LoadedInput generated_input(const nlohmann::json& input) {
  const auto name = input["generator"].get<std::string>();
  require_known_keys(input, generator_keys(name), fmt::format("input generator {}", name));
  LoadedInput loaded;
  if (name == "cone") {
    loaded.heights = cone(input);
  } else if (name == "step") {
    loaded.heights = step(input);
  } else if (name == "slope") {
    loaded.heights = slope(input);
  } else if (name == "strips") {
    loaded.heights = strips(input);
  } else if (name == "hills") {
    loaded.heights = hills(input);
  } else if (name == "box") {
    loaded.heights = box(input);
  } else if (name == "terrain") {
    loaded.heights = noise_terrain(input);
  } else if (name == "flat") {
    loaded.heights = blank_field(input);
  } else {  // example_3x3: generator_keys refused every other name
    loaded.heights = example_3x3();
  }
  if (name != "example_3x3" && name != "terrain") add_noise(loaded.heights, input);
  const auto& grid = loaded.heights;
  const std::string cell = grid.cell_size_y == grid.cell_size_x ? fmt::format("{}", grid.cell_size_x)
                                                                : fmt::format("{}x{}", grid.cell_size_x, grid.cell_size_y);
  loaded.description =
      fmt::format("generated {} {}x{}, cell {} {}", name, grid.width, grid.height, cell, grid.horizontal_unit);
  return loaded;
}

LoadedInput file_input(const nlohmann::json& input, const std::filesystem::path& dataset_dir) {
  require_known_keys(input, {"file", "cell_size", "cell_size_y", "vertical_scale", "srgb", "red_channel"}, "input file");
  std::filesystem::path path = input["file"].get<std::string>();
  if (path.is_relative()) path = dataset_dir / path;
  HeightmapReadOptions options;
  std::tie(options.cell_size, options.cell_size_y) = json_cell_sizes(input, 0.0, "input file");
  options.image_vertical_scale = json_number(input, "vertical_scale", 1.0, 1e-9, 1e9, "input file");
  options.srgb = json_bool(input, "srgb", false, "input file");
  options.red_channel = json_bool(input, "red_channel", false, "input file");
  auto file = read_heightmap(path, options);
  LoadedInput loaded;
  loaded.heights = std::move(file.heights);
  loaded.notes = std::move(file.notes);
  const auto& heights = loaded.heights;
  loaded.description = fmt::format("{} ({}), {}x{}, cell {:.4g}x{:.4g} {}", path.filename().string(), file.format,
                                   heights.width, heights.height, heights.cell_size_x, heights.cell_size_y,
                                   heights.horizontal_unit);
  loaded.source = path;
  return loaded;
}

// The window [x, y, width, height] read as whole numbers in 64 bits, so that no sum overflows.
Heightmap cropped(const Heightmap& heights, const nlohmann::json& crop) {
  if (!crop.is_array() || crop.size() != 4) throw InputError("crop must be [x, y, width, height]");
  const nlohmann::json window = {{"x", crop[0]}, {"y", crop[1]}, {"width", crop[2]}, {"height", crop[3]}};
  const long long x0 = json_integer(window, "x", 0, 0, heights.width - 1, "crop");
  const long long y0 = json_integer(window, "y", 0, 0, heights.height - 1, "crop");
  const long long width = json_integer(window, "width", 1, 1, heights.width, "crop");
  const long long height = json_integer(window, "height", 1, 1, heights.height, "crop");
  if (x0 + width > heights.width || y0 + height > heights.height) {
    throw InputError(fmt::format("crop [{}, {}, {}, {}] does not fit the {}x{} input", x0, y0, width, height,
                                 heights.width, heights.height));
  }
  Heightmap out = heights;
  out.width = static_cast<int>(width);
  out.height = static_cast<int>(height);
  out.values.assign(static_cast<std::size_t>(width * height), 0.0);
  out.valid.clear();
  if (heights.has_mask()) out.valid.assign(out.values.size(), 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int source_x = static_cast<int>(x0) + x, source_y = static_cast<int>(y0) + y;
      out.at(x, y) = heights.at(source_x, source_y);
      if (heights.has_mask()) out.valid[out.index(x, y)] = heights.valid[heights.index(source_x, source_y)];
    }
  }
  return out;
}

// Input fields beside a heightmap: at most this many, names this long.
constexpr std::size_t most_fields = 8;
constexpr std::size_t longest_field_name = 64;

// The grid a field must match before the crop: its generators default to it.
struct GridShape {
  int width = 0, height = 0;
  double cell_size_x = 1.0, cell_size_y = 1.0;
};

// Each of input["fields"] (a file or a generator, as the heightmap; a generator without a grid gets
// the heightmap's) loaded, cropped as the heightmap, and refused unless it has the heightmap's size,
// finite values and no no-data cells.
void load_fields(const nlohmann::json& fields, const GridShape& shape, const nlohmann::json& crop,
                 const std::filesystem::path& dataset_dir, LoadedInput& loaded) {
  if (!fields.is_object()) throw InputError(fmt::format("input fields must be an object of named fields, not {}", fields.dump()));
  if (fields.size() > most_fields) {
    throw InputError(fmt::format("input fields: {} fields given, at most {} are read", fields.size(), most_fields));
  }
  for (const auto& [name, given] : fields.items()) {
    const std::string what = fmt::format("input field '{}'", name.substr(0, longest_field_name));
    if (name.empty() || name.size() > longest_field_name) throw InputError(what + ": a name of 1 to 64 characters");
    nlohmann::json spec = given;
    if (spec.is_object() && spec.contains("generator") && spec["generator"].is_string() && !spec.contains("width")) {
      spec["width"] = shape.width;
      spec["height"] = shape.height;
      spec["cell_size"] = shape.cell_size_x;
      spec["cell_size_y"] = shape.cell_size_y;
    }
    LoadedInput field;
    if (spec.is_object() && spec.contains("file") && spec["file"].is_string()) {
      field = file_input(spec, dataset_dir);
    } else if (spec.is_object() && spec.contains("generator") && spec["generator"].is_string()) {
      field = generated_input(spec);
    } else {
      throw InputError(fmt::format("{} needs a string 'file' or 'generator': {}", what, given.dump()));
    }
    if (field.heights.width != shape.width || field.heights.height != shape.height) {
      throw InputError(fmt::format("{} is {}x{} cells, the heightmap {}x{}: a field covers the heightmap cell for cell",
                                   what, field.heights.width, field.heights.height, shape.width, shape.height));
    }
    if (!crop.is_null()) field.heights = cropped(field.heights, crop);
    if (field.heights.has_mask()) throw InputError(what + " has no-data cells: every cell needs a value");
    check_finite(field.heights, what);
    loaded.description += fmt::format("; field {}: {}", name, field.description);
    loaded.notes.insert(loaded.notes.end(), field.notes.begin(), field.notes.end());
    loaded.fields.emplace(name, std::move(field.heights));
  }
}

}  // namespace

LoadedInput load_input(const nlohmann::json& input, const nlohmann::json& crop, const std::filesystem::path& dataset_dir) {
  LoadedInput loaded;
  const bool heightmap = input.is_object() && (input.contains("file") || input.contains("generator"));
  if (!crop.is_null() && !heightmap) {
    throw InputError(fmt::format("crop {} cuts a heightmap ('file' or 'generator'); input {} is none", crop.dump(),
                                 input.dump()));
  }
  if (input.is_null() || input.empty()) {
    loaded.description = "none: the algorithm makes its own field";
    return loaded;
  }
  if (input.contains("mesh") && input["mesh"].is_string()) {
    require_known_keys(input, {"mesh"}, "input mesh");
    std::filesystem::path path = input["mesh"].get<std::string>();
    if (path.is_relative()) path = dataset_dir / path;
    auto file = read_mesh(path);
    loaded.description = fmt::format("{} ({} vertices, {} triangles)", path.filename().string(),
                                     file.mesh.positions.size(), file.mesh.triangles.size());
    loaded.notes = std::move(file.notes);
    loaded.mesh = std::move(file.mesh);
    loaded.source = path;
    return loaded;
  }
  if (input.contains("global_grid") && input["global_grid"].is_string()) {
    require_known_keys(input, {"global_grid", "variable"}, "input global grid");
    std::filesystem::path path = input["global_grid"].get<std::string>();
    if (path.is_relative()) path = dataset_dir / path;
    loaded.global_grid = read_global_grid(path.string(), input.value("variable", std::string()));
    loaded.description = fmt::format("{} ({}, {}x{} cells)", path.filename().string(), loaded.global_grid->variable,
                                     loaded.global_grid->elevation.width, loaded.global_grid->elevation.height);
    loaded.source = path;
    return loaded;
  }
  if (input.contains("volume") && input["volume"].is_string()) {
    require_known_keys(input, {"volume"}, "input volume");
    std::filesystem::path path = input["volume"].get<std::string>();
    if (path.is_relative()) path = dataset_dir / path;
    loaded.volume = read_volume(path);
    loaded.description = fmt::format("{} ({}x{}x{} samples)", path.filename().string(), loaded.volume->nx,
                                     loaded.volume->ny, loaded.volume->nz);
    loaded.source = path;
    return loaded;
  }
  nlohmann::json surface = input;
  if (surface.is_object()) surface.erase("fields");
  if (input.contains("file") && input["file"].is_string()) {
    loaded = file_input(surface, dataset_dir);
  } else if (input.contains("generator") && input["generator"].is_string()) {
    loaded = generated_input(surface);
  } else {
    throw InputError(fmt::format("input {} needs a string 'file', 'mesh', 'volume' or 'generator'", input.dump()));
  }
  const GridShape shape{loaded.heights.width, loaded.heights.height, loaded.heights.cell_size_x,
                        loaded.heights.cell_size_y};
  if (!crop.is_null()) {
    loaded.heights = cropped(loaded.heights, crop);
    loaded.description += fmt::format(", crop {}", crop.dump());
  }
  check_finite(loaded.heights, loaded.description);
  check_fits_float(loaded.heights, loaded.description);
  check_cell_size(loaded.heights, loaded.description);
  if (count_valid(loaded.heights) == 0) throw InputError(loaded.description + ": every cell is no-data");
  if (input.contains("fields")) load_fields(input["fields"], shape, crop, dataset_dir, loaded);
  return loaded;
}

}  // namespace gt
