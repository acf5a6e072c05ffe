// The import and preprocess stages (thesis 2, 2.2) and the names of every stage.
#include "analysis/pipeline/stages.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/pipeline/heading_part.h"

#include "analysis/core/skeleton.h"
#include "analysis/io/corpus_io.h"
#include "analysis/normalise/skeleton_chains.h"
#include "analysis/synth/demo_corpus.h"

namespace bunraku::analysis::pipeline {

const char* stageName(Stage stage)
{
    switch (stage) {
    case Stage::Import: return "import";
    case Stage::Preprocess: return "preprocess";
    case Stage::Normalise: return "normalise";
    case Stage::Decompose: return "decompose";
    case Stage::Fluctuations: return "fluctuations";
    case Stage::Axes: return "axes";
    }
    return "?";
}

const char* stageTitle(Stage stage)
{
    switch (stage) {
    case Stage::Import: return "Import";
    case Stage::Preprocess: return "Preprocessing (2.2)";
    case Stage::Normalise: return "Normalisation (3)";
    case Stage::Decompose: return "Decomposition (4)";
    case Stage::Fluctuations: return "Spectra and ARMA (4.3.2)";
    case Stage::Axes: return "Motion axes, phase and gains (5)";
    }
    return "?";
}

Result<CorpusInput> makeCorpusInput(Corpus corpus)
{
    if (auto status = validateCorpus(corpus); !status) return status.error();
    CorpusInput input;
    input.key = corpusKey(corpus);
    input.corpus = std::make_shared<const Corpus>(std::move(corpus));
    return input;
}

Result<CorpusInput> importCorpus(const std::string& source)
{
    if (source == "demo") return makeCorpusInput(synth::generateDemoCorpus().corpus);
    auto corpus = io::readCorpus(source);
    if (!corpus) return corpus.error();
    return makeCorpusInput(std::move(corpus).value());
}

std::string headingPartFor(const Corpus& corpus, const std::string& part)
{
    if (corpus.takes.empty()) return part;
    const Take& first = corpus.takes.front();
    if (first.channelIndex(part, "yaw") || !first.skeleton || !first.skeleton->skeleton) return part;
    auto chains = skeletonChains(*first.skeleton);
    if (!chains) return part;
    for (const auto& chain : *chains) {
        if (chain.name != "right_arm" && chain.name != "left_arm") continue;
        const int chest = first.skeleton->skeleton->joints[std::size_t(chain.joints.front())].parent;
        if (chest < 0) continue;
        const std::string& name = first.skeleton->skeleton->joints[std::size_t(chest)].name;
        if (first.channelIndex(name, "yaw")) return name;
    }
    return part;
}

StageKey preprocessKey(StageKey corpus, const PreprocessParameters& p)
{
    return KeyBuilder("preprocess").add(corpus).add(parametersText(p)).key();
}

Result<PreprocessOutput> runPreprocess(const Corpus& corpus, const PreprocessParameters& parameters, const RunControl& control)
{
    if (auto status = validate(parameters); !status) return status.error();
    preprocess::PreprocessOptions options = parameters.options();
    options.headingPart = headingPartFor(corpus, options.headingPart);
    return preprocess::preprocessCorpus(corpus, options, control);
}

} // namespace bunraku::analysis::pipeline
