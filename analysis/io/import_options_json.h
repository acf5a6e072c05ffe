#pragma once
/// Import options as JSON: a project stores the options of each imported take (the BVH joint
/// map, up axis, unit scale, position mode and layout; the CSV and FASTRAK rates, units and
/// stations) so that reopening imports the same take. Every field of ImportOptions and of the
/// structs in it is listed once, by name, in import_options_json.cpp (one
/// NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT line per struct): a new field is one more
/// name there. Fields missing from the JSON keep their defaults, so older projects still open.

#include "analysis/core/result.h"
#include "analysis/io/take_reader.h"

#include <nlohmann/json.hpp>

#include <string>

namespace bunraku::analysis::io {

/// Every field of `options` by name.
nlohmann::json importOptionsToJson(const ImportOptions& options);

/// The options stored by importOptionsToJson; Parse errors name `where` (the file and entry),
/// the field and what was expected. Rates, the unit scale and stations are range-checked.
Result<ImportOptions> importOptionsFromJson(const nlohmann::json& json, const std::string& where);

} // namespace bunraku::analysis::io
