#pragma once
/// The native corpus format: a folder with `corpus.json` (format "bunraku-corpus", version 1,
/// name, rate_hz, units, convention, neutral_emotion, channels, takes[] with function, emotion,
/// take, file, frames) and one CSV per take (take_csv.h). Format: docs/FORMATS.md.

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/io/take_csv.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bunraku::analysis::io {

class StagedFolder;

inline constexpr const char* kCorpusFormatName = "bunraku-corpus";
inline constexpr int kCorpusFormatVersion = 1;

/// True when `folder` contains an entry named corpus.json (readCorpus says when it is not a file).
bool isCorpusFolder(const std::filesystem::path& folder);

/// The most frames corpus.json may declare for one take.
inline constexpr Eigen::Index kMaxCorpusTakeFrames = 100'000'000;

/// What corpus.json says, checked field by field (no take file read yet).
struct CorpusManifest {
    struct Entry {
        TakeLabels labels; ///< source empty when the manifest names none
        std::string file;  ///< relative to the corpus folder, never climbing out of it
        std::optional<Eigen::Index> frames;
        std::string skeleton; ///< the take's skeleton file (skeleton_io.h), empty when it has none
        std::string motion;   ///< its motion file, given with `skeleton`
    };
    std::string name;
    double rateHz = 0.0;
    std::string convention = Corpus{}.convention;
    std::string neutralEmotion = Corpus{}.neutralEmotion;
    std::vector<Channel> channels;
    std::vector<Entry> takes; ///< at least one
};

/// Parses corpus.json text; errors name `sourceName`, the line or field and what was expected.
Result<CorpusManifest> parseCorpusManifest(const std::string& text, const std::string& sourceName);

/// Reads corpus.json and every take CSV it lists. Checks the format name/version, that each
/// CSV's channels match the manifest's, its frame count matches `frames` and its time column
/// the corpus rate, then validateCorpus. `control` is told the fraction of takes read and stops
/// the reading between two takes (Cancelled).
Result<Corpus> readCorpus(const std::filesystem::path& folder, const RunControl& control = {});

/// Writes the corpus (validated first) into `folder`, creating it when needed. The whole folder
/// is built in a hidden sibling and swapped in (staged_folder.h): on failure or a kill the
/// previous contents of `folder` are left untouched, and a folder holding files this program
/// did not write there is refused. Take files are named `<function>_<emotion>_<k>.csv`
/// (characters outside [A-Za-z0-9_-] become '-').
Status writeCorpus(const Corpus& corpus, const std::filesystem::path& folder);
/// The corpus's files (corpus.json and the take CSVs) written into a staged folder, for outputs
/// that add files of their own (the demo's ground truth) before committing.
Status writeCorpusFiles(const Corpus& corpus, StagedFolder& folder);

} // namespace bunraku::analysis::io
