// libFuzzer target: a case file (datasets/cases/*.json) of arbitrary bytes, loaded as the driver
// loads --cases, then each case's input resolved (generators, crops; files under the bundled
// datasets folder) as a run would before any algorithm starts. Bad input must end in InputError.
#include <cstddef>
#include <cstdint>

#include "compare/cases.hpp"
#include "compare/inputs.hpp"
#include "core/errors.hpp"
#include "fuzz/fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = gt::fuzz::write_input(data, size, "cases.json");
  try {
    for (const gt::CaseSpec& spec : gt::load_cases(path.parent_path()))
      gt::load_input(spec.input, spec.crop, GT_DATASET_DIR);
  } catch (const gt::InputError&) {
  }
  return 0;
}
