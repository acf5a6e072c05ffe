#pragma once
/// The one way the project's JSON readers parse a document: every error of the JSON library (a
/// syntax error, ill-formed UTF-8, a number beyond a double such as 1e400) comes back as a Parse
/// error "file:line: what" on one line, never as an exception escaping to the caller.

#include "analysis/core/result.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace bunraku::analysis::io {

/// The parsed document, or a Parse error naming `sourceName`, the line of the fault and
/// `expectation` ("expected JSON: " + the library's reason, bytes outside printable ASCII
/// written as \xNN).
Result<nlohmann::json> parseJsonText(std::string_view text, const std::string& sourceName,
                                     const std::string& expectation = "expected JSON");

/// The library's message of `error` without its "[json.exception...]" and "parse error at line
/// L, column C:" prefixes, printable on one line, at most 200 characters.
std::string jsonErrorReason(const nlohmann::json::exception& error);

} // namespace bunraku::analysis::io
