#include "app/design_controller.h"

#include "app/analysis_controller.h"
#include "app/commands.h"

#include "analysis/axis/axis_channels.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cmath>

namespace bunraku::app {
namespace {

namespace pl = analysis::pipeline;

const TakeId kDesignedId = TakeId::live(QStringLiteral("designed"));
const TakeId kFunctionalId = TakeId::live(QStringLiteral("functional"));

/// The gain edits with each phrase index moved by `remap` (an empty result drops the edit).
template <typename Remap> std::vector<pl::GainEdit> remapGainEdits(const std::vector<pl::GainEdit>& edits, Remap remap)
{
    pl::DesignEdits result;
    for (const pl::GainEdit& edit : edits)
        for (int phrase : remap(edit.phrase)) result.setGain({phrase, edit.dof, edit.g0, edit.g1});
    return result.gains;
}

/// Phrase `split` divided in two: both halves keep its gains, later phrases move up by one.
std::vector<pl::GainEdit> gainsAfterSplit(const std::vector<pl::GainEdit>& edits, int split)
{
    return remapGainEdits(edits, [split](int phrase) -> std::vector<int> {
        if (phrase < split) return {phrase};
        if (phrase == split) return {phrase, phrase + 1};
        return {phrase + 1};
    });
}

/// Phrases `left` and `left + 1` merged: the merged phrase keeps the gains of `kept`.
std::vector<pl::GainEdit> gainsAfterMerge(const std::vector<pl::GainEdit>& edits, int left, int kept)
{
    return remapGainEdits(edits, [left, kept](int phrase) -> std::vector<int> {
        if (phrase < left) return {phrase};
        if (phrase == kept) return {left};
        if (phrase == left || phrase == left + 1) return {};
        return {phrase - 1};
    });
}

/// Edited boundaries from all boundaries (0, inner..., last).
pl::PhraseBoundaries editedBoundaries(const std::vector<Eigen::Index>& all)
{
    pl::PhraseBoundaries boundaries{false, {}};
    for (std::size_t i = 1; i + 1 < all.size(); ++i) boundaries.inner.push_back(all[i]);
    return boundaries;
}

std::vector<std::string> dofNames()
{
    std::vector<std::string> names;
    for (const auto& channel : analysis::axisCoordinateChannels()) names.push_back(channel.name());
    return names;
}

} // namespace

DesignController::DesignController(Document& document, AnalysisController& analysis, QObject* parent)
    : QObject(parent), m_document(document), m_analysis(analysis)
{
    connect(&analysis, &AnalysisController::resultChanged, this, [this](int slot) {
        if (slot == AnalysisController::kAxesSlot) resolveInputs();
    });
    connect(&document, &Document::corpusChanged, this, [this] {
        m_prepared.reset();
        m_designed.reset();
    });
    connect(&document, &Document::selectionChanged, this, [this](TakeSlot slot) {
        if (slot == TakeSlot::A) resolveInputs();
    });
    connect(&document, &Document::parametersChanged, this, [this](ParameterSections sections) {
        if (sections & (kWarpSection | kGainSection | kBoundarySection)) redesign();
    });
}

template <class Command, class... Arguments>
bool DesignController::pushEdit(const std::function<void(pl::DesignEdits&)>& edit, Arguments&&... arguments)
{
    AnalysisParameters after = m_document.parameters();
    edit(after.design);
    return pushParameters(m_document, new Command(&m_document, std::move(after), std::forward<Arguments>(arguments)...));
}

void DesignController::resolveInputs()
{
    const auto axes = m_analysis.axes();
    if (!axes) return;
    const std::string& function = m_analysis.cellFunction();
    const pl::FunctionAxis* functionAxis = axes->function(function);
    if (!functionAxis) return;
    auto next = std::make_shared<Prepared>();
    next->axes = axes;
    next->function = *functionAxis;
    next->cell = axes->cell(function, m_analysis.cellEmotion());
    if (!next->cell)
        for (const auto& cell : axes->cells)
            if (cell.function == function) {
                next->cell = &cell;
                break;
            }
    if (m_prepared && m_prepared->axes == axes && m_prepared->function.function == function && m_prepared->cell == next->cell) return;
    m_prepared = std::move(next);
    auto functional = std::make_shared<analysis::Take>(m_prepared->function.basis->functional);
    m_document.setLiveTake(QStringLiteral("functional"), tr("%1 functional (average take)").arg(QString::fromStdString(function)),
                           functional);
    emit prepared();
    redesign();
}

TakeId DesignController::sourceId() const { return m_prepared ? kFunctionalId : TakeId(); }

QString DesignController::targetCell() const
{
    return m_prepared && m_prepared->cell ? QString::fromStdString(m_prepared->cell->function + "/" + m_prepared->cell->emotion)
                                          : QString();
}

analysis::WarpCurve DesignController::warpCurve() const
{
    return m_prepared ? pl::warpInUse(m_prepared->function, m_document.parameters().design) : analysis::WarpCurve{};
}

analysis::GainSet DesignController::gains() const
{
    if (!m_prepared) return {};
    const auto extracted = m_prepared->extracted();
    return pl::gainsInUse(m_prepared->function, m_document.parameters().design, extracted ? extracted->gains.dofNames : dofNames());
}

std::vector<Eigen::Index> DesignController::boundaries() const
{
    return m_prepared ? pl::boundariesInUse(m_prepared->function, m_document.parameters().design.boundaries)
                      : std::vector<Eigen::Index>{};
}

std::vector<double> DesignController::boundarySeconds() const
{
    const double rate = functionalRateHz();
    const auto frames = boundaries();
    std::vector<double> seconds;
    for (std::size_t i = 1; i + 1 < frames.size() && rate > 0.0; ++i) seconds.push_back(double(frames[i]) / rate);
    return seconds;
}

double DesignController::functionalRateHz() const { return m_prepared ? m_prepared->function.basis->functional.rateHz : 0.0; }

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
    pushEdit<MovePhraseBoundary>([&](pl::DesignEdits& d) { d.boundaries = editedBoundaries(all); });
}

bool DesignController::addBoundary(double frame)
{
    std::vector<Eigen::Index> all = boundaries();
    if (all.size() < 2 || !std::isfinite(frame)) return false;
    const auto at = Eigen::Index(std::lround(frame));
    const auto next = std::upper_bound(all.begin(), all.end(), at);
    // both new phrases at least 2 frames long, as gain extraction needs (extractGains)
    if (next == all.begin() || next == all.end() || at - *(next - 1) < 2 || *next - at < 2) return false;
    const int phrase = int(next - all.begin()) - 1;
    all.insert(next, at);
    return pushEdit<AddPhraseBoundary>([&](pl::DesignEdits& d) {
        d.boundaries = editedBoundaries(all);
        d.gains = gainsAfterSplit(d.gains, phrase);
    });
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
    return pushEdit<RemovePhraseBoundary>([&](pl::DesignEdits& d) {
        d.boundaries = editedBoundaries(all);
        d.gains = gainsAfterMerge(d.gains, index, kept);
    });
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

std::vector<double> DesignController::boundarySecondsOn(const TakeId& takeId) const
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

bool DesignController::showsBoundariesOn(const TakeId& takeId) const
{
    return ready() && (takeId == sourceId() || takeId == kDesignedId);
}

double DesignController::functionalFrameAt(const TakeId& takeId, double seconds) const
{
    const double frame = seconds * functionalRateHz();
    return takeId == kDesignedId ? analysis::evaluateWarp(warpCurve(), frame) : frame;
}

analysis::GainSet DesignController::extractedGains() const
{
    m_extractionError.clear();
    if (!m_prepared || !m_prepared->cell) return {};
    const analysis::DesignParameters& extracted = m_prepared->cell->extracted;
    const std::vector<Eigen::Index> frames = boundaries();
    if (frames == m_prepared->function.boundaries) return extracted.gains;
    if (m_extractedFrom == m_prepared && m_extractedFor == frames) {
        m_extractionError = m_extractedFailure;
        return m_extractedGains;
    }
    QElapsedTimer clock;
    clock.start();
    auto gains = analysis::extractGainsForBoundaries(m_prepared->function.basis->coordinates, extracted, frames);
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
    pushEdit<ReplaceDesignEdits>([](pl::DesignEdits& d) { d.boundaries = {}; },
                                 QCoreApplication::translate("commands", "Reset phrase boundaries"));
}

Eigen::VectorXd DesignController::extractedWarp() const
{
    return m_prepared && m_prepared->cell ? m_prepared->cell->extracted.phase.emotionalToFunctional : Eigen::VectorXd();
}

analysis::WarpCurve DesignController::extractedCurve() const
{
    return m_prepared && m_prepared->cell ? m_prepared->cell->extracted.phase.curve : analysis::WarpCurve{};
}

analysis::ApproximationError DesignController::approximationError() const
{
    return m_prepared && m_prepared->cell ? m_prepared->cell->approximation : analysis::ApproximationError{};
}

void DesignController::editWarp(const analysis::WarpCurve& curve)
{
    if (!analysis::validateWarpCurve(curve).ok()) return;
    pushEdit<MoveWarpPoint>([&](pl::DesignEdits& d) { d.warp = curve; });
}

void DesignController::editGain(int phrase, int dof, double g0, double g1)
{
    AnalysisParameters after = m_document.parameters();
    after.design.setGain({phrase, dof, g0, g1});
    // keyboard or wheel steps of one cell's sliders merge; a slider drag is one interaction
    pushParameters(m_document, new SetPhraseGain(&m_document, std::move(after)),
                   QStringLiteral("design.gains/%1/%2").arg(phrase).arg(dof));
}

void DesignController::resetWarpToIdentity()
{
    pushEdit<ReplaceDesignEdits>([](pl::DesignEdits& d) { d.warp.reset(); },
                                 QCoreApplication::translate("commands", "Reset warp to identity"));
}

void DesignController::resetWarpToExtracted()
{
    const analysis::WarpCurve curve = extractedCurve();
    if (!analysis::validateWarpCurve(curve).ok()) return;
    pushEdit<ReplaceDesignEdits>([&](pl::DesignEdits& d) { d.warp = curve; },
                                 QCoreApplication::translate("commands", "Reset warp to extracted"));
}

void DesignController::resetGains()
{
    pushEdit<ReplaceDesignEdits>([](pl::DesignEdits& d) { d.gains.clear(); }, QCoreApplication::translate("commands", "Reset phrase gains"));
}

void DesignController::useExtractedGains()
{
    const analysis::GainSet extracted = extractedGains();
    if (extracted.phrases.empty()) return;
    pushEdit<ReplaceDesignEdits>(
        [&](pl::DesignEdits& d) {
            d.gains.clear();
            for (std::size_t p = 0; p < extracted.phrases.size(); ++p)
                for (std::size_t q = 0; q < extracted.phrases[p].dofs.size(); ++q)
                    d.setGain({int(p), int(q), extracted.phrases[p].dofs[q].g0, extracted.phrases[p].dofs[q].g1});
        },
        QCoreApplication::translate("commands", "Use extracted gains"));
}

QString DesignController::designedLabel() const
{
    if (!m_prepared) return {};
    const pl::DesignEdits& design = m_document.parameters().design;
    // The warp: the identity, the cell's extracted one, or how many of its points are off the
    // identity (moved by hand).
    QString warp;
    const analysis::WarpCurve extracted = extractedCurve();
    if (!design.warp) {
        warp = tr("identity warp");
    } else if (!extracted.points.empty() && design.warp->points == extracted.points) {
        warp = tr("warp extracted from %1").arg(targetCell());
    } else {
        int moved = 0;
        for (const analysis::WarpPoint& point : design.warp->points)
            if (std::abs(point.source - point.output) > 1e-9) ++moved;
        warp = tr("warp: %1 of %2 points moved").arg(moved).arg(design.warp->points.size());
    }
    int gains = 0;
    for (const pl::GainEdit& edit : design.gains)
        if (edit.g0 != 1.0 || edit.g1 != 1.0) ++gains;
    const QString gainText = gains == 0 ? tr("no gains") : gains == 1 ? tr("1 phrase gain set") : tr("%1 phrase gains set").arg(gains);
    const int phrases = std::max(1, int(boundaries().size()) - 1);
    const QString phraseText = phrases == 1 ? (design.boundaries.suggested ? tr("1 suggested phrase") : tr("1 phrase set"))
                                            : (design.boundaries.suggested ? tr("%1 suggested phrases") : tr("%1 phrases set")).arg(phrases);
    return tr("designed from %1 functional (%2; %3; %4)")
        .arg(QString::fromStdString(m_prepared->function.function), warp, gainText, phraseText);
}

void DesignController::redesign()
{
    if (!m_prepared) return;
    QElapsedTimer clock;
    clock.start();
    analysis::DesignedMotion motion = pl::designFunction(m_prepared->function, m_document.parameters().design);
    motion.take.labels.source = "designed";
    m_designed = std::make_shared<const analysis::Take>(std::move(motion.take));
    m_lastMilliseconds = double(clock.nsecsElapsed()) / 1e6;
    m_designed = m_document.setLiveTake(QStringLiteral("designed"), designedLabel(), m_designed, kFunctionalId);
    emit designed();
}

} // namespace bunraku::app
