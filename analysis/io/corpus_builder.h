#pragma once
/// A corpus from take files (BVH, CSV, FASTRAK): labels parsed from the file names with a
/// pattern, each file imported with the same options (the BVH part map reported per file), every
/// take brought to one rate when the files' rates differ (reported), the neutral emotion chosen.
/// `bunraku corpus` and the workbench's File > New Corpus from Files both call buildCorpus.
/// Rules: docs/FORMATS.md, "Corpus from files".

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/io/take_reader.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis::io {

/// The default file-name pattern.
inline constexpr const char* kDefaultLabelPattern = "{function}_{emotion}_{take}";

/// Checks a pattern: {function} once, {emotion} and {take} at most once, {any} (or {*}) any
/// number of times, other characters literal; a placeholder directly after another needs a
/// literal between them.
Status checkLabelPattern(std::string_view pattern);

/// The labels of a file name's stem under the pattern: {take} matches digits, the other
/// placeholders the shortest text that lets the rest match; nullopt when the stem does not
/// match. Without {emotion} the emotion is empty; without {take} the index is 0.
std::optional<TakeLabels> parseTakeLabels(std::string_view stem, std::string_view pattern);

/// The take files among `inputs`: files as given, folders expanded to the take files directly
/// inside them, of one format (the .bvh files; without any, the FBX/glTF/Collada files; then the
/// .csv files; else the FASTRAK .txt/.fastrak/.fst files), sorted by name. Errors name a missing input or a folder without
/// take files.
Result<std::vector<std::filesystem::path>> collectTakeFiles(const std::vector<std::filesystem::path>& inputs);

/// A file and the labels it will have in the corpus.
struct CorpusSource {
    std::filesystem::path file;
    TakeLabels labels;
};

/// The labels of every file by `pattern` (checked first). A file that does not match is an
/// error naming it and the pattern; takes without an index are numbered 1, 2, ... in file order
/// within their function x emotion cell; a missing emotion becomes "none".
Result<std::vector<CorpusSource>> labelTakeFiles(const std::vector<std::filesystem::path>& files, std::string_view pattern);

struct CorpusBuildOptions {
    ImportOptions import;       ///< the same for every file (BVH part map, side, units...)
    std::string name;           ///< the corpus's name
    std::string neutralEmotion; ///< empty: "neutral", "normal" or "none" when present, else the first emotion
    double rateHz = 0.0;        ///< 0: the rate most files have (the highest of a tie)
};

/// What happened to one file.
struct CorpusFileReport {
    std::filesystem::path file;
    TakeLabels labels;
    double rateHz = 0.0;      ///< the file's own rate
    Eigen::Index frames = 0;  ///< the file's own frames
    Eigen::Index framesInCorpus = 0;
    std::string partMap;      ///< BVH: "head=Head (name), ...", empty for other formats
    bool resampled = false;
};

struct CorpusBuild {
    Corpus corpus;
    std::vector<CorpusFileReport> files;
    /// Decisions worth saying: the rate chosen and the takes resampled, the neutral emotion.
    std::vector<std::string> notes;
};

/// Imports every source (checking `control` between files and reporting progress), resamples
/// takes whose rate is not the corpus's (skeletons by spherical interpolation of the joints'
/// rotations, their parts posed again; other takes linearly), and validates the corpus. Errors
/// name the file; duplicate labels name both files.
Result<CorpusBuild> buildCorpus(const std::vector<CorpusSource>& sources, const CorpusBuildOptions& options,
                                const RunControl& control = {});

/// The take at another rate (frames at k / toHz over the same duration; linear interpolation of
/// every channel, spherical of a skeleton's rotations, parts re-posed from the skeleton).
Result<Take> resampleTake(const Take& take, double toHz);

} // namespace bunraku::analysis::io
