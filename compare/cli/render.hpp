// `groundtruth render INPUT --out out.png [--backend cpu|gpu] [--width W --height H]
//  [--azimuth A --elevation E --fov F --distance K | --eye X,Y,Z --target X,Y,Z] [--look L]
//  [--vertical-scale S] [--cell-size C] [--image-vertical-scale V] [--gl egl|osmesa]`:
// a mesh or a heightmap Phong-shaded to a PNG by the reference rasterizer (cpu, exact, slow) or the
// GL pipeline (gpu), the twins of reference/render/phong.hpp and gpu/render/phong.hpp.
//
// Input: by extension, .off .obj .ply .stl are meshes (core/io/mesh_io.hpp, as they are); anything
//   else is a heightmap (core/io/heightmap_io.hpp: PNG, TIFF/GeoTIFF, EXR, volcano JSON, npz),
//   meshed as a closed terrain solid (reference/render/terrain_solid.hpp: x east, y up, z south,
//   metres; its heights times vertical_scale; cell_size overrides the file's, and
//   image_vertical_scale gives 8/16-bit images their height range).
// Camera (right-handed world, +y up; c and r the centre and half diagonal of the mesh's bounding
//   box):
//   orbit (default)  eye = c + K·r·(cos e·sin a, sin e, cos e·cos a) for azimuth a (from +z towards
//                    +x), elevation e and distance K, looking at c; K = 0 (the default) fits the
//                    bounding sphere in the narrower field of view: K = 1/sin(half of it) (2.5 is
//                    render.phong's and render.terrain's orbit_camera)
//   free             --eye and --target, both or neither
//   up = +y (or -z, north, when the view is vertical); vertical field of view F; near and far
//   bracket the bounding sphere: far = 2(d + r), near = max((d - r)/2, far/1000), d = |eye - c|.
// Look: auto (terrain for heightmaps, with the ramp from the lowest to the highest surface height;
//   plain for meshes), plain, terrain (ramp over the mesh's y extent for meshes) or cave (seed 004's
//   colour strip, moss and bump, in the mesh's units).
// Output: a PNG of W x H pixels (RGB8, background black), written under a temporary name in the
//   target's folder and renamed into place; a path that names the input is refused. A line on
//   stdout says what was drawn: size, backend (and GL renderer), look, the share of covered pixels,
//   the mesh and the camera.
// Returns the exit status: 0 written; 2, with the reason on stderr as "groundtruth: ..." and nothing
//   written, for: an unreadable or empty mesh or heightmap (no faces, no 2x2 block of valid
//   samples, NaN heights), a camera inside a closed mesh (the generalised winding number of the
//   mesh at the eye, Σ solid angles / 4π, is >= 1/2: it would see only the back faces; an inward-
//   facing mesh such as a room seen from inside has -1 and is drawn), a camera that sees nothing
//   (no pixel centre covered by the reference rasterizer's coverage of the scene), sizes outside
//   [1, 16384], an unusable camera (eye at target, field of view outside (0, 180)), an output that
//   is not a .png in an existing folder or that names the input, and no GL context for --backend gpu.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gt {

struct RenderOptions {
  std::filesystem::path input, out;
  std::string backend = "cpu";   // cpu | gpu
  std::string gl = "egl";        // egl | osmesa, for gpu
  int width = 512, height = 512;
  double azimuth_deg = 35.0, elevation_deg = 35.0, fov_deg = 35.0;
  double distance = 0.0;         // orbit distance in bounding-box half diagonals; 0: fit the view
  std::vector<double> eye, target;  // free camera: three coordinates each, or both empty
  std::string look = "auto";     // auto | plain | terrain | cave
  double vertical_scale = 1.0;   // heightmaps: multiplies heights
  double cell_size = 0.0;        // heightmaps: overrides the file's cell size when > 0
  double image_vertical_scale = 1.0;  // heightmaps: metres per unit of 8/16-bit images
};

int render_command(const RenderOptions& options);

}  // namespace gt
