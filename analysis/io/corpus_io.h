#pragma once
/// The native corpus format: a folder with `corpus.json` (format "bunraku-corpus", version 1,
/// name, rate_hz, units, convention, neutral_emotion, channels, takes[] with function, emotion,
/// take, file, frames) and one CSV per take (take_csv.h). Format: docs/FORMATS.md.

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/io/take_csv.h"

#include <filesystem>

namespace bunraku::analysis::io {

inline constexpr const char* kCorpusFormatName = "bunraku-corpus";
inline constexpr int kCorpusFormatVersion = 1;

/// True when `folder` contains a corpus.json.
bool isCorpusFolder(const std::filesystem::path& folder);

/// Reads corpus.json and every take CSV it lists. Checks the format name/version, that each
/// CSV's channels match the manifest's and its frame count matches `frames`, then validateCorpus.
Result<Corpus> readCorpus(const std::filesystem::path& folder);

/// Writes the corpus (validated first) into `folder`, creating it when needed. The whole folder
/// is written into a temporary sibling folder and swapped in by renames, so on failure the
/// previous contents of `folder` are left untouched. Take files are named
/// `<function>_<emotion>_<k>.csv` (characters outside [A-Za-z0-9_-] become '-').
Status writeCorpus(const Corpus& corpus, const std::filesystem::path& folder);

} // namespace bunraku::analysis::io
