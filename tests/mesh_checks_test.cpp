// Tests of the mesh checks (compare/checks/mesh.hpp), mesh IO (core/io/mesh_io.hpp) and
// check-mesh (compare/cli/check_mesh.hpp): small meshes built here whose every count is known by
// hand (cube, tetrahedron, torus, an open cube, a flipped face, a non-manifold edge, crossing
// triangles, degenerate and duplicate triangles), malformed files, write -> read round trips, and
// the four CGAL demo meshes that datasets/fetch.sh puts in datasets/real/meshes (a missing file
// fails with a hint to run the script).
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "compare/checks/mesh.hpp"
#include "compare/cli/check_mesh.hpp"
#include "core/errors.hpp"
#include "core/io/mesh_io.hpp"
#include "tests/support/refusal.hpp"

namespace gt {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::refusal;

const fs::path real_mesh_dir = fs::path(GT_DATASET_DIR) / "real" / "meshes";

// ---- meshes built here ----

// Unit cube [0,1]^3, vertex x + 2y + 4z, two outward counter-clockwise triangles per face; the
// face at z = 0 comes first.
Mesh unit_cube() {
  Mesh cube;
  for (int i = 0; i < 8; ++i) cube.positions.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  cube.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return cube;
}

// Corner at the origin and the three unit points, faces outward: volume 1/6.
Mesh tetrahedron() {
  Mesh tetra;
  tetra.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return tetra;
}

// A torus of `around` x `across` quads (radii 3 and 1), each split into two outward triangles.
Mesh torus(int around, int across) {
  Mesh ring;
  const auto vertex = [&](int i, int j) { return static_cast<std::uint32_t>((i % around) * across + j % across); };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < across; ++j) {
      const double u = 2 * std::numbers::pi * i / around, v = 2 * std::numbers::pi * j / across;
      ring.positions.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  }
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < across; ++j) {
      ring.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      ring.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  }
  return ring;
}

Mesh flipped(Mesh mesh, std::size_t triangle) {
  std::swap(mesh.triangles[triangle][1], mesh.triangles[triangle][2]);
  return mesh;
}

std::string check_names(const std::vector<Check>& checks) {
  std::string names;
  for (const Check& check : checks) names += check.name + " ";
  return names;
}

const Check& find_check(const std::vector<Check>& checks, const std::string& name) {
  for (const Check& check : checks) {
    if (check.name == name) return check;
  }
  throw std::runtime_error("no check " + name + " among " + check_names(checks));
}

// ---- closed, oriented meshes ----

TEST(MeshChecks, UnitCubeIsWatertightWithVolumeOne) {
  const MeshReport report = check_mesh(unit_cube());
  EXPECT_TRUE(is_watertight_and_oriented(report)) << describe(report);
  EXPECT_EQ(report.raw.edges, 18u);
  EXPECT_EQ(report.raw.border_edges, 0u);
  EXPECT_TRUE(report.cgal.soup_is_polygon_mesh);
  EXPECT_TRUE(report.cgal.closed);
  EXPECT_EQ(report.cgal.bounds_volume, true);
  EXPECT_DOUBLE_EQ(report.cgal.volume.value(), 1.0);  // CGAL sums tetrahedra of volume det / 6
  EXPECT_EQ(report.cgal.area, 6.0);
  EXPECT_EQ(report.openmesh.euler_characteristic, 2);
  EXPECT_EQ(report.openmesh.genus, 0.0);
  EXPECT_EQ(report.openmesh.components, 1u);
  EXPECT_TRUE(report.libraries_agree) << report.disagreement;
}

TEST(MeshChecks, TetrahedronHasVolumeOneSixth) {
  const MeshReport report = check_mesh(tetrahedron());
  EXPECT_TRUE(is_watertight_and_oriented(report)) << describe(report);
  EXPECT_DOUBLE_EQ(report.cgal.volume.value(), 1.0 / 6.0);
  EXPECT_EQ(report.openmesh.euler_characteristic, 2);
  EXPECT_EQ(report.openmesh.genus, 0.0);
}

TEST(MeshChecks, TorusHasGenusOne) {
  const MeshReport report = check_mesh(torus(12, 8));
  EXPECT_TRUE(is_watertight_and_oriented(report)) << describe(report);
  EXPECT_EQ(report.openmesh.euler_characteristic, 0);
  EXPECT_EQ(report.cgal.euler_characteristic, 0);
  EXPECT_EQ(report.openmesh.genus, 1.0);
  EXPECT_GT(report.cgal.volume.value(), 0.0);
}

TEST(MeshChecks, InsideOutCubeIsConsistentButFacesInward) {
  Mesh cube = unit_cube();
  for (std::size_t i = 0; i < cube.triangles.size(); ++i) cube = flipped(cube, i);
  const MeshReport report = check_mesh(cube);
  EXPECT_EQ(report.raw.misoriented_edges, 0u);
  EXPECT_DOUBLE_EQ(report.cgal.volume.value(), -1.0);
  EXPECT_EQ(report.cgal.bounds_volume, true);  // CGAL: the complement of the cube is a volume
  EXPECT_EQ(report.cgal.outward, false);
  EXPECT_FALSE(is_watertight_and_oriented(report));
  EXPECT_THAT(describe(report), HasSubstr("oriented inward"));
  EXPECT_EQ(find_check(mesh_checks(report, "cpu", true), "mesh.bounds_volume.cpu").status, Outcome::fail);
}

// ---- defects ----

TEST(MeshChecks, CubeWithoutOneFaceHasFourBorderEdgesAndTheLibrariesAgree) {
  Mesh cube = unit_cube();
  cube.triangles.erase(cube.triangles.begin(), cube.triangles.begin() + 2);
  const MeshReport report = check_mesh(cube);
  EXPECT_FALSE(report.cgal.closed);
  EXPECT_EQ(report.raw.border_edges, 4u);
  EXPECT_EQ(report.cgal.border_edges, 4u);
  EXPECT_EQ(report.openmesh.boundary_halfedges, 4u);
  EXPECT_EQ(report.openmesh.boundary_loops, 1u);
  EXPECT_EQ(report.openmesh.euler_characteristic, 1);
  EXPECT_EQ(report.openmesh.genus, 0.0);
  EXPECT_FALSE(report.cgal.volume.has_value());
  EXPECT_TRUE(report.libraries_agree) << report.disagreement;
  EXPECT_FALSE(is_watertight_and_oriented(report));
  EXPECT_THAT(describe(report), HasSubstr("4 border edges (not closed)"));
}

TEST(MeshChecks, CubeWithOneFlippedFaceIsNotConsistentlyOriented) {
  const MeshReport report = check_mesh(flipped(flipped(unit_cube(), 0), 1));
  EXPECT_EQ(report.raw.misoriented_edges, 4u);
  EXPECT_FALSE(report.cgal.soup_is_polygon_mesh);
  EXPECT_GT(report.cgal.reversed_faces, 0u);
  EXPECT_GT(report.openmesh.rejected_faces, 0u);
  EXPECT_FALSE(is_watertight_and_oriented(report));
  EXPECT_THAT(describe(report), HasSubstr("4 edges used twice in the same direction"));
}

TEST(MeshChecks, ThirdTriangleOnAnEdgeMakesItNonManifold) {
  Mesh fan;
  fan.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fan.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const MeshReport report = check_mesh(fan);
  EXPECT_EQ(report.raw.non_manifold_edges, 1u);
  EXPECT_EQ(report.cgal.non_manifold_edges, 1u);
  EXPECT_FALSE(report.cgal.soup_is_polygon_mesh);
  EXPECT_EQ(report.openmesh.rejected_faces, 1u);
  EXPECT_GT(report.cgal.split_vertices, 0u);
  EXPECT_GT(report.cgal.split_contacts, 0u);  // the split faces touch along the edge: not counted as crossing
  EXPECT_EQ(report.cgal.self_intersections, 0u);
  EXPECT_FALSE(report.libraries_agree);       // they see different surfaces, and say why
  EXPECT_THAT(report.disagreement, HasSubstr("do not form a polygon mesh as they are"));
  EXPECT_FALSE(is_watertight_and_oriented(report));
  EXPECT_THAT(describe(report), HasSubstr("1 non-manifold edge"));
}

TEST(MeshChecks, CrossingTrianglesIntersect) {
  Mesh crossing;
  crossing.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {0.2, 0.8, 0}};
  crossing.triangles = {{0, 1, 2}, {3, 4, 5}};
  const MeshReport report = check_mesh(crossing);
  EXPECT_EQ(report.cgal.self_intersections, 1u);
  EXPECT_FALSE(report.cgal.self_intersections_capped);
  EXPECT_EQ(report.openmesh.components, 2u);
  EXPECT_THAT(describe(report), HasSubstr("1 self-intersecting face pair"));
}

TEST(MeshChecks, RawBufferCountsDegenerateDuplicateAndOutOfRangeTriangles) {
  Mesh cube = unit_cube();
  cube.positions.push_back({0.5, 0, 0});                  // 8: on the edge from 0 to 1
  cube.positions.push_back({std::nan(""), 0, 0});         // 9: not finite
  cube.triangles.push_back({0, 0, 3});                    // repeated index
  cube.triangles.push_back({0, 8, 1});                    // zero area
  cube.triangles.push_back({2, 1, 0});                    // duplicate of {0, 2, 1}
  cube.triangles.push_back({0, 1, 99});                   // out of range
  cube.triangles.push_back({0, 1, 9});                    // non-finite corner
  const MeshReport report = check_mesh(cube);
  EXPECT_EQ(report.raw.repeated_index_triangles, 1u);
  EXPECT_EQ(report.raw.zero_area_triangles, 1u);
  EXPECT_EQ(report.cgal.degenerate_faces, 1u);
  EXPECT_EQ(report.raw.duplicate_triangles, 1u);
  EXPECT_EQ(report.raw.out_of_range_triangles, 1u);
  EXPECT_EQ(report.raw.nonfinite_triangles, 1u);
  EXPECT_EQ(report.raw.unreferenced_vertices, 0u);
  EXPECT_FALSE(is_watertight_and_oriented(report));
  const auto checks = mesh_checks(report, "cpu", true);
  EXPECT_EQ(find_check(checks, "mesh.degenerate.cpu").value, 2.0);
  EXPECT_EQ(find_check(checks, "mesh.degenerate.cpu").status, Outcome::fail);
  EXPECT_EQ(find_check(checks, "mesh.duplicates.cpu").status, Outcome::fail);
  EXPECT_EQ(find_check(checks, "mesh.invalid.cpu").value, 2.0);
}

TEST(MeshChecks, EmptyMeshPassesVacuously) {
  const MeshReport report = check_mesh(Mesh{});
  EXPECT_TRUE(is_watertight_and_oriented(report)) << describe(report);
  EXPECT_EQ(report.raw.triangles, 0u);
}

// ---- report forms ----

TEST(MeshChecks, ChecksOfAClosedMeshPassAndNameTheBackend) {
  const auto checks = mesh_checks(check_mesh(unit_cube()), "gpu", true);
  for (const char* name : {"invalid", "degenerate", "duplicates", "closed", "manifold", "oriented", "bounds_volume",
                           "self_intersections", "libraries_agree"}) {
    const Check& check = find_check(checks, fmt::format("mesh.{}.gpu", name));
    EXPECT_EQ(check.status, Outcome::pass) << check.name << ": " << check.detail;
    EXPECT_EQ(check.threshold, 0.0) << check.name;
  }
  for (const char* name : {"euler", "genus", "components", "area", "volume"}) {
    const Check& check = find_check(checks, fmt::format("mesh.{}.gpu", name));
    EXPECT_EQ(check.status, Outcome::pass) << check.name;
    EXPECT_FALSE(check.threshold.has_value()) << check.name;
  }
  EXPECT_EQ(find_check(checks, "mesh.euler.gpu").value, 2.0);
  EXPECT_DOUBLE_EQ(find_check(checks, "mesh.volume.gpu").value, 1.0);
}

TEST(MeshChecks, AnOpenChunkMayHaveBorderEdges) {
  Mesh cube = unit_cube();
  cube.triangles.erase(cube.triangles.begin(), cube.triangles.begin() + 2);
  const auto checks = mesh_checks(check_mesh(cube), "cpu", false);
  EXPECT_THAT(check_names(checks), ::testing::Not(HasSubstr("mesh.closed.")));
  EXPECT_THAT(check_names(checks), ::testing::Not(HasSubstr("mesh.bounds_volume.")));
  EXPECT_EQ(find_check(checks, "mesh.border_edges.cpu").value, 4.0);
  const Check& volume = find_check(checks, "mesh.volume.cpu");  // not applicable to an open mesh: no value, no skip
  EXPECT_EQ(volume.status, Outcome::pass);
  EXPECT_TRUE(std::isnan(volume.value));
  EXPECT_THAT(volume.detail, HasSubstr("not applicable"));
  for (const Check& check : checks) EXPECT_NE(check.status, Outcome::fail) << check.name << ": " << check.detail;
}

TEST(MeshChecks, ClosedCheckCountsBorderEdges) {
  Mesh cube = unit_cube();
  cube.triangles.pop_back();
  const Check closed = find_check(mesh_checks(check_mesh(cube), "cpu", true), "mesh.closed.cpu");
  EXPECT_EQ(closed.value, 3.0);
  EXPECT_EQ(closed.status, Outcome::fail);
}

TEST(MeshChecks, JsonHoldsEveryLayer) {
  Mesh cube = unit_cube();
  cube.triangles.pop_back();
  const nlohmann::json json = to_json(check_mesh(cube));
  EXPECT_EQ(json["watertight_and_oriented"], false);
  EXPECT_EQ(json["raw"]["border_edges"], 3);
  EXPECT_EQ(json["cgal"]["closed"], false);
  EXPECT_TRUE(json["cgal"]["volume"].is_null());
  EXPECT_EQ(json["openmesh"]["boundary_loops"], 1);
  EXPECT_EQ(json["libraries_agree"], true);
  EXPECT_EQ(json["problems"].size(), 1u);
}

// ---- files ----

class MeshFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "mesh_checks_test.XXXXXX").string();
    folder = mkdtemp(pattern.data());
  }
  void TearDown() override { fs::remove_all(folder); }

  fs::path write_text(const std::string& name, const std::string& text) const {
    const fs::path file = folder / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

  fs::path folder;
};

TEST_F(MeshFiles, RoundTripsKeepPositionsAndTrianglesExactly) {
  Mesh mesh = torus(5, 4);
  mesh.positions[0] = {1.0 / 3.0, -2.5e-7, 12345.678901234567};
  for (const char* extension : {".ply", ".obj", ".off", ".PLY"}) {
    const fs::path file = folder / (std::string("torus") + extension);
    write_mesh(mesh, file);
    const MeshFile read = read_mesh(file);
    EXPECT_EQ(read.mesh.positions, mesh.positions) << extension;
    EXPECT_EQ(read.mesh.triangles, mesh.triangles) << extension;
    EXPECT_TRUE(read.notes.empty()) << extension;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 4) << "no partial files left";
}

TEST_F(MeshFiles, BinaryPlyIsLittleEndian) {
  const fs::path file = folder / "cube.ply";
  write_mesh(unit_cube(), file);
  std::ifstream in(file, std::ios::binary);
  std::string header(200, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header.size()));
  EXPECT_THAT(header, HasSubstr("format binary_little_endian 1.0"));
  EXPECT_THAT(header, HasSubstr("property double x"));
}

TEST_F(MeshFiles, WritingRefusesUnknownExtensionsAndMissingFolders) {
  EXPECT_THAT(refusal([&] { write_mesh(unit_cube(), folder / "cube.stl"); }), HasSubstr("unknown mesh extension"));
  EXPECT_THAT(refusal([&] { write_mesh(unit_cube(), folder / "missing" / "cube.ply"); }),
              HasSubstr("cannot write"));
  EXPECT_TRUE(fs::is_empty(folder));
}

TEST_F(MeshFiles, QuadsAreFannedWithANote) {
  const fs::path file = write_text("quad.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n4 0 1 2 3\n3 0 1 4\n");
  const MeshFile read = read_mesh(file);
  EXPECT_EQ(read.format, "off");
  const std::vector<std::array<std::uint32_t, 3>> expected = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}};
  EXPECT_EQ(read.mesh.triangles, expected);
  ASSERT_EQ(read.notes.size(), 1u);
  EXPECT_THAT(read.notes[0], HasSubstr("1 of 2 faces had more than 3 corners"));
}

TEST_F(MeshFiles, AsciiPlyAndObjAreRead) {
  const fs::path ply = write_text("tetra.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                  "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                                  "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const fs::path obj = write_text("tetra.obj", "# tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                               "f 1 3 2\nf 1/1 2/2 4/4\nf -4 -1 -2\nf 2//1 3//1 4//1\n");
  for (const fs::path& file : {ply, obj}) {
    const MeshFile read = read_mesh(file);
    EXPECT_EQ(read.mesh.triangles, tetrahedron().triangles) << file;
    EXPECT_TRUE(is_watertight_and_oriented(check_mesh(read.mesh))) << file;
  }
}

TEST_F(MeshFiles, StlCornersAreMergedIntoSharedVertices) {
  std::string text = "solid tetra\n";
  const Mesh tetra = tetrahedron();
  for (const auto& triangle : tetra.triangles) {
    text += " facet normal 0 0 0\n  outer loop\n";
    for (const auto index : triangle) {
      const auto& p = tetra.positions[index];
      text += fmt::format("   vertex {} {} {}\n", p[0], p[1], p[2]);
    }
    text += "  endloop\n endfacet\n";
  }
  const MeshFile read = read_mesh(write_text("tetra.stl", text + "endsolid tetra\n"));
  EXPECT_EQ(read.mesh.positions.size(), 4u);
  EXPECT_EQ(read.mesh.triangles.size(), 4u);
  EXPECT_TRUE(is_watertight_and_oriented(check_mesh(read.mesh)));
  ASSERT_EQ(read.notes.size(), 1u);
  EXPECT_THAT(read.notes[0], HasSubstr("merged into 4 vertices"));
}

TEST_F(MeshFiles, BinaryStlIsRead) {
  std::string bytes(80, ' ');
  const std::uint32_t count = 4;
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  const Mesh tetra = tetrahedron();
  for (const auto& triangle : tetra.triangles) {
    std::array<float, 12> values{};  // normal, then three corners
    for (int corner = 0; corner < 3; ++corner) {
      const auto& position = tetra.positions[triangle[corner]];
      for (int axis = 0; axis < 3; ++axis) values[3 + 3 * corner + axis] = static_cast<float>(position[axis]);
    }
    bytes.append(reinterpret_cast<const char*>(values.data()), sizeof(values));
    bytes.append(2, '\0');
  }
  const MeshFile read = read_mesh(write_text("tetra.stl", bytes));
  EXPECT_EQ(read.format, "stl");
  EXPECT_EQ(read.mesh.triangles.size(), 4u);
  EXPECT_TRUE(is_watertight_and_oriented(check_mesh(read.mesh)));
}

TEST_F(MeshFiles, IndicesOutOfRangeAreRefused) {
  const std::string tetra_vertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  EXPECT_THAT(refusal([&] { read_mesh(write_text("bad.off", "OFF\n4 1 0\n" + tetra_vertices + "3 0 1 4\n")); }),
              HasSubstr("bad.off"));
  // CGAL's OBJ reader lets index V + 1 through (its bound is off by one); the range check does not.
  EXPECT_THAT(refusal([&] { read_mesh(write_text("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")); }),
              HasSubstr("bad.obj: face 0 names vertex 3, out of range (the file has 3 vertices)"));
  EXPECT_THAT(refusal([&] { read_mesh(write_text("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n")); }),
              HasSubstr("out of range"));
  EXPECT_THAT(refusal([&] {
                read_mesh(write_text("bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                                "property float y\nproperty float z\nelement face 1\n"
                                                "property list uchar int vertex_indices\nend_header\n"
                                                "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"));
              }),
              HasSubstr("out of range"));
}

// A binary little-endian PLY of one triangle whose face list claims `corners` indices (3: a valid file).
std::string binary_triangle_ply(std::uint32_t corners) {
  std::string text =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
  const float coordinates[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::int32_t indices[3] = {0, 1, 2};
  text.append(reinterpret_cast<const char*>(coordinates), sizeof coordinates);
  text.append(reinterpret_cast<const char*>(&corners), sizeof corners);
  text.append(reinterpret_cast<const char*>(indices), sizeof indices);
  return text;
}

TEST_F(MeshFiles, AsciiStlWithATabAfterSolidIsReadAsAscii) {
  // CGAL's own test takes only a space or a line break after "solid" as ASCII.
  const MeshFile file = read_mesh(write_text("tab.stl", "solid\tname\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                                        "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid name\n"));
  ASSERT_EQ(file.mesh.triangles.size(), 1u);
  EXPECT_EQ(file.mesh.positions.size(), 3u);
  EXPECT_EQ(file.mesh.positions[1][0], 1.0);
}

TEST_F(MeshFiles, BinaryPlyWithAnHonestListIsRead) {
  // The list check of the PLY bomb below refuses only counts the file cannot hold.
  const MeshFile file = read_mesh(write_text("triangle.ply", binary_triangle_ply(3)));
  ASSERT_EQ(file.mesh.triangles.size(), 1u);
  EXPECT_EQ(file.mesh.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
}

TEST_F(MeshFiles, MalformedFilesAreRefusedWithTheirName) {
  const std::vector<std::pair<fs::path, std::string>> cases = {
      {write_text("short.off", "OFF\n8 12 0\n0 0 0\n1 0 0\n"), "short.off: the OFF header declares 8 vertices"},
      {write_text("truncated.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2"),
       "cannot read"},
      {write_text("huge.off", "OFF\n2000000000 2000000000 0\n0 0 0\n"), "more than its"},
      {write_text("negative.off", "OFF\n-5 1 0\n0 0 0\n"), "no valid OFF header"},
      {write_text("garbage.off", "this is not a mesh\n"), "no valid OFF header"},
      {write_text("empty.off", ""), "no valid OFF header"},
      {write_text("points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"), "no faces"},
      {write_text("line.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"), "face 0 has 2 corners"},
      {write_text("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"), "nan.obj"},
      {write_text("garbage.obj", "hello world\n"), "cannot read"},
      {write_text("garbage.ply", "ply\nformat nonsense\n"), "cannot read"},
      {write_text("truncated.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                                   "property float y\nproperty float z\nend_header\n\x01\x02"),
       "cannot read"},
      {write_text("garbage.stl", "not an stl file"), "neither binary STL"},
      // Hostile counts and indices (issue 18): refused before anything is sized from them.
      {write_text("corner_bomb.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000000 0 1 2\n"),
       "face 0 declares 1000000000 corners but its line holds 3 indices"},
      {write_text("wrapping_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 18446744073709551615\n"),
       "corner 2 is '18446744073709551615', not a vertex index"},
      {write_text("fraction_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2.7\n"),
       "corner 2 is '2.7', not a vertex index"},
      {write_text("list_bomb.ply", binary_triangle_ply(4000000000u)), "a list claims 4000000000 entries"},
      {write_text("element_bomb.ply", "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nend_header\n"),
       "declares 4000000000 instances"},
      {write_text("ascii_list_bomb.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                         "end_header\n0 0 0\n1 0 0\n0 1 0\n99999999 0 1 2\n"),
       "list count '99999999'"},
      {write_text("mesh.xyz", "OFF\n"), "unknown mesh extension '.xyz'"},
      {folder / "missing.off", "no such file"},
  };
  for (const auto& [file, expected] : cases) {
    const fs::path& path = file;  // clang 14 cannot capture a structured binding
    const std::string message = refusal([&] { read_mesh(path); });
    EXPECT_THAT(message, HasSubstr(file.filename().string())) << file;
    EXPECT_THAT(message, HasSubstr(expected)) << file;
  }
}

TEST_F(MeshFiles, CheckMeshCommandExitStatus) {
  write_mesh(unit_cube(), folder / "cube.off");
  Mesh open_cube = unit_cube();
  open_cube.triangles.pop_back();
  write_mesh(open_cube, folder / "open.off");
  ::testing::internal::CaptureStdout();
  EXPECT_EQ(check_mesh_command(folder / "cube.off", false), 0);
  EXPECT_EQ(check_mesh_command(folder / "open.off", true), 1);
  const std::string printed = ::testing::internal::GetCapturedStdout();
  EXPECT_THAT(printed, HasSubstr("watertight and consistently oriented"));
  EXPECT_THAT(printed, HasSubstr("\"border_edges\": 3"));
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(check_mesh_command(folder / "missing.off", false), 2);
  EXPECT_THAT(::testing::internal::GetCapturedStderr(), HasSubstr("groundtruth: cannot open"));
}

// ---- the CGAL demo meshes (datasets/fetch.sh) ----

MeshReport check_real_mesh(const std::string& name) {
  const fs::path file = real_mesh_dir / name;
  if (!fs::exists(file)) throw std::runtime_error(file.string() + " is missing: run datasets/fetch.sh");
  return check_mesh(read_mesh(file).mesh);
}

TEST(RealMeshes, BunnyIsClosedGenusZero) {
  const MeshReport report = check_real_mesh("bunny00.off");
  EXPECT_TRUE(is_watertight_and_oriented(report)) << describe(report);
  EXPECT_EQ(report.raw.vertices, 37706u);
  EXPECT_EQ(report.raw.triangles, 75408u);
  EXPECT_EQ(report.cgal.self_intersections, 0u);
  EXPECT_EQ(report.openmesh.euler_characteristic, 2);
  EXPECT_EQ(report.openmesh.genus, 0.0);
}

TEST(RealMeshes, ElephantIsClosedGenusThree) {
  const MeshReport report = check_real_mesh("elephant.off");
  EXPECT_TRUE(is_watertight_and_oriented(report)) << describe(report);
  EXPECT_EQ(report.openmesh.euler_characteristic, -4);
  EXPECT_EQ(report.openmesh.genus, 3.0);
}

// Closed, manifold, oriented, genus 0 — and 101 pairs of faces that cross (checked pair by pair
// with CGAL's exact do_intersect: the pairs share no vertex), so check-mesh says not watertight.
TEST(RealMeshes, CowIsClosedGenusZeroButSelfIntersecting) {
  const MeshReport report = check_real_mesh("cow.off");
  EXPECT_TRUE(report.cgal.closed);
  EXPECT_EQ(report.raw.non_manifold_edges + report.cgal.non_manifold_vertices, 0u);
  EXPECT_EQ(report.raw.misoriented_edges, 0u);
  EXPECT_EQ(report.openmesh.euler_characteristic, 2);
  EXPECT_EQ(report.openmesh.genus, 0.0);
  EXPECT_EQ(report.cgal.self_intersections, 101u);
  EXPECT_TRUE(report.libraries_agree) << report.disagreement;
  EXPECT_EQ(mesh_problems(report), std::vector<std::string>{"101 self-intersecting face pairs"});
}

TEST(RealMeshes, ElephantWithHolesIsOpen) {
  const MeshReport report = check_real_mesh("elephant-with-holes.off");
  EXPECT_FALSE(report.cgal.closed);
  EXPECT_EQ(report.cgal.border_edges, 1353u);
  EXPECT_EQ(report.openmesh.boundary_halfedges, 1353u);
  EXPECT_EQ(report.openmesh.boundary_loops, 106u);
  EXPECT_EQ(report.openmesh.euler_characteristic, -110);
  EXPECT_EQ(report.openmesh.genus, 3.0);
  EXPECT_EQ(report.cgal.self_intersections, 173u);  // crossing pairs, as in the cow
  EXPECT_TRUE(report.libraries_agree) << report.disagreement;
  EXPECT_FALSE(is_watertight_and_oriented(report));
  ::testing::internal::CaptureStdout();
  EXPECT_EQ(check_mesh_command(real_mesh_dir / "elephant-with-holes.off", false), 1);
  EXPECT_THAT(::testing::internal::GetCapturedStdout(), HasSubstr("1353 border edges (not closed)"));
}

}  // namespace
}  // namespace gt
