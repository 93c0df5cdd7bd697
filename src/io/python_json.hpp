#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace motoflex {

// JSON files written by Python's json module (BAM's logs). Python writes NaN, Infinity and
// -Infinity as bare words, which are not JSON; read_python_json turns each into a marker
// string instead of failing with a syntax error at some byte, so that the caller can name the
// field that holds it (see bare_non_finite_word).

// Reads and parses `path`. Throws InputError(shown, line, "", ...) when the file cannot be read
// or is not JSON (line = the line of the syntax error, counted from 1).
nlohmann::json read_python_json(const std::string& path, const std::string& shown);

// "NaN", "Infinity" or "-Infinity" if `value` stands for one of Python's bare words; empty
// otherwise (including for an ordinary string "NaN").
std::optional<std::string> bare_non_finite_word(const nlohmann::json& value);

}  // namespace motoflex
