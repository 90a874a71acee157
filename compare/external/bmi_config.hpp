// The config file groundtruth hands an outside model's BMI initialize(): one case, as text lines
// `key value` (a C model reads it with fscanf, a Python one with split()), `#` starting a comment.
//
//   algorithm erosion.thermal        the algorithm graded
//   case adhoc.erosion.thermal.volcano
//   rows 128                         the grid: rows (y) and columns (x), row-major
//   columns 128
//   spacing_y 10                     the distance between rows and between columns
//   spacing_x 10
//   horizontal_unit m
//   <parameter> <value>              every parameter of the algorithm's table (`groundtruth list`),
//                                    defaults filled in: numbers as %.17g, true/false, bare words
//
// Inputs: the algorithm and case names, the state's grid, the resolved parameters.
// Output: the file at `path` (its folder created); throws std::runtime_error when it cannot be written.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/stepper.hpp"

namespace gt {

void write_bmi_config(const std::filesystem::path& path, const std::string& algorithm, const std::string& case_name,
                      const StateGrid& grid, const nlohmann::json& params);

}  // namespace gt
