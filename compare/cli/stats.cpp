// stats: read the DEM, describe it, print, and optionally write stats.json and the plots.
#include "compare/cli/stats.hpp"

#include <cstdio>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/case_descriptors.hpp"
#include "compare/descriptors/terrain_descriptors.hpp"
#include "compare/output_folder.hpp"
#include "compare/report/descriptor_plots.hpp"
#include "compare/report/report_common.hpp"
#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/heightmap_io.hpp"
#include "core/memory.hpp"

namespace gt {

namespace {

constexpr int exit_measured = 0;
constexpr int exit_bad_input = 2;

nlohmann::json stats_json(const std::filesystem::path& file, const HeightmapFile& read,
                          const TerrainDescriptors& descriptors) {
  return {{"file", file.string()}, {"format", read.format}, {"notes", read.notes},
          {"descriptors", to_json(descriptors)}};
}

void print_table(const std::filesystem::path& file, const HeightmapFile& read, const TerrainDescriptors& descriptors) {
  const auto& dem = read.heights;
  fmt::print("{} ({}): {}x{} cells of {:.4g}x{:.4g} {}, {} valid\n", file.string(), read.format, dem.width,
             dem.height, dem.cell_size_x, dem.cell_size_y, dem.horizontal_unit, descriptors.valid_cells);
  for (const auto& note : read.notes) fmt::print("  note: {}\n", note);
  for (const auto& note : descriptors.notes) fmt::print("  note: {}\n", note);
  for (const auto& scalar : scalar_descriptors(descriptors)) {
    fmt::print("  {:<48} {:>12.5g} {}\n", scalar.label, scalar.value, scalar.unit);
  }
  if (descriptors.drainage) {
    fmt::print("  {:<48} {}\n", "Strahler streams per order (1, 2, ...)",
               fmt::join(descriptors.drainage->streams_per_order.begin() + 1,
                         descriptors.drainage->streams_per_order.end(), ", "));
  }
}

void write_outputs(const std::filesystem::path& out, const std::filesystem::path& file,
                   const nlohmann::json& document, const TerrainDescriptors& descriptors) {
  write_folder_atomically(out, [&](const std::filesystem::path& folder) {
    write_file_atomically(folder / "stats.json", document.dump(2) + '\n');
    std::string reason;
    const auto panels = descriptor_panels({{file.filename().string(), &descriptors}});
    // --out asks for both files: a picture that cannot be drawn (a full disk, no matplotlib) ends
    // the command with exit 2 and leaves --out as it was, not a folder without its picture.
    if (!plot_series(panels, folder, "descriptors.png", "terrain descriptors", reason)) {
      throw InputError(fmt::format("stats: descriptors.png not drawn: {}", reason));
    }
  });
}

}  // namespace

int stats_command(const std::filesystem::path& file, const StatsOptions& options) {
  try {
    if (!options.out.empty()) check_output_folder(options.out);
    HeightmapReadOptions read_options;
    read_options.cell_size = options.cell_size;
    read_options.image_vertical_scale = options.image_vertical_scale;
    const HeightmapFile read = read_heightmap(file, read_options);
    check_cell_size(read.heights, file.string());
    check_finite(read.heights, file.string());
    // The reader weighed the grid alone; the descriptors need several times more (an 8000² .npy
    // admitted at 488 MiB reached 3.8 GB): weighed before they start.
    require_memory(memory_for(double(read.heights.width) * double(read.heights.height), "cells",
                              descriptor_bytes_per_cell),
                   fmt::format("stats: the descriptors of {}x{} cells", read.heights.width, read.heights.height));
    DescriptorOptions descriptor_options;
    descriptor_options.stream_threshold_cells = options.stream_threshold_cells;
    const TerrainDescriptors descriptors = describe_terrain(read.heights, descriptor_options);
    const auto document = stats_json(file, read, descriptors);
    if (options.as_json) {
      fmt::print("{}\n", document.dump(2));
    } else {
      print_table(file, read, descriptors);
    }
    if (!options.out.empty()) write_outputs(options.out, file, document, descriptors);
    return exit_measured;
  } catch (const InputError& error) {
    fmt::print(stderr, "groundtruth: {}: {}\n", file.string(), error.what());
    return exit_bad_input;
  }
}

}  // namespace gt
