// Strict JSON objects (issue 11): a key nobody reads is a typo that silently drops a check or a
// setting, so every object a user writes (case files, inputs, expectations) is checked against the
// keys its reader knows, and an unknown one is bad input naming the closest known key.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gt {

// Throws InputError "<where>: unknown key 'X' (did you mean 'Y'?); known: ..." for the first key of
// `object` not in `known`. `object` must be a JSON object (else InputError too).
void require_known_keys(const nlohmann::json& object, const std::vector<std::string>& known, const std::string& where);

// The same against a shape, which says what each value must be: null (anything); "number",
// "integer", "boolean" or "string"; an object (a strict object: its keys the known ones, each
// present one checked against its shape); an array of one shape (an array, every element of that
// shape); an array of several shapes (an array of exactly that many elements, each of its shape:
// ["integer", "integer", "number"] is a cell). A case's "expect" is checked this way before any
// case runs, so that a malformed one is refused with exit 2 instead of ending its case in error.
void require_shape(const nlohmann::json& value, const nlohmann::json& shape, const std::string& where);

// object[key] as a whole number in [min, max], or `fallback` when the key is absent. Refuses
// (InputError naming `where` and the key) a value of another type, a fraction, or one outside the
// range, instead of truncating it: 4294967312 is not read as 16.
long long json_integer(const nlohmann::json& object, const std::string& key, long long fallback, long long min,
                       long long max, const std::string& where);

// object[key] as a finite number in [min, max], or `fallback` when absent; refuses other types,
// NaN and infinities the same way.
double json_number(const nlohmann::json& object, const std::string& key, double fallback, double min, double max,
                   const std::string& where);

// The deepest nesting a JSON file we read may have. Case files nest 5 levels and report.json 6;
// copying, comparing and dumping a nlohmann::json recurse once a level, so a file nested 200,000
// levels deep overflowed the stack of every command that read it.
constexpr int max_json_depth = 64;

// `in` parsed as JSON, refused while it is read (InputError "<where>: JSON nested deeper than 64
// levels") before any value deeper than max_json_depth is built. Syntax errors are the parser's
// own exceptions, for the caller to word. The ordered variant keeps the keys' order.
nlohmann::json parse_json_bounded(std::istream& in, const std::string& where);
nlohmann::ordered_json parse_ordered_json_bounded(std::istream& in, const std::string& where);

// object[key] as true/false; `fallback` when absent; InputError (naming `where`) when not a boolean.
bool json_bool(const nlohmann::json& object, const std::string& key, bool fallback, const std::string& where);

}  // namespace gt
