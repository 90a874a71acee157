// libFuzzer target: a report.json of arbitrary bytes read as history, merge and a run's workers
// read one (compare/report_diff.hpp read_report: the bounded parse, then report_from_json's
// checks, which diff-reports and --baseline run too). Bad input must end in InputError: an outcome
// it does not know, a field of the wrong type, a case name that is no dotted identifier, JSON
// deeper than the depth limit.
#include <cstddef>
#include <cstdint>

#include "compare/report_diff.hpp"
#include "compare/result.hpp"  // gt::Report, which report_diff.hpp only declares
#include "core/errors.hpp"
#include "fuzz/fuzz_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = gt::fuzz::write_input(data, size, "report.json");
  try {
    (void)gt::read_report(path);
  } catch (const gt::InputError&) {
  }
  return 0;
}
