// Outputs to judge (issue 34): a user's cave mesh and rendered image graded where the GPU twin's
// stand (`run --candidate`), and `compare-mesh`. Each honest candidate passes; each buggy one fails
// the check meant to catch it; bad files exit 2 before anything is written.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/checks/cave_mesh.hpp"
#include "core/io/mesh_io.hpp"
#include "core/params/cave.hpp"
#include "tests/support/cli_report.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using gt::testing::report_of;
using gt::testing::run_groundtruth;

const nlohmann::json& check_of(const nlohmann::json& report_case, const std::string& name) {
  static const nlohmann::json missing = {{"status", "missing"}};
  for (const auto& check : report_case["checks"]) {
    if (check["name"] == name) return check;
  }
  return missing;
}

// Runs `case_name` with the candidate and returns the exit status and the case's report.
struct Graded {
  int status = 0;
  nlohmann::json report_case;
  std::string err;
};

Graded grade(const std::string& case_name, const fs::path& candidate, const fs::path& out, const fs::path& cwd) {
  const auto run = run_groundtruth({"run", case_name, "--candidate", candidate.string(), "--out", out.string(), "--quiet"}, cwd);
  Graded graded{run.status, nullptr, run.err};
  if (fs::exists(out / "report.json")) graded.report_case = report_of(out)["cases"][0];
  return graded;
}

// The reference's own files of a case (--backend cpu): its mesh or its image.
fs::path reference_file(const std::string& case_name, const std::string& file, const gt::testing::TemporaryFolder& folder) {
  const auto out = folder / ("reference_" + case_name);
  const auto run = run_groundtruth({"run", case_name, "--backend", "cpu", "--out", out.string(), "--quiet"}, folder.path());
  EXPECT_EQ(run.status, 0) << run;
  return out / case_name / file;
}

// ---- a cave block's mesh --------------------------------------------------------------------------

const std::string block_case = "cave.marching_tetrahedra.solid.block12";

gt::Mesh changed(const fs::path& file, const std::function<void(gt::Mesh&)>& change) {
  gt::Mesh mesh = gt::read_mesh(file).mesh;
  change(mesh);
  return mesh;
}

fs::path written(const gt::Mesh& mesh, const fs::path& file) {
  gt::write_mesh(mesh, file);
  return file;
}

TEST(CandidateOutputs, AnHonestCaveMeshPassesAndEachBugFailsItsCheck) {
  gt::testing::TemporaryFolder folder;
  const fs::path truth = reference_file(block_case, "mesh.cpu.ply", folder);
  ASSERT_TRUE(fs::is_regular_file(truth));
  {  // A float mesher's mesh: ref<double>'s positions rounded to float (as a float PLY would hold them).
    const auto honest = written(changed(truth, [](gt::Mesh& mesh) {
                                  for (auto& position : mesh.positions) {
                                    for (double& c : position) c = static_cast<float>(c);
                                  }
                                }),
                                folder / "honest.ply");
    const Graded graded = grade(block_case, honest, folder / "honest", folder.path());
    ASSERT_EQ(graded.status, 0) << graded.err << graded.report_case.dump(1);
    for (const char* name : {"mesh.on_lattice_edges.candidate", "mesh.closed.candidate", "mesh.oriented.candidate",
                             "spec.vertex_crossing.candidate", "parity.crossing_edges.candidate_vs_double",
                             "parity.hausdorff.candidate_vs_double"}) {
      EXPECT_EQ(check_of(graded.report_case, name)["status"], "pass") << name;
    }
    // The Hausdorff bound is derived before the candidate is read: graded, not informative.
    EXPECT_TRUE(check_of(graded.report_case, "parity.hausdorff.candidate_vs_double")["threshold"].is_number());
    EXPECT_EQ(check_of(graded.report_case, "determinism.gpu")["status"], "missing") << "the GPU does not run";
  }
  struct Bug {
    std::string name;
    std::function<void(gt::Mesh&)> change;
    std::string caught_by;
  };
  const std::vector<Bug> bugs = {
      {"flipped", [](gt::Mesh& mesh) { std::swap(mesh.triangles[0][1], mesh.triangles[0][2]); }, "mesh.oriented.candidate"},
      // Every vertex at its edge's midpoint: the seed's first version, not linear interpolation.
      {"midpoints",
       [](gt::Mesh& mesh) {
         gt::key_by_lattice_edges(mesh);
         for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
           const gt::LatticeEdge edge = gt::lattice_edge_from_key(mesh.edge_keys[vertex]);
           for (int axis = 0; axis < 3; ++axis) {
             mesh.positions[vertex][axis] = double(edge.lower_point[axis]) + 0.5 * ((edge.direction >> axis) & 1);
           }
         }
       },
       "spec.vertex_crossing.candidate"},
      // One vertex pushed off its lattice edge by 0.01 across it.
      {"off_edge",
       [](gt::Mesh& mesh) {
         gt::key_by_lattice_edges(mesh);
         const gt::LatticeEdge edge = gt::lattice_edge_from_key(mesh.edge_keys[0]);
         const int across = (edge.direction & 1) == 0 ? 0 : ((edge.direction & 2) == 0 ? 1 : 2);
         mesh.positions[0][across] += 0.01;
       },
       "mesh.on_lattice_edges.candidate"},
      // The whole block meshed 20 lattice units away along x.
      {"moved", [](gt::Mesh& mesh) { for (auto& position : mesh.positions) position[0] += 20.0; },
       "parity.hausdorff.candidate_vs_double"},
  };
  for (const Bug& bug : bugs) {
    const auto file = written(changed(truth, bug.change), folder / (bug.name + ".ply"));
    const Graded graded = grade(block_case, file, folder / bug.name, folder.path());
    EXPECT_EQ(graded.status, 1) << bug.name << graded.err;
    EXPECT_EQ(check_of(graded.report_case, bug.caught_by)["status"], "fail") << bug.name;
  }
  {  // Another threshold's mesh of the same noise: its crossing edges are not the block's.
    const fs::path other = reference_file("cave.marching_tetrahedra.mutant_probe.solid8_threshold", "mesh.cpu.ply", folder);
    const Graded graded = grade("cave.marching_tetrahedra.mutant_probe.solid8", other, folder / "threshold", folder.path());
    EXPECT_EQ(graded.status, 1) << graded.err;
    EXPECT_EQ(check_of(graded.report_case, "parity.crossing_edges.candidate_vs_double")["status"], "fail");
  }
}

TEST(CandidateOutputs, BadMeshFilesExitTwoAndWriteNothing) {
  gt::testing::TemporaryFolder folder;
  std::ofstream(folder / "points.off") << "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n";
  std::ofstream(folder / "mesh.txt") << "not a mesh\n";
  for (const auto& [file, message] : {std::pair{"points.off", "no faces"}, std::pair{"mesh.txt", "mesh.txt"}}) {
    const Graded graded = grade(block_case, folder / file, folder / "out", folder.path());
    EXPECT_EQ(graded.status, 2) << file;
    EXPECT_THAT(graded.err, HasSubstr(message));
    EXPECT_FALSE(fs::exists(folder / "out"));
  }
  // An algorithm that steps takes no output file, and says which ones do.
  const Graded stepping = grade("erosion.thermal.spec.example_3x3", folder / "points.off", folder / "out", folder.path());
  EXPECT_EQ(stepping.status, 2);
  EXPECT_THAT(stepping.err, HasSubstr("cave.marching_tetrahedra (mesh)"));
  EXPECT_THAT(stepping.err, HasSubstr("render.phong (image)"));
}

// ---- a rendered image -------------------------------------------------------------------------------

OIIO::ImageBuf image_of(const fs::path& file) {
  OIIO::ImageBuf image(file.string());
  EXPECT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::UINT8)) << image.geterror();
  return image;
}

fs::path with_pixels_changed(const fs::path& file, const fs::path& out, int x0, int y0, int side, int levels) {
  OIIO::ImageBuf image = image_of(file);
  const OIIO::ImageSpec& spec = image.spec();
  std::vector<unsigned char> pixels(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  image.get_pixels(image.roi(), OIIO::TypeDesc::UINT8, pixels.data());
  for (int y = y0; y < std::min(spec.height, y0 + side); ++y) {
    for (int x = x0; x < std::min(spec.width, x0 + side); ++x) {
      for (int c = 0; c < 3; ++c) {
        auto& value = pixels[(static_cast<std::size_t>(y) * spec.width + x) * spec.nchannels + c];
        value = static_cast<unsigned char>(std::clamp(int(value) + levels, 0, 255));
      }
    }
  }
  OIIO::ImageBuf changed(spec);
  changed.set_pixels(changed.roi(), OIIO::TypeDesc::UINT8, pixels.data());
  EXPECT_TRUE(changed.write(out.string())) << changed.geterror();
  return out;
}

TEST(CandidateOutputs, AnHonestImagePassesAndABrightPatchFails) {
  gt::testing::TemporaryFolder folder;
  for (const std::string case_name : {"render.phong.mutant_probe.quad", "render.phong.bunny00"}) {
    const fs::path truth = reference_file(case_name, "cpu.png", folder);
    const bool probe = case_name.find("mutant_probe") != std::string::npos;
    // The probe's closed form allows one level off it: the reference's own image passes. On the
    // bunny, a renderer that rounds every channel one level up (the 8-bit target's other rounding).
    const fs::path honest = probe ? truth : with_pixels_changed(truth, folder / "up_one_level.png", 0, 0, 1 << 20, 1);
    Graded graded = grade(case_name, honest, folder / ("honest_" + case_name), folder.path());
    ASSERT_EQ(graded.status, 0) << case_name << graded.err << graded.report_case.dump(1);
    EXPECT_EQ(check_of(graded.report_case, "image.psnr.candidate_vs_cpu")["status"], "pass");
    EXPECT_TRUE(fs::exists(folder / ("honest_" + case_name) / case_name / "candidate_vs_cpu_mask.png"));
    // The headline names what was graded (the candidate file, not the GL renderer), and so does
    // report.json's environment.
    EXPECT_THAT(gt::testing::read_text(folder / ("honest_" + case_name) / "index.html"),
                HasSubstr("Graded in the GPU twin's place: the candidate file "));
    EXPECT_THAT(gt::testing::read_text(folder / ("honest_" + case_name) / "report.json"),
                HasSubstr("\"graded\": \"the candidate file "));
    if (probe) {
      EXPECT_EQ(check_of(graded.report_case, "spec.phong_quad.candidate")["status"], "pass");
    }
    // A patch of a fifth of the width, 40 levels brighter, in the middle of the picture (a shading
    // bug in one tile): 4 % of the pixels, the bound 0.5 %.
    const int side = image_of(truth).spec().width / 5, corner = image_of(truth).spec().width / 2 - side / 2;
    const fs::path dark = with_pixels_changed(truth, folder / "bright.png", corner, corner, side, 40);
    graded = grade(case_name, dark, folder / ("dark_" + case_name), folder.path());
    EXPECT_EQ(graded.status, 1) << case_name;
    EXPECT_EQ(check_of(graded.report_case, "image.share_beyond_tolerance_outside_edges.candidate_vs_cpu")["status"],
              "fail")
        << case_name;
    if (probe) {
      EXPECT_EQ(check_of(graded.report_case, "spec.phong_quad.candidate")["status"], "fail");
    }
  }
}

TEST(CandidateOutputs, ImagesOfAnotherSizeOrWithoutColourExitTwo) {
  gt::testing::TemporaryFolder folder;
  OIIO::ImageBuf small(OIIO::ImageSpec(32, 64, 3, OIIO::TypeDesc::UINT8));
  ASSERT_TRUE(small.write((folder / "small.png").string()));
  OIIO::ImageBuf grey(OIIO::ImageSpec(64, 64, 1, OIIO::TypeDesc::UINT8));
  ASSERT_TRUE(grey.write((folder / "grey.png").string()));
  for (const auto& [file, message] : {std::pair{"small.png", "32 × 64 pixels where the case renders 64 × 64"},
                                      std::pair{"grey.png", "1 channels; a rendered image is RGB or RGBA"}}) {
    const Graded graded = grade("render.phong.mutant_probe.quad", folder / file, folder / "out", folder.path());
    EXPECT_EQ(graded.status, 2) << file;
    EXPECT_THAT(graded.err, HasSubstr(message));
    EXPECT_FALSE(fs::exists(folder / "out"));
  }
}

// ---- compare-mesh ------------------------------------------------------------------------------------

TEST(CompareMesh, SaysWhereTwoMeshesDifferAndColoursThem) {
  gt::testing::TemporaryFolder folder;
  const fs::path truth = reference_file(block_case, "mesh.cpu.ply", folder);
  // One vertex pulled 0.3 lattice units out along x: the farthest vertex, and the distance.
  const gt::Mesh original = gt::read_mesh(truth).mesh;
  const std::size_t moved_vertex = original.positions.size() / 2;
  const auto moved = written(changed(truth, [&](gt::Mesh& mesh) { mesh.positions[moved_vertex][0] += 0.3; }),
                             folder / "moved.ply");
  auto run = run_groundtruth({"compare-mesh", truth.string(), moved.string(), "--json", "--out", "coloured"}, folder.path());
  ASSERT_EQ(run.status, 0) << run;  // same topology, no tolerance given
  nlohmann::json out = nlohmann::json::parse(run.out);
  const auto& farthest = out["b"]["farthest_vertices"][0];
  EXPECT_EQ(farthest["vertex"], moved_vertex);
  EXPECT_GT(farthest["distance"].get<double>(), 0.0);
  EXPECT_LE(farthest["distance"].get<double>(), 0.3 + 1e-12);  // its old place is on A; rounding of the sum
  EXPECT_GE(out["hausdorff"].get<double>(), farthest["distance"].get<double>());
  EXPECT_TRUE(out["topology_differs"].empty());
  for (const char* file : {"a_to_b.ply", "b_to_a.ply"}) {
    const gt::Mesh coloured = gt::read_mesh(folder / "coloured" / file).mesh;
    EXPECT_EQ(coloured.triangles.size(), original.triangles.size()) << file;
  }
  // A tolerance below the distance: exit 1; above it: exit 0.
  run = run_groundtruth({"compare-mesh", truth.string(), moved.string(), "--tolerance", "0.01"}, folder.path());
  EXPECT_EQ(run.status, 1) << run;
  EXPECT_THAT(run.out, HasSubstr(fmt::format("farthest vertex of B from A: #{}", moved_vertex)));
  run = run_groundtruth({"compare-mesh", truth.string(), moved.string(), "--tolerance", "0.5"}, folder.path());
  EXPECT_EQ(run.status, 0) << run;
  // One triangle flipped: the topology differs (no longer watertight and oriented).
  const auto flipped = written(changed(truth, [](gt::Mesh& mesh) { std::swap(mesh.triangles[0][1], mesh.triangles[0][2]); }),
                               folder / "flipped.ply");
  run = run_groundtruth({"compare-mesh", truth.string(), flipped.string(), "--json"}, folder.path());
  EXPECT_EQ(run.status, 1) << run;
  out = nlohmann::json::parse(run.out);
  EXPECT_THAT(out["topology_differs"].dump(), HasSubstr("watertight_and_oriented"));
  // Bad input: exit 2, and --out never lands on an input.
  run = run_groundtruth({"compare-mesh", truth.string(), "missing.ply"}, folder.path());
  EXPECT_EQ(run.status, 2) << run;
  run = run_groundtruth({"compare-mesh", truth.string(), moved.string(), "--out", folder.path().string()}, folder.path());
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_TRUE(fs::exists(moved));
}

// ---- check-mesh --annotate ------------------------------------------------------------------------

TEST(CheckMesh, AnnotatesTheVerticesOfEachProblem) {
  gt::testing::TemporaryFolder folder;
  const fs::path truth = reference_file(block_case, "mesh.cpu.ply", folder);
  const gt::Mesh original = gt::read_mesh(truth).mesh;
  const auto flipped = written(changed(truth, [](gt::Mesh& mesh) { std::swap(mesh.triangles[0][1], mesh.triangles[0][2]); }),
                               folder / "flipped.ply");
  auto run = run_groundtruth({"check-mesh", flipped.string(), "--annotate", "annotated.ply"}, folder.path());
  EXPECT_EQ(run.status, 1) << run;
  // The flipped triangle's three edges are misoriented: its three corners, and only they, carry problems.
  const gt::MeshFile annotated = gt::read_mesh(folder / "annotated.ply");
  EXPECT_EQ(annotated.mesh.positions.size(), original.positions.size());
  std::ifstream file(folder / "annotated.ply", std::ios::binary);
  std::string header;
  for (std::string line; std::getline(file, line) && line != "end_header";) header += line + "\n";
  ASSERT_THAT(header, HasSubstr("property double x\nproperty double y\nproperty double z\nproperty uchar red\n"
                                 "property uchar green\nproperty uchar blue\nproperty uchar alpha\n"
                                 "property double problems\n"));
  std::vector<std::size_t> with_problems;
  for (std::size_t vertex = 0; vertex < original.positions.size(); ++vertex) {
    std::array<char, 3 * 8 + 4 + 8> record{};
    file.read(record.data(), record.size());
    double problems = 0.0;
    std::memcpy(&problems, record.data() + 3 * 8 + 4, sizeof problems);
    if (problems > 0.0) with_problems.push_back(vertex);
  }
  std::vector<std::size_t> corners(original.triangles[0].begin(), original.triangles[0].end());
  std::ranges::sort(corners);
  EXPECT_EQ(with_problems, corners);
  // Never over the mesh being checked, and only .ply.
  run = run_groundtruth({"check-mesh", flipped.string(), "--annotate", flipped.string()}, folder.path());
  EXPECT_EQ(run.status, 2) << run;
  run = run_groundtruth({"check-mesh", flipped.string(), "--annotate", "annotated.obj"}, folder.path());
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_EQ(gt::read_mesh(flipped).mesh.triangles, changed(truth, [](gt::Mesh& mesh) {
              std::swap(mesh.triangles[0][1], mesh.triangles[0][2]);
            }).triangles);
}

}  // namespace
