#include "app/analysis_controller.h"

#include "analysis/axis/segment_inertia.h"

#include "analysis/body/body_description.h"
#include "analysis/body/body_fit.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton.h"
#include "analysis/io/atomic_file.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/report/html_report.h"

#include <QCoreApplication>
#include <QScopedValueRollback>

namespace bunraku::app {

namespace pl = analysis::pipeline;

namespace {

using Controller = AnalysisController;
// Each slot with its result type (and its stage, where its results are filed in the cache).
constexpr TypedSlot<pl::PreprocessOutput> kPreprocess{Controller::kPreprocessSlot, pl::Stage::Preprocess};
constexpr TypedSlot<pl::NormaliseOutput> kNormalise{Controller::kNormaliseSlot, pl::Stage::Normalise};
constexpr TypedSlot<pl::DecomposeOutput> kDecompose{Controller::kDecomposeSlot, pl::Stage::Decompose};
constexpr TypedSlot<pl::AxisOutput> kAxes{Controller::kAxesSlot, pl::Stage::Axes};
constexpr TypedSlot<analysis::BodyMotion> kNormalisedBody{Controller::kNormalisedBodySlot, std::nullopt};
constexpr TypedSlot<analysis::BodyMotion> kWeightedBody{Controller::kWeightedSlot, std::nullopt};
TypedSlot<pl::TakeAxis> takeAxisOf(TakeSlot slot) { return {Controller::takeAxisSlot(slot), std::nullopt}; }
TypedSlot<analysis::KimonoSimulation> kimonoOf(TakeSlot slot) { return {Controller::kimonoSlot(slot), std::nullopt}; }

} // namespace

QString AnalysisController::slotTitle(int slot)
{
    switch (slot) {
    case kPreprocessSlot: return tr("Preprocessing");
    case kNormaliseSlot: return tr("Normalisation");
    case kDecomposeSlot: return tr("Decomposition");
    case kAxesSlot: return tr("Motion axes");
    case kTakeAxisSlot: return tr("Motion axis of take A");
    case kTakeAxisBSlot: return tr("Motion axis of take B");
    case kNormalisedBodySlot: return tr("Normalised take as one body");
    case kWeightedSlot: return tr("Weighted take");
    case kKimonoSlot: return tr("Kimono of take A");
    case kKimonoBSlot: return tr("Kimono of take B");
    }
    return QString();
}

AnalysisController::AnalysisController(Document& document, QObject* parent, std::shared_ptr<Executor> executor)
    : QObject(parent),
      m_document(document),
      m_stageCache(std::make_shared<pl::StageCache>()),
      m_scheduler(new StageScheduler(this, std::move(executor), m_stageCache))
{
    connect(m_scheduler, &StageScheduler::finished, this, &AnalysisController::stageFinished);
    connect(m_scheduler, &StageScheduler::failed, this, [this](int slot, const QString& message) {
        if (slot != kWeightedSlot) return;
        m_weightError = message;
        emit weightedChanged();
    });
    connect(&document, &Document::corpusChanged, this, &AnalysisController::corpusChanged);
    connect(&document, &Document::parametersChanged, this, [this](ParameterSections sections) {
        if (sections & (kPreprocessSection | kNormaliseSection | kDecomposeSection | kAxisSection)) update();
        if (sections & kWeightSection) synthesiseWeighted();
        if (sections & kAxisSection) {
            requestTakeAxis(TakeSlot::A);
            requestTakeAxis(TakeSlot::B);
        }
    });
    // Take A renamed (a live take recomputed with the same content): its axis is renamed too.
    connect(&document, &Document::takeLabelChanged, this, [this](const TakeId& id) {
        if (id != m_document.selectedId(TakeSlot::A) || !m_axisTakes[0] || m_document.take(id) != m_axisTakes[0]) return;
        m_axisLabels[0] = m_document.takeLabel(id);
        if (isCurrent(kTakeAxisSlot)) publishAxis();
    });
    // The take shown recomputed (a design drag step): its axis and kimono follow; its cell, and
    // so the normalised and weighted takes, are the same (resolveCell keeps a live take's cell).
    connect(&document, &Document::selectedTakeReplaced, this, [this](TakeSlot slot) {
        requestTakeAxis(slot);
        requestKimono(slot);
    });
    connect(&document, &Document::selectionChanged, this, [this](TakeSlot slot) {
        requestTakeAxis(slot);
        requestKimono(slot);
        if (slot != TakeSlot::A) return;
        resolveCell();
        publishNormalised();
        synthesiseWeighted();
    });
    corpusChanged();
}

bool AnalysisController::isCurrent(int slot) const
{
    return m_scheduler->state(slot) == SlotState::Finished;
}

void AnalysisController::corpusChanged()
{
    m_preprocessed.reset();
    m_normalised.reset();
    m_decomposed.reset();
    m_axes.reset();
    m_weighted.reset();
    m_weightError.clear();
    m_function.clear();
    m_emotion.clear();
    m_corpus = {};
    // The results above were let go: the stages are asked again, so that each one announces its
    // result, from the cache at once when the corpus is the one it was (a corpus opened again).
    for (int slot : {kPreprocessSlot, kNormaliseSlot, kDecomposeSlot, kAxesSlot}) m_scheduler->clear(slot);
    for (TakeSlot take : {TakeSlot::A, TakeSlot::B}) { // the axis take is published again too
        m_scheduler->clear(takeAxisSlot(take));
        m_scheduler->clear(kimonoSlot(take));
    }
    if (!m_document.corpus().takes.empty()) {
        m_corpus.corpus = m_document.sharedCorpus();
        m_corpus.key = pl::corpusKey(*m_corpus.corpus);
    }
    resolveCell();
    update();
    requestTakeAxis(TakeSlot::A);
    requestTakeAxis(TakeSlot::B);
    requestKimono(TakeSlot::A);
    requestKimono(TakeSlot::B);
}

void AnalysisController::update()
{
    if (!m_corpus.corpus) {
        for (int slot : {kPreprocessSlot, kNormaliseSlot, kDecomposeSlot, kAxesSlot}) m_scheduler->clear(slot);
        return;
    }
    const pl::ChainParameters parameters = m_document.parameters();
    m_keys = pl::chainKeys(m_corpus.key, parameters);
    auto cache = m_stageCache;
    const pl::CorpusInput corpus = m_corpus;
    m_scheduler->request(kPreprocess, m_keys.preprocess, [corpus, parameters, cache](const analysis::RunControl& control) {
        return pl::preprocessStage(corpus, parameters.preprocess, cache.get(), control);
    });
    // A stage starts once its input for the current keys is there; until then a running job of
    // an older key is cancelled (its inputs changed) and the last result stays shown.
    const auto pre = m_scheduler->result(kPreprocess);
    if (pre) {
        const pl::StageKey preKey = m_keys.preprocess;
        m_scheduler->request(kNormalise, m_keys.normalise, [pre, preKey, parameters, cache](const analysis::RunControl& control) {
            return pl::normaliseStage(preKey, *pre, parameters.normalise, cache.get(), control);
        });
    } else {
        m_scheduler->clear(kNormaliseSlot);
    }
    const auto normalised = m_scheduler->result(kNormalise);
    const bool fromNormalised = parameters.decompose.input == pl::DecomposeInput::Normalised;
    if (fromNormalised ? bool(normalised) : bool(pre)) {
        const pl::StageKey inputKey = fromNormalised ? m_keys.normalise : m_keys.preprocess;
        std::shared_ptr<const analysis::Corpus> input =
            fromNormalised ? std::shared_ptr<const analysis::Corpus>(normalised, &normalised->normalised)
                           : std::shared_ptr<const analysis::Corpus>(pre, &pre->corpus);
        m_scheduler->request(kDecompose, m_keys.decompose, [input, inputKey, parameters, cache](const analysis::RunControl& control) {
            return pl::decomposeStage(inputKey, *input, parameters.decompose, cache.get(), control);
        });
    } else {
        m_scheduler->clear(kDecomposeSlot);
    }
    if (normalised) {
        const pl::StageKey normalisedKey = m_keys.normalise;
        const std::string neutral = m_corpus.corpus->neutralEmotion;
        m_scheduler->request(kAxes, m_keys.axes, [normalised, normalisedKey, neutral, parameters, cache](const analysis::RunControl& control) {
            return pl::axisStage(normalisedKey, *normalised, neutral, parameters.axis, cache.get(), control);
        });
    } else {
        m_scheduler->clear(kAxesSlot);
    }
}

void AnalysisController::stageFinished(int slot)
{
    switch (slot) {
    case kPreprocessSlot:
        m_preprocessed = m_scheduler->result(kPreprocess);
        update();
        break;
    case kNormaliseSlot:
        // Only a result for the current key is delivered: it was computed with these parameters.
        m_normalised = m_scheduler->result(kNormalise);
        m_normalisedParameters = m_document.parameters().normalise;
        publishNormalised();
        update();
        break;
    case kDecomposeSlot:
        m_decomposed = m_scheduler->result(kDecompose);
        resolveCell();
        synthesiseWeighted();
        break;
    case kAxesSlot:
        m_axes = m_scheduler->result(kAxes);
        break;
    case kTakeAxisSlot: publishAxis(); break;
    case kKimonoSlot: publishKimono(); break;
    case kNormalisedBodySlot:
        if (auto body = m_scheduler->result(kNormalisedBody)) {
            const QScopedValueRollback<bool> publishing(m_publishing, true);
            m_document.setLiveBody(QStringLiteral("normalised"), m_pendingNormalisedLabel, *body, m_pendingNormalisedGhost);
        }
        break;
    case kWeightedSlot:
        if (auto body = m_scheduler->result(kWeightedBody)) {
            const QScopedValueRollback<bool> publishing(m_publishing, true);
            m_weightError.clear();
            m_weighted = m_document.setLiveBody(QStringLiteral("weighted"), m_pendingWeightedLabel, *body);
            emit weightedChanged();
        }
        break;
    }
    emit resultChanged(slot);
}

void AnalysisController::resolveCell()
{
    const TakeId idA = m_document.selectedId(TakeSlot::A);
    const TakePointer takeA = m_document.take(idA);
    if (takeA && idA.isCorpus()) {
        m_function = takeA->labels.function;
        m_emotion = takeA->labels.emotion;
    } else if (m_function.empty() && !m_document.corpus().takes.empty()) {
        // A shows a derived take (a project may reopen on one): start from the corpus's first take.
        m_function = m_document.corpus().takes.front().labels.function;
        m_emotion = m_document.corpus().takes.front().labels.emotion;
    }
}

std::pair<std::string, std::string> AnalysisController::weightedCell() const
{
    const std::string& neutral = m_document.corpus().neutralEmotion;
    if (m_emotion != neutral || !m_decomposed) return {m_function, m_emotion};
    // The neutral emotion has z = 0: weight the chosen emotion of the function, else its first.
    const auto& emotions = m_decomposed->components.emotions;
    for (const auto& component : emotions)
        if (component.function == m_function && component.emotion == m_weightEmotion && component.emotion != neutral)
            return {m_function, component.emotion};
    for (const auto& component : emotions)
        if (component.function == m_function && component.emotion != neutral) return {m_function, component.emotion};
    return {m_function, m_emotion};
}

void AnalysisController::setWeightEmotion(const QString& emotion)
{
    if (emotion.toStdString() == m_weightEmotion) return;
    m_weightEmotion = emotion.toStdString();
    synthesiseWeighted();
}

QStringList AnalysisController::weightableEmotions() const
{
    QStringList emotions;
    if (!m_decomposed) return emotions;
    for (const auto& component : m_decomposed->components.emotions)
        if (component.function == m_function && component.emotion != m_document.corpus().neutralEmotion)
            emotions << QString::fromStdString(component.emotion);
    return emotions;
}

QString AnalysisController::normaliseParametersText(const pl::NormaliseParameters& parameters)
{
    QString text = tr("tau %1, T_cmp %2, scales 1-%3").arg(parameters.tau).arg(parameters.searchBand).arg(parameters.maxScale);
    const pl::NormaliseParameters defaults;
    if (parameters.coupling != defaults.coupling) text += tr(", coupling %1").arg(QString::fromStdString(parameters.coupling));
    // Always named: the default (optimal) is not the thesis's (greedy), so neither goes without saying.
    return text + tr(", %1 path").arg(QString::fromStdString(pl::pathName(parameters.path)));
}

QString AnalysisController::decompositionText(const pl::DecomposeOutput& decomposed)
{
    if (!decomposed.km2o) return tr("least squares");
    // Cells with one take (docs/KM2O.md): KM2O may be estimable for none or only some cells.
    if (!decomposed.km2o->estimable()) return tr("least squares (KM2O not estimable: no cell has two takes)");
    const bool partial = !decomposed.km2o->notes.empty();
    return tr("KM2O, M = %1%2%3")
        .arg(decomposed.km2o->correlationLength)
        .arg(decomposed.parameters.correlationLength == 0 ? tr(" (chosen by P)") : QString())
        .arg(partial ? QStringLiteral("; ") + QString::fromStdString(decomposed.km2o->outcome()) : QString());
}

void AnalysisController::publishNormalised()
{
    // Publishing the take shown as A announces a new selection, which would publish it again.
    if (m_publishing) return;
    const QScopedValueRollback<bool> publishing(m_publishing, true);
    TakeId idA = m_document.selectedId(TakeSlot::A);
    // A derived take shown as A (the normalised take itself, or another): the normalised take is
    // recomputed for the corpus take it was computed from, never kept with older parameters.
    if (!idA.isCorpus()) {
        const TakeId normalised = TakeId::live(QStringLiteral("normalised"));
        for (const auto& derived : m_document.derivedTakes())
            if (derived.id == normalised) idA = derived.ghostId;
    }
    const TakePointer takeA = m_document.take(idA);
    if (!m_normalised || !takeA || !idA.isCorpus()) return;
    const pl::CellNormalisation* cell = m_normalised->cell(takeA->labels.function, takeA->labels.emotion);
    if (!cell) return;
    for (std::size_t k = 0; k < cell->takeIndices.size(); ++k) {
        if (cell->takeIndices[k] != takeA->labels.takeIndex) continue;
        auto take = std::make_shared<analysis::Take>(cell->normalisations[k].normalised);
        take->labels.takeIndex = takeA->labels.takeIndex;
        // The label names the take, its reference and the parameters it was computed with.
        const QString label = tr("%1 normalised to %2 (%3)")
                                  .arg(m_document.takeLabel(idA), QString::fromStdString(cell->referenceName),
                                       normaliseParametersText(m_normalisedParameters));
        if (take->skeleton && take->frameCount() > m_backgroundBodyFrames) {
            // A long take's body is made off the GUI thread (stageFinished publishes it).
            m_pendingNormalisedLabel = label;
            m_pendingNormalisedGhost = idA;
            const pl::StageKey key = pl::KeyBuilder("normalised body").add(m_keys.normalise).add(idA.toString().toStdString()).key();
            m_scheduler->request(kNormalisedBody, key, [take](const analysis::RunControl& control) -> analysis::Result<pl::Shared<analysis::BodyMotion>> {
                auto body = std::make_shared<const analysis::BodyMotion>(analysis::bodyMotion(*take, control));
                if (control.cancelled()) return analysis::makeError(analysis::ErrorCode::Cancelled, "cancelled");
                return body;
            });
            return;
        }
        m_scheduler->clear(kNormalisedBodySlot);
        m_document.setLiveTake(QStringLiteral("normalised"), label, take, idA);
        return;
    }
}

void AnalysisController::synthesiseWeighted()
{
    // As publishNormalised: the weighted take shown as A announces a new selection when it is
    // replaced, which must not synthesise it again.
    if (m_publishing || !m_decomposed || m_function.empty()) return;
    const QScopedValueRollback<bool> publishing(m_publishing, true);
    const auto [function, emotion] = weightedCell();
    const double weight = m_document.parameters().design.emotionWeight;
    const QString label = tr("%1/%2 a=%3 (%4)")
                              .arg(QString::fromStdString(function), QString::fromStdString(emotion))
                              .arg(weight, 0, 'f', 2)
                              .arg(decompositionText(*m_decomposed));
    qint64 frames = 0;
    for (const auto& component : m_decomposed->components.functions)
        if (component.function == function) frames = component.values.rows();
    if (frames > m_backgroundBodyFrames) {
        // A long take: y + a z and its body off the GUI thread (stageFinished publishes it).
        m_pendingWeightedLabel = label;
        const pl::StageKey key = pl::KeyBuilder("weighted body").add(m_keys.decompose).add(function).add(emotion).add(weight).key();
        m_scheduler->request(kWeightedBody, key,
                             // Init-captures: clang 14 (the sanitizer builds) cannot capture structured bindings.
                             [decomposed = m_decomposed, function = function, emotion = emotion, weight](const analysis::RunControl& control)
                                 -> analysis::Result<pl::Shared<analysis::BodyMotion>> {
                                 auto take = pl::weightedTake(*decomposed, function, emotion, weight);
                                 if (!take) return take.error();
                                 control.report(0.5);
                                 auto body = std::make_shared<const analysis::BodyMotion>(
                                     analysis::bodyMotion(std::move(take).value(), control.step(0.5, 1.0)));
                                 if (control.cancelled()) return analysis::makeError(analysis::ErrorCode::Cancelled, "cancelled");
                                 return body;
                             });
        return;
    }
    m_scheduler->clear(kWeightedSlot);
    auto take = pl::weightedTake(*m_decomposed, function, emotion, weight);
    if (!take) {
        m_weightError = QString::fromStdString(take.error().message);
        emit weightedChanged();
        return;
    }
    m_weightError.clear();
    m_weighted = std::make_shared<const analysis::Take>(std::move(take).value());
    // As published: the weighted body's motion (Document::setLiveTake).
    m_weighted = m_document.setLiveTake(QStringLiteral("weighted"), label, m_weighted);
    emit weightedChanged();
}

void AnalysisController::publishAxis()
{
    const auto axis = m_scheduler->result(takeAxisOf(TakeSlot::A));
    if (!axis) return;
    const pl::Shared<analysis::Take> coordinates(axis, &axis->coordinates);
    // Named as the take it was computed from is listed (an imported file's name, a designed
    // take's recipe), not by the take's own labels (a derived take has none of its own).
    m_document.setLiveTake(QStringLiteral("axis"), tr("motion axis of %1").arg(m_axisLabels[0]), coordinates);
}

void AnalysisController::publishKimono()
{
    const auto simulated = kimono(TakeSlot::A, m_kimonoTakes[0]);
    if (!m_kimonoShown) {
        if (m_document.take(TakeId::live(QStringLiteral("kimono")))) m_document.setLiveTake(QStringLiteral("kimono"), QString(), nullptr);
        return;
    }
    if (!simulated || !m_kimonoTakes[0]) return;
    const QString label = m_document.takeLabel(m_document.selectedId(TakeSlot::A));
    m_document.setLiveTake(QStringLiteral("kimono"), tr("kimono of %1").arg(label),
                           std::make_shared<const analysis::Take>(analysis::kimonoTake(*m_kimonoTakes[0], *simulated)));
}

void AnalysisController::requestTakeAxis(TakeSlot slot)
{
    const int id = takeAxisSlot(slot);
    const TakePointer take = m_document.selectedTake(slot);
    TakePointer& asked = m_axisTakes[slot == TakeSlot::A ? 0 : 1];
    QString& label = m_axisLabels[slot == TakeSlot::A ? 0 : 1];
    // Nothing to pose (an axis take, for one): the axis needs the puppet's parts or a skeleton's
    // joints (the performer's segments).
    if (!take || !(analysis::hasPuppetLayout(*take) || analysis::usesSegmentModel(*take))) {
        asked.reset();
        label.clear();
        m_scheduler->clear(id);
        return;
    }
    const pl::AxisParameters parameters = m_document.parameters().axis;
    asked = take;
    label = m_document.takeLabel(m_document.selectedId(slot));
    m_scheduler->request(takeAxisOf(slot), pl::takeAxisKey(pl::takeKey(*take), parameters),
                         [take, parameters](const analysis::RunControl& control) -> analysis::Result<pl::Shared<pl::TakeAxis>> {
                             auto axis = pl::runTakeAxis(*take, parameters, control);
                             if (!axis) return axis.error();
                             return std::make_shared<const pl::TakeAxis>(std::move(axis).value());
                         });
}

analysis::BodyDescription AnalysisController::viewBody(const analysis::Take& take)
{
    return take.skeleton ? analysis::bodyForTake(analysis::defaultBodyDescription(), take) : analysis::defaultBodyDescription();
}

void AnalysisController::setKimonoShown(bool shown)
{
    if (shown == m_kimonoShown) return;
    m_kimonoShown = shown;
    requestKimono(TakeSlot::A);
    requestKimono(TakeSlot::B);
    if (!shown) publishKimono(); // the "kimono" take goes with the cloth
}

analysis::Status AnalysisController::setClothParameters(const analysis::ClothParameters& parameters)
{
    if (auto status = analysis::validate(parameters); !status) return status;
    m_clothParameters = parameters;
    requestKimono(TakeSlot::A);
    requestKimono(TakeSlot::B);
    emit clothParametersChanged(m_clothParameters);
    return analysis::okStatus();
}

void AnalysisController::requestKimono(TakeSlot slot)
{
    const int id = kimonoSlot(slot);
    const TakePointer take = m_document.selectedTake(slot);
    TakePointer& asked = m_kimonoTakes[slot == TakeSlot::A ? 0 : 1];
    if (!m_kimonoShown || !take || !analysis::hasPuppetLayout(*take)) {
        asked.reset();
        m_scheduler->clear(id);
        return;
    }
    asked = take;
    // The key: the take's content, its skeleton's bones (the body is fitted to them) and the
    // cloth parameters; the body itself is fitted in the job, off the GUI thread.
    pl::KeyBuilder key("view-kimono");
    key.add(pl::kimonoKey(pl::takeKey(*take), analysis::defaultBodyDescription(), m_clothParameters));
    if (take->skeleton && take->skeleton->skeleton) {
        const analysis::Skeleton& skeleton = *take->skeleton->skeleton;
        key.add(std::int64_t(skeleton.joints.size()));
        for (const auto& joint : skeleton.joints) key.add(joint.name).add(joint.offset.x()).add(joint.offset.y()).add(joint.offset.z());
        for (const Eigen::Vector3d& t : take->skeleton->staticTranslations) key.add(t.x()).add(t.y()).add(t.z());
    }
    const analysis::ClothParameters parameters = m_clothParameters;
    m_scheduler->request(kimonoOf(slot), key.key(),
                         [take, parameters](const analysis::RunControl& control) -> analysis::Result<pl::Shared<analysis::KimonoSimulation>> {
                             auto kimono = pl::runKimono(*take, viewBody(*take), parameters, control);
                             if (!kimono) return kimono.error();
                             return std::make_shared<const analysis::KimonoSimulation>(std::move(kimono).value());
                         });
}

pl::Shared<analysis::KimonoSimulation> AnalysisController::kimono(TakeSlot slot, const TakePointer& take) const
{
    if (!take || m_kimonoTakes[slot == TakeSlot::A ? 0 : 1] != take) return nullptr;
    return m_scheduler->result(kimonoOf(slot));
}

pl::Shared<pl::TakeAxis> AnalysisController::takeAxis(TakeSlot slot, const TakePointer& take) const
{
    if (!take || m_axisTakes[slot == TakeSlot::A ? 0 : 1] != take) return nullptr;
    return m_scheduler->result(takeAxisOf(slot));
}

analysis::Result<std::string> AnalysisController::reportHtml() const
{
    if (!m_corpus.corpus) return analysis::makeError(analysis::ErrorCode::InvalidArgument, "no corpus is open");
    pl::ChainOptions chainOptions;
    chainOptions.threads = m_scheduler->threads();
    auto chain = pl::runChain(m_corpus, m_document.parameters(), m_stageCache.get(), chainOptions);
    if (!chain) return chain.error();
    analysis::report::ReportOptions options;
    options.title = "Bunraku motion analysis: " + (m_corpus.corpus->name.empty() ? std::string("corpus") : m_corpus.corpus->name);
    options.corpusSource = m_document.corpusSource().toStdString();
    options.generator = "Bunraku Motion Workbench, File > Export Report";
    return analysis::report::htmlReport(*chain, m_document.parameters(), options);
}

analysis::Status AnalysisController::exportReport(const std::filesystem::path& file) const
{
    auto html = reportHtml();
    if (!html) return html.error();
    return analysis::io::writeFileAtomically(file, *html);
}

} // namespace bunraku::app
