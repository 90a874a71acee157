// Angular power spectrum of a field on the unit sphere and its log-log exponent (issue 13: a
// generated planet's spherical power spectrum beside the Earth's). Like a heightmap's radial spectrum
// (power_spectrum.hpp), real relief falls roughly as a power of the degree, C_l ∝ l^-β (ETOPO 1°
// gives β from 2.2 to 2.9 as the band's upper end goes from l = 10 to 128); the exponent says how
// much of a surface's relief lies in its large features and how much in the small, whatever its
// vertical unit.
//
// angular_power_spectrum(sample, nside, lmax)
//   sample(direction) -> the field at a unit direction; it is read at the 12·nside² pixel centres
//   of a HEALPix map (Górski et al. 2005, RING order) whose spherical-harmonic coefficients a_lm,
//   l, m <= lmax, HEALPix C++ takes by quadrature with 3 Jacobi iterations (map2alm_iter; Debian
//   libhealpix-cxx-dev).
//   Output: C_l = Σ_m |a_lm|² / (2l + 1) for l = 0..lmax (extract_powspec) with orthonormal Y_lm,
//   in the field's unit squared: Σ_l (2l + 1)·C_l / 4π is the field's mean square (Parseval; to the
//   quadrature's accuracy when the field is not band-limited to lmax).
//   Throws InputError for nside outside [1, 1024], lmax outside [1, 3·nside − 1] or a non-finite
//   sample.
//
// spectral_exponent(spectrum, l_low, l_high)
//   β of the least-squares line log C_l = a − β·log l over l_low <= l <= l_high.
//   Throws InputError for 1 <= l_low < l_high <= spectrum's last l not holding, or a C_l <= 0 there.
#pragma once

#include <array>
#include <functional>
#include <vector>

namespace gt {

using SphereSampler = std::function<double(const std::array<double, 3>& direction)>;

std::vector<double> angular_power_spectrum(const SphereSampler& sample, int nside, int lmax);

double spectral_exponent(const std::vector<double>& spectrum, int l_low, int l_high);

}  // namespace gt
