// Radially averaged power spectrum of a heightmap and its slope β, after Perron, Kirchner &
// Dietrich 2008 (JGR 113, F04003, "Spectral signatures of characteristic spatial scales and
// nonfractal structure in landscapes", their section on the two-dimensional DFT): detrend by the
// least-squares plane, taper with an elliptical Hann window, take the 2-D DFT, divide the DFT
// periodogram |Z|²/(Nx²·Ny²) by the window's mean square so that it sums to the variance (Parseval;
// the same as |Z|²/(Nx·Ny·W_ss) with W_ss the window's summed square), and average it over rings of
// radial frequency. Equation numbers are not quoted (not checked against the paper): the formulas
// are written out in power_spectrum.hpp instead.
// Decisions where the paper leaves room:
//   - no-data cells are set onto the fitted plane (0 after detrending) and the window's mean square
//     is taken over valid cells only (the effective taper is w·mask), so the spectrum keeps the
//     variance of the valid heights;
//   - the window's semi-axes are (N+1)/2 cells about the centre (N-1)/2, so it vanishes one cell
//     beyond each edge, not on the edge cells (the geometry of Perron's published 2DSpecTools);
//   - the spectrum is the density S = P/(Δfx·Δfy), which, unlike the periodogram P, does not depend
//     on the grid's size or spacing; coefficients are counted two-sided;
//   - bins are 1/20 decade wide on edges fixed in cycles per metre; a bin's frequency is the
//     geometric mean of its coefficients' frequencies (close to where a power law takes the bin's
//     mean), its power the arithmetic mean of their S;
//   - β is fitted one point a bin (see the header).
// Units: heights and cell sizes in one length unit (m); frequencies in cycles/m; S in m²/(cycle/m)².
#include "compare/descriptors/power_spectrum.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/memory.hpp"

namespace gt {

namespace {

// Residual RMS about the plane, relative to the largest |height|, at or below which a grid counts
// as a plane: rounding in the fit leaves about 1e-15 of the heights.
constexpr double flat_relative_rms = 1e-10;
constexpr double band_low_cycles_per_side = 4.0;
constexpr double band_high_cells_per_wavelength = 8.0;

// FFTW's planner is not thread-safe (its execute is): plans are made and destroyed under this lock.
std::mutex fftw_planner_mutex;

struct FftwFree {
  void operator()(void* memory) const { fftw_free(memory); }
};

struct FftwPlanDestroy {
  void operator()(fftw_plan plan) const {
    const std::lock_guard lock(fftw_planner_mutex);
    fftw_destroy_plan(plan);
  }
};

using FftwPlan = std::unique_ptr<std::remove_pointer_t<fftw_plan>, FftwPlanDestroy>;

template <class T>
std::unique_ptr<T[], FftwFree> fftw_array(std::size_t count) {
  auto* memory = static_cast<T*>(fftw_malloc(sizeof(T) * count));
  if (memory == nullptr) throw std::bad_alloc();
  return std::unique_ptr<T[], FftwFree>(memory);
}

void check_spectrum_input(const Heightmap& dem) {
  if (dem.width < spectrum_min_side || dem.height < spectrum_min_side) {
    throw InputError(fmt::format("too small for a spectrum: the grid is {}x{} cells, at least {}x{} needed",
                                 dem.width, dem.height, spectrum_min_side, spectrum_min_side));
  }
  check_cell_size(dem, "power spectrum");
  check_finite(dem, "power spectrum");
  const double cells = static_cast<double>(dem.width) * static_cast<double>(dem.height);
  const double coefficients = static_cast<double>(dem.height) * static_cast<double>(dem.width / 2 + 1);
  require_memory(memory_for(cells, "real cells", sizeof(double)) +
                     memory_for(coefficients, "complex coefficients", sizeof(std::complex<double>)),
                 fmt::format("power spectrum ({}x{})", dem.width, dem.height));
}

// z = mean_z + slope_x·(x - mean_x) + slope_y·(y - mean_y) in cell indices, by least squares over
// the valid cells (centred sums keep the normal equations well conditioned).
struct Plane {
  double mean_x = 0.0, mean_y = 0.0, mean_z = 0.0;
  double slope_x = 0.0, slope_y = 0.0;
  double largest_abs_height = 0.0;
  std::size_t valid_cells = 0;

  double at(int x, int y) const { return mean_z + slope_x * (x - mean_x) + slope_y * (y - mean_y); }
};

Plane valid_means(const Heightmap& dem) {
  Plane plane;
  for (int y = 0; y < dem.height; ++y) {
    for (int x = 0; x < dem.width; ++x) {
      if (!dem.is_valid(x, y)) continue;
      plane.mean_x += x;
      plane.mean_y += y;
      plane.mean_z += dem.at(x, y);
      plane.largest_abs_height = std::max(plane.largest_abs_height, std::abs(dem.at(x, y)));
      ++plane.valid_cells;
    }
  }
  if (plane.valid_cells == 0) throw InputError("power spectrum: no valid cell");
  const double n = static_cast<double>(plane.valid_cells);
  plane.mean_x /= n;
  plane.mean_y /= n;
  plane.mean_z /= n;
  return plane;
}

Plane least_squares_plane(const Heightmap& dem) {
  Plane plane = valid_means(dem);
  double sxx = 0.0, sxy = 0.0, syy = 0.0, sxz = 0.0, syz = 0.0;
  for (int y = 0; y < dem.height; ++y) {
    for (int x = 0; x < dem.width; ++x) {
      if (!dem.is_valid(x, y)) continue;
      const double dx = x - plane.mean_x, dy = y - plane.mean_y, dz = dem.at(x, y) - plane.mean_z;
      sxx += dx * dx;
      sxy += dx * dy;
      syy += dy * dy;
      sxz += dx * dz;
      syz += dy * dz;
    }
  }
  const double determinant = sxx * syy - sxy * sxy;
  if (!(determinant > 1e-9 * sxx * syy)) {
    throw InputError(fmt::format("power spectrum: the {} valid cells lie on one line, which fixes no plane to "
                                 "detrend by", plane.valid_cells));
  }
  plane.slope_x = (syy * sxz - sxy * syz) / determinant;
  plane.slope_y = (sxx * syz - sxy * sxz) / determinant;
  return plane;
}

// The elliptical Hann window at cell (x, y) (header, step 3).
double hann_weight(const Heightmap& dem, int x, int y) {
  const double u = (x - 0.5 * (dem.width - 1)) / (0.5 * (dem.width + 1));
  const double v = (y - 0.5 * (dem.height - 1)) / (0.5 * (dem.height + 1));
  const double rho = std::sqrt(u * u + v * v);
  return rho < 1.0 ? 0.5 * (1.0 + std::cos(std::numbers::pi * rho)) : 0.0;
}

struct WindowedResiduals {
  std::size_t masked_cells = 0;
  double residual_sum_squares = 0.0;  // of the un-windowed residuals over valid cells
  double window_sum_squares = 0.0;    // Σ w² over valid cells
};

// Writes w·(z - plane) into `real` (row-major, 0 at no-data cells).
WindowedResiduals fill_windowed_residuals(const Heightmap& dem, const Plane& plane, bool hann_window, double* real) {
  WindowedResiduals out;
  for (int y = 0; y < dem.height; ++y) {
    for (int x = 0; x < dem.width; ++x) {
      const std::size_t i = dem.index(x, y);
      if (!dem.is_valid(i)) {
        real[i] = 0.0;
        ++out.masked_cells;
        continue;
      }
      const double residual = dem.values[i] - plane.at(x, y);
      const double weight = hann_window ? hann_weight(dem, x, y) : 1.0;
      real[i] = weight * residual;
      out.residual_sum_squares += residual * residual;
      out.window_sum_squares += weight * weight;
    }
  }
  return out;
}

void refuse_a_plane(const Plane& plane, const WindowedResiduals& residuals) {
  const double rms = std::sqrt(residuals.residual_sum_squares / static_cast<double>(plane.valid_cells));
  if (rms <= flat_relative_rms * plane.largest_abs_height) {
    throw InputError(fmt::format("power spectrum: no relief about the least-squares plane (residual RMS {:.3g} "
                                 "for heights up to {:.3g}): a plane has no spectrum",
                                 rms, plane.largest_abs_height));
  }
}

void refuse_an_empty_window(const WindowedResiduals& residuals) {
  if (residuals.window_sum_squares > 0.0) return;
  throw InputError("power spectrum: every valid cell lies outside the elliptical window (only corners are valid)");
}

// The r2c DFT of the Ny × Nx row-major `real`: Ny × (Nx/2 + 1) coefficients, x halved.
std::unique_ptr<std::complex<double>[], FftwFree> forward_dft(int width, int height, double* real) {
  const std::size_t count = static_cast<std::size_t>(height) * static_cast<std::size_t>(width / 2 + 1);
  auto coefficients = fftw_array<std::complex<double>>(count);
  FftwPlan plan;
  {
    const std::lock_guard lock(fftw_planner_mutex);
    plan.reset(fftw_plan_dft_r2c_2d(height, width, real, reinterpret_cast<fftw_complex*>(coefficients.get()),
                                    FFTW_ESTIMATE));
  }
  if (!plan) throw std::runtime_error("power spectrum: FFTW made no plan");
  fftw_execute(plan.get());
  return coefficients;
}

// Bin k holds 10^(k/B) <= f < 10^((k+1)/B), B = spectrum_bins_per_decade.
int bin_index(double frequency) {
  return static_cast<int>(std::floor(spectrum_bins_per_decade * std::log10(frequency)));
}

double bin_edge(int index) { return std::pow(10.0, static_cast<double>(index) / spectrum_bins_per_decade); }

struct Bin {
  double power_sum = 0.0;
  double log_frequency_sum = 0.0;
  int coefficients = 0;
};

RadialSpectrum to_spectrum(const std::map<int, Bin>& bins, std::size_t masked_cells) {
  RadialSpectrum spectrum;
  spectrum.masked_cells = masked_cells;
  for (const auto& [index, bin] : bins) {
    spectrum.frequency_per_m.push_back(std::exp(bin.log_frequency_sum / bin.coefficients));
    spectrum.power.push_back(bin.power_sum / bin.coefficients);
    spectrum.coefficients.push_back(bin.coefficients);
  }
  return spectrum;
}

// Averages S = |Z|²·dx·dy / Σ_valid w² (header, step 5) over the bins of radial frequency. Column i
// of the half spectrum stands for i and -i, except 0 and the Nyquist column of an even width.
std::map<int, Bin> radial_bins(const Heightmap& dem, const std::complex<double>* coefficients,
                               double window_sum_squares) {
  const int half_width = dem.width / 2 + 1;
  const double length_x = dem.width * dem.cell_size_x, length_y = dem.height * dem.cell_size_y;
  const double density_scale = dem.cell_size_x * dem.cell_size_y / window_sum_squares;
  std::map<int, Bin> bins;
  for (int j = 0; j < dem.height; ++j) {
    const int signed_j = 2 * j <= dem.height ? j : j - dem.height;
    const double frequency_y = signed_j / length_y;
    for (int i = 0; i < half_width; ++i) {
      if (i == 0 && j == 0) continue;
      const int twins = (i == 0 || 2 * i == dem.width) ? 1 : 2;
      const double frequency = std::hypot(i / length_x, frequency_y);
      const double density = std::norm(coefficients[static_cast<std::size_t>(j) * half_width + i]) * density_scale;
      Bin& bin = bins[bin_index(frequency)];
      bin.power_sum += twins * density;
      bin.log_frequency_sum += twins * std::log(frequency);
      bin.coefficients += twins;
    }
  }
  return bins;
}

}  // namespace

RadialSpectrum radial_power_spectrum(const Heightmap& dem, const SpectrumOptions& options) {
  check_spectrum_input(dem);
  const Plane plane = least_squares_plane(dem);
  auto real = fftw_array<double>(dem.size());
  const WindowedResiduals residuals = fill_windowed_residuals(dem, plane, options.hann_window, real.get());
  refuse_a_plane(plane, residuals);
  refuse_an_empty_window(residuals);
  const auto coefficients = forward_dft(dem.width, dem.height, real.get());
  return to_spectrum(radial_bins(dem, coefficients.get(), residuals.window_sum_squares), residuals.masked_cells);
}

std::optional<SpectralSlope> spectral_slope(const RadialSpectrum& spectrum, double low_frequency_per_m,
                                            double high_frequency_per_m) {
  std::vector<double> log_frequency, log_power;
  for (std::size_t i = 0; i < spectrum.frequency_per_m.size(); ++i) {
    const double frequency = spectrum.frequency_per_m[i];
    const int bin = bin_index(frequency);
    const bool inside = bin_edge(bin) >= low_frequency_per_m && bin_edge(bin + 1) <= high_frequency_per_m;
    if (!inside || !(spectrum.power[i] > 0.0)) continue;
    log_frequency.push_back(std::log10(frequency));
    log_power.push_back(std::log10(spectrum.power[i]));
  }
  const auto fit = fit_line(log_frequency, log_power);
  if (!fit) return std::nullopt;
  return SpectralSlope{-fit->slope, *fit, low_frequency_per_m, high_frequency_per_m};
}

std::pair<double, double> default_spectral_band(const Heightmap& dem) {
  const double shorter_side = std::min(dem.width * dem.cell_size_x, dem.height * dem.cell_size_y);
  const double coarser_cell = std::max(dem.cell_size_x, dem.cell_size_y);
  return {band_low_cycles_per_side / shorter_side, 1.0 / (band_high_cells_per_wavelength * coarser_cell)};
}

}  // namespace gt
