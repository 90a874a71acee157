// check-mesh: read the file, check it, print, and map the verdict to the exit status.
#include "compare/cli/check_mesh.hpp"

#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/checks/mesh.hpp"
#include "core/errors.hpp"
#include "core/io/mesh_io.hpp"

namespace gt {

namespace {

constexpr int exit_watertight = 0;
constexpr int exit_not_watertight = 1;
constexpr int exit_unreadable = 2;

void print_report(const std::filesystem::path& file, const MeshFile& read, const MeshReport& report, bool as_json) {
  if (as_json) {
    const nlohmann::json out = {
        {"file", file.string()}, {"format", read.format},          {"notes", read.notes},
        {"report", to_json(report)}, {"locations", locations_json(report)}};
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("{} ({}): {}\n", file.string(), read.format, describe(report));
  for (const std::string& note : read.notes) fmt::print("  note: {}\n", note);
}

}  // namespace

int check_mesh_command(const std::filesystem::path& file, bool as_json) {
  MeshFile read;
  try {
    read = read_mesh(file);
  } catch (const InputError& error) {
    fmt::print(stderr, "groundtruth: {}\n", error.what());
    return exit_unreadable;
  }
  const MeshReport report = check_mesh(read.mesh);
  print_report(file, read, report, as_json);
  return is_watertight_and_oriented(report) ? exit_watertight : exit_not_watertight;
}

}  // namespace gt
