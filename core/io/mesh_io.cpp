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
#include <cstring>
#include <fstream>
#include <limits>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/exceptions.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/OFF/File_scanner_OFF.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/IO/STL/STL_reader.h>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/text_file.hpp"

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

[[noreturn]] void refuse(const std::string& file, const std::string& reason) {
  throw InputError(fmt::format("cannot read {}: {}", file, reason));
}

// ---- OFF ---------------------------------------------------------------------------------------
// CGAL's read_OFF sizes a face from its first number before reading the rest, so a line "1000000000"
// allocates 8 GB, and it reads indices as doubles cast to size_t ("2.7" is 2, 2^64-1 wraps to 0).
// Here CGAL's File_scanner_OFF still reads the header (OFF, COFF, NOFF, 4OFF, nOFF, binary) and
// the vertices; the faces are read here: an ASCII face line is a corner count, that many
// indices, then an optional colour; counts and indices must be plain decimal integers, the
// indices below the vertex count, and no face may claim more corners than the bytes left hold.

std::uintmax_t bytes_left(std::istream& in, std::uintmax_t file_size) {
  const std::streamoff position = in.tellg();
  return position < 0 || static_cast<std::uintmax_t>(position) > file_size ? 0 : file_size - position;
}

// A token of only decimal digits (at most 19, so it fits in 64 bits) as a number; nullopt otherwise.
std::optional<std::uint64_t> plain_unsigned(const std::string& token) {
  if (token.empty() || token.size() > 19 || !std::all_of(token.begin(), token.end(), [](unsigned char c) {
        return std::isdigit(c) != 0;
      })) {
    return std::nullopt;
  }
  return std::stoull(token);
}

// The next face line of an ASCII OFF (comments and blank lines skipped), split into tokens.
std::vector<std::string> next_face_tokens(std::istream& in) {
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream fields(line);
    std::vector<std::string> tokens;
    for (std::string token; fields >> token;) tokens.push_back(token);
    if (!tokens.empty()) return tokens;
  }
  return {};
}

void read_ascii_off_face(std::istream& in, std::size_t face, std::size_t vertices, const std::string& file,
                         Polygon& polygon) {
  const std::vector<std::string> tokens = next_face_tokens(in);
  if (tokens.empty()) refuse(file, fmt::format("the file ends before face {} (the header declares more)", face));
  const std::optional<std::uint64_t> corners = plain_unsigned(tokens[0]);
  if (!corners) refuse(file, fmt::format("face {}: corner count '{}' is not a whole number", face, tokens[0]));
  if (*corners > tokens.size() - 1) {
    refuse(file, fmt::format("face {} declares {} corners but its line holds {} indices", face, *corners,
                             tokens.size() - 1));
  }
  polygon.resize(*corners);
  for (std::size_t corner = 0; corner < *corners; ++corner) {
    const std::string& token = tokens[corner + 1];
    const std::optional<std::uint64_t> index = plain_unsigned(token);
    if (!index || *index >= vertices) {
      refuse(file, fmt::format("face {}: corner {} is '{}', not a vertex index (0 to {})", face, corner, token,
                               vertices - 1));
    }
    polygon[corner] = *index;
  }
}

void read_binary_off_face(CGAL::File_scanner_OFF& scanner, std::size_t face, std::uintmax_t file_size,
                          const std::string& file, Polygon& polygon) {
  std::size_t corners = 0;
  scanner.scan_facet(corners, face);
  // scan_facet stores the int32 count in a size_t: a negative count arrives huge.
  if (!scanner.in() || corners > bytes_left(scanner.in(), file_size) / 4) {
    refuse(file, fmt::format("binary face {} declares {} corners, more than the bytes left hold", face,
                             static_cast<std::int64_t>(static_cast<std::int32_t>(corners))));
  }
  polygon.resize(corners);
  for (std::size_t corner = 0; corner < corners; ++corner) {
    scanner.scan_facet_vertex_index(polygon[corner], corner + 1, face);
    if (!scanner.in()) refuse(file, fmt::format("binary face {}: corner {} is not a vertex index", face, corner));
  }
  scanner.skip_to_next_facet(face);
}

// The next token of an OFF header, '#' comments skipped; empty at the end.
std::string next_header_token(std::istream& in) {
  std::string token;
  while (in >> token) {
    if (token[0] != '#') return token;
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return {};
}

std::int64_t big_endian_int32(std::istream& in) {
  unsigned char bytes[4] = {};
  in.read(reinterpret_cast<char*>(bytes), 4);
  return static_cast<std::int32_t>((std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
                                   (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]});
}

// The header is read here and handed to CGAL's File_scanner_OFF: CGAL's own header reader estimates
// the halfedges as int((V + F + 10)·2.1), undefined behaviour beyond INT_MAX (found by fuzzing,
// also with keywords it scans differently from any word split). Grammar: one word
// [ST][C][N][4][n]OFF, optionally the word BINARY, then [dimension] V F E as decimal words or as
// big-endian int32. Each vertex needs three numbers and each face four, each a character and a
// separator (binary: 4 bytes a number): V ≤ size/6 and F ≤ size/8, and the counts stay below
// 400 MB's worth so that CGAL's arithmetic on them fits an int.
CGAL::File_header_OFF read_off_header(std::istream& in, std::uintmax_t file_size, const std::string& file) {
  const auto bad_header = [&file] {
    refuse(file, "no valid OFF header (OFF keyword, then vertex, face and edge counts)");
  };
  std::string keyword = next_header_token(in);
  CGAL::File_header_OFF header(false);
  const auto take_prefix = [&keyword](const char* prefix) {
    const bool present = keyword.rfind(prefix, 0) == 0;
    if (present) keyword.erase(0, std::strlen(prefix));
    return present;
  };
  header.set_textures(take_prefix("ST"));
  header.set_colors(take_prefix("C"));
  header.set_normals(take_prefix("N"));
  header.set_homogeneous(take_prefix("4"));
  header.set_dimensional(take_prefix("n"));
  if (keyword != "OFF") bad_header();
  const std::streampos after_keyword = in.tellg();
  header.set_binary(next_header_token(in) == "BINARY");
  std::vector<std::int64_t> counts;
  const std::size_t wanted = header.n_dimensional() ? 4 : 3;
  if (header.binary()) {
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    while (in && counts.size() < wanted) counts.push_back(big_endian_int32(in));
  } else {
    in.clear();
    in.seekg(after_keyword);
    while (counts.size() < wanted) {
      const std::optional<std::uint64_t> count = plain_unsigned(next_header_token(in));
      if (!count) bad_header();
      counts.push_back(static_cast<std::int64_t>(std::min<std::uint64_t>(*count, INT32_MAX)));
    }
  }
  if (!in || std::any_of(counts.begin(), counts.end(), [](std::int64_t count) { return count < 0; })) bad_header();
  if (header.n_dimensional() && counts[0] != 3) refuse(file, fmt::format("an nOFF of dimension {}: only 3-D meshes", counts[0]));
  const std::int64_t vertices = counts[wanted - 3];
  const std::int64_t faces = counts[wanted - 2];
  const std::uintmax_t largest = std::min<std::uintmax_t>(file_size, 400'000'000);
  if (static_cast<std::uintmax_t>(vertices) > largest / 6 || static_cast<std::uintmax_t>(faces) > largest / 8) {
    refuse(file, fmt::format("the OFF header declares {} vertices and {} faces, more than its {} bytes can hold "
                             "(or than CGAL's OFF reader can count)",
                             vertices, faces, file_size));
  }
  header.set_vertices(static_cast<std::size_t>(vertices));
  header.set_facets(static_cast<std::size_t>(faces));
  header.set_index_offset(0);
  return header;
}

bool read_off_soup(const std::string& file, Soup& soup) {
  const std::uintmax_t file_size = std::filesystem::file_size(file);
  std::ifstream in(file, std::ios::binary);
  CGAL::File_scanner_OFF scanner(in, read_off_header(in, file_size, file));
  const std::size_t vertices = scanner.size_of_vertices();
  const std::size_t faces = scanner.size_of_facets();
  soup.points.reserve(vertices);
  for (std::size_t vertex = 0; vertex < vertices; ++vertex) {
    double x = 0.0, y = 0.0, z = 0.0, w = 1.0;
    scanner.scan_vertex(x, y, z, w);
    scanner.skip_to_next_vertex(vertex);
    if (!in) return false;
    soup.points.emplace_back(x / w, y / w, z / w);
  }
  soup.polygons.resize(faces);
  for (std::size_t face = 0; face < faces; ++face) {
    if (scanner.binary()) {
      read_binary_off_face(scanner, face, file_size, file, soup.polygons[face]);
    } else {
      read_ascii_off_face(in, face, vertices, file, soup.polygons[face]);
    }
  }
  return true;
}

// ---- PLY ---------------------------------------------------------------------------------------
// CGAL's PLY reader sizes a list from its count before reading it (a binary face claiming 4·10⁹
// indices allocates 16 GB) and reserves elements from the header's counts. check_ply_sizes walks
// the header and the data first and refuses counts the file's bytes cannot hold, and a property
// before any element (CGAL would add it to an element that does not exist); what it does not judge
// (malformed values, missing properties) is left to CGAL.

struct PlyProperty {
  std::string name;
  std::string type;    // a scalar's type, or a list's item type
  int size = 0;        // bytes of a scalar, or of a list's items
  int count_size = 0;  // bytes of a list's count; 0 for a scalar
  bool count_signed = false;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  std::string format;  // ascii, binary_little_endian, binary_big_endian
  std::vector<PlyElement> elements;
  std::uintmax_t data_offset = 0;
};

int ply_type_size(const std::string& type, const std::string& file) {
  static const std::pair<const char*, int> sizes[] = {
      {"char", 1},  {"uchar", 1},  {"int8", 1},  {"uint8", 1},  {"short", 2},   {"ushort", 2},   {"int16", 2},
      {"uint16", 2}, {"int", 4},   {"uint", 4},  {"int32", 4},  {"uint32", 4},  {"float", 4},    {"float32", 4},
      {"double", 8}, {"float64", 8}};
  for (const auto& [name, size] : sizes) {
    if (type == name) return size;
  }
  refuse(file, fmt::format("PLY property type '{}' is not a PLY type", type));
}

// CGAL reads a vertex's x, y and z only as float or double: other types make release builds read
// through a null pointer (found by fuzzing; CGAL asserts it in debug builds only).
void check_ply_coordinate_type(const PlyElement& element, const PlyProperty& property, const std::string& file) {
  const bool coordinate = element.name == "vertex" && (property.name == "x" || property.name == "y" || property.name == "z");
  const bool floating = property.count_size == 0 && (property.type == "float" || property.type == "float32" ||
                                                     property.type == "double" || property.type == "float64");
  if (coordinate && !floating) {
    refuse(file, fmt::format("PLY vertex coordinate '{}' is stored as {}{}: CGAL's reader takes float or double only",
                             property.name, property.count_size ? "a list of " : "", property.type));
  }
}

PlyHeader read_ply_header(std::istream& in, std::uintmax_t file_size, const std::string& file) {
  PlyHeader header;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string keyword;
    fields >> keyword;
    if (keyword == "end_header") {
      header.data_offset = static_cast<std::uintmax_t>(in.tellg());
      return header;
    }
    if (keyword == "format") fields >> header.format;
    if (keyword == "element") {
      PlyElement element;
      std::string count;
      fields >> element.name >> count;
      const std::optional<std::uint64_t> parsed = plain_unsigned(count);
      // Every instance takes at least one byte.
      if (!parsed || *parsed > file_size) {
        refuse(file, fmt::format("PLY element '{}' declares {} instances, more than its {} bytes can hold",
                                 element.name, count, file_size));
      }
      element.count = *parsed;
      header.elements.push_back(element);
    }
    // CGAL's reader adds a property to its last element without asking whether there is one.
    if (keyword == "property" && header.elements.empty()) {
      refuse(file, "a PLY property comes before any element (found by fuzzing: CGAL reads past its element list)");
    }
    if (keyword == "property") {
      std::string type, count_type, item_type;
      fields >> type;
      PlyProperty property;
      if (type == "list") {
        fields >> count_type >> item_type >> property.name;
        property.count_size = ply_type_size(count_type, file);
        property.count_signed = count_type[0] != 'u';
        property.size = ply_type_size(item_type, file);
        property.type = item_type;
      } else {
        fields >> property.name;
        property.size = ply_type_size(type, file);
        property.type = type;
      }
      check_ply_coordinate_type(header.elements.back(), property, file);
      header.elements.back().properties.push_back(property);
    }
  }
  return header;  // no end_header: CGAL refuses the file
}

std::int64_t binary_ply_count(const unsigned char* bytes, const PlyProperty& property, bool big_endian) {
  std::uint64_t value = 0;
  for (int i = 0; i < property.count_size; ++i) {
    const int byte = big_endian ? i : property.count_size - 1 - i;
    value = (value << 8) | bytes[byte];
  }
  const int bits = 8 * property.count_size;
  if (property.count_signed && bits < 64 && (value >> (bits - 1)) != 0) return static_cast<std::int64_t>(value) - (std::int64_t{1} << bits);
  return static_cast<std::int64_t>(value);
}

void check_binary_ply_lists(const std::vector<unsigned char>& data, const PlyHeader& header, const std::string& file) {
  const bool big_endian = header.format == "binary_big_endian";
  std::uintmax_t at = 0;
  for (const PlyElement& element : header.elements) {
    for (std::uint64_t instance = 0; instance < element.count; ++instance) {
      for (const PlyProperty& property : element.properties) {
        if (property.count_size == 0) {
          at += property.size;
          continue;
        }
        if (at + property.count_size > data.size()) return;  // truncated: CGAL says so
        const std::int64_t count = binary_ply_count(&data[at], property, big_endian);
        at += property.count_size;
        if (count < 0 || static_cast<std::uint64_t>(count) > (data.size() - at) / property.size) {
          refuse(file, fmt::format("PLY {} {}: a list claims {} entries, more than the {} bytes left hold",
                                   element.name, instance, count, data.size() - at));
        }
        at += static_cast<std::uintmax_t>(count) * property.size;
      }
      if (at > data.size()) return;
    }
  }
}

void check_ascii_ply_lists(std::istream& in, std::uintmax_t file_size, const PlyHeader& header,
                           const std::string& file) {
  std::string token;
  for (const PlyElement& element : header.elements) {
    for (std::uint64_t instance = 0; instance < element.count; ++instance) {
      for (const PlyProperty& property : element.properties) {
        if (!(in >> token)) return;  // truncated: CGAL says so
        if (property.count_size == 0) continue;
        const std::optional<std::uint64_t> count = plain_unsigned(token);
        // Each entry takes a character and a separator.
        if (!count || *count > bytes_left(in, file_size) / 2) {
          refuse(file, fmt::format("PLY {} {}: list count '{}' is not a count the bytes left can hold",
                                   element.name, instance, token));
        }
        for (std::uint64_t item = 0; item < *count; ++item) {
          if (!(in >> token)) return;
        }
      }
    }
  }
}

void check_ply_sizes(const std::string& file) {
  const std::uintmax_t file_size = std::filesystem::file_size(file);
  std::ifstream in(file, std::ios::binary);
  const PlyHeader header = read_ply_header(in, file_size, file);
  if (header.format == "ascii") {
    check_ascii_ply_lists(in, file_size, header, file);
  } else if (header.data_offset > 0) {
    std::vector<unsigned char> data(file_size - header.data_offset);
    in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size()));
    check_binary_ply_lists(data, header, file);
  }
}

// ---- STL ---------------------------------------------------------------------------------------
// CGAL's read_STL takes a file for ASCII only when "solid" is followed by a space or a line break
// ("solid<TAB>name" is read as binary garbage) and guesses again on failure. Here the size decides:
// a binary STL is exactly 84 + 50·N bytes for the N triangles its header declares; any other file
// is ASCII and must start with "solid".

bool read_stl_soup(const std::string& file, Soup& soup) {
  const std::uintmax_t file_size = std::filesystem::file_size(file);
  std::ifstream in(file, std::ios::binary);
  unsigned char header[84] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  const std::uintmax_t declared = static_cast<std::uintmax_t>(header[80]) | (static_cast<std::uintmax_t>(header[81]) << 8) |
                                  (static_cast<std::uintmax_t>(header[82]) << 16) |
                                  (static_cast<std::uintmax_t>(header[83]) << 24);
  in.clear();
  in.seekg(0);
  std::vector<std::array<std::size_t, 3>> triangles;
  if (file_size >= 84 && file_size == 84 + 50 * declared) {
    if (!CGAL::IO::internal::parse_binary_STL(in, soup.points, triangles, false)) return false;
  } else {
    std::string first_word;
    in >> first_word;
    if (first_word != "solid") {
      refuse(file, fmt::format("neither binary STL (84 + 50·N bytes for the N = {} triangles its header declares, "
                               "but the file has {} bytes) nor ASCII STL (the first word is not 'solid')",
                               declared, file_size));
    }
    in.seekg(0);
    if (!CGAL::IO::internal::parse_ASCII_STL(in, soup.points, triangles, false)) return false;
  }
  for (const auto& triangle : triangles) soup.polygons.emplace_back(triangle.begin(), triangle.end());
  return true;
}

struct ReadableFormat {
  std::string_view extension;  // lower case, with the dot
  SoupReader read;
  std::string_view refusals;   // what CGAL's reader refuses without saying which, for the message
};

const ReadableFormat readable_formats[] = {
    {".off",
     [](const std::string& file, Soup& soup) {
       return read_off_soup(file, soup);
     },
     "fewer vertices or faces than the header declares, or a vertex line with fewer than three numbers"},
    {".obj",
     [](const std::string& file, Soup& soup) {
       return CGAL::IO::read_OBJ(file, soup.points, soup.polygons, CGAL::parameters::verbose(false));
     },
     "a line that is not OBJ, a vertex with fewer than three coordinates, or no vertices or no faces"},
    {".ply",
     [](const std::string& file, Soup& soup) {
       check_ply_sizes(file);
       return CGAL::IO::read_PLY(file, soup.points, soup.polygons, CGAL::parameters::verbose(false));
     },
     "no valid PLY header, faces without a vertex_indices or vertex_index list, or fewer data than the "
     "header declares"},
    {".stl",
     [](const std::string& file, Soup& soup) {
       return read_stl_soup(file, soup);
     },
     "malformed ASCII STL (solid ... facet ... endsolid)"},
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

[[noreturn]] void refuse_oversized(const path& file) {
  throw InputError(fmt::format("cannot read {}: it declares more data than fits in memory", file.string()));
}

Soup read_soup(const path& file, const ReadableFormat& format) {
  Soup soup;
  bool read = false;
  try {
    read = format.read(file.string(), soup);
  } catch (const std::bad_alloc&) {
    refuse_oversized(file);
  } catch (const std::length_error&) {
    refuse_oversized(file);
  } catch (const CGAL::Failure_exception& failure) {
    // CGAL's readers assert what they assume of the file (a PLY coordinate stored as float, say:
    // found by fuzzing); on a user's file that is bad input, not a bug of ours.
    throw InputError(fmt::format("cannot read {}: CGAL's {} reader stopped at an assumption the file breaks: {}",
                                 file.string(), format.extension.substr(1), failure.expression()));
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
  require_regular_file(file, "cannot open");
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
  write_file_atomically(file, [&](const path& temporary) {
    if (!format.write(temporary.string(), points_of(mesh), triangles)) {
      throw InputError(fmt::format("cannot write {}: the folder is missing or not writable", file.string()));
    }
  });
}

}  // namespace gt
