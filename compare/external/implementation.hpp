// An outside implementation of an algorithm, as the user names it: a shared library exposing the
// C Basic Model Interface (include/groundtruth/bmi.h) and the registration function that fills it.
//
// parse_implementation("libmine.so:register_mine") -> {library, "register_mine"}; without ":NAME"
// the function is register_bmi. Throws InputError for an empty library or symbol.
#pragma once

#include <filesystem>
#include <string>

namespace gt {

struct ExternalImplementation {
  std::filesystem::path library;           // absolute once parsed
  std::string register_symbol = "register_bmi";
  std::string text() const { return library.string() + ":" + register_symbol; }
  // The name it is shown by: the library's file name.
  std::string label() const { return library.filename().string(); }
};

ExternalImplementation parse_implementation(const std::string& text);

}  // namespace gt
