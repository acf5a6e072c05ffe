#pragma once
/// Writing the demo corpus to disk: the native corpus folder (analysis/io/corpus_io.h) with the
/// ground truth in its `truth/` subfolder (format: docs/DEMO-CORPUS.md).

#include "analysis/core/result.h"
#include "analysis/synth/demo_corpus.h"

#include <filesystem>

namespace bunraku::analysis::synth {

/// The folder of the ground truth beside a corpus: `corpusFolder / "truth"`.
std::filesystem::path groundTruthFolder(const std::filesystem::path& corpusFolder);

/// Writes demo.corpus with io::writeCorpus into `folder` (replacing it), then the ground truth
/// into groundTruthFolder(folder). On a failure the error names the file.
Status writeDemoCorpus(const DemoCorpus& demo, const std::filesystem::path& folder);

} // namespace bunraku::analysis::synth
