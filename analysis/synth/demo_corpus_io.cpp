#include "analysis/synth/demo_corpus_io.h"

#include "analysis/io/corpus_io.h"

namespace bunraku::analysis::synth {

std::filesystem::path groundTruthFolder(const std::filesystem::path& corpusFolder) { return corpusFolder / "truth"; }

Status writeDemoCorpus(const DemoCorpus& demo, const std::filesystem::path& folder)
{
    // The corpus first: writeCorpus swaps the whole folder in, so the truth must come after.
    if (Status status = io::writeCorpus(demo.corpus, folder); !status) return status;
    return writeGroundTruth(demo.truth, groundTruthFolder(folder));
}

} // namespace bunraku::analysis::synth
