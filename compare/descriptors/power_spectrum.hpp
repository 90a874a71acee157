// Radially averaged power spectrum of a heightmap and its log-log slope β (issue 16), after Perron,
// Kirchner & Dietrich 2008: real topography follows S(f) ∝ f^-β with β ≈ 2 over a wide band; eroded
// terrain rolls off below the hillslope length.
//
// radial_power_spectrum(dem, options)
//   Input: a heightmap of at least 16×16 cells, heights and cell sizes in one length unit (called
//   metres below: "per_m" reads "per horizontal unit" for other units), cell_size_x != cell_size_y
//   allowed, no-data cells allowed.
//   Steps, on the Nx × Ny grid (Nx = width, Ny = height):
//     1. subtract the least-squares plane z = a + b·x + c·y fitted over the valid cells;
//     2. set no-data cells to 0, that is onto the plane (their stored values are never read);
//     3. multiply by the elliptical Hann window w = ½(1 + cos πρ) for ρ < 1, else 0, where
//        ρ² = ((x - (Nx-1)/2) / ((Nx+1)/2))² + ((y - (Ny-1)/2) / ((Ny+1)/2))² (cell indices):
//        centred on the grid, reaching 0 one cell beyond each edge;
//     4. Z(i, j): the 2-D DFT of the windowed grid (FFTW, r2c);
//     5. the periodogram P(i, j) = |Z|² / (Nx²·Ny²·W2), W2 = Σ_valid w² / (Nx·Ny): the DFT
//        periodogram divided by the mean square of the effective window w·mask, so that it sums to
//        the variance of the detrended valid heights (exactly without the window, in expectation with
//        it); the power spectral density S = P·(Nx·dx)·(Ny·dy) = P / (Δfx·Δfy);
//     6. averaging S over the coefficients of each radial-frequency bin.
//   Output: RadialSpectrum (below). Frequencies: fx = i/(Nx·dx), fy = j/(Ny·dy) with i, j the
//   signed DFT indices in (-N/2, N/2], f = sqrt(fx² + fy²) in cycles per metre. Coefficients are
//   counted over the whole two-sided spectrum (a coefficient and its conjugate twin count as two);
//   the zero-frequency one is left out. Bin k holds the coefficients with
//   10^(k/20) <= f < 10^((k+1)/20): 20 bins a decade, on edges fixed in cycles per metre so that
//   spectra of different grids share bins. Only bins with at least one coefficient are listed.
//   Parseval: Σ_bins power·coefficients·Δfx·Δfy = variance of the valid heights about their plane,
//   exactly when hann_window is false (Δfx = 1/(Nx·dx), Δfy = 1/(Ny·dy)).
//   Throws InputError: a grid under 16 cells on a side ("too small for a spectrum: ..."), a bad
//   cell size, a NaN or infinite valid height, valid cells that fix no plane (fewer than three, or
//   all on one line), heights without relief about their plane (a plane: residual RMS at most
//   1e-10 of the largest |height|), valid cells all outside the window (only corners valid), or a
//   transform that does not fit in memory (core/memory.hpp).
//   Thread-safe (FFTW's planner is serialised).
//
// spectral_slope(spectrum, low, high)
//   β = -slope of the least-squares line log10 S = intercept - β·log10 f through the bins that lie
//   wholly inside [low, high] (both edges) and have positive power: one point a bin, so that each
//   interval of log-frequency weighs the same (a point per coefficient would give the top octave of
//   a band three quarters of the weight). Whole bins only: a bin cut by the band's edge may hold a
//   single ring of 4 coefficients (4 cycles across a square grid is one). std::nullopt when fewer
//   than two bins qualify (an empty or inverted band included).
//   The few coefficients of the band's lowest bins dominate β's uncertainty: on one 256×256
//   fractal surface it is about 0.2 (one standard deviation; tests/descriptors_spectrum_test.cpp
//   bounds it by 0.25), and it shrinks as the band gains octaves on larger grids.
//
// default_spectral_band(dem)
//   [4 / min(Nx·dx, Ny·dy), 1 / (8·max(dx, dy))] cycles per metre: from 4 cycles across the shorter
//   side (below it the window's main lobe, ±2 coefficients wide, and the removed plane mix the few
//   lowest coefficients, and bins hold only a handful of them) to a quarter of the lower Nyquist
//   frequency, wavelengths of 8 cells (above it gridding and interpolation smooth a DEM, power
//   beyond Nyquist aliases back, and bins past the lower Nyquist are no longer whole rings). The
//   band holds no bin (low >= high) unless the limiting side exceeds 32 cells.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "compare/descriptors/fit.hpp"
#include "core/grid.hpp"

namespace gt {

constexpr int spectrum_min_side = 16;
constexpr int spectrum_bins_per_decade = 20;

struct SpectrumOptions {
  // false: no window (the plain DFT periodogram, for Parseval checks; leaks at the grid's edges).
  bool hann_window = true;
};

struct RadialSpectrum {
  std::vector<double> frequency_per_m;  // ascending; geometric mean of the bin's coefficients' f
  std::vector<double> power;            // mean S of the bin's coefficients, m² per (cycle/m)² (m⁴)
  std::vector<int> coefficients;        // coefficients averaged in the bin (>= 1)
  std::size_t masked_cells = 0;         // no-data cells set onto the plane
};

struct SpectralSlope {
  double beta = 0.0;
  LineFit fit;  // log10(power) against log10(frequency_per_m); fit.slope = -beta
  double low_frequency_per_m = 0.0;
  double high_frequency_per_m = 0.0;
};

RadialSpectrum radial_power_spectrum(const Heightmap& dem, const SpectrumOptions& options = {});

std::optional<SpectralSlope> spectral_slope(const RadialSpectrum& spectrum, double low_frequency_per_m,
                                            double high_frequency_per_m);

std::pair<double, double> default_spectral_band(const Heightmap& dem);

}  // namespace gt
