// Runs the three versions of a generated field and measures how they agree; see field_twin.hpp.
#include "compare/field_twin.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "compare/case_descriptors.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/field_files.hpp"
#include "compare/report/images.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "gpu/timing.hpp"

namespace gt {
namespace {

void report_stage(const RunOptions& options, const std::string& what) {
  if (options.progress != nullptr) options.progress->stage(what);
}

struct ReferenceRuns {
  Grid<double> cpu;       // ref<double>
  Grid<float> cpu_float;  // ref<float>
};

struct GpuOutputs {
  Grid<float> first;   // the result compared
  Grid<float> second;  // a second run, for determinism
  std::string backend = "gpu";  // the check and file name part: gpu, or candidate (a user's file)
  std::string label = "GPU";
  // A candidate's values as the file holds them, and whether they are double: a double field is
  // graded against ref<double> alone (the float logic bound is float arithmetic's).
  Grid<double> values;
  bool double_precision = false;
  bool repeated = true;  // determinism is measured (a file is read once: not applicable)
};

// A user's field file (run --candidate) in the GPU's place.
GpuOutputs candidate_outputs(const CandidateField& candidate) {
  GpuOutputs outputs;
  outputs.backend = "candidate";
  outputs.label = "candidate " + candidate.file.filename().string();
  outputs.values = candidate.values;
  outputs.first = candidate.values.cast<float>();
  outputs.second = outputs.first;
  outputs.double_precision = candidate.double_precision;
  outputs.repeated = false;
  return outputs;
}

// First run gives the result, a second from the same input checks determinism, then `gpu_reps`
// timed runs (upload and download excluded).
GpuOutputs run_gpu(const FieldTwin& twin, const Grid<float>& grid, const RunOptions& options, CaseResult& result) {
  report_stage(options, "gpu");
  GpuFieldRunner runner = twin.make_gpu();
  GpuOutputs outputs;
  runner.load(grid);
  runner.run();
  outputs.first = runner.result();
  outputs.values = outputs.first.cast<double>();
  runner.load(grid);
  runner.run();
  outputs.second = runner.result();
  if (options.gpu_reps == 0) return outputs;
  std::vector<double> times;
  for (int rep = 0; rep < options.gpu_reps; ++rep) {
    runner.load(grid);
    times.push_back(gpu_wall_ms(runner.run));
  }
  result.timings.gpu_ms = median(times);
  result.timings.gpu_reps = options.gpu_reps;
  return outputs;
}

// ref<double> timed (its first run is the warm-up), then ref<float>.
ReferenceRuns run_references(const FieldTwin& twin, const Heightmap& grid, const RunOptions& options,
                             CaseResult& result) {
  ReferenceRuns runs;
  report_stage(options, "cpu reference (double)");
  runs.cpu = twin.reference_double(grid);
  time_cpu(options.cpu_reps, [&] { runs.cpu = twin.reference_double(grid); }, result.timings);
  report_stage(options, "cpu reference (float)");
  runs.cpu_float = twin.reference_float(grid.cast<float>());
  return runs;
}

void add_parity_pair(const std::string& what, const FieldDifference& difference, const Bounds& bounds,
                     CaseResult& result) {
  result.checks.push_back(
      bounded_check("parity.max_abs." + what, difference.max_abs, bounds.strict, bounds.loose, bounds.model));
  result.checks.push_back(bounded_check("parity.rms." + what, difference.rms, bounds.strict, bounds.loose, bounds.model));
}

void add_determinism_check(const GpuOutputs& gpu, CaseResult& result) {
  if (!gpu.repeated) {
    result.checks.push_back(not_applicable_check("determinism." + gpu.backend, "a file is read once: nothing to repeat"));
    return;
  }
  const auto repeat = field_difference(gpu.first, gpu.second);
  result.checks.push_back(bounded_check("determinism.gpu", static_cast<double>(repeat.differing_bits), 0.0,
                                        std::nullopt, "cells whose bits differ between two GPU runs of the same grid"));
}

const char* const gpu_parity_names[] = {"parity.max_abs.gpu_vs_float", "parity.rms.gpu_vs_float",
                                        "parity.max_abs.gpu_vs_double", "parity.rms.gpu_vs_double", "determinism.gpu"};

// ref<double>'s field without the samples the precision bounds leave out, and those bounds saying so.
struct PrecisionTruth {
  Grid<double> field;
  Bounds bounds;
};

PrecisionTruth precision_truth(const FieldTwin::GeneratedField& declared, const Grid<double>& truth) {
  PrecisionTruth kept{truth, declared.precision};
  const auto& excused = declared.precision_excused;
  const auto left_out =
      static_cast<std::size_t>(std::count_if(excused.begin(), excused.end(), [](std::uint8_t mark) { return mark != 0; }));
  if (left_out == 0) return kept;
  if (!kept.field.has_mask()) kept.field.valid.assign(kept.field.size(), 1);
  for (std::size_t sample = 0; sample < excused.size(); ++sample) {
    if (excused[sample] != 0) kept.field.valid[sample] = 0;
  }
  kept.bounds.model += fmt::format("; {} of {} samples left out, {}", left_out, truth.size(), declared.precision_excused_why);
  return kept;
}

// The whole output against the bounds the twin declares.
void add_parity(const FieldTwin& twin, const ReferenceRuns& runs, const std::optional<GpuOutputs>& gpu,
                const std::string& unavailable, CaseResult& result) {
  const PrecisionTruth truth = precision_truth(twin.bounds, runs.cpu);
  add_parity_pair("float_vs_double", field_difference(truth.field, runs.cpu_float), truth.bounds, result);
  if (!gpu) {
    for (const char* name : gpu_parity_names) result.checks.push_back(skipped_check(name, unavailable));
    return;
  }
  const std::string& backend = gpu->backend;
  if (gpu->double_precision) {
    const auto difference = field_difference(runs.cpu_float.cast<double>(), gpu->values);
    const std::string why = "a double field against ref<float>: the float reference's own rounding; informative";
    result.checks.push_back(informative_check("parity.max_abs." + backend + "_vs_float", difference.max_abs, why));
    result.checks.push_back(informative_check("parity.rms." + backend + "_vs_float", difference.rms, why));
  } else {
    add_parity_pair(backend + "_vs_float", field_difference(runs.cpu_float, gpu->first), twin.bounds.logic, result);
  }
  add_parity_pair(backend + "_vs_double", field_difference(truth.field, gpu->values), truth.bounds, result);
  add_determinism_check(*gpu, result);
}

// The field from both sides on its own colour scale, and where the GPU departs from the truth.
void write_pictures(const Grid<double>& cpu, const std::optional<GpuOutputs>& gpu, const std::filesystem::path& folder,
                    CaseResult& result) {
  const auto totals = field_totals(cpu);
  const double exaggeration = write_height_image(cpu, totals.low, totals.high, folder / "cpu.png");
  const ColourScale values = height_scale(totals.low, totals.high, "1");
  add_picture(result, "cpu.png", "CPU reference (double)", values);
  if (!gpu) return;
  write_height_image(gpu->values, totals.low, totals.high, folder / (gpu->backend + ".png"), exaggeration);
  add_picture(result, gpu->backend + ".png", gpu->label, values);
  const std::string difference_file = gpu->backend + "_vs_double.png";
  const auto disagreement = write_difference_image(cpu, gpu->values, folder / difference_file);
  add_picture(result, difference_file, gpu->label + " - reference (double)", difference_scale(disagreement, "1"));
}

// A generator's output is a dimensionless value.
void write_artifacts(const ReferenceRuns& runs, const std::optional<GpuOutputs>& gpu, const RunOptions& options,
                     CaseResult& result) {
  report_stage(options, "pictures");
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  if (options.pictures) write_pictures(runs.cpu, gpu, folder, result);
  write_field_files(runs.cpu, {"cpu", "value", "cpu", "1", "CPU reference (double)"}, options, result);
  write_field_files(runs.cpu_float.cast<double>(), {"cpu_float", "value", "cpu_float", "1", "CPU reference (float)"},
                    options, result);
  if (gpu) write_field_files(gpu->values, {gpu->backend, "value", gpu->backend, "1", gpu->label}, options, result);
}

}  // namespace

nlohmann::json cell_values_shape() {
  return nlohmann::json::array({nlohmann::json::array({"integer", "integer", "number"})});
}

nlohmann::json field_spec_shape() {
  nlohmann::json shape = descriptor_expect_shape();
  shape.update({{"cells", cell_values_shape()}, {"total", "number"}, {"tolerance", "number"}});
  return shape;
}

void add_field_spec_checks(const nlohmann::json& expect, const Grid<double>& output, const std::string& backend,
                           CaseResult& result) {
  if (!expect.is_object()) return;
  const double tolerance = expect.value("tolerance", 0.0);
  const std::string model = fmt::format("expected values from the seed's worked example; tolerance {}", tolerance);
  if (expect.contains("cells")) {
    double worst = 0.0;
    for (const auto& cell : expect["cells"]) {
      const int x = cell.at(0), y = cell.at(1);
      const double expected = cell.at(2);
      if (!output.inside(x, y)) throw InputError(fmt::format("expected cell ({}, {}) is outside the grid", x, y));
      worst = std::max(worst, std::abs(output.at(x, y) - expected));
    }
    result.checks.push_back(bounded_check("spec.cells." + backend, worst, tolerance, std::nullopt, model));
  }
  if (expect.contains("total")) {
    const double deviation = std::abs(field_totals(output).sum - expect["total"].get<double>());
    result.checks.push_back(bounded_check("spec.total." + backend, deviation, tolerance, std::nullopt, model));
  }
}

std::vector<std::string> field_spec_names(const nlohmann::json& expect, const std::string& backend) {
  std::vector<std::string> names;
  if (!expect.is_object()) return names;
  if (expect.contains("cells")) names.push_back("spec.cells." + backend);
  if (expect.contains("total")) names.push_back("spec.total." + backend);
  return names;
}

void run_field_twin(const FieldTwin& twin, const Heightmap& grid, const nlohmann::json& expect,
                    const RunOptions& options, CaseResult& result) {
  const ReferenceRuns runs = run_references(twin, grid, options, result);
  std::optional<GpuOutputs> gpu;
  if (options.candidate.field) {
    gpu = candidate_outputs(*options.candidate.field);
    result.notes.push_back(fmt::format("graded: {} ({} values), standing where the GPU twin stands",
                                       options.candidate.field->file.string(),
                                       gpu->double_precision ? "double" : "float"));
  } else if (options.gpu_available) {
    try {
      gpu = run_gpu(twin, grid.cast<float>(), options, result);
    } catch (const std::exception& error) {
      result.error = fmt::format("GPU twin failed: {}", error.what());
    }
  }
  const std::string unavailable = gpu ? "" : (result.error.empty() ? options.gpu_unavailable_reason : result.error);
  add_parity(twin, runs, gpu, unavailable, result);
  add_field_spec_checks(expect, runs.cpu, "cpu", result);
  if (gpu) {
    add_field_spec_checks(expect, gpu->values, gpu->backend, result);
  } else {
    for (const auto& name : field_spec_names(expect, "gpu")) result.checks.push_back(skipped_check(name, unavailable));
  }
  write_artifacts(runs, gpu, options, result);
  if (case_describes_terrain(result) && options.descriptors) {
    report_stage(options, "terrain descriptors");
    const Grid<double> cpu_float = runs.cpu_float.cast<double>();
    const std::optional<Grid<double>> gpu_heights =
        gpu && !options.candidate.field ? std::optional<Grid<double>>(gpu->values) : std::nullopt;
    add_case_descriptors({nullptr, &runs.cpu, &cpu_float, gpu_heights ? &*gpu_heights : nullptr}, expect, options,
                         result);
    if (!gpu) {
      for (const auto& name : descriptor_gpu_check_names(expect)) result.checks.push_back(skipped_check(name, unavailable));
    }
    if (options.candidate.field) result.notes.push_back("terrain descriptors of the references alone: the candidate's values are in its field files");
  }
}

}  // namespace gt
