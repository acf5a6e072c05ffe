#include "app/document.h"

#include "analysis/core/skeleton_take.h"

#include <algorithm>
#include <chrono>

namespace bunraku::app {

Document::Document(QObject* parent) : QObject(parent), m_corpus(std::make_shared<analysis::Corpus>()) {}

Document::~Document() = default;

void Document::setCorpus(analysis::Corpus corpus, const QString& source,
                         std::shared_ptr<const analysis::synth::DemoGroundTruth> truth)
{
    m_undo.clear();
    m_truth = std::move(truth);
    m_corpus = std::make_shared<const analysis::Corpus>(std::move(corpus));
    m_corpusSource = source;
    m_derived.clear();
    m_parameters = {};
    m_importSerial = 0;
    ++m_version;
    m_selected[0] = m_corpus->takes.empty() ? TakeId() : TakeId::corpus(0);
    m_selected[1] = {};
    m_time = 0.0;
    emit corpusChanged();
    emit derivedTakesChanged();
    emit selectionChanged(TakeSlot::A);
    emit selectionChanged(TakeSlot::B);
    emit currentTimeChanged(m_time);
}

TakePointer Document::take(const TakeId& id) const
{
    if (id.isCorpus()) {
        if (id.index() >= m_corpus->takes.size()) return nullptr;
        return TakePointer(m_corpus, &m_corpus->takes[id.index()]); // aliasing: keeps the corpus alive
    }
    const int index = indexOfDerived(id);
    return index < 0 ? nullptr : m_derived[std::size_t(index)].take;
}

QString Document::takeLabel(const TakeId& id) const
{
    if (id.isCorpus()) {
        const TakePointer found = take(id);
        return found ? QString::fromStdString(found->displayName()) : QString();
    }
    const int index = indexOfDerived(id);
    return index < 0 ? QString() : m_derived[std::size_t(index)].label;
}

QString Document::takeName(const TakeId& id) const
{
    if (!id.isLive()) return takeLabel(id);
    const QString& kind = id.name();
    const TakePointer found = take(id);
    if (!found || found->labels.function.empty()) return kind;
    return QString::fromStdString(found->labels.function) + QLatin1Char(' ') + kind;
}

void Document::selectTake(TakeSlot slot, const TakeId& id)
{
    if (m_selected[int(slot)] == id) return;
    if (!id.isEmpty() && !take(id)) return;
    if (slot == TakeSlot::A && id.isEmpty()) return;
    m_selected[int(slot)] = id;
    emit selectionChanged(slot);
    setCurrentTime(m_time);
}

void Document::setCurrentTime(double seconds)
{
    const double clamped = std::clamp(seconds, 0.0, duration());
    if (clamped == m_time) return;
    m_time = clamped;
    emit currentTimeChanged(m_time);
}

double Document::duration() const
{
    double longest = 0.0;
    for (const auto& id : m_selected)
        if (const TakePointer shown = take(id)) longest = std::max(longest, shown->duration());
    return longest;
}

double Document::rateHz() const
{
    const TakePointer shown = selectedTake(TakeSlot::A);
    return shown && shown->rateHz > 0.0 ? shown->rateHz : 5.0;
}

TakePointer Document::ghostOf(const TakeId& id) const
{
    const int index = indexOfDerived(id);
    if (index < 0) return nullptr;
    const DerivedTake& derived = m_derived[std::size_t(index)];
    return derived.ghostId.isEmpty() ? derived.perChannelGhost : take(derived.ghostId);
}

TakePointer Document::perChannelGhostOf(const TakeId& id) const
{
    const int index = indexOfDerived(id);
    return index < 0 ? nullptr : m_derived[std::size_t(index)].perChannelGhost;
}

std::optional<analysis::PerChannelDistance> Document::perChannelDistanceOf(const TakeId& id) const
{
    const int index = indexOfDerived(id);
    if (index < 0 || !m_derived[std::size_t(index)].perChannelGhost) return std::nullopt;
    return m_derived[std::size_t(index)].perChannelDistance;
}

TakePointer Document::setLiveTake(const QString& name, const QString& label, TakePointer take, const TakeId& ghostId)
{
    // One motion: the figure, the graphs and every export show the body's.
    if (take && take->skeleton) {
        auto body = analysis::bodyMotion(*take);
        if (body.perChannel) return setLiveBody(name, label, std::move(body), ghostId);
    }
    return publishLive(name, label, std::move(take), nullptr, {}, ghostId);
}

TakePointer Document::setLiveBody(const QString& name, const QString& label, analysis::BodyMotion body, const TakeId& ghostId)
{
    TakePointer perChannelGhost;
    if (body.perChannel) {
        auto ghost = std::make_shared<analysis::Take>(body.take);
        ghost->values = *body.perChannel;
        ghost->skeleton = nullptr;
        ghost->labels.source = "per-channel (thesis) result of " + body.take.labels.source;
        perChannelGhost = std::move(ghost);
    }
    return publishLive(name, label, std::make_shared<const analysis::Take>(std::move(body.take)), std::move(perChannelGhost),
                       body.distance, ghostId);
}

TakePointer Document::publishLive(const QString& name, const QString& label, TakePointer take, TakePointer perChannelGhost,
                                  const analysis::PerChannelDistance& distance, const TakeId& ghostId)
{
    const TakeId id = TakeId::live(name);
    const int index = indexOfDerived(id);
    if (!take) {
        if (index < 0) return nullptr;
        m_derived.erase(m_derived.begin() + index);
        if (m_selected[1] == id) selectTake(TakeSlot::B, {});
        emit derivedTakesChanged();
        return nullptr;
    }
    if (index >= 0) {
        const bool relabelled = m_derived[std::size_t(index)].label != label;
        m_derived[std::size_t(index)].take = take;
        m_derived[std::size_t(index)].label = label;
        m_derived[std::size_t(index)].ghostId = ghostId;
        m_derived[std::size_t(index)].perChannelGhost = std::move(perChannelGhost);
        m_derived[std::size_t(index)].perChannelDistance = distance;
        if (relabelled) emit takeLabelChanged(id);
        emit takeChanged(id);
        bool shown = false;
        for (int slot = 0; slot < 2; ++slot)
            if (m_selected[slot] == id) {
                shown = true;
                emit selectedTakeReplaced(TakeSlot(slot));
            }
        if (shown) setCurrentTime(m_time); // a shorter take: the time stays inside the takes shown
        return take;
    }
    m_derived.push_back(DerivedTake{id, label, take, QString(), ghostId, nullptr, std::move(perChannelGhost), distance});
    emit derivedTakesChanged();
    return take;
}

void Document::restoreParameters(const AnalysisParameters& values)
{
    const ParameterSections sections = changedSections(m_parameters, values);
    m_parameters = values;
    m_undo.clear();
    ++m_version;
    if (sections) emit parametersChanged(sections);
}

qint64 Document::clockMilliseconds() const
{
    if (m_clock) return m_clock();
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void Document::beginInteraction()
{
    m_interaction = ++m_interactionSerial;
    emit interactionChanged(true);
}

void Document::endInteraction()
{
    if (m_interaction == 0) return;
    m_interaction = 0;
    emit interactionChanged(false);
}

void Document::applyParameters(const AnalysisParameters& values, CommandKey)
{
    const ParameterSections sections = changedSections(m_parameters, values);
    if (!sections) return;
    m_parameters = values;
    ++m_version;
    emit parametersChanged(sections);
}

ParameterSections changedSections(const AnalysisParameters& a, const AnalysisParameters& b)
{
    ParameterSections sections;
    if (!(a.preprocess == b.preprocess)) sections |= kPreprocessSection;
    if (!(a.normalise == b.normalise)) sections |= kNormaliseSection;
    if (!(a.decompose == b.decompose)) sections |= kDecomposeSection;
    if (!(a.fluctuations == b.fluctuations)) sections |= kFluctuationSection;
    if (!(a.axis == b.axis)) sections |= kAxisSection;
    if (a.design.emotionWeight != b.design.emotionWeight) sections |= kWeightSection;
    analysis::pipeline::DesignEdits warpA, warpB;
    warpA.warp = a.design.warp;
    warpB.warp = b.design.warp;
    if (!(warpA == warpB)) sections |= kWarpSection;
    if (!(a.design.gains == b.design.gains)) sections |= kGainSection;
    if (!(a.design.boundaries == b.design.boundaries)) sections |= kBoundarySection;
    return sections;
}

void Document::insertImportedTake(const DerivedTake& take, int position, CommandKey)
{
    position = std::clamp(position, 0, int(m_derived.size()));
    m_derived.insert(m_derived.begin() + position, take);
    ++m_version;
    emit derivedTakesChanged();
}

void Document::restoreProject(std::vector<DerivedTake> imported, const AnalysisParameters& parameters)
{
    if (!imported.empty()) {
        m_derived.reserve(m_derived.size() + imported.size());
        for (DerivedTake& take : imported) m_derived.push_back(std::move(take));
        ++m_version;
        emit derivedTakesChanged();
    }
    restoreParameters(parameters);
}

void Document::removeImportedTake(const TakeId& id, CommandKey)
{
    const int index = indexOfDerived(id);
    if (index < 0) return;
    m_derived.erase(m_derived.begin() + index);
    ++m_version;
    for (int slot = 1; slot >= 0; --slot) {
        if (m_selected[slot] != id) continue;
        m_selected[slot] = slot == 0 && !m_corpus->takes.empty() ? TakeId::corpus(0) : TakeId();
        emit selectionChanged(TakeSlot(slot));
    }
    emit derivedTakesChanged();
}

int Document::indexOfDerived(const TakeId& id) const
{
    const auto found = std::find_if(m_derived.begin(), m_derived.end(), [&](const DerivedTake& d) { return d.id == id; });
    return found == m_derived.end() ? -1 : int(found - m_derived.begin());
}

TakeId Document::nextImportedId() { return TakeId::imported(std::size_t(++m_importSerial)); }

} // namespace bunraku::app
