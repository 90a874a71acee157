// Descriptors of a case's terrains, their parity and fidelity checks, and the plot that puts
// before, after and a real DEM side by side.
#include "compare/case_descriptors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "compare/checks/threshold.hpp"
#include "compare/descriptors/terrain_descriptors.hpp"
#include "compare/report/descriptor_plots.hpp"
#include "core/errors.hpp"
#include "core/io/heightmap_io.hpp"

namespace gt {

const std::vector<FidelityTarget>& fidelity_targets() {
  static const std::vector<FidelityTarget> targets{
      {"drainage.hack_exponent", 0.5, 0.7,
       "Hack 1957 (h ≈ 0.6); Rigon et al. 1996 (0.5–0.6 on real basins)"},
      {"drainage.exceedance_exponent_d8", 0.38, 0.48,
       "Rodríguez-Iturbe et al. 1992: P(A ≥ a) ∝ a^-0.43±0.03 on real basins (±0.05 here: D8's single direction)"},
      {"drainage.bifurcation_ratio", 3.0, 5.0, "Horton 1945, Strahler 1957: R_B ≈ 3–5 on natural networks"},
      {"drainage.length_ratio", 1.5, 3.0, "Horton 1945: R_L ≈ 1.5–3 on natural networks"},
      {"spectrum.beta", 1.7, 2.3,
       "Huang & Turcotte 1989, Perron et al. 2008: real topography's spectrum falls as f^-β, β ≈ 2"}};
  return targets;
}

bool case_describes_terrain(const CaseResult& result) {
  return result.algorithm.starts_with("erosion.") || result.name.starts_with("terrain.");
}

nlohmann::json descriptor_expect_shape() { return {{"fidelity", "boolean"}}; }

namespace {

// The real DEM every case is shown beside: Jacksboro (Tennessee, 3″ cells), the most dissected
// relief among the bundled DEMs. Measured once per process.
struct RealTerrain {
  std::string name;
  std::optional<TerrainDescriptors> descriptors;
  std::string unavailable;
};

const RealTerrain& real_terrain(const std::filesystem::path& dataset_dir) {
  static const RealTerrain real = [&] {
    RealTerrain out{"Jacksboro (real DEM)", std::nullopt, ""};
    try {
      const auto file = read_heightmap(dataset_dir / "real" / "jacksboro_fault_dem.npz");
      out.descriptors = describe_terrain(file.heights);
    } catch (const std::exception& error) {
      out.unavailable = error.what();
    }
    return out;
  }();
  return real;
}

std::map<std::string, double> scalar_map(const TerrainDescriptors& descriptors) {
  std::map<std::string, double> out;
  for (const auto& scalar : scalar_descriptors(descriptors)) out[scalar.name] = scalar.value;
  return out;
}

// parity.descriptors.<pair>: the worst continuous descriptor as a share of half its resolution.
Check descriptor_parity(const std::string& pair, const TerrainDescriptors& truth, const TerrainDescriptors& other) {
  const auto other_values = scalar_map(other);
  double worst_share = 0.0;
  std::string worst = "every continuous descriptor equal";
  for (const auto& scalar : scalar_descriptors(truth)) {
    if (!scalar.parity_resolution) continue;
    const auto found = other_values.find(scalar.name);
    const double difference = found == other_values.end() ? std::numeric_limits<double>::infinity()
                                                          : std::abs(found->second - scalar.value);
    const double share = difference / (0.5 * *scalar.parity_resolution);
    if (share > worst_share || std::isnan(share)) {
      worst_share = std::isnan(share) ? std::numeric_limits<double>::infinity() : share;
      worst = found == other_values.end()
                  ? fmt::format("{} measured on ref<double>'s result only", scalar.name)
                  : fmt::format("{}: {:.6g} against ref<double>'s {:.6g} (quoted to {})", scalar.name, found->second,
                                scalar.value, *scalar.parity_resolution);
    }
  }
  return bounded_check("parity.descriptors." + pair, worst_share, 1.0, std::nullopt,
                       "largest difference of a continuous descriptor (HI, slope mean and percentiles, β) from "
                       "ref<double>'s, as a share of half the resolution it is quoted at: rounded for a table, both "
                       "would read the same; worst: " + worst);
}

void add_fidelity_checks(const std::string& backend, const TerrainDescriptors& descriptors, CaseResult& result) {
  const auto values = scalar_map(descriptors);
  for (const auto& target : fidelity_targets()) {
    const std::string name = fmt::format("fidelity.{}.{}", target.descriptor, backend);
    const auto found = values.find(target.descriptor);
    if (found == values.end()) {
      result.checks.push_back(not_applicable_check(name, "not measured on this terrain (see the case's notes)"));
      continue;
    }
    const double outside = std::max({0.0, target.low - found->second, found->second - target.high});
    result.checks.push_back(bounded_check(
        name, outside, 0.0, std::numeric_limits<double>::infinity(),
        fmt::format("{} = {:.3f}; distance outside the target [{}, {}] of {} (warn only: unlike Earth, not wrong)",
                    target.descriptor, found->second, target.low, target.high, target.source)));
  }
}

bool wants_fidelity(const nlohmann::json& expect) {
  return expect.is_object() && expect.value("fidelity", false);
}

struct Described {
  std::string key;    // report.json key: before, cpu, cpu_float, gpu
  std::string label;  // plot legend
  TerrainDescriptors descriptors;
};

std::vector<Described> describe_all(const CaseTerrains& terrains, CaseResult& result) {
  std::vector<Described> out;
  const auto add = [&](const char* key, const char* label, const Grid<double>* terrain) {
    if (!terrain) return;
    try {
      out.push_back({key, label, describe_terrain(*terrain)});
    } catch (const InputError& error) {
      result.notes.push_back(fmt::format("descriptors of {}: {}", label, error.what()));
    }
  };
  add("before", "before", terrains.input);
  add("cpu", "after, CPU (double)", terrains.cpu);
  add("cpu_float", "after, CPU (float)", terrains.cpu_float);
  add("gpu", "after, GPU", terrains.gpu);
  return out;
}

const Described* find(const std::vector<Described>& described, const std::string& key) {
  for (const auto& entry : described) {
    if (entry.key == key) return &entry;
  }
  return nullptr;
}

void attach_descriptor_plot(const std::vector<Described>& described, const RealTerrain& real,
                            const RunOptions& options, CaseResult& result) {
  std::vector<DescribedTerrain> shown;
  for (const auto& entry : described) {
    if (entry.key != "cpu_float") shown.push_back({entry.label, &entry.descriptors});
  }
  if (real.descriptors) shown.push_back({real.name, &*real.descriptors});
  attach_plot(descriptor_panels(shown), options, "descriptors.png",
              "terrain descriptors: before, after and a real DEM (hypsometry, slope, power spectrum, Horton)", result);
}

}  // namespace

std::vector<std::string> descriptor_gpu_check_names(const nlohmann::json& expect) {
  std::vector<std::string> names = {"parity.descriptors.gpu_vs_double"};
  if (wants_fidelity(expect)) {
    for (const auto& target : fidelity_targets()) names.push_back(fmt::format("fidelity.{}.gpu", target.descriptor));
  }
  return names;
}

void add_case_descriptors(const CaseTerrains& terrains, const nlohmann::json& expect, const RunOptions& options,
                          CaseResult& result) {
  const auto described = describe_all(terrains, result);
  const auto& real = real_terrain(options.dataset_dir.empty() ? std::filesystem::path(GT_DATASET_DIR)
                                                              : options.dataset_dir);
  const bool fidelity = wants_fidelity(expect);
  nlohmann::json json = {{"terrains", nlohmann::json::object()}, {"fidelity", fidelity}};
  for (const auto& entry : described) json["terrains"][entry.key] = to_json(entry.descriptors);
  if (real.descriptors) {
    json["real"] = {{"name", real.name}, {"descriptors", to_json(*real.descriptors)}};
  } else {
    result.notes.push_back("real DEM descriptors unavailable: " + real.unavailable);
  }
  result.descriptors = json;

  if (const auto* truth = find(described, "cpu")) {
    if (const auto* gpu = find(described, "gpu")) {
      Check check = descriptor_parity("gpu_vs_double", truth->descriptors, gpu->descriptors);
      result.checks.push_back(
          terrains.ends_of_a_run
              ? informative_check(check.name, check.value,
                                  "the GPU's end of an iterated run beside ref<double>'s: rounding differences grow "
                                  "along the run by an amount no error model gives before it, so this is shown, not "
                                  "judged (the parity.shadow.* checks grade each step). " + check.detail)
              : check);
    }
    if (const auto* cpu_float = find(described, "cpu_float")) {
      Check check = descriptor_parity("float_vs_double", truth->descriptors, cpu_float->descriptors);
      result.checks.push_back(informative_check(
          check.name, check.value,
          "ref<float> keeps heights as plain floats, so erosion below a height's float spacing is lost (the float "
          "trap; the GPU keeps b0 + Δb): how much that moves the statistics is shown, not judged. " + check.detail));
    }
    if (fidelity) add_fidelity_checks("cpu", truth->descriptors, result);
  }
  if (const auto* gpu = find(described, "gpu"); gpu && fidelity) add_fidelity_checks("gpu", gpu->descriptors, result);
  attach_descriptor_plot(described, real, options, result);
}

}  // namespace gt
