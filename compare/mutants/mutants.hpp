// The mutant registry (issue 11): named, deliberate bugs that prove the checks can fail. Each
// family registers its mutants in compare/mutants/<family>.cpp; core/mutant.hpp holds the switch
// the twins read (a reference's `mutant_active(name)`, a shader's `#ifdef GT_MUTANT_...`).
//
// Two kinds, each to be killed by the kind of check meant for it:
//   one_twin    the bug is in one twin only (usually the GPU): the twins disagree, and a parity
//               check (`parity.*`, or `image.*` where rendered images are compared) must fail, or
//               the twin disagrees with its own rerun (`determinism.*`: state left over from the
//               last run, which the first run, the one compared, cannot show), or the twin's own
//               ledger or invariant fails (a check of the `.gpu` or `.cpu_float` backend: a GPU bug
//               that loses material is seen by the GPU's ledger, as an outside implementation's is);
//   both_twins  the same bug in both twins: they agree with each other, so only a check against
//               something outside them (ledgers against what was asked, spec vectors, invariants:
//               `mass.*`, `spec.*`, `mesh.*`, ...) can fail. Parity and determinism checks do not
//               count for this kind.
// Calibrated pairs: for an error model, one mutant at a few times its bound (killed) and one below
// it (must_survive: it survives, or the check raises false alarms).
// A mutant names the cases that must kill it: small ones, so that the whole registry runs in the
// test suite (tests/mutants_test.cpp) and in `groundtruth report`.
#pragma once

#include <string>
#include <vector>

namespace gt {

enum class MutantKind { one_twin, both_twins };

const char* mutant_kind_name(MutantKind kind);

struct Mutant {
  std::string name;                 // family.algorithm.what, e.g. erosion.pipe.half_rain
  MutantKind kind = MutantKind::one_twin;
  std::string description;          // the bug, one line
  std::vector<std::string> cases;   // case-name patterns run under the mutant; each must match a case
  // A calibration mutant: a deviation an honest twin may show, below its error model's bound. It
  // must survive (no check may fail on it that passed unmutated); its partner above the bound must
  // be killed. Together they show a bound is neither loose nor tight beyond its model.
  bool must_survive = false;
};

// Per family (one file each).
std::vector<Mutant> thermal_mutants();  // compare/mutants/thermal.cpp: erosion.thermal*, erosion family
std::vector<Mutant> dissolution_mutants();  // compare/mutants/dissolution.cpp: erosion.dissolution, erosion family
std::vector<Mutant> pipe_mutants();     // compare/mutants/pipe.cpp: erosion.pipe, erosion family
std::vector<Mutant> particle_mutants();  // compare/mutants/particle.cpp: erosion.particle, erosion family
std::vector<Mutant> beyer_mutants();     // compare/mutants/beyer.cpp: erosion.beyer, erosion family
std::vector<Mutant> layered_mutants();   // compare/mutants/layered.cpp: erosion.layered, erosion family
std::vector<Mutant> noise_mutants();    // compare/mutants/noise.cpp
std::vector<Mutant> cave_mutants();     // compare/mutants/cave.cpp
std::vector<Mutant> render_mutants();   // compare/mutants/render.cpp
std::vector<Mutant> planet_mutants();   // compare/mutants/planet.cpp

// Every registered mutant, in family order.
const std::vector<Mutant>& mutants();

// The family of a mutant: the first component of its name (erosion, noise, cave, render).
std::string mutant_family(const Mutant& mutant);

// Throws InputError naming the closest registered names.
const Mutant& find_mutant(const std::string& name);

// Whether a failing check of this name counts as killing a mutant of this kind.
bool check_kind_kills(MutantKind kind, const std::string& check_name);

}  // namespace gt
