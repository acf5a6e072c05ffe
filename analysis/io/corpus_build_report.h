#pragma once
/// What building a corpus from take files did (`bunraku corpus`): per file its labels, frames,
/// rate and part map, as JSON and as a table, with the build's notes.

#include "analysis/io/corpus_builder.h"

#include <nlohmann/json.hpp>

#include <string>

namespace bunraku::analysis::io {

/// One entry per file: file, function, emotion, take, frames, rate_hz, frames_in_corpus,
/// resampled, part_map.
nlohmann::json corpusBuildFilesJson(const CorpusBuild& build);
/// A line per file (columns as wide as their longest entry), then a "note:" line per note.
std::string corpusBuildTable(const CorpusBuild& build);

} // namespace bunraku::analysis::io
