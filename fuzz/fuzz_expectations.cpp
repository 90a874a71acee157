// libFuzzer target: an expectations file (datasets/expectations.txt) of arbitrary bytes, judged
// against the bundled case suite. Bad input must end in InputError.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "compare/cases.hpp"
#include "compare/expectations.hpp"
#include "core/errors.hpp"
#include "fuzz/fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::vector<gt::CaseSpec> suite = gt::load_cases(GT_DATASET_DIR "/cases");
  const auto path = gt::fuzz::write_input(data, size, "expectations.txt");
  try {
    gt::load_expectations(path, suite);
  } catch (const gt::InputError&) {
  }
  return 0;
}
