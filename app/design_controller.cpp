#include "app/design_controller.h"

#include "app/commands.h"
#include "app/parameters.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/body/body_description.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cmath>


namespace bunraku::app {
namespace {

/// The axis model of the default body, built once (it is the same for every take).
const analysis::AxisModel& defaultAxisModel()
{
    static const analysis::AxisModel model = analysis::makeAxisModel(analysis::defaultBodyDescription());
    return model;
}

QString gainKey(int phrase, int dof) { return QStringLiteral("%1/%2").arg(phrase).arg(dof); }

const QString kDesignedId = QStringLiteral("live/designed");

/// The gain edits ("phrase/dof" -> {g0, g1}) with each phrase index moved by `remap` (-1: dropped).
template <typename Remap> QVariantMap remapGainEdits(const QVariantMap& edits, Remap remap)
{
    QVariantMap result;
    for (auto it = edits.begin(); it != edits.end(); ++it) {
        const QStringList where = it.key().split('/');
        if (where.size() != 2) continue;
        for (int phrase : remap(where[0].toInt())) result.insert(gainKey(phrase, where[1].toInt()), it.value());
    }
    return result;
}

/// Phrase `split` divided in two: both halves keep its gains, later phrases move up by one.
QVariantMap gainsAfterSplit(const QVariantMap& edits, int split)
{
    return remapGainEdits(edits, [split](int phrase) -> std::vector<int> {
        if (phrase < split) return {phrase};
        if (phrase == split) return {phrase, phrase + 1};
        return {phrase + 1};
    });
}

/// Phrases `left` and `left + 1` merged: the merged phrase keeps the gains of `kept` (one of
/// them), later phrases move down by one.
QVariantMap gainsAfterMerge(const QVariantMap& edits, int left, int kept)
{
    return remapGainEdits(edits, [left, kept](int phrase) -> std::vector<int> {
        if (phrase < left) return {phrase};
        if (phrase == kept) return {left};
        if (phrase == left || phrase == left + 1) return {};
        return {phrase - 1};
    });
}

} // namespace

analysis::WarpCurve warpFromVariant(const QVariant& value)
{
    analysis::WarpCurve curve;
    for (const QVariant& entry : value.toList()) {
        const QVariantList pair = entry.toList();
        if (pair.size() == 2) curve.points.push_back({pair[0].toDouble(), pair[1].toDouble()});
    }
    if (!curve.points.empty()) curve.outputFrames = Eigen::Index(std::floor(curve.points.back().output)) + 1;
    return curve;
}

QVariant warpToVariant(const analysis::WarpCurve& curve)
{
    QVariantList list;
    for (const auto& point : curve.points) list.append(QVariant(QVariantList{point.output, point.source}));
    return list;
}

DesignController::DesignController(Document& document, QObject* parent) : QObject(parent), m_document(document)
{
    m_recomputer = new Recomputer(
        document, [this] { return snapshot(); }, [this](const JobOutput& output) { accept(output); }, this, 20,
        [this] { return m_inputSerial; });
    m_recomputer->setObjectName(tr("Design preparation"));
    connect(&document, &Document::corpusChanged, this, [this] {
        m_prepared.reset();
        m_designed.reset();
        m_sourceId.clear();
        m_targetId.clear();
        resolveInputs();
    });
    connect(&document, &Document::selectionChanged, this, [this](TakeSlot slot) {
        if (slot == TakeSlot::A) resolveInputs();
    });
    connect(&document, &Document::parameterChanged, this, [this](const QString& key) {
        if (key == parameters::kDesignWarp || key == parameters::kDesignGains || key == parameters::kDesignBoundaries)
            redesign();
    });
}

void DesignController::resolveInputs()
{
    const auto& corpus = m_document.corpus();
    const QString idA = m_document.selectedId(TakeSlot::A);
    const TakePointer takeA = m_document.take(idA);
    if (!takeA || !idA.startsWith(QStringLiteral("corpus/"))) return; // keep the current design inputs
    const std::string& function = takeA->labels.function;
    QString source;
    QString target;
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        const auto& labels = corpus.takes[i].labels;
        if (labels.function != function) continue;
        if (labels.emotion == corpus.neutralEmotion && source.isEmpty()) source = Document::corpusTakeId(i);
        if (labels.emotion != corpus.neutralEmotion && target.isEmpty()) target = Document::corpusTakeId(i);
    }
    if (takeA->labels.emotion != corpus.neutralEmotion) target = idA;
    if (source.isEmpty()) source = idA;
    if (source == m_sourceId && target == m_targetId) return;
    m_sourceId = source;
    m_targetId = target;
    ++m_inputSerial;
    m_recomputer->schedule();
}

Job DesignController::snapshot()
{
    const TakePointer source = m_document.take(m_sourceId);
    if (!source) return {};
    const TakePointer target = m_document.take(m_targetId);
    const QString sourceId = m_sourceId;
    const QString targetId = m_targetId;
    return [source, target, sourceId, targetId](const analysis::RunControl& control) -> JobOutput {
        const auto& model = defaultAxisModel();
        auto basis = analysis::prepareDesign(model, *source, {}, control);
        if (!basis) return {{}, QString::fromStdString(basis.error().message)};
        auto prepared = std::make_shared<Prepared>();
        prepared->sourceId = sourceId;
        prepared->targetId = targetId;
        prepared->boundaries = analysis::suggestPhraseBoundaries(basis->coordinates);
        if (target && !control.cancelled()) {
            auto targetBasis = analysis::prepareDesign(model, *target, {}, control);
            if (targetBasis) {
                analysis::ExtractionOptions options;
                options.boundaries = prepared->boundaries;
                auto extracted = analysis::extractDesign(basis->coordinates, targetBasis->coordinates, options, control);
                if (extracted) prepared->extracted = std::move(extracted).value();
            }
        }
        if (control.cancelled()) return {{}, QStringLiteral("cancelled")};
        prepared->basis = std::make_shared<const analysis::DesignBasis>(std::move(basis).value());
        return {std::shared_ptr<const Prepared>(std::move(prepared)), {}};
    };
}

void DesignController::accept(const JobOutput& output)
{
    if (!output.value.has_value()) return;
    m_prepared = std::any_cast<std::shared_ptr<const Prepared>>(output.value);
    emit prepared();
    redesign();
}

analysis::WarpCurve DesignController::warpCurve() const
{
    analysis::WarpCurve curve = warpFromVariant(m_document.parameter(parameters::kDesignWarp));
    if (analysis::validateWarpCurve(curve).ok()) return curve;
    const Eigen::Index frames = m_prepared ? m_prepared->basis->functional.frameCount() : 0;
    return frames > 1 ? analysis::identityWarp(frames) : analysis::WarpCurve{};
}

analysis::GainSet DesignController::gains() const
{
    if (!m_prepared) return {};
    std::vector<std::string> names;
    for (const auto& channel : analysis::axisCoordinateChannels()) names.push_back(channel.name());
    if (m_prepared->extracted) names = m_prepared->extracted->gains.dofNames;
    analysis::GainSet set = analysis::unitGains(boundaries(), names);
    const QVariantMap edits = m_document.parameter(parameters::kDesignGains).toMap();
    for (auto it = edits.begin(); it != edits.end(); ++it) {
        const QStringList where = it.key().split('/');
        const QVariantList values = it.value().toList();
        if (where.size() != 2 || values.size() != 2) continue;
        const auto phrase = std::size_t(where[0].toInt());
        const auto dof = std::size_t(where[1].toInt());
        if (phrase >= set.phrases.size() || dof >= set.phrases[phrase].dofs.size()) continue;
        set.phrases[phrase].dofs[dof].g0 = values[0].toDouble();
        set.phrases[phrase].dofs[dof].g1 = values[1].toDouble();
    }
    return set;
}

std::vector<Eigen::Index> DesignController::boundaries() const
{
    if (!m_prepared) return {};
    const Eigen::Index last = m_prepared->basis->functional.frameCount() - 1;
    const QVariantList edited = m_document.parameter(parameters::kDesignBoundaries).toList();
    if (edited.isEmpty() || last < 2) return m_prepared->boundaries;
    std::vector<Eigen::Index> inner;
    for (const QVariant& value : edited) inner.push_back(value.toLongLong());
    if (inner.front() == 0) inner.erase(inner.begin()); // {0} (or {0, last} of older projects): no inner boundary
    if (!inner.empty() && inner.back() == last) inner.pop_back();
    std::vector<Eigen::Index> result{0};
    for (const Eigen::Index frame : inner) {
        if (frame <= result.back() || frame >= last) return m_prepared->boundaries; // not valid here
        result.push_back(frame);
    }
    result.push_back(last);
    return result;
}

std::vector<double> DesignController::boundarySeconds() const
{
    const double rate = functionalRateHz();
    const auto frames = boundaries();
    std::vector<double> seconds;
    for (std::size_t i = 1; i + 1 < frames.size() && rate > 0.0; ++i) seconds.push_back(double(frames[i]) / rate);
    return seconds;
}

double DesignController::functionalRateHz() const
{
    if (!m_prepared) return 0.0;
    const TakePointer source = m_document.take(m_prepared->sourceId);
    return source ? source->rateHz : 0.0;
}

namespace {

/// The parameter value of the boundaries `all` (0, inner..., last): the inner ones, or {0}
/// when there is none (the empty list means "suggested"; {0} does not depend on the take's
/// length, so it keeps its meaning for another functional take).
QVariantList innerAsVariant(const std::vector<Eigen::Index>& all)
{
    QVariantList inner;
    for (std::size_t i = 1; i + 1 < all.size(); ++i) inner.append(qlonglong(all[i]));
    if (inner.isEmpty() && all.size() >= 2) inner = {qlonglong(0)};
    return inner;
}

} // namespace

void DesignController::moveBoundary(int index, double frame)
{
    std::vector<Eigen::Index> all = boundaries();
    const auto position = std::size_t(index) + 1;
    if (index < 0 || position + 1 >= all.size()) return;
    // Both phrases stay at least 2 frames long, as gain extraction needs (as addBoundary).
    const auto low = double(all[position - 1] + 2);
    const auto high = double(all[position + 1] - 2);
    if (high < low) return;
    all[position] = Eigen::Index(std::lround(std::clamp(frame, low, high)));
    changeParameter(m_document, parameters::kDesignBoundaries, innerAsVariant(all),
                    QCoreApplication::translate("commands", "Move phrase boundary"));
}

bool DesignController::addBoundary(double frame)
{
    std::vector<Eigen::Index> all = boundaries();
    if (all.size() < 2 || !std::isfinite(frame)) return false;
    const auto at = Eigen::Index(std::lround(frame));
    const auto next = std::upper_bound(all.begin(), all.end(), at); // the first boundary after `at`
    // both new phrases at least 2 frames long, as gain extraction needs (extractGains)
    if (next == all.begin() || next == all.end() || at - *(next - 1) < 2 || *next - at < 2) return false;
    const int phrase = int(next - all.begin()) - 1;
    all.insert(next, at);
    const QVariantMap edits = m_document.parameter(parameters::kDesignGains).toMap();
    return changeParameters(m_document,
                            {{parameters::kDesignBoundaries, innerAsVariant(all)},
                             {parameters::kDesignGains, gainsAfterSplit(edits, phrase)}},
                            QCoreApplication::translate("commands", "Add phrase boundary"));
}

bool DesignController::removeBoundary(int index)
{
    std::vector<Eigen::Index> all = boundaries();
    const auto position = std::size_t(index) + 1;
    if (index < 0 || position + 1 >= all.size()) return false;
    const Eigen::Index leftFrames = all[position] - all[position - 1];
    const Eigen::Index rightFrames = all[position + 1] - all[position];
    const int kept = rightFrames > leftFrames ? index + 1 : index;
    all.erase(all.begin() + std::ptrdiff_t(position));
    const QVariantMap edits = m_document.parameter(parameters::kDesignGains).toMap();
    return changeParameters(m_document,
                            {{parameters::kDesignBoundaries, innerAsVariant(all)},
                             {parameters::kDesignGains, gainsAfterMerge(edits, index, kept)}},
                            QCoreApplication::translate("commands", "Remove phrase boundary"));
}

int DesignController::nearestBoundary(double frame) const
{
    const std::vector<Eigen::Index> all = boundaries();
    int best = -1;
    double bestDistance = 0.0;
    for (std::size_t i = 1; i + 1 < all.size(); ++i) {
        const double distance = std::abs(double(all[i]) - frame);
        if (best < 0 || distance < bestDistance) {
            best = int(i) - 1;
            bestDistance = distance;
        }
    }
    return best;
}

std::vector<double> DesignController::boundarySecondsOn(const QString& takeId) const
{
    if (takeId != kDesignedId) return boundarySeconds();
    const double rate = functionalRateHz();
    const analysis::WarpCurve curve = warpCurve();
    const auto frames = boundaries();
    std::vector<double> seconds;
    for (std::size_t i = 1; i + 1 < frames.size() && rate > 0.0; ++i)
        seconds.push_back(analysis::inverseWarp(curve, double(frames[i])) / rate);
    return seconds;
}

double DesignController::functionalFrameAt(const QString& takeId, double seconds) const
{
    const double frame = seconds * functionalRateHz();
    return takeId == kDesignedId ? analysis::evaluateWarp(warpCurve(), frame) : frame;
}

analysis::GainSet DesignController::extractedGains() const
{
    m_extractionError.clear();
    if (!m_prepared || !m_prepared->extracted) return {};
    const std::vector<Eigen::Index> frames = boundaries();
    if (frames == m_prepared->boundaries) return m_prepared->extracted->gains;
    if (m_extractedFrom == m_prepared && m_extractedFor == frames) {
        m_extractionError = m_extractedFailure;
        return m_extractedGains;
    }
    QElapsedTimer clock;
    clock.start();
    auto gains = analysis::extractGainsForBoundaries(m_prepared->basis->coordinates, *m_prepared->extracted, frames);
    m_lastExtractionMilliseconds = double(clock.nsecsElapsed()) / 1e6;
    m_extractedFrom = m_prepared;
    m_extractedFor = frames;
    m_extractedFailure = gains ? QString() : QString::fromStdString(gains.error().message);
    m_extractionError = m_extractedFailure;
    m_extractedGains = gains ? std::move(gains).value() : analysis::GainSet{};
    return m_extractedGains;
}

void DesignController::resetBoundaries()
{
    changeParameter(m_document, parameters::kDesignBoundaries, parameters::defaultValue(parameters::kDesignBoundaries),
                    QCoreApplication::translate("commands", "Reset phrase boundaries"));
}

Eigen::VectorXd DesignController::extractedWarp() const
{
    return m_prepared && m_prepared->extracted ? m_prepared->extracted->phase.emotionalToFunctional : Eigen::VectorXd();
}

analysis::WarpCurve DesignController::extractedCurve() const
{
    return m_prepared && m_prepared->extracted ? m_prepared->extracted->phase.curve : analysis::WarpCurve{};
}

void DesignController::editWarp(const analysis::WarpCurve& curve)
{
    if (!analysis::validateWarpCurve(curve).ok()) return;
    changeParameter(m_document, parameters::kDesignWarp, warpToVariant(curve),
                    QCoreApplication::translate("commands", "Move warp point"));
}

void DesignController::editGain(int phrase, int dof, double g0, double g1)
{
    QVariantMap edits = m_document.parameter(parameters::kDesignGains).toMap();
    edits.insert(gainKey(phrase, dof), QVariantList{g0, g1});
    // keyboard or wheel steps of one cell's sliders merge; a slider drag is one interaction
    stepParameter(m_document, parameters::kDesignGains, edits, QCoreApplication::translate("commands", "Set phrase gain"),
                  parameters::kDesignGains + QLatin1Char('/') + gainKey(phrase, dof));
}

void DesignController::resetWarpToIdentity()
{
    changeParameter(m_document, parameters::kDesignWarp, parameters::defaultValue(parameters::kDesignWarp),
                    QCoreApplication::translate("commands", "Reset warp to identity"));
}

void DesignController::resetWarpToExtracted()
{
    const analysis::WarpCurve curve = extractedCurve();
    if (!analysis::validateWarpCurve(curve).ok()) return;
    changeParameter(m_document, parameters::kDesignWarp, warpToVariant(curve),
                    QCoreApplication::translate("commands", "Reset warp to extracted"));
}

void DesignController::resetGains()
{
    changeParameter(m_document, parameters::kDesignGains, parameters::defaultValue(parameters::kDesignGains),
                    QCoreApplication::translate("commands", "Reset phrase gains"));
}

void DesignController::useExtractedGains()
{
    const analysis::GainSet extracted = extractedGains();
    if (extracted.phrases.empty()) return;
    QVariantMap edits;
    const auto& phrases = extracted.phrases;
    for (std::size_t p = 0; p < phrases.size(); ++p)
        for (std::size_t d = 0; d < phrases[p].dofs.size(); ++d)
            edits.insert(gainKey(int(p), int(d)), QVariantList{phrases[p].dofs[d].g0, phrases[p].dofs[d].g1});
    changeParameter(m_document, parameters::kDesignGains, edits, QCoreApplication::translate("commands", "Use extracted gains"));
}

void DesignController::redesign()
{
    if (!m_prepared) return;
    QElapsedTimer clock;
    clock.start();
    analysis::DesignedMotion motion = analysis::designMotion(*m_prepared->basis, warpCurve(), gains());
    motion.take.labels.source = "designed";
    m_designed = std::make_shared<const analysis::Take>(std::move(motion.take));
    m_lastMilliseconds = double(clock.nsecsElapsed()) / 1e6;
    m_document.setLiveTake(QStringLiteral("designed"), tr("designed from %1").arg(m_document.takeLabel(m_prepared->sourceId)),
                           m_designed, m_prepared->sourceId);
    emit designed();
}

} // namespace bunraku::app
