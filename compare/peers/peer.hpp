// Peers: other libraries' implementations of a twin's work, timed beside it in the performance
// table on the same input and thread count (issue 17), marked as peers there. Each peer's file
// says what it computes and how that differs from our twin (the outputs are not compared: a peer
// is the same kind of work, not the same function).
//
// Peer::prepare(resolved, width, height) -> the work to time: the peer evaluated over the
//   width × height grid the twin's resolved parameters lay out. The returned callable writes into
//   storage it owns, so the compiler cannot drop the work.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/params/noise.hpp"

namespace gt {

struct Peer {
  std::string name;  // library, version, function and precision, e.g. "GLM 0.9.9 glm::simplex(dvec3)"
  std::function<std::function<void()>(const nlohmann::json& resolved, int width, int height)> prepare;
};

// The work of evaluating function(point) at every sample of a noise grid, point = origin +
// (i·step, j·step, 0, 0) in double, into storage the returned callable owns. A template, so that
// the peer's call is inlined as the reference's own is.
template <class Function>
std::function<void()> over_noise_grid(const NoiseSampling& sampling, Function function) {
  auto values = std::make_shared<std::vector<double>>(static_cast<std::size_t>(sampling.width) * sampling.height);
  return [sampling, values, function] {
    for (int j = 0; j < sampling.height; ++j) {
      for (int i = 0; i < sampling.width; ++i) {
        const std::array<double, 4> point = {sampling.origin[0] + i * sampling.step,
                                             sampling.origin[1] + j * sampling.step, sampling.origin[2],
                                             sampling.origin[3]};
        (*values)[static_cast<std::size_t>(j) * sampling.width + i] = function(point);
      }
    }
  };
}

// GLM's Gustavson ports (glm/gtc/noise.hpp): glm::simplex for simplex2/3/4, glm::perlin for perlin3.
std::vector<Peer> glm_noise_peers(NoiseBasis basis, Fractal fractal);

// libnoise (Debian libnoise-dev): GradientCoherentNoise3D for perlin3, module::Perlin for fbm.
std::vector<Peer> libnoise_peers(NoiseBasis basis, Fractal fractal);

}  // namespace gt
