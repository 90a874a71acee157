// Mesh files through CGAL's polygon-soup readers and writers (see mesh_io.hpp for the formats and
// the refusals). The soup is read into CGAL points and index lists, checked (corners, index range,
// finite coordinates), fan-triangulated where a polygon has more than three corners, and copied
// into a Mesh with its indices in file order.
#include "core/io/mesh_io.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <new>
#include <stdexcept>
#include <string_view>

#include <unistd.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {

namespace {

using std::filesystem::path;
using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Polygon = std::vector<std::size_t>;

struct Soup {
  std::vector<Point> points;
  std::vector<Polygon> polygons;
};

using SoupReader = bool (*)(const std::string& file, Soup& soup);

struct ReadableFormat {
  std::string_view extension;  // lower case, with the dot
  SoupReader read;
  std::string_view refusals;   // what CGAL's reader refuses without saying which, for the message
};

const ReadableFormat readable_formats[] = {
    {".off",
     [](const std::string& file, Soup& soup) {
       return CGAL::IO::read_OFF(file, soup.points, soup.polygons, CGAL::parameters::verbose(false));
     },
     "fewer vertices or faces than the header declares, a vertex line with fewer than three numbers, a "
     "face line with fewer indices than its corner count, or a vertex index out of range"},
    {".obj",
     [](const std::string& file, Soup& soup) {
       return CGAL::IO::read_OBJ(file, soup.points, soup.polygons, CGAL::parameters::verbose(false));
     },
     "a line that is not OBJ, a vertex with fewer than three coordinates, or no vertices or no faces"},
    {".ply",
     [](const std::string& file, Soup& soup) {
       return CGAL::IO::read_PLY(file, soup.points, soup.polygons, CGAL::parameters::verbose(false));
     },
     "no valid PLY header, faces without a vertex_indices or vertex_index list, or fewer data than the "
     "header declares"},
    {".stl",
     [](const std::string& file, Soup& soup) {
       return CGAL::IO::read_STL(file, soup.points, soup.polygons, CGAL::parameters::verbose(false));
     },
     "neither ASCII STL (solid ... endsolid) nor binary STL (80-byte header, triangle count, 50 bytes "
     "per triangle)"},
};

std::string lower_extension(const path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

const ReadableFormat& readable_format_of(const path& file) {
  const std::string extension = lower_extension(file);
  for (const ReadableFormat& format : readable_formats) {
    if (format.extension == extension) return format;
  }
  throw InputError(fmt::format("cannot read {}: unknown mesh extension '{}' (use .off, .obj, .ply or .stl)",
                               file.string(), extension));
}

// CGAL's OFF reader sizes its arrays from the header before reading the data; a header claiming
// more vertices or faces than the file can hold is refused first. Each vertex needs at least three
// numbers and each face four (a count and three indices), each of at least one character and a
// separator (binary OFF needs more: 4 bytes a number).
void check_off_counts(const path& file) {
  std::ifstream in(file, std::ios::binary);
  CGAL::File_header_OFF header(false);
  if (!(in >> header)) {
    throw InputError(fmt::format("cannot read {}: no valid OFF header (OFF keyword, then vertex, face and edge "
                                 "counts)",
                                 file.string()));
  }
  const std::uintmax_t size = std::filesystem::file_size(file);
  const std::uintmax_t vertices = header.size_of_vertices();
  const std::uintmax_t faces = header.size_of_facets();
  if (vertices > size || faces > size || 6 * vertices + 8 * faces > size + 1) {
    throw InputError(fmt::format("cannot read {}: the OFF header declares {} vertices and {} faces, more than "
                                 "its {} bytes can hold",
                                 file.string(), header.size_of_vertices(), header.size_of_facets(), size));
  }
}

[[noreturn]] void refuse_oversized(const path& file) {
  throw InputError(fmt::format("cannot read {}: it declares more data than fits in memory", file.string()));
}

Soup read_soup(const path& file, const ReadableFormat& format) {
  if (format.extension == ".off") check_off_counts(file);
  Soup soup;
  bool read = false;
  try {
    read = format.read(file.string(), soup);
  } catch (const std::bad_alloc&) {
    refuse_oversized(file);
  } catch (const std::length_error&) {
    refuse_oversized(file);
  }
  if (!read) {
    throw InputError(fmt::format("cannot read {}: CGAL's {} reader refused it ({})", file.string(),
                                 format.extension.substr(1), format.refusals));
  }
  return soup;
}

std::vector<std::array<double, 3>> positions_of(const std::vector<Point>& points, const path& file) {
  if (points.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(fmt::format("cannot read {}: {} vertices, more than 32-bit indices address", file.string(),
                                 points.size()));
  }
  std::vector<std::array<double, 3>> positions;
  positions.reserve(points.size());
  for (const Point& point : points) {
    const std::array<double, 3> position{point.x(), point.y(), point.z()};
    if (!std::all_of(position.begin(), position.end(), [](double c) { return std::isfinite(c); })) {
      throw InputError(fmt::format("cannot read {}: vertex {} has a non-finite coordinate ({}, {}, {})",
                                   file.string(), positions.size(), position[0], position[1], position[2]));
    }
    positions.push_back(position);
  }
  return positions;
}

void check_polygon(const Polygon& polygon, std::size_t face, std::size_t vertices, const path& file) {
  if (polygon.size() < 3) {
    throw InputError(fmt::format("cannot read {}: face {} has {} corners, a face needs at least 3", file.string(),
                                 face, polygon.size()));
  }
  for (const std::size_t index : polygon) {
    if (index >= vertices) {
      throw InputError(fmt::format("cannot read {}: face {} names vertex {}, out of range (the file has {} vertices)",
                                   file.string(), face, index, vertices));
    }
  }
}

// Triangles in file order; a polygon of n > 3 corners becomes the fan (v0 v_i v_i+1), i = 1..n-2.
std::vector<std::array<std::uint32_t, 3>> triangles_of(const Soup& soup, const path& file,
                                                       std::vector<std::string>& notes) {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(soup.polygons.size());
  std::size_t fanned = 0;
  for (std::size_t face = 0; face < soup.polygons.size(); ++face) {
    const Polygon& polygon = soup.polygons[face];
    check_polygon(polygon, face, soup.points.size(), file);
    if (polygon.size() > 3) ++fanned;
    for (std::size_t corner = 1; corner + 1 < polygon.size(); ++corner) {
      triangles.push_back({static_cast<std::uint32_t>(polygon[0]), static_cast<std::uint32_t>(polygon[corner]),
                           static_cast<std::uint32_t>(polygon[corner + 1])});
    }
  }
  if (fanned > 0) {
    notes.push_back(fmt::format("{} of {} faces had more than 3 corners: triangulated as fans around their first "
                                "corner ({} triangles in all)",
                                fanned, soup.polygons.size(), triangles.size()));
  }
  return triangles;
}

using SoupWriter = bool (*)(const std::string& file, const std::vector<Point>& points,
                            const std::vector<std::array<int, 3>>& triangles);

struct WritableFormat {
  std::string_view extension;
  SoupWriter write;
};

const WritableFormat writable_formats[] = {
    {".ply",
     [](const std::string& file, const std::vector<Point>& points, const std::vector<std::array<int, 3>>& triangles) {
       return CGAL::IO::write_PLY(file, points, triangles, CGAL::parameters::use_binary_mode(true));
     }},
    {".obj",
     [](const std::string& file, const std::vector<Point>& points, const std::vector<std::array<int, 3>>& triangles) {
       return CGAL::IO::write_OBJ(file, points, triangles, CGAL::parameters::stream_precision(17));
     }},
    {".off",
     [](const std::string& file, const std::vector<Point>& points, const std::vector<std::array<int, 3>>& triangles) {
       return CGAL::IO::write_OFF(file, points, triangles, CGAL::parameters::stream_precision(17));
     }},
};

const WritableFormat& writable_format_of(const path& file) {
  const std::string extension = lower_extension(file);
  for (const WritableFormat& format : writable_formats) {
    if (format.extension == extension) return format;
  }
  throw InputError(fmt::format("cannot write {}: unknown mesh extension '{}' (use .ply, .obj or .off)",
                               file.string(), extension));
}

// The writers store int32 indices.
std::vector<std::array<int, 3>> writable_triangles(const Mesh& mesh, const path& file) {
  if (mesh.positions.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw InputError(fmt::format("cannot write {}: {} vertices, more than the int32 indices of the file address",
                                 file.string(), mesh.positions.size()));
  }
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& triangle : mesh.triangles) {
    triangles.push_back({static_cast<int>(triangle[0]), static_cast<int>(triangle[1]), static_cast<int>(triangle[2])});
  }
  return triangles;
}

std::vector<Point> points_of(const Mesh& mesh) {
  std::vector<Point> points;
  points.reserve(mesh.positions.size());
  for (const auto& position : mesh.positions) points.emplace_back(position[0], position[1], position[2]);
  return points;
}

}  // namespace

MeshFile read_mesh(const path& file) {
  const ReadableFormat& format = readable_format_of(file);
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    throw InputError(fmt::format("cannot open {}: no such file", file.string()));
  }
  const Soup soup = read_soup(file, format);
  if (soup.polygons.empty()) {
    throw InputError(fmt::format("cannot read {}: no faces (an empty file, or points only)", file.string()));
  }
  MeshFile result;
  result.format = format.extension.substr(1);
  result.mesh.positions = positions_of(soup.points, file);
  result.mesh.triangles = triangles_of(soup, file, result.notes);
  if (format.extension == ".stl") {
    result.notes.push_back(fmt::format("STL: corners at identical coordinates merged into {} vertices",
                                       result.mesh.positions.size()));
  }
  return result;
}

void write_mesh(const Mesh& mesh, const path& file) {
  const WritableFormat& format = writable_format_of(file);
  const std::vector<std::array<int, 3>> triangles = writable_triangles(mesh, file);
  const path temporary = file.parent_path() / fmt::format(".{}.{}.partial", file.filename().string(), getpid());
  const bool written = format.write(temporary.string(), points_of(mesh), triangles);
  std::error_code error;
  if (written) std::filesystem::rename(temporary, file, error);
  if (!written || error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw InputError(fmt::format("cannot write {}: {}", file.string(),
                                 written ? error.message() : "the folder is missing or not writable"));
  }
}

}  // namespace gt
