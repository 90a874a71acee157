// Parameter table and per-run constants of Beneš's dissolution erosion (see dissolution.hpp).
#include "core/params/dissolution.hpp"

#include <cmath>

namespace gt {
namespace {

constexpr Choice<DissolutionShare> share_choices[] = {{"pairwise", DissolutionShare::pairwise},
                                                      {"mean_level", DissolutionShare::mean_level}};

}  // namespace

const char* dissolution_share_name(DissolutionShare share) { return choice_name(share_choices, share); }

const ParamTable<DissolutionParams>& dissolution_param_table() {
  using P = DissolutionParams;
  static const ParamTable<P> table = {
      integer_param("iterations", &P::iterations, 0, 100000, "count",
                    "iterations (rain, evaporation, dissolution, transport each)"),
      real_param("rain", &P::rain, 0.0, 10.0, "m", "K_r of eq. 2.1: water added to every valid cell each iteration"),
      real_param("evaporation", &P::evaporation, 0.0, 50.0, "1/iteration",
                 "K_e of eq. 2.2: the water kept is d·e^{-K_e} each iteration"),
      real_param("evaporation_threshold", &P::evaporation_threshold, 0.0, 10.0, "m",
                 "T of eq. 2.3: subtracted after evaporation; water below it dries up"),
      real_param("saturation", &P::saturation, 0.0, 10.0, "1",
                 "K_s of eq. 2.4: material one unit of water can carry (S = K_s·d)"),
      real_param("dissolution_rate", &P::dissolution_rate, 0.0, 1.0, "1",
                 "share of S - s dissolved from the terrain per iteration where s < S (1: eq. 2.5)"),
      real_param("deposition_rate", &P::deposition_rate, 0.0, 1.0, "1",
                 "share of s - S deposited per iteration where s > S (1: eq. 2.5)"),
      choice_param("water_share", &P::water_share, share_choices, "",
                   "water a cell gives before eq. 2.8 shares it: pairwise (the thesis: Σ min(d, Δh/2), clamped to d; "
                   "can overshoot) or mean_level (min(d, h − mean surface of the cell and its lower neighbours))"),
  };
  return table;
}

const ParamSpecs& dissolution_param_specs() {
  static const ParamSpecs specs = param_specs(dissolution_param_table());
  return specs;
}

DissolutionParams dissolution_params_from_json(const nlohmann::json& resolved) {
  return params_from_json(dissolution_param_table(), resolved);
}

DissolutionConstants dissolution_constants(const DissolutionParams& params) {
  return {.rain = params.rain,
          .retained = std::exp(-params.evaporation),
          .evaporation_threshold = params.evaporation_threshold,
          .saturation = params.saturation,
          .dissolution_rate = params.dissolution_rate,
          .deposition_rate = params.deposition_rate,
          .water_share = params.water_share};
}

}  // namespace gt
