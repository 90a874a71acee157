// The Phong twin's bridge from the reference's scene to the GPU's draw, shared by `render.phong`
// (render_phong.cpp) and any other case that renders a reference::PhongScene on both twins (for
// example terrain renders): every field of the scene, its look and the look's parameters included;
// and the parameters of a `render.phong` case.
#pragma once

#include <array>

#include "core/param_table.hpp"
#include "gpu/render/phong.hpp"
#include "reference/render/cave_look.hpp"
#include "reference/render/phong.hpp"

namespace gt {

// The returned draw refers to scene.mesh and scene.normals: keep `scene` alive while it is used.
gpu::PhongDraw phong_draw(const reference::PhongScene& scene);

// The parameters of a render.phong case (render_phong.cpp says what each does) and their
// declarations (core/param_table.hpp). Lengths in the mesh's units.
struct PhongRenderParams {
  int width = 256;  // pixels
  int height = 256;
  double fov_deg = 40.0;
  bool fixed_camera = false;  // camera = fixed (eye, target, near, far), else orbit
  double azimuth_deg = 30.0;
  double elevation_deg = 20.0;
  reference::Vec3 eye{0.0, 0.0, 0.0};
  reference::Vec3 target{0.0, 0.0, -1.0};
  double near = 0.1;
  double far = 200.0;
  int subpixel_bits = 8;
  reference::Look look = reference::Look::plain;
  double light_power = 0.0;  // 0: automatic
  double min_covered_share = 0.0;
  reference::CaveLook cave;        // the cave look's noises and moss (its colour strip is the scene's)
  reference::Vec3 up{0.0, 1.0, 0.0};  // the terrain look's height axis
  reference::TerrainLook terrain;  // the terrain look's rock slopes
  bool quad = false;               // generated = quad, else the seed's cave
  std::array<int, 3> block_origin{-24, -24, -24};  // of the generated cave, lattice units
  std::array<int, 3> block_size{48, 48, 48};
  reference::CaveNormals normals = reference::CaveNormals::analytic;  // of the generated cave's vertices
};
const ParamTable<PhongRenderParams>& phong_render_param_table();

}  // namespace gt
