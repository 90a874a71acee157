// libnoise 1.0 (Debian libnoise-dev) as a peer of the noise twins' CPU reference.
//
// noise.perlin3 <- noise::GradientCoherentNoise3D at QUALITY_BEST: Perlin's gradient noise with
//   the quintic fade of improved noise, but libnoise's own integer hash and gradient table.
// noise.fbm     <- noise::module::Perlin: a sum of octaves of that noise with the fbm's octave
//   count (libnoise takes whole octaves only: a fractional count has no peer), lacunarity and
//   gain as persistence; libnoise does not divide by the sum of weights (one multiplication).
// Both in double at the twin's own sample points, origin + (i·step, j·step, z).
#include <cmath>
#include <stdexcept>

#include <libnoise/noise.h>

#include "compare/peers/peer.hpp"

namespace gt {
namespace {

constexpr const char* version = "libnoise 1.0";

Peer gradient_noise_peer() {
  return {std::string(version) + " GradientCoherentNoise3D (QUALITY_BEST, double)",
          [](const nlohmann::json& resolved, int width, int height) {
            const NoiseParams params = noise_params_from_json(NoiseBasis::perlin3, Fractal::none, resolved, width, height);
            return over_noise_grid(params.sampling, [](const std::array<double, 4>& point) {
              return noise::GradientCoherentNoise3D(point[0], point[1], point[2], 0, noise::QUALITY_BEST);
            });
          }};
}

Peer fbm_peer() {
  return {std::string(version) + " module::Perlin (QUALITY_BEST, double)",
          [](const nlohmann::json& resolved, int width, int height) -> std::function<void()> {
            const NoiseParams params = noise_params_from_json(NoiseBasis::perlin3, Fractal::fbm, resolved, width, height);
            const auto& fractal = params.fractal_params;
            if (fractal.octaves != std::floor(fractal.octaves) || fractal.octaves > noise::module::PERLIN_MAX_OCTAVE) {
              throw std::invalid_argument("libnoise takes whole octave counts up to 30");
            }
            auto module = std::make_shared<noise::module::Perlin>();
            module->SetFrequency(1.0);
            module->SetOctaveCount(static_cast<int>(fractal.octaves));
            module->SetLacunarity(fractal.lacunarity);
            module->SetPersistence(fractal.gain);
            module->SetNoiseQuality(noise::QUALITY_BEST);
            return over_noise_grid(params.sampling, [module](const std::array<double, 4>& point) {
              return module->GetValue(point[0], point[1], point[2]);
            });
          }};
}

}  // namespace

std::vector<Peer> libnoise_peers(NoiseBasis basis, Fractal fractal) {
  if (basis == NoiseBasis::perlin3 && fractal == Fractal::none) return {gradient_noise_peer()};
  if (basis == NoiseBasis::perlin3 && fractal == Fractal::fbm) return {fbm_peer()};
  return {};
}

}  // namespace gt
