// The cube sphere as a mesh; see sphere_mesh.hpp.
//
// Welding: a corner is a point of the integer lattice of the cube [−R, R]³ (face space (2x − R,
// R − 2y, R) through the face's signed permutation), so the corners that neighbouring faces share
// are one key, whichever face computes them; its position is computed once, from the lattice point:
// normalise(f(X/R), f(Y/R), f(Z/R)), the warp applied per axis (f is odd and f(±1) = ±1, so this is
// the face's own warp, eq. 4.3).
#include "core/planet/sphere_mesh.hpp"

#include <map>

#include "core/vec3.hpp"

#include "core/mutant.hpp"

namespace gt {

Mesh sphere_mesh(const CubeSphere& sphere, CubeWarp cube_warp) {
  const int resolution = sphere.resolution();
  Mesh mesh;
  std::map<std::array<int, 3>, std::uint32_t> welded;
  // Mutant planet.mesh.key_without_z: the weld keyed on (X, Y) alone, so corners that differ only
  // in Z are one vertex.
  const bool key_without_z = mutant_active("planet.mesh.key_without_z");
  // Mutant planet.mesh.index_after_push: a new corner's index is the vertex count once it is added
  // (one past its own), so the last corner's triangles name a vertex that does not exist.
  const std::uint32_t index_shift = mutant_active("planet.mesh.index_after_push") ? 1 : 0;
  const auto corner = [&](int face, int x, int y) {
    const FaceMatrix& matrix = face_matrix(static_cast<CubeFace>(face));
    const std::array<int, 3> face_space{2 * x - resolution, resolution - 2 * y, resolution};
    std::array<int, 3> lattice{};
    for (int row = 0; row < 3; ++row) {
      for (int column = 0; column < 3; ++column) lattice[row] += matrix[row][column] * face_space[column];
    }
    const std::array<int, 3> key{lattice[0], lattice[1], key_without_z ? 0 : lattice[2]};
    const auto [found, inserted] =
        welded.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()) + index_shift);
    if (inserted) {
      const Vec3 warped{warp(double(lattice[0]) / resolution, cube_warp), warp(double(lattice[1]) / resolution, cube_warp),
                        warp(double(lattice[2]) / resolution, cube_warp)};
      mesh.positions.push_back(normalised(warped));
    }
    return found->second;
  };
  for (int face = 0; face < cube_face_count; ++face) {
    // Mutant planet.mesh.flipped_front_face: the front face's triangles wound clockwise.
    const bool flipped = face == 0 && mutant_active("planet.mesh.flipped_front_face");
    for (int y = 0; y < resolution; ++y) {
      for (int x = 0; x < resolution; ++x) {
        // a grows rightward and b downward as seen from outside: top-left, bottom-left, bottom-right
        // is counter-clockwise.
        const std::uint32_t top_left = corner(face, x, y), top_right = corner(face, x + 1, y);
        const std::uint32_t bottom_left = corner(face, x, y + 1), bottom_right = corner(face, x + 1, y + 1);
        if (flipped) {
          mesh.triangles.push_back({top_left, bottom_right, bottom_left});
          mesh.triangles.push_back({top_left, top_right, bottom_right});
        } else {
          mesh.triangles.push_back({top_left, bottom_left, bottom_right});
          mesh.triangles.push_back({top_left, bottom_right, top_right});
        }
      }
    }
  }
  return mesh;
}

}  // namespace gt
