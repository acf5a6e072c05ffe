#pragma once
/// Writing the demo corpus to disk: the native corpus folder (analysis/io/corpus_io.h) with the
/// ground truth in its `truth/` subfolder (format: docs/DEMO-CORPUS.md), built and swapped in as
/// one folder (analysis/io/staged_folder.h).

#include "analysis/core/result.h"
#include "analysis/synth/demo_corpus.h"

#include <filesystem>

namespace bunraku::analysis::io {
class StagedFolder;
}

namespace bunraku::analysis::synth {

/// The folder of the ground truth beside a corpus: `corpusFolder / "truth"`.
std::filesystem::path groundTruthFolder(const std::filesystem::path& corpusFolder);

/// Writes demo.corpus and its ground truth into `folder` in one staged write: the folder holds
/// the old content or the new corpus with its truth, never one without the other. On a failure
/// the error names the file.
Status writeDemoCorpus(const DemoCorpus& demo, const std::filesystem::path& folder);

/// Writes `corpus` into `folder` in one staged write together with a copy of the ground truth of
/// the corpus folder `truthOf` (its `truth/`), when it has one. Returns whether a truth was copied.
Result<bool> writeCorpusKeepingTruth(const Corpus& corpus, const std::filesystem::path& folder,
                                     const std::filesystem::path& truthOf);

/// The ground truth's files written into `subfolder` of a staged folder.
Status writeGroundTruthFiles(const DemoGroundTruth& truth, io::StagedFolder& folder, const std::filesystem::path& subfolder);

} // namespace bunraku::analysis::synth
