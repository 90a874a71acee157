// The Phong twin's bridge from the reference's scene to the GPU's draw, shared by `render.phong`
// (render_phong.cpp) and any other case that renders a reference::PhongScene on both twins (for
// example terrain renders): every field of the scene, its look and the look's parameters included.
#pragma once

#include "gpu/render/phong.hpp"
#include "reference/render/phong.hpp"

namespace gt {

// The returned draw refers to scene.mesh and scene.normals: keep `scene` alive while it is used.
gpu::PhongDraw phong_draw(const reference::PhongScene& scene);

}  // namespace gt
