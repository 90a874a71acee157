// Dotted identifiers: the names of cases and mutants ("erosion.pipe.flux.volcano"). They become
// folder names under --out and shader defines, so only lower-case letters, digits, '_' and single
// dots between non-empty parts are allowed, at most 200 characters: no "../x", "/abs" or "".
#pragma once

#include <string_view>

namespace gt {

bool is_dotted_identifier(std::string_view name);

}  // namespace gt
