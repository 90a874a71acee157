// `groundtruth diff-image A B [--json] [--out diff.png] [--tolerance T]`: the image differences of
// compare/checks/image.hpp between any two image files OpenImageIO reads.
//
// Prints on stdout a paragraph — max, mean, RMS, PSNR, pixels beyond the tolerance at the same
// position (strict) and after the 3x3 neighbourhood allowance (tolerant) — or, with as_json, one
// JSON object with every number (psnr_db null when the images are identical). With `out`, writes
// the difference heat map there and the verdict mask beside it as <stem>.mask.png, each under a
// temporary name renamed into place; an output path naming an input is refused.
// Returns the exit status: 0 no pixel fails the neighbourhood-tolerant comparison, 1 some do,
// 2 bad input (unreadable or non-image file, different sizes or channel counts, an output that
// would overwrite an input, an unwritable output), with the reason on stderr as "groundtruth: ...".
#pragma once

#include <filesystem>

namespace gt {

struct DiffImageOptions {
  std::filesystem::path a, b;
  bool as_json = false;
  std::filesystem::path out;       // heat map; empty: no pictures
  double tolerance = 4.0 / 255.0;  // per channel, in OpenImageIO's normalised values
};

int diff_image_command(const DiffImageOptions& options);

}  // namespace gt
