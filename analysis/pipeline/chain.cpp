#include "analysis/pipeline/chain.h"

namespace bunraku::analysis::pipeline {
namespace {

/// The cached result of `stage` under `key`, or `compute()` stored under it.
template <class T, class Compute>
Result<Shared<T>> cached(StageCache* cache, Stage stage, StageKey key, Compute&& compute)
{
    if (cache)
        if (Shared<T> found = cache->find<T>(stage, key)) return found;
    Result<T> computed = compute();
    if (!computed) return computed.error();
    auto value = std::make_shared<const T>(std::move(computed).value());
    if (cache) {
        cache->countRun(stage);
        cache->store<T>(stage, key, value);
    }
    return Shared<T>(std::move(value));
}

} // namespace

StageKey ChainKeys::of(Stage stage) const
{
    switch (stage) {
    case Stage::Import: return import;
    case Stage::Preprocess: return preprocess;
    case Stage::Normalise: return normalise;
    case Stage::Decompose: return decompose;
    case Stage::Fluctuations: return fluctuations;
    case Stage::Axes: return axes;
    }
    return {};
}

ChainKeys chainKeys(StageKey corpus, const ChainParameters& p)
{
    ChainKeys keys;
    keys.import = corpus;
    keys.preprocess = preprocessKey(corpus, p.preprocess);
    keys.normalise = normaliseKey(keys.preprocess, p.normalise);
    keys.decompose = decomposeKey(p.decompose.input == DecomposeInput::Normalised ? keys.normalise : keys.preprocess, p.decompose);
    keys.fluctuations = fluctuationKey(keys.decompose, p.fluctuations);
    keys.axes = axisKey(keys.normalise, p.axis);
    return keys;
}

Result<Shared<PreprocessOutput>> preprocessStage(const CorpusInput& corpus, const PreprocessParameters& parameters, StageCache* cache,
                                                 const RunControl& control)
{
    return cached<PreprocessOutput>(cache, Stage::Preprocess, preprocessKey(corpus.key, parameters),
                                    [&] { return runPreprocess(*corpus.corpus, parameters, control); });
}

Result<Shared<NormaliseOutput>> normaliseStage(StageKey preprocessedKey, const PreprocessOutput& preprocessed,
                                               const NormaliseParameters& parameters, StageCache* cache, const RunControl& control)
{
    return cached<NormaliseOutput>(cache, Stage::Normalise, normaliseKey(preprocessedKey, parameters),
                                   [&] { return runNormalise(preprocessed.corpus, parameters, control); });
}

Result<Shared<DecomposeOutput>> decomposeStage(StageKey inputKey, const Corpus& input, const DecomposeParameters& parameters,
                                               StageCache* cache, const RunControl& control)
{
    return cached<DecomposeOutput>(cache, Stage::Decompose, decomposeKey(inputKey, parameters),
                                   [&] { return runDecompose(input, parameters, control); });
}

Result<Shared<FluctuationOutput>> fluctuationStage(StageKey decomposedKey, const DecomposeOutput& decomposed,
                                                   const FluctuationParameters& parameters, StageCache* cache,
                                                   const RunControl& control)
{
    return cached<FluctuationOutput>(cache, Stage::Fluctuations, fluctuationKey(decomposedKey, parameters),
                                     [&] { return runFluctuations(decomposed.components, parameters, control); });
}

Result<Shared<AxisOutput>> axisStage(StageKey normalisedKey, const NormaliseOutput& normalised, const std::string& neutralEmotion,
                                     const AxisParameters& parameters, StageCache* cache, const RunControl& control)
{
    return cached<AxisOutput>(cache, Stage::Axes, axisKey(normalisedKey, parameters),
                              [&] { return runAxes(normalised, neutralEmotion, parameters, control); });
}

Result<ChainResult> runChain(const CorpusInput& corpus, const ChainParameters& parameters, StageCache* cache,
                             const ChainOptions& options)
{
    if (auto status = validate(parameters); !status) return status.error();
    ChainResult result;
    result.corpus = corpus;
    result.keys = chainKeys(corpus.key, parameters);
    auto control = [&](Stage stage) {
        return RunControl{options.stop,
                          [&options, stage](double fraction) {
                              if (options.progress) options.progress(stage, fraction);
                          },
                          options.threads};
    };
    auto failed = [](Stage stage, const Error& error) {
        return makeError(error.code, std::string(stageTitle(stage)) + ": " + error.message);
    };
    if (options.progress) options.progress(Stage::Import, 1.0);

    auto preprocessed = preprocessStage(corpus, parameters.preprocess, cache, control(Stage::Preprocess));
    if (!preprocessed) return failed(Stage::Preprocess, preprocessed.error());
    result.preprocessed = *preprocessed;
    if (options.progress) options.progress(Stage::Preprocess, 1.0);

    const bool decompose = options.decomposition || options.fluctuations;
    const bool fromNormalised = parameters.decompose.input == DecomposeInput::Normalised;
    if (options.normalisation || options.axes || (decompose && fromNormalised)) {
        auto normalised = normaliseStage(result.keys.preprocess, *result.preprocessed, parameters.normalise, cache, control(Stage::Normalise));
        if (!normalised) return failed(Stage::Normalise, normalised.error());
        result.normalised = *normalised;
        if (options.progress) options.progress(Stage::Normalise, 1.0);
    }

    if (decompose) {
        auto decomposed = decomposeStage(fromNormalised ? result.keys.normalise : result.keys.preprocess,
                                         fromNormalised ? result.normalised->normalised : result.preprocessed->corpus,
                                         parameters.decompose, cache, control(Stage::Decompose));
        if (!decomposed) return failed(Stage::Decompose, decomposed.error());
        result.decomposed = *decomposed;
        if (options.progress) options.progress(Stage::Decompose, 1.0);
    }

    if (options.fluctuations) {
        auto fluctuations = fluctuationStage(result.keys.decompose, *result.decomposed, parameters.fluctuations, cache,
                                             control(Stage::Fluctuations));
        if (!fluctuations) return failed(Stage::Fluctuations, fluctuations.error());
        result.fluctuations = *fluctuations;
        if (options.progress) options.progress(Stage::Fluctuations, 1.0);
    }
    if (options.axes) {
        auto axes = axisStage(result.keys.normalise, *result.normalised, corpus.corpus->neutralEmotion, parameters.axis, cache,
                              control(Stage::Axes));
        if (!axes) return failed(Stage::Axes, axes.error());
        result.axes = *axes;
        if (options.progress) options.progress(Stage::Axes, 1.0);
    }
    return result;
}

} // namespace bunraku::analysis::pipeline
