// Runs the three versions of a field algorithm and measures how they agree; see field_twin.hpp.
#include "compare/field_twin.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "compare/checks/error_model.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/report/images.hpp"
#include "core/errors.hpp"
#include "core/rng.hpp"
#include "core/io/heightmap_io.hpp"
#include "compare/timing.hpp"
#include "gpu/timing.hpp"

namespace gt {
namespace {

void report_stage(const RunOptions& options, const std::string& what) {
  if (options.progress != nullptr) options.progress->stage(what);
}

struct GpuOutputs {
  Grid<float> first;
  Grid<float> second;
};

// First run gives the result, a second run from the same input checks determinism, then
// `gpu_reps` timed runs of the iterations alone (upload and download excluded).
GpuOutputs run_gpu(const FieldTwin& twin, const Grid<float>& input, const RunOptions& options, CaseResult& result) {
  report_stage(options, "gpu");
  GpuFieldRunner runner = twin.make_gpu();
  GpuOutputs outputs;
  runner.load(input);
  runner.run();
  outputs.first = runner.result();
  runner.load(input);
  runner.run();
  outputs.second = runner.result();
  if (options.gpu_reps == 0) return outputs;
  std::vector<double> times;
  for (int rep = 0; rep < options.gpu_reps; ++rep) {
    runner.load(input);
    times.push_back(gpu_wall_ms(runner.run));
  }
  result.timings.gpu_ms = median(times);
  result.timings.gpu_reps = options.gpu_reps;
  return outputs;
}

Grid<double> run_reference(const FieldTwin& twin, const Heightmap& input, const RunOptions& options,
                           CaseResult& result) {
  report_stage(options, "cpu reference (double)");
  Grid<double> output = twin.reference_double(input);  // also the warm-up run
  time_cpu(options.cpu_reps, [&] { output = twin.reference_double(input); }, result.timings);
  return output;
}

// Roundings of one float height over a run: the input's conversion to float, then every addition.
double float_roundings(const FieldTwin& twin) { return twin.additions_per_cell + 1.0; }

void add_mass_checks(const FieldTwin& twin, const Heightmap& input, const Grid<double>& cpu, const Grid<float>& cpu_float,
                     const std::optional<Grid<float>>& gpu, const RunOptions& options, CaseResult& result) {
  if (!twin.conserves_mass) return;
  const auto totals = field_totals(input);
  const auto double_bounds = mass_drift_bounds(unit_roundoff_double, twin.additions_per_cell, totals);
  const auto float_bounds = mass_drift_bounds(unit_roundoff_float, float_roundings(twin), totals);
  result.checks.push_back(bounded_check("mass.relative_drift.cpu", relative_mass_drift(input, cpu),
                                        double_bounds.strict, double_bounds.loose, double_bounds.model));
  result.checks.push_back(bounded_check("mass.relative_drift.cpu_float", relative_mass_drift(input, cpu_float),
                                        float_bounds.strict, float_bounds.loose, float_bounds.model));
  if (gpu) {
    result.checks.push_back(bounded_check("mass.relative_drift.gpu", relative_mass_drift(input, *gpu),
                                          float_bounds.strict, float_bounds.loose, float_bounds.model));
  } else {
    result.checks.push_back(skipped_check("mass.relative_drift.gpu", options.gpu_unavailable_reason));
  }
}

// κ: max |ref(h') - ref(h)| / max |h' - h| for h' = h with every valid height moved by one float
// rounding, up or down as the counter RNG says. One more run of the double reference.
double measured_amplification(const FieldTwin& twin, const Heightmap& input, const Grid<double>& cpu,
                              const RunOptions& options) {
  report_stage(options, "cpu reference (double), perturbed input");
  Heightmap perturbed = input;
  for (std::size_t i = 0; i < perturbed.size(); ++i) {
    const double direction = (random_u32(0, static_cast<std::uint32_t>(i), 0, 1) & 1u) != 0 ? 1.0 : -1.0;
    const double magnitude = std::max(std::abs(input.values[i]), double{std::numeric_limits<float>::min()});
    perturbed.values[i] += direction * unit_roundoff_float * magnitude;
  }
  const double moved = field_difference(input, perturbed).max_abs;
  const double response = field_difference(cpu, twin.reference_double(perturbed)).max_abs;
  return response / moved;
}

void add_parity_pair(const std::string& what, const FieldDifference& difference, double range, const Bounds& bounds,
                     CaseResult& result) {
  result.checks.push_back(bounded_check("parity.max_abs." + what, difference.max_abs / range, bounds.strict,
                                        bounds.loose, bounds.model));
  result.checks.push_back(
      bounded_check("parity.rms." + what, difference.rms / range, bounds.strict, bounds.loose, bounds.model));
}

void add_parity_checks(const FieldTwin& twin, const Heightmap& input, const Grid<double>& cpu,
                       const Grid<float>& cpu_float, const std::optional<GpuOutputs>& gpu, const RunOptions& options,
                       CaseResult& result) {
  const auto totals = field_totals(input);
  const bool generated = twin.generated.has_value();
  const double range = generated ? 1.0 : (totals.high > totals.low ? totals.high - totals.low : 1.0);
  const double magnitude = std::max(std::abs(totals.low), std::abs(totals.high)) / range;
  const auto logic = generated ? twin.generated->logic : parity_bounds_same_arithmetic(twin.additions_per_cell, magnitude);
  const auto precision =
      generated ? twin.generated->precision
                : parity_bounds_float_vs_double(float_roundings(twin), magnitude,
                                                measured_amplification(twin, input, cpu, options),
                                                twin.largest_switched_transfer);
  add_parity_pair("float_vs_double", field_difference(cpu, cpu_float), range, precision, result);
  if (!gpu) {
    for (const char* name : {"parity.max_abs.gpu_vs_float", "parity.rms.gpu_vs_float", "parity.max_abs.gpu_vs_double",
                             "parity.rms.gpu_vs_double", "determinism.gpu"}) {
      result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    }
    return;
  }
  add_parity_pair("gpu_vs_float", field_difference(cpu_float, gpu->first), range, logic, result);
  add_parity_pair("gpu_vs_double", field_difference(cpu, gpu->first), range, precision, result);
  const auto repeat = field_difference(gpu->first, gpu->second);
  result.checks.push_back(bounded_check("determinism.gpu", static_cast<double>(repeat.differing_bits), 0.0,
                                        std::nullopt, "cells whose bits differ between two GPU runs of the same input"));
}

template <class Real>
void add_spec_checks(const nlohmann::json& expect, const Grid<Real>& output, const std::string& backend,
                     CaseResult& result) {
  const double tolerance = expect.value("tolerance", 0.0);
  const std::string model = fmt::format("expected values from the seed's worked example; tolerance {}", tolerance);
  if (expect.contains("cells")) {
    double worst = 0.0;
    for (const auto& cell : expect["cells"]) {
      const int x = cell.at(0), y = cell.at(1);
      const double expected = cell.at(2);
      if (!output.inside(x, y)) throw InputError(fmt::format("expected cell ({}, {}) is outside the grid", x, y));
      worst = std::max(worst, std::abs(static_cast<double>(output.at(x, y)) - expected));
    }
    result.checks.push_back(bounded_check("spec.cells." + backend, worst, tolerance, std::nullopt, model));
  }
  if (expect.contains("total")) {
    const double deviation = std::abs(field_totals(output).sum - expect["total"].template get<double>());
    result.checks.push_back(bounded_check("spec.total." + backend, deviation, tolerance, std::nullopt, model));
  }
}

void add_artifact(CaseResult& result, const std::string& file, const std::string& kind, const std::string& caption) {
  result.artifacts.push_back({result.name + "/" + file, kind, caption});
}

// Input, results and the change they made, on the input's colour scale.
void write_change_pictures(const Heightmap& input, const Grid<double>& cpu, const Grid<float>& cpu_float,
                           const std::optional<GpuOutputs>& gpu, const std::filesystem::path& folder,
                           CaseResult& result) {
  const auto totals = field_totals(input);
  const double exaggeration = write_height_image(input, totals.low, totals.high, folder / "before.png");
  add_artifact(result, "before.png", "image", "input");
  write_height_image(cpu, totals.low, totals.high, folder / "after_cpu.png", exaggeration);
  add_artifact(result, "after_cpu.png", "image", "after, CPU reference (double)");
  if (gpu) {
    write_height_image(gpu->first.cast<double>(), totals.low, totals.high, folder / "after_gpu.png", exaggeration);
    add_artifact(result, "after_gpu.png", "image", "after, GPU");
  }
  const auto change = write_difference_image(input, cpu, folder / "change_cpu.png");
  add_artifact(result, "change_cpu.png", "image",
               fmt::format("after - before, CPU (red gain, blue loss; ±{:.3g} {})", change.scale_used, input.vertical_unit));
  if (gpu) {
    const auto disagreement =
        write_difference_image(cpu_float.cast<double>(), gpu->first.cast<double>(), folder / "gpu_vs_float.png");
    add_artifact(result, "gpu_vs_float.png", "image",
                 fmt::format("GPU - reference (float) (±{:.3g} {})", disagreement.scale_used, input.vertical_unit));
  }
}

// A generated field from both sides on its own colour scale, and where the GPU departs from the truth.
void write_generated_pictures(const Grid<double>& cpu, const std::optional<GpuOutputs>& gpu,
                              const std::filesystem::path& folder, CaseResult& result) {
  const auto totals = field_totals(cpu);
  const double exaggeration = write_height_image(cpu, totals.low, totals.high, folder / "cpu.png");
  add_artifact(result, "cpu.png", "image", "CPU reference (double)");
  if (!gpu) return;
  const auto gpu_values = gpu->first.cast<double>();
  write_height_image(gpu_values, totals.low, totals.high, folder / "gpu.png", exaggeration);
  add_artifact(result, "gpu.png", "image", "GPU");
  const auto disagreement = write_difference_image(cpu, gpu_values, folder / "gpu_vs_double.png");
  add_artifact(result, "gpu_vs_double.png", "image",
               fmt::format("GPU - reference (double) (±{:.3g})", disagreement.scale_used));
}

// The parameters beside a written field, so that a generated terrain is a dataset of its own.
void write_provenance(const Grid<double>& field, const std::filesystem::path& file, const CaseResult& result) {
  const nlohmann::json provenance = {
      {"case", result.name},
      {"algorithm", result.algorithm},
      {"params", result.params},
      {"input", result.input},
      {"grid", {{"width", field.width}, {"height", field.height}, {"cell_size_x", field.cell_size_x},
                {"cell_size_y", field.cell_size_y}, {"horizontal_unit", field.horizontal_unit},
                {"vertical_unit", field.vertical_unit}}}};
  std::ofstream(file) << provenance.dump(2) << '\n';
}

void write_artifacts(const FieldTwin& twin, const Heightmap& input, const Grid<double>& cpu,
                     const Grid<float>& cpu_float, const std::optional<GpuOutputs>& gpu, const RunOptions& options,
                     CaseResult& result) {
  report_stage(options, "pictures");
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  if (twin.generated) {
    write_generated_pictures(cpu, gpu, folder, result);
  } else {
    write_change_pictures(input, cpu, cpu_float, gpu, folder, result);
  }
  write_heightmap(cpu, folder / "cpu.exr");
  add_artifact(result, "cpu.exr", "field", "CPU reference (double), float32 EXR");
  write_provenance(cpu, folder / "cpu.json", result);
  add_artifact(result, "cpu.json", "field", "how cpu.exr was made: algorithm, parameters, input, grid");
  if (!gpu) return;
  write_heightmap(gpu->first.cast<double>(), folder / "gpu.exr");
  add_artifact(result, "gpu.exr", "field", "GPU, float32 EXR");
}

}  // namespace

void run_field_twin(const FieldTwin& twin, const Heightmap& input, const nlohmann::json& expect,
                    const RunOptions& options, CaseResult& result) {
  const Grid<double> cpu = run_reference(twin, input, options, result);
  report_stage(options, "cpu reference (float)");
  const Grid<float> input_float = input.cast<float>();
  const Grid<float> cpu_float = twin.reference_float(input_float);
  std::optional<GpuOutputs> gpu;
  if (options.gpu_available) {
    try {
      gpu = run_gpu(twin, input_float, options, result);
    } catch (const std::exception& error) {
      result.error = fmt::format("GPU twin failed: {}", error.what());
    }
  }
  const std::string unavailable = gpu ? "" : (result.error.empty() ? options.gpu_unavailable_reason : result.error);
  RunOptions checked_options = options;
  checked_options.gpu_unavailable_reason = unavailable;
  add_mass_checks(twin, input, cpu, cpu_float, gpu ? std::optional<Grid<float>>(gpu->first) : std::nullopt,
                  checked_options, result);
  add_parity_checks(twin, input, cpu, cpu_float, gpu, checked_options, result);
  if (expect.is_object()) {
    add_spec_checks(expect, cpu, "cpu", result);
    if (gpu) add_spec_checks(expect, gpu->first, "gpu", result);
  }
  write_artifacts(twin, input, cpu, cpu_float, gpu, options, result);
}

}  // namespace gt
