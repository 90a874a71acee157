// GLM's noise functions as peers of the noise twins' CPU reference.
//
// glm::simplex and glm::perlin (glm/gtc/noise.hpp) are ports of Gustavson and McEwan's GLSL
// (webgl-noise): simplex noise with permutation polynomials mod 289 instead of a table, and
// classic Perlin noise with a quintic fade. They sample the twin's own grid, origin +
// (i·step, j·step, z, w), in double like the reference (GLM's functions are templates over the
// scalar type). Fractal sums have no GLM counterpart: none is offered for them.
#include <glm/gtc/noise.hpp>
#include <glm/glm.hpp>

#include "compare/peers/peer.hpp"

namespace gt {
namespace {

template <class Function>
Peer glm_peer(NoiseBasis basis, std::string name, Function function) {
  return {std::move(name), [basis, function](const nlohmann::json& resolved, int width, int height) {
            const NoiseParams params = noise_params_from_json(basis, Fractal::none, resolved, width, height);
            return over_noise_grid(params.sampling, [function](const std::array<double, 4>& point) {
              return function(glm::dvec4(point[0], point[1], point[2], point[3]));
            });
          }};
}

}  // namespace

std::vector<Peer> glm_noise_peers(NoiseBasis basis, Fractal fractal) {
  if (fractal != Fractal::none) return {};
  const std::string version = "GLM " + std::to_string(GLM_VERSION_MAJOR) + "." + std::to_string(GLM_VERSION_MINOR) +
                              "." + std::to_string(GLM_VERSION_PATCH);
  switch (basis) {
    case NoiseBasis::simplex2:
      return {glm_peer(basis, version + " glm::simplex(dvec2)",
                       [](const glm::dvec4& p) { return glm::simplex(glm::dvec2(p)); })};
    case NoiseBasis::simplex3:
      return {glm_peer(basis, version + " glm::simplex(dvec3)",
                       [](const glm::dvec4& p) { return glm::simplex(glm::dvec3(p)); })};
    case NoiseBasis::simplex4:
      return {glm_peer(basis, version + " glm::simplex(dvec4)", [](const glm::dvec4& p) { return glm::simplex(p); })};
    case NoiseBasis::perlin3:
      return {glm_peer(basis, version + " glm::perlin(dvec3)",
                       [](const glm::dvec4& p) { return glm::perlin(glm::dvec3(p)); })};
    case NoiseBasis::perlin3_texture: return {};
  }
  return {};
}

}  // namespace gt
