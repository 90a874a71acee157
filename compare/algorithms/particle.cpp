// `erosion.particle`: seed 000's particle (droplet) water erosion, Hydra's kernel (§4.4.1,
// Algorithms 4-7, eqs. 4.5-4.6, Appendix A; digest 000 §4.4), with its colour transport (§4.5,
// Algorithm 8, eq. 4.9) and flow map (§4.7, eqs. 4.12-4.13): parameters to constants
// (core/params/particle.hpp), the twins (reference/erosion/particle.hpp, gpu/erosion/particle.hpp)
// as a droplet twin that the stepped runner runs (compare/droplet_twin.hpp: state, orderings, shadow
// bounds, ledger, race statistics), the hand-derived droplets of a case and the performance rows
// beside the thesis's Table 5.1, with its spacing study (Tables 5.3–5.5: our GPU's race droplets by
// spacing and interpolation; the sequential reference does the same work at any spacing).
//
// Inputs:  a heightmap, normalised to [0, 1] as seed 000 does unless `normalised` is off; with
//          `colour`, a bundled texture resampled bilinearly to the grid and sRGB-decoded.
// Outputs: the state {terrain} of each twin in the input's own heights; Hydra's depth and sediment
//          maps of ref<double>'s run; the transported colour; the flow map of the eroded terrain.
// Units:   heights in the input's vertical unit (the twins' normalised heights are dimensionless);
//          positions in texels (the cell size does not enter); colour linear RGBA; flow 0..1.
// Decisions: the droplets of a pass are ordered as `ordering` says (core/params/droplets.hpp) and
//          ref<double> runs them one after the other (the truth). No iteration number enters
//          Hydra's kernel (a droplet starts at every texel each iteration), so a state resumes
//          from its heights alone. The colour and the flow map are whole-run checks beside the
//          stepped state: no droplet's path reads them back into the terrain.
// Checks, beside the runner's and the droplet twin's:
//   spec.droplet.{positions,sediment,cells}.cpu  the case's hand-derived droplet ("expect": "droplet"),
//                                       ref<double>, within the case's tolerance
//   colour.created.{cpu,cpu_float}      no colour channel leaves the range it started in (blends are
//                                       convex combinations); colour.psnr_db.float_vs_double shown
//   parity.colour.channels_differing.gpu_vs_float, parity.side_maps.cells_differing.gpu_vs_float
//                                       batch and disjoint: colour and side maps bit for bit; race:
//                                       race.colour_channels_differing, race.colour_psnr_db reported
//   flow.max_abs.float_vs_double, parity.flow.cells_differing.gpu_vs_float   the flow map each twin
//                                       draws on ref<float>'s eroded terrain (race: race.flow.* reported)
// Mutants: compare/mutants/particle.cpp.
#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/report/images.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/droplet_twin.hpp"
#include "compare/field_files.hpp"
#include "compare/field_twin.hpp"
#include "core/errors.hpp"
#include "core/io/heightmap_io.hpp"
#include "core/params/particle.hpp"
#include "core/params/thermal.hpp"
#include "gpu/erosion/flow_map.hpp"
#include "gpu/erosion/particle.hpp"
#include "reference/erosion/flow_map.hpp"
#include "reference/erosion/particle.hpp"

namespace gt {
namespace {

// The GPU object lives as long as the closures.
DropletGpu particle_gpu(std::shared_ptr<gpu::ParticleErosion> gpu) {
  return {[gpu](const Grid<float>& heights, int) { gpu->load(heights); }, [gpu](int count) { gpu->step(count); },
          [gpu] { return gpu->result(); }};
}

ParticleConstants with_setup(ParticleConstants constants, DropletSetup setup) {
  constants.spacing = setup.spacing;
  constants.ordering = setup.ordering;
  return constants;
}

// The twins on `given` (normalised when asked); `constants` are those of the twins' heights.
DropletTwin particle_twin(const Heightmap& given, bool normalised, const ParticleConstants& constants) {
  DropletTwin twin;
  twin.algorithm = "erosion.particle";
  set_droplet_input(twin, given, normalised);
  twin.setup = {constants.spacing, constants.ordering};
  twin.iterations = constants.iterations;
  twin.lifetime = constants.lifetime;
  twin.apart_spacing = 2 * droplet_reach(constants.lifetime) + 1;
  twin.roundings_per_step = 7.0;  // 4 corner stores + 1 deposit + 2 sediment updates
  // A step erodes (each of 4 distinct corners, or the texel, once) or deposits (at the texel):
  // one write to a cell at most.
  twin.writes_per_cell_per_step = 1.0;
  // Hydra's iterations are alike: the first iteration's number does not enter.
  twin.reference_double = [constants](const Grid<double>& heights, int, int count, DropletSetup setup) {
    return reference::particle_erosion(heights, with_setup(constants, setup), count, reference_ordering(setup.ordering));
  };
  twin.reference_float = [constants](const Grid<float>& heights, int, int count, DropletSetup setup) {
    return reference::particle_erosion(heights, with_setup(constants, setup), count, reference_ordering(setup.ordering));
  };
  twin.make_gpu = [constants, width = given.width, height = given.height](DropletSetup setup) {
    return particle_gpu(std::make_shared<gpu::ParticleErosion>(width, height, with_setup(constants, setup)));
  };
  return twin;
}

struct ParticleScenario {
  DropletTwin twin;
  ParticleConstants constants;
  std::optional<reference::ColourMap<double>> colour;  // transported when the case asks (§4.5)
  std::optional<FlowConstants> flow;                   // drawn when the case asks (§4.7)
};

// Hydra's redraw of a colour texture to the heightmap's size (§4.5, eqs. 4.8): GL's linear filter at
// each texel centre (clamp to edge) on the stored [0, 1] values, then Algorithm 2's sRGB decoding
// of red, green and blue (alpha as stored, 1 without an alpha channel).
reference::ColourMap<double> bundled_colour(const std::string& name, const Heightmap& grid) {
  const auto file = std::filesystem::path(GT_DATASET_DIR) / "real" / "textures" / (name + ".png");
  auto image = OIIO::ImageInput::open(file.string());
  if (!image) {
    throw InputError(fmt::format("erosion.particle: the colour {} is missing (datasets/fetch.sh fetches it)",
                                 file.string()));
  }
  const OIIO::ImageSpec spec = image->spec();
  std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
  if (!image->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) {
    throw InputError(fmt::format("cannot read the pixels of {}: {}", file.string(), image->geterror()));
  }
  const auto texel = [&](int x, int y, int channel) {
    x = std::clamp(x, 0, spec.width - 1);
    y = std::clamp(y, 0, spec.height - 1);
    if (channel == 3 && spec.nchannels < 4) return 1.0;
    const int stored = spec.nchannels >= 3 ? channel : 0;
    return double(pixels[(std::size_t(y) * std::size_t(spec.width) + std::size_t(x)) * std::size_t(spec.nchannels) +
                         std::size_t(stored)]);
  };
  reference::ColourMap<double> colour;
  colour.width = grid.width;
  colour.height = grid.height;
  colour.valid = grid.valid;
  colour.values.resize(grid.size());
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const double u = (x + 0.5) / grid.width * spec.width - 0.5, v = (y + 0.5) / grid.height * spec.height - 0.5;
      const int x0 = static_cast<int>(std::floor(u)), y0 = static_cast<int>(std::floor(v));
      const double fx = u - x0, fy = v - y0;
      for (int channel = 0; channel < 4; ++channel) {
        const double sampled = (texel(x0, y0, channel) * (1 - fx) + texel(x0 + 1, y0, channel) * fx) * (1 - fy) +
                               (texel(x0, y0 + 1, channel) * (1 - fx) + texel(x0 + 1, y0 + 1, channel) * fx) * fy;
        colour.at(x, y)[std::size_t(channel)] = channel < 3 ? srgb_to_linear(sampled) : sampled;
      }
    }
  }
  return colour;
}

ParticleScenario make_scenario(const nlohmann::json& resolved, const Heightmap& given) {
  if (given.size() == 0) throw InputError("erosion.particle erodes a heightmap: the case needs an input");
  check_finite(given, "erosion.particle input");
  check_fits_float(given, "erosion.particle input");
  const bool normalised = resolved.at("normalised").get<bool>();
  const Heightmap input = normalised ? normalise_heights(given) : given;
  ParticleScenario scenario{{}, particle_constants(resolved, input)};
  const auto& c = scenario.constants;
  scenario.twin = particle_twin(given, normalised, c);
  scenario.twin.erosion_contrast = resolved.at("erosion_contrast");
  scenario.twin.deposition_contrast = resolved.at("deposition_contrast");
  auto& notes = scenario.twin.notes;
  const std::string colour = resolved.at("colour");
  if (colour != "none") {
    scenario.colour = bundled_colour(colour, given);
    notes.push_back(fmt::format("colour {}.png resampled bilinearly to {}x{} texels and sRGB-decoded (§4.5); colour "
                                "mixing {}, {}",
                                colour, given.width, given.height, c.colour_mixing,
                                c.interpolate_colour ? "deposits spread bilinearly (Algorithm 8)" : "deposits at the texel"));
  }
  if (given.has_mask()) {
    notes.push_back("no-data cells behave as outside the grid: they read 0 and writes to them are lost (Hydra's "
                    "empty regions); the ledger counts what crosses them");
  }
  notes.push_back(fmt::format(
      "ordering {}: {} droplets per pass, {} passes per iteration, lifetime {}; batch quantum {:.6g}",
      droplet_ordering_name(c.ordering),
      static_cast<long long>((given.width + c.spacing - 1) / c.spacing) * ((given.height + c.spacing - 1) / c.spacing),
      c.spacing * c.spacing, c.lifetime, c.quantum));
  for (auto& warning : particle_warnings(c)) notes.push_back(std::move(warning));
  scenario.flow = flow_constants(resolved, c);
  if (scenario.flow) {
    const auto& flow = *scenario.flow;
    notes.push_back(fmt::format(
        "flow map (§4.7) drawn on ref<float>'s eroded terrain by every twin: spacing {}, contrast {} (f_c = {:.6g}, "
        "eq. 4.13), {}, ordering {}{}",
        flow.spacing, resolved.at("flow_contrast").get<double>(), flow.factor,
        flow.interpolate ? "concentration over 4 texel centres" : "concentration at the droplet's texel",
        droplet_ordering_name(flow.ordering),
        flow.ordering == DropletOrdering::batch ? " (weights counted in 2^-10, F = 1 - (1 - f_c)^Σw)" : ""));
  }
  return scenario;
}

// A hand-derived trajectory in the case (compare/droplet_twin.hpp droplet_spec_shape()), traced by
// ref<double> on the case's input from the start texel.
void add_droplet_spec(const ParticleScenario& scenario, const nlohmann::json& expect, CaseResult& result) {
  if (!expect.is_object() || !expect.contains("droplet")) return;
  const auto& spec = expect["droplet"];
  DropletTrace trace{.heights_after = scenario.twin.input};
  const auto path = reference::run_one_droplet(trace.heights_after, scenario.constants, spec.at("start")[0].get<int>(),
                                               spec.at("start")[1].get<int>());
  trace.positions.assign(path.positions.begin(), path.positions.end());
  trace.sediment = path.sediment;
  add_droplet_spec_checks(spec, trace, result);
}

// A linear value in [0, 1] (clamped) sRGB-encoded.
double srgb_encoded(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// The flow map's colour bar: concentration 0 black to 1 white, as the picture encodes it.
ColourScale flow_scale() {
  return sampled_scale("grey (sRGB)", 0.0, 1.0, "1", [](double flow) {
    const auto grey = static_cast<float>(srgb_encoded(flow));
    return std::array<float, 3>{grey, grey, grey};
  });
}

// The colour picture of a map: sRGB-encoded RGB8, each texel a block of identical pixels so that the
// longer side reaches 256 px (as compare/report/images.hpp enlarges); masked texels grey.
template <class Real>
void write_colour_image(const reference::ColourMap<Real>& colour, const std::filesystem::path& png) {
  const int factor = std::max(1, (255 + std::max(colour.width, colour.height)) / std::max(colour.width, colour.height));
  const int width = colour.width * factor, height = colour.height * factor;
  std::vector<std::uint8_t> pixels(std::size_t(width) * std::size_t(height) * 3);
  const auto encode = [](double linear) { return static_cast<std::uint8_t>(std::lround(255.0 * srgb_encoded(linear))); };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t cell = colour.index(x / factor, y / factor);
      for (int channel = 0; channel < 3; ++channel) {
        pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3 + std::size_t(channel)] =
            colour.is_valid(cell) ? encode(double(colour.values[cell][std::size_t(channel)])) : 128;
      }
    }
  }
  auto output = OIIO::ImageOutput::create(png.string());
  if (!output || !output->open(png.string(), OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8)) ||
      !output->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !output->close()) {
    throw std::runtime_error(fmt::format("cannot write {}", png.string()));
  }
}

// How far a transported colour map leaves the range its channels started in (0 included: texels off
// the grid and no-data texels read black): the largest excess over every channel, away from the
// texels x <= 1 and y <= 1, where upstream's truncated corner gives weights outside [0, 1] and the
// blend extrapolates as Hydra's does.
template <class Real>
double colour_created(const reference::ColourMap<double>& before, const reference::ColourMap<Real>& after) {
  std::array<double, 4> low{0, 0, 0, 0}, high{0, 0, 0, 0};
  for (std::size_t i = 0; i < before.size(); ++i) {
    for (std::size_t ch = 0; ch < 4; ++ch) {
      low[ch] = std::min(low[ch], before.values[i][ch]);
      high[ch] = std::max(high[ch], before.values[i][ch]);
    }
  }
  double excess = 0.0;
  for (int y = 2; y < after.height; ++y) {
    for (int x = 2; x < after.width; ++x) {
      for (std::size_t ch = 0; ch < 4; ++ch) {
        const double value = double(after.at(x, y)[ch]);
        excess = std::max({excess, value - high[ch], low[ch] - value});
      }
    }
  }
  return excess;
}

template <class A, class B>
std::size_t channels_differing(const reference::ColourMap<A>& a, const reference::ColourMap<B>& b) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t ch = 0; ch < 4; ++ch) differing += float(a.values[i][ch]) != float(b.values[i][ch]) ? 1 : 0;
  }
  return differing;
}

// PSNR of b against a over red, green and blue of the valid texels, peak 1 (linear colour):
// 10·log10(1 / mean squared difference); +inf when equal.
template <class A, class B>
double colour_psnr(const reference::ColourMap<A>& a, const reference::ColourMap<B>& b) {
  double squares = 0.0;
  std::size_t samples = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a.is_valid(i)) continue;
    for (std::size_t ch = 0; ch < 3; ++ch) {
      const double difference = double(b.values[i][ch]) - double(a.values[i][ch]);
      squares += difference * difference;
      ++samples;
    }
  }
  return squares > 0.0 ? 10.0 * std::log10(double(samples) / squares) : INFINITY;
}

reference::ColourMap<float> colour_as_float(const reference::ColourMap<double>& colour) {
  reference::ColourMap<float> out;
  out.width = colour.width;
  out.height = colour.height;
  out.valid = colour.valid;
  out.values.resize(colour.size());
  for (std::size_t i = 0; i < colour.size(); ++i) {
    for (std::size_t ch = 0; ch < 4; ++ch) out.values[i][ch] = static_cast<float>(colour.values[i][ch]);
  }
  return out;
}

// A colour map's channels as field files colour_<channel>_<backend> (linear, dimensionless).
template <class Real>
void write_colour_fields(const reference::ColourMap<Real>& colour, const Grid<double>& layout,
                         const std::string& backend, const std::string& when, const RunOptions& options,
                         CaseResult& result) {
  static constexpr const char* channels[4] = {"red", "green", "blue", "alpha"};
  Grid<double> channel = layout;
  for (std::size_t ch = 0; ch < 4; ++ch) {
    for (std::size_t cell = 0; cell < channel.size(); ++cell) channel.values[cell] = double(colour.values[cell][ch]);
    const std::string field = fmt::format("colour_{}", channels[ch]);
    write_field_files(channel,
                      {fmt::format("{}_{}", field, backend), field, backend, "1",
                       fmt::format("{} of the transported colour (linear), {}", channels[ch], when)},
                      options, result);
  }
}

// The GPU's colour of the whole run against ref<float>'s (`float_run`, from `colour`): bit for bit
// in batch and disjoint orderings, with the side maps; a race's distance reported.
void add_gpu_colour_checks(const ParticleScenario& scenario, const reference::ColourMap<float>& colour,
                           const reference::DropletRun<float>& float_run, const RunOptions& options,
                           CaseResult& result) {
  const auto& c = scenario.constants;
  const auto& input = scenario.twin.input;
  gpu::ParticleErosion gpu(input.width, input.height, c, true);
  gpu.load(input.cast<float>());
  gpu.load_colour(colour);
  gpu.run();
  const auto gpu_colour = gpu.colour_result();
  write_colour_fields(gpu_colour, input, "gpu", "after the run, GPU", options, result);
  const double differing = double(channels_differing(float_run.colour, gpu_colour));
  if (c.ordering == DropletOrdering::race) {
    result.checks.push_back(informative_check(
        "race.colour_channels_differing.gpu_vs_float", differing,
        "colour channels the racing GPU leaves different from the sequential ref<float>"));
    result.checks.push_back(informative_check("race.colour_psnr_db.gpu_vs_float",
                                              colour_psnr(float_run.colour, gpu_colour),
                                              "PSNR of the racing GPU's colour against the sequential ref<float>'s, "
                                              "RGB, peak 1"));
    return;
  }
  result.checks.push_back(bounded_check("parity.colour.channels_differing.gpu_vs_float", differing, 0.0, std::nullopt,
                                        "the whole run's colour, GPU against ref<float>: every bit equal"));
  const double side_maps = double(field_difference(float_run.eroded_at_droplet, gpu.eroded_at_droplet()).differing_bits +
                                  field_difference(float_run.deposited_at_droplet, gpu.deposited_at_droplet()).differing_bits);
  result.checks.push_back(bounded_check("parity.side_maps.cells_differing.gpu_vs_float", side_maps, 0.0, std::nullopt,
                                        "Hydra's depth and sediment maps (before their contrasts), GPU against "
                                        "ref<float>: every bit equal"));
}

std::vector<std::string> colour_gpu_checks(DropletOrdering ordering) {
  if (ordering == DropletOrdering::race) {
    return {"race.colour_channels_differing.gpu_vs_float", "race.colour_psnr_db.gpu_vs_float"};
  }
  return {"parity.colour.channels_differing.gpu_vs_float", "parity.side_maps.cells_differing.gpu_vs_float"};
}

// Colour transport (§4.5) of a case that asks for it, on the whole run: the sequential truth creates
// no colour; with `gpu`, the GPU's colour against ref<float>'s.
void add_colour_checks(const ParticleScenario& scenario, bool gpu, const RunOptions& options, CaseResult& result) {
  const auto& c = scenario.constants;
  const auto& colour = *scenario.colour;
  const auto& input = scenario.twin.input;
  const auto truth = reference::particle_erosion(input, c, c.iterations, DropletOrdering::race, &colour);
  result.checks.push_back(bounded_check(
      "colour.created.cpu", colour_created(colour, truth.colour), 1e-12, std::nullopt,
      "largest excess of a channel over the range it started in (0 included), ref<double>, texels x, y >= 2: "
      "blends are convex combinations, so only rounding (u per blend) may step outside"));
  const reference::ColourMap<float> colour_float = colour_as_float(colour);
  const auto float_run = reference::particle_erosion(input.cast<float>(), c, c.iterations,
                                                     reference_ordering(c.ordering), &colour_float);
  result.checks.push_back(informative_check(
      "colour.psnr_db.float_vs_double", colour_psnr(truth.colour, float_run.colour),
      "PSNR of ref<float>'s colour against the sequential ref<double>'s, RGB, peak 1 (batch: another blend)"));
  result.checks.push_back(informative_check("colour.created.cpu_float", colour_created(colour, float_run.colour),
                                            "as colour.created.cpu for ref<float> (batch: the weighted mean's "
                                            "2^-20 quanta)"));
  if (!options.report_dir.empty()) {
    const auto folder = options.report_dir / result.name;
    write_colour_image(colour, folder / "colour_before.png");
    add_picture(result, "colour_before.png", "colour map before (sRGB)");
    write_colour_image(truth.colour, folder / "colour_after_cpu.png");
    add_picture(result, "colour_after_cpu.png", "colour map after the droplets carried it, ref<double> (sRGB)");
    write_colour_fields(colour, input, "input", "before the droplets", options, result);
    write_colour_fields(truth.colour, input, "cpu", "after the run, ref<double> (sequential)", options, result);
  }
  if (gpu) add_gpu_colour_checks(scenario, colour_float, float_run, options, result);
}

// The flow map as a grey colour map (R = G = B = F, linear), for write_colour_image.
template <class Real>
reference::ColourMap<Real> flow_as_colour(const Grid<Real>& flow) {
  reference::ColourMap<Real> grey;
  grey.width = flow.width;
  grey.height = flow.height;
  grey.valid = flow.valid;
  grey.values.resize(flow.size());
  for (std::size_t i = 0; i < flow.size(); ++i) grey.values[i] = {flow.values[i], flow.values[i], flow.values[i], 1};
  return grey;
}

// The GPU's flow map of `eroded` against ref<float>'s (`float_map`): bit for bit in batch and
// disjoint orderings; a race's distance from the sequential map reported.
void add_gpu_flow_checks(const FlowConstants& flow, const Grid<float>& eroded, const Grid<float>& float_map,
                         const RunOptions& options, CaseResult& result) {
  gpu::FlowMap gpu(eroded.width, eroded.height, flow);
  gpu.load(eroded);
  gpu.run();
  const Grid<float> gpu_flow = gpu.result();
  const FieldDifference difference = field_difference(float_map, gpu_flow);
  if (flow.ordering == DropletOrdering::race) {
    result.checks.push_back(informative_check("race.flow.cells_differing.gpu_vs_float", double(difference.differing_bits),
                                              "flow map texels the racing GPU leaves different from the sequential "
                                              "ref<float> (paths crossing in a pass overwrite each other)"));
    result.checks.push_back(informative_check("race.flow.max_abs.gpu_vs_float", difference.max_abs,
                                              "largest concentration difference, racing GPU against ref<float>"));
  } else {
    result.checks.push_back(bounded_check(
        "parity.flow.cells_differing.gpu_vs_float", double(difference.differing_bits), 0.0, std::nullopt,
        "the flow map after the plug pass, GPU against ref<float> on the same heights: every bit equal (disjoint: no "
        "two droplets of a pass touch a common texel; batch: integer weight counts)"));
  }
  if (!options.report_dir.empty()) {
    write_colour_image(flow_as_colour(gpu_flow), options.report_dir / result.name / "flow_gpu.png");
    write_field_files(gpu_flow.cast<double>(), {"flow_gpu", "flow", "gpu", "1", "flow map (§4.7), GPU"}, options,
                      result);
    add_picture(result, "flow_gpu.png", "flow map, GPU (as flow_cpu.png)", flow_scale());
  }
}

std::vector<std::string> flow_gpu_checks(DropletOrdering ordering) {
  if (ordering == DropletOrdering::race) return {"race.flow.cells_differing.gpu_vs_float", "race.flow.max_abs.gpu_vs_float"};
  return {"parity.flow.cells_differing.gpu_vs_float"};
}

// The flow map (§4.7) of the eroded terrain `eroded` (ref<float>'s: every twin reads the same
// heights, so the flow kernels are compared alone), drawn by both references and, with `gpu`, the GPU.
void add_flow_checks(const FlowConstants& flow, const Grid<float>& eroded, bool gpu, const RunOptions& options,
                     CaseResult& result) {
  FlowConstants sequential = flow;
  sequential.ordering = DropletOrdering::race;
  FlowConstants twinned = flow;
  twinned.ordering = reference_ordering(flow.ordering);
  const auto truth = reference::flow_map(eroded.cast<double>(), sequential);
  const auto float_run = reference::flow_map(eroded, twinned);
  result.notes.push_back(fmt::format("flow map: {} droplets; the plug pass filled {} texels left at 0 (ref<double>)",
                                     truth.droplets, truth.plugged));
  const Grid<double> float_as_double = float_run.concentration.cast<double>();
  result.checks.push_back(informative_check(
      "flow.max_abs.float_vs_double", field_difference(truth.concentration, float_as_double).max_abs,
      flow.ordering == DropletOrdering::batch ? "batch ref<float> against the sequential ref<double>: another rule"
                                              : "ref<float> against ref<double>, both sequential"));
  if (!options.report_dir.empty()) {
    const auto folder = options.report_dir / result.name;
    write_colour_image(flow_as_colour(truth.concentration), folder / "flow_cpu.png");
    write_field_files(truth.concentration, {"flow_cpu", "flow", "cpu", "1", "flow map (§4.7), ref<double> (sequential)"},
                      options, result);
    add_picture(result, "flow_cpu.png",
                "flow map, ref<double> (sequential): concentration 0 black to 1 white, shown as a linear image (sRGB)",
                flow_scale());
  }
  if (gpu) add_gpu_flow_checks(flow, eroded, float_run.concentration, options, result);
}

// Hydra's Table 5.1 (digest 000 §6.2): total time of 50 iterations at spacing 4, lifetime 50.
struct PublishedTiming {
  const char* device;
  int size;
  double ms_for_50_iterations;
};
constexpr PublishedTiming hydra_table_5_1[] = {
    {"NVIDIA RTX 3080 12GB", 128, 3},     {"NVIDIA RTX 3080 12GB", 256, 9},   {"NVIDIA RTX 3080 12GB", 512, 20},
    {"NVIDIA RTX 3080 12GB", 1024, 72},   {"NVIDIA GTX 745 4GB", 128, 38},    {"NVIDIA GTX 745 4GB", 256, 172},
    {"NVIDIA GTX 745 4GB", 512, 804},     {"NVIDIA GTX 745 4GB", 1024, 3575}};
// The thesis measured up to 1024²; the sequential reference takes seconds an iteration there.
constexpr int largest_benchmark_side = 1024;

// Per iteration, as our droplet rows count them.
BenchmarkRow published_table_5_1_row(const PublishedTiming& published) {
  const double ms = published.ms_for_50_iterations / 50.0;
  const double steps = double(published.size) * published.size * 50;  // every droplet its whole life, as quoted
  return published_row("erosion.particle", fmt::format("{} (Hydra, thesis Table 5.1)", published.device),
                       published.size, 1, ms,
                       fmt::format("race droplets (Hydra's fragment shader), total of 50 iterations / 50; {:.3g} "
                                   "droplet steps/s if every droplet lives 50 steps",
                                   steps / (ms * 1e-3)));
}

// Hydra's spacing study (digest 000 §6.4–6.5): total time of 50 iterations by droplet spacing,
// Table 5.3 at spacing 16 with and without interpolation (128–1024 px), Tables 5.4 and 5.5 by
// spacing at 256 and 512 px. The 16 px values of 5.4/5.5 agree with 5.3's rows without
// interpolation: the spacing tables are taken as measured without it.
struct PublishedSpacingTiming {
  const char* device;
  const char* table;
  int size;
  int spacing;
  bool interpolate;
  double ms_for_50_iterations;
};
constexpr const char* rtx = "NVIDIA RTX 3080 12GB";
constexpr const char* gtx = "NVIDIA GTX 745 4GB";
constexpr PublishedSpacingTiming hydra_spacing_tables[] = {
    {rtx, "5.3", 128, 16, false, 23},   {rtx, "5.3", 256, 16, false, 38},   {rtx, "5.3", 512, 16, false, 48},
    {rtx, "5.3", 1024, 16, false, 203}, {rtx, "5.3", 128, 16, true, 23},    {rtx, "5.3", 256, 16, true, 62},
    {rtx, "5.3", 512, 16, true, 83},    {rtx, "5.3", 1024, 16, true, 344},  {gtx, "5.3", 128, 16, false, 72},
    {gtx, "5.3", 256, 16, false, 282},  {gtx, "5.3", 512, 16, false, 1301}, {gtx, "5.3", 128, 16, true, 103},
    {gtx, "5.3", 256, 16, true, 407},   {gtx, "5.3", 512, 16, true, 1915},  {rtx, "5.4", 256, 1, false, 5.55},
    {rtx, "5.4", 256, 2, false, 6.80},  {rtx, "5.4", 256, 4, false, 9},     {rtx, "5.4", 256, 8, false, 16},
    {rtx, "5.4", 256, 16, false, 40},   {rtx, "5.4", 256, 32, false, 90},   {gtx, "5.4", 256, 1, false, 120},
    {gtx, "5.4", 256, 2, false, 142},   {gtx, "5.4", 256, 4, false, 184},   {gtx, "5.4", 256, 8, false, 236},
    {gtx, "5.4", 256, 16, false, 285},  {gtx, "5.4", 256, 32, false, 334},  {rtx, "5.5", 512, 1, false, 9},
    {rtx, "5.5", 512, 2, false, 11},    {rtx, "5.5", 512, 4, false, 20},    {rtx, "5.5", 512, 8, false, 42},
    {rtx, "5.5", 512, 16, false, 48},   {rtx, "5.5", 512, 32, false, 202},  {gtx, "5.5", 512, 1, false, 516},
    {gtx, "5.5", 512, 2, false, 617},   {gtx, "5.5", 512, 4, false, 836},   {gtx, "5.5", 512, 8, false, 1082},
    {gtx, "5.5", 512, 16, false, 1281}, {gtx, "5.5", 512, 32, false, 1414}};

// A configuration the study times: a spacing, with or without interpolation.
struct SpacingVariant {
  int spacing;
  bool interpolate;
  std::string name() const { return fmt::format("spacing {}{}", spacing, interpolate ? ", interpolated" : ""); }
  bool operator==(const SpacingVariant&) const = default;
};

BenchmarkRow published_spacing_row(const PublishedSpacingTiming& published) {
  const SpacingVariant variant{published.spacing, published.interpolate};
  return published_row(
      "erosion.particle",
      fmt::format("{} (Hydra, thesis Table {}: {})", published.device, published.table, variant.name()),
      published.size, 1, published.ms_for_50_iterations / 50.0,
      fmt::format("race droplets, {}, total of 50 iterations / 50, as published", variant.name()));
}

// The study at one grid side: our GPU's race droplets in each variant the tables have at that side
// (backend "gpu (spacing s[, interpolated])"), then the tables' rows of that side.
std::vector<BenchmarkRow> spacing_study_rows(const Heightmap& field, int reps, bool gpu_available,
                                             const Environment& environment) {
  const int size = field.width;
  std::vector<SpacingVariant> timed;  // with a GPU, each variant the tables have at this side, once
  for (const auto& published : hydra_spacing_tables) {
    const SpacingVariant variant{published.spacing, published.interpolate};
    if (gpu_available && published.size == size && std::ranges::find(timed, variant) == timed.end()) {
      timed.push_back(variant);
    }
  }
  std::vector<BenchmarkRow> rows;
  for (const SpacingVariant& variant : timed) {
    const auto resolved = resolve_params("erosion.particle", particle_param_specs(),
                                         {{"iterations", 1}, {"spacing", variant.spacing},
                                          {"interpolate", variant.interpolate}});
    const auto twin = particle_twin(field, false, particle_constants(resolved, field));
    rows.push_back(droplet_gpu_row(twin, DropletOrdering::race, reps, environment,
                                   fmt::format("gpu ({})", variant.name())));
  }
  for (const auto& published : hydra_spacing_tables) {
    if (published.size == size) rows.push_back(published_spacing_row(published));
  }
  return rows;
}

std::vector<BenchmarkRow> hydra_particle_rows() {
  std::vector<BenchmarkRow> rows;
  for (const auto& published : hydra_table_5_1) rows.push_back(published_table_5_1_row(published));
  return rows;
}

// A noisy cone normalised to [0, 1] with Hydra's defaults at spacing 4.
std::vector<BenchmarkRow> benchmark_particle(const BenchmarkOptions& options, bool gpu_available,
                                             const Environment& environment) {
  std::vector<BenchmarkRow> rows;
  for (const int size : options.sizes) {
    if (size > largest_benchmark_side) continue;
    const nlohmann::json input = {{"generator", "cone"}, {"width", size}, {"height", size}, {"cell_size", 1.0},
                                  {"peak", 30.0}, {"noise", 1.0}, {"seed", 7}};
    const Heightmap field = normalise_heights(load_input(input, nullptr, {}).heights);
    const auto resolved = resolve_params("erosion.particle", particle_param_specs(), {{"iterations", 1}});
    std::ranges::move(droplet_benchmark_rows(particle_twin(field, false, particle_constants(resolved, field)),
                                             options.reps, gpu_available, environment),
                      std::back_inserter(rows));
    if (options.studies) std::ranges::move(spacing_study_rows(field, options.reps, gpu_available, environment),
                                           std::back_inserter(rows));
  }
  return rows;
}

// The droplet twin's own finish, then the colour and flow checks of a case that asks for them.
SteppedTwin particle_stepped_twin(const std::shared_ptr<const ParticleScenario>& scenario) {
  SteppedTwin twin = droplet_stepped_twin({scenario, &scenario->twin});
  twin.finish = [droplets = twin.finish, scenario](const std::vector<BackendEnd>& ends, const nlohmann::json& expect,
                                                   const RunOptions& options, CaseResult& result) {
    droplets(ends, expect, options, result);
    const bool gpu = ends.size() > 2;
    if (scenario->colour) add_colour_checks(*scenario, gpu, options, result);
    if (scenario->flow) {
      add_flow_checks(*scenario->flow, scenario->twin.own.twin_heights<float>(ends[1].final), gpu, options, result);
    }
  };
  twin.finish_gpu_checks = [droplets = twin.finish_gpu_checks, scenario](const nlohmann::json& expect) {
    std::vector<std::string> names = droplets(expect);
    const DropletOrdering ordering = scenario->constants.ordering;
    if (scenario->colour) std::ranges::copy(colour_gpu_checks(ordering), std::back_inserter(names));
    if (scenario->flow) std::ranges::copy(flow_gpu_checks(ordering), std::back_inserter(names));
    return names;
  };
  return twin;
}

PreparedTwin prepare_particle(const nlohmann::json& resolved, const LoadedInput& input) {
  const auto scenario = std::make_shared<const ParticleScenario>(make_scenario(resolved, input.heights));
  return {.kind = particle_stepped_twin(scenario),
          .extra_checks = [scenario](const nlohmann::json& expect, const RunOptions&, CaseResult& result) {
            add_droplet_spec(*scenario, expect, result);
          }};
}

nlohmann::json particle_expect_shape() {
  nlohmann::json shape = descriptor_expect_shape();
  shape["droplet"] = droplet_spec_shape();
  return shape;
}

}  // namespace

Algorithm particle_algorithm() {
  return {.name = "erosion.particle",
          .summary = "droplet water erosion (Hydra's kernel), sequential, racing, disjoint or batch droplets",
          .source = "seed 000 §4.4.1, Algorithms 4-7, eqs. 4.5-4.6, Appendix A (digest 000 §4.4)",
          .params = &particle_param_specs(),
          .prepare = prepare_particle,
          .kind = CaseKind::stepped,
          .benchmark = benchmark_particle,
          .published = hydra_particle_rows(),
          .expect_shape = particle_expect_shape(),
          // The input, ref<double>'s run with its two side maps (5 doubles), the GPU's copies,
          // the difference and change maps of the checks (6 doubles), the descriptors, and the
          // runner's states at its checkpoints (droplet_checkpoint_memory). Colour adds the map in
          // double three times (input, truth, copies) and in float four times (ref<float>, the GPU's
          // upload, result and its sums): about 200 B a cell. The flow map: the eroded heights in
          // double, ref<double>'s map and its copy of the heights, ref<float>'s, the GPU's 4 buffers
          // and download, the grey pictures' RGBA maps (4 doubles): about 100 B a cell. Measured
          // within this by tests/memory_estimates_test.cpp at 768² without colour (the colour share
          // is estimated).
          .memory = [](const nlohmann::json& resolved, const LoadedInput& input) {
            const double colour = resolved.at("colour") == "none" ? 0.0 : 200.0;
            const double flow = resolved.at("flow_map").get<bool>() ? 100.0 : 0.0;
            const double cells = static_cast<double>(input.heights.size());
            return memory_for(cells, "cells", 300 + colour + flow + descriptor_bytes_per_cell) +
                   droplet_checkpoint_memory(cells, resolved.at("iterations").get<int>());
          }};
}

}  // namespace gt
