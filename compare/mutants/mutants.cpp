// The registry of compare/mutants/mutants.hpp: the families' lists joined, look-up, and which
// checks may kill which kind.
#include "compare/mutants/mutants.hpp"

#include <set>

#include <fmt/format.h>

#include "core/closest.hpp"
#include "core/errors.hpp"

namespace gt {
namespace {

std::vector<Mutant> all_mutants() {
  std::vector<Mutant> all;
  for (auto family : {thermal_mutants, dissolution_mutants, pipe_mutants, particle_mutants, beyer_mutants,
                      layered_mutants, noise_mutants, cave_mutants, render_mutants, planet_mutants}) {
    for (auto& mutant : family()) all.push_back(std::move(mutant));
  }
  std::set<std::string> names;
  for (const auto& mutant : all) {
    if (!names.insert(mutant.name).second) throw std::logic_error("mutant registered twice: " + mutant.name);
  }
  return all;
}

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

const char* mutant_kind_name(MutantKind kind) { return kind == MutantKind::one_twin ? "one-twin" : "both-twins"; }

const std::vector<Mutant>& mutants() {
  static const std::vector<Mutant> registry = all_mutants();
  return registry;
}

std::string mutant_family(const Mutant& mutant) { return mutant.name.substr(0, mutant.name.find('.')); }

const Mutant& find_mutant(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& mutant : mutants()) {
    if (mutant.name == name) return mutant;
    names.push_back(mutant.name);
  }
  throw InputError(fmt::format("unknown mutant '{}'{}; `groundtruth mutants --list` shows them", name,
                               did_you_mean(name, names)));
}

bool check_kind_kills(MutantKind kind, const std::string& check_name) {
  // image.*.<twin>_vs_cpu compare the twins' pictures; image.uncovered_share.cpu holds one picture
  // to what was asked.
  const bool compares_pictures = starts_with(check_name, "image.") && check_name.find("_vs_") != std::string::npos;
  const bool compares_twins = starts_with(check_name, "parity.") || compares_pictures;
  const bool compares_reruns = starts_with(check_name, "determinism.");
  // A ledger or invariant of a float twin's own run (a name ending .gpu or .cpu_float) holds that
  // twin to what was asked, so it sees a bug in that twin alone as well; one of ref<double>'s cannot.
  const bool holds_a_float_twin = ends_with(check_name, ".gpu") || ends_with(check_name, ".cpu_float");
  if (kind == MutantKind::one_twin) return compares_twins || compares_reruns || holds_a_float_twin;
  return !compares_twins && !compares_reruns;
}

}  // namespace gt
