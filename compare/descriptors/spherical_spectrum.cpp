// Angular power spectrum on the sphere through HEALPix C++; see spherical_spectrum.hpp.
#include "compare/descriptors/spherical_spectrum.hpp"

#include <cmath>

#include <fmt/format.h>
#include <healpix_cxx/alm.h>
#include <healpix_cxx/alm_healpix_tools.h>
#include <healpix_cxx/alm_powspec_tools.h>
#include <healpix_cxx/healpix_map.h>
#include <healpix_cxx/powspec.h>

#include "core/errors.hpp"

namespace gt {

std::vector<double> angular_power_spectrum(const SphereSampler& sample, int nside, int lmax) {
  if (nside < 1 || nside > 1024) throw InputError(fmt::format("HEALPix nside {} outside [1, 1024]", nside));
  if (lmax < 1 || lmax > 3 * nside - 1) {
    throw InputError(fmt::format("spectrum degree {} outside [1, {}] for nside {}", lmax, 3 * nside - 1, nside));
  }
  Healpix_Map<double> map(nside, RING, SET_NSIDE);
  for (int pixel = 0; pixel < map.Npix(); ++pixel) {
    const vec3 centre = map.pix2vec(pixel);
    const double value = sample({centre.x, centre.y, centre.z});
    if (!std::isfinite(value)) throw InputError(fmt::format("a non-finite value at HEALPix pixel {}", pixel));
    map[pixel] = value;
  }
  Alm<xcomplex<double>> coefficients(lmax, lmax);
  map2alm_iter(map, coefficients, 3);
  PowSpec power(1, lmax);
  extract_powspec(coefficients, power);
  std::vector<double> spectrum(static_cast<std::size_t>(lmax) + 1);
  for (int degree = 0; degree <= lmax; ++degree) spectrum[static_cast<std::size_t>(degree)] = power.tt(degree);
  return spectrum;
}

double spectral_exponent(const std::vector<double>& spectrum, int l_low, int l_high) {
  if (l_low < 1 || l_high <= l_low || static_cast<std::size_t>(l_high) >= spectrum.size()) {
    throw InputError(fmt::format("spectral band {}..{} is not within 1..{} with two degrees or more", l_low, l_high,
                                 spectrum.size() == 0 ? 0 : spectrum.size() - 1));
  }
  double sum_x = 0.0, sum_y = 0.0, sum_xx = 0.0, sum_xy = 0.0;
  const double count = l_high - l_low + 1;
  for (int degree = l_low; degree <= l_high; ++degree) {
    const double power = spectrum[static_cast<std::size_t>(degree)];
    if (!(power > 0.0)) throw InputError(fmt::format("no positive power at degree {} to fit a slope through", degree));
    const double x = std::log(double(degree)), y = std::log(power);
    sum_x += x;
    sum_y += y;
    sum_xx += x * x;
    sum_xy += x * y;
  }
  const double slope = (count * sum_xy - sum_x * sum_y) / (count * sum_xx - sum_x * sum_x);
  return -slope;
}

}  // namespace gt
