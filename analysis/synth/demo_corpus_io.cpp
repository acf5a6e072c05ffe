#include "analysis/synth/demo_corpus_io.h"

#include "analysis/io/corpus_io.h"
#include "analysis/io/staged_folder.h"

namespace bunraku::analysis::synth {

std::filesystem::path groundTruthFolder(const std::filesystem::path& corpusFolder) { return corpusFolder / "truth"; }

Status writeDemoCorpus(const DemoCorpus& demo, const std::filesystem::path& folder)
{
    auto staged = io::StagedFolder::begin(folder);
    if (!staged) return staged.error();
    if (Status status = io::writeCorpusFiles(demo.corpus, *staged); !status) return status;
    if (Status status = writeGroundTruthFiles(demo.truth, *staged, "truth"); !status) return status;
    return staged->commit();
}

Result<bool> writeCorpusKeepingTruth(const Corpus& corpus, const std::filesystem::path& folder, const std::filesystem::path& truthOf)
{
    auto staged = io::StagedFolder::begin(folder);
    if (!staged) return staged.error();
    if (Status status = io::writeCorpusFiles(corpus, *staged); !status) return status.error();
    const std::filesystem::path source = groundTruthFolder(truthOf);
    std::error_code ec;
    const bool hasTruth = std::filesystem::is_regular_file(source / "truth.json", ec);
    if (hasTruth)
        if (Status status = staged->copyFolder(source, "truth"); !status) return status.error();
    if (Status status = staged->commit(); !status) return status.error();
    return hasTruth;
}

} // namespace bunraku::analysis::synth
