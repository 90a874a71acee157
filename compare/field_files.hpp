// Fields as data (issue 19): a case's state fields written for other tools. Each field goes into
// the case's folder as <stem>.exr (float32, NaN no-data) and <stem>.npy (NumPy, shape (height,
// width), NaN no-data; float64 for ref<double>'s fields, backend "cpu", float32 for the others),
// listed as "field" artifacts, and described in the case's fields.json sidecar: the case,
// algorithm, parameters and input it came from, the grid (size, cell size, units), and for every
// file its field, backend ("input", "cpu", "cpu_float", "gpu"), unit, meaning and npy_dtype. Each call adds its entry to fields.json (created on the first call), so the
// parts of a driver that own different fields write them independently. Nothing is written when
// options.report_dir is empty.
//
// A 3-D field (the cave's density) is written by write_volume_field_file as <stem>.npy (float32,
// shape (nz, ny, nx), the array core/io/volume_io.hpp reads back: an ad-hoc cave run takes it as
// --input) and as <stem>.exr, the z slices one under the other (an nx x ny·nz image, row z·ny + y),
// its grid {nx, ny, nz, spacing, origin}. A file on another grid than the
// sidecar's first carries its own "grid".
#pragma once

#include <string>

#include "compare/field_twin.hpp"
#include "compare/result.hpp"
#include "core/grid.hpp"
#include "core/volume.hpp"

namespace gt {

struct FieldFile {
  std::string stem;     // file name without extension, e.g. "water_cpu"
  std::string field;    // e.g. "water"
  std::string backend;  // "input", "cpu", "cpu_float" or "gpu"
  std::string unit;     // e.g. "m", "m/s", "1"
  std::string meaning;  // one line, e.g. "water depth d after the last step, ref<double>"
};

void write_field_files(const Grid<double>& values, const FieldFile& file, const RunOptions& options,
                       CaseResult& result);

void write_volume_field_file(const Volume<double>& values, const FieldFile& file, const RunOptions& options,
                             CaseResult& result);

}  // namespace gt
