#pragma once
/// Motion design (thesis 5.5) in the workbench: the pipeline's motion-axis stage (run by the
/// AnalysisController) prepares each function's functional take - the neutral cell's average
/// take (3.7) - with its axis, relative motion and phrase boundaries, and extracts the phase and
/// gains of every emotional cell. For take A's function (and take A's cell, or the function's
/// first emotional cell) every edit of the warp curve or a phrase gain re-synthesises the
/// designed take at once (pipeline::designFunction, well under a millisecond) and publishes it
/// as the live take "designed" with the functional take ("functional") as its ghost. Edits are
/// the typed undo commands MoveWarpPoint, SetPhraseGain, MovePhraseBoundary, AddPhraseBoundary,
/// RemovePhraseBoundary and ReplaceDesignEdits; a drag is one undo step. Phrase boundaries are added and removed one at a time, each one undo
/// step together with the gain edits that follow the new phrase structure (a split phrase's
/// gains are copied to both halves; two merged phrases keep the gains of the longer one, the
/// left one on a tie). The extracted gains follow the boundaries in use: the extraction's
/// phase is kept and the gains are re-extracted per phrase (extractGainsForBoundaries, a few
/// microseconds for the demo takes, so on the GUI thread and cached).
///
/// The boundaries are typed (pipeline::PhraseBoundaries): suggested, or the inner boundaries the
/// user set (possibly none).

#include "app/document.h"

#include "analysis/design/motion_design.h"
#include "analysis/pipeline/stages.h"

#include <QObject>

#include <functional>
#include <memory>
#include <optional>

namespace bunraku::app {

class AnalysisController;

class DesignController : public QObject {
    Q_OBJECT
public:
    DesignController(Document& document, AnalysisController& analysis, QObject* parent = nullptr);

    /// True once the functional take is prepared.
    bool ready() const { return m_prepared != nullptr; }

    /// The warp curve in use: the edited one, else the identity over the functional frames.
    analysis::WarpCurve warpCurve() const;
    /// The gains in use: the phrase structure of the functional take with the edited values.
    analysis::GainSet gains() const;
    /// The phrase boundaries in use, functional frames (0, inner..., last): the edited inner
    /// boundaries (design.boundaries) when valid for the functional take, else the suggested
    /// ones. Empty before the preparation finished.
    std::vector<Eigen::Index> boundaries() const;
    /// The inner boundaries in seconds of the functional take (the timeline's marks).
    std::vector<double> boundarySeconds() const;
    /// The frame rate of the functional take (Hz), 0 before the preparation finished.
    double functionalRateHz() const;
    /// The gains extracted for the boundaries in use (the extraction's phase, gains per phrase
    /// re-extracted when the boundaries differ from the suggested ones); empty without an
    /// emotional take.
    analysis::GainSet extractedGains() const;
    /// Wall time of the last gain re-extraction, milliseconds (0 before the first).
    double lastExtractionMilliseconds() const { return m_lastExtractionMilliseconds; }
    /// Why extractedGains() is empty for the boundaries in use (e.g. a phrase too short), empty
    /// when the extraction succeeded.
    QString extractionError() const
    {
        (void)extractedGains();
        return m_extractionError;
    }
    /// The inner boundaries in seconds on the take `takeId`: the functional take's times, and on
    /// the designed take ("live/designed") the designed times u / rate whose warp reaches each
    /// boundary, warp(u) = boundary (inverseWarp of the monotone curve).
    std::vector<double> boundarySecondsOn(const TakeId& takeId) const;
    /// Whether the take `takeId` shows the design's phrase boundaries (editable): the
    /// functional take or the designed take, once the design is ready.
    bool showsBoundariesOn(const TakeId& takeId) const;
    /// The functional frame shown at `seconds` of the take `takeId`: seconds * rate, through the
    /// warp on the designed take.
    double functionalFrameAt(const TakeId& takeId, double seconds) const;
    /// The index (among the inner ones) of the inner boundary nearest to functional frame
    /// `frame`, -1 when there is none.
    int nearestBoundary(double frame) const;
    /// The extracted correspondence (emotional frame -> functional frame), empty when unknown.
    Eigen::VectorXd extractedWarp() const;
    /// The extracted control points, empty when unknown.
    analysis::WarpCurve extractedCurve() const;
    /// Thesis 5.4.1 (eq. 5.18, Fig. 5.16) for the emotional cell of targetCell(): the
    /// approximation error per largest scale and axis DOF (computed by the axis stage); empty
    /// without an emotional cell.
    analysis::ApproximationError approximationError() const;
    /// "live/functional": the functional take (the neutral cell's average take).
    TakeId sourceId() const;
    /// The emotional cell the phase and gains were extracted from ("function/emotion"), empty when none.
    QString targetCell() const;
    /// The designed take's label: its functional take and what it was designed with ("designed
    /// from wave functional (warp: 3 of 28 points moved; 2 phrase gains set; 4 suggested phrases)").
    QString designedLabel() const;
    /// The designed take, null before the preparation finished.
    TakePointer designedTake() const { return m_designed; }
    /// Wall time of the last synthesis, milliseconds.
    double lastSynthesisMilliseconds() const { return m_lastMilliseconds; }

    // Edits (each pushes one undoable command; inside a document interaction they merge).
    void editWarp(const analysis::WarpCurve& curve);
    void editGain(int phrase, int dof, double g0, double g1);
    void resetWarpToIdentity();
    void resetWarpToExtracted();
    void resetGains();
    /// Sets every gain to the extracted one (one undo step).
    void useExtractedGains();
    /// Moves inner boundary `index` (0-based among the inner ones) to `frame` (functional
    /// frames), clamped so it stays at least 2 frames after its predecessor and before its
    /// successor (phrases keep at least 2 frames, as gain extraction needs; boundaries keep
    /// their order and stay inside the take). Inside a document
    /// interaction (a drag) the moves merge into one undo step.
    void moveBoundary(int index, double frame);
    /// Back to the suggested boundaries.
    void resetBoundaries();
    /// Adds an inner boundary at functional frame `frame` (rounded), splitting the phrase that
    /// holds it; one undo step with the gains that follow. False (nothing changes) when either
    /// new phrase would be shorter than 2 frames (on or next to a boundary, outside the take).
    bool addBoundary(double frame);
    /// Removes inner boundary `index` (0-based among the inner ones), merging its two phrases;
    /// one undo step with the gains that follow. False for a bad index.
    bool removeBoundary(int index);

signals:
    /// The preparation finished (new phrase structure, extracted curve).
    void prepared();
    /// The designed take was re-synthesised.
    void designed();

private:
    struct Prepared {
        analysis::pipeline::FunctionAxis function;
        const analysis::pipeline::CellAxis* cell = nullptr; ///< into `axes`, null without an emotional cell
        analysis::pipeline::Shared<analysis::pipeline::AxisOutput> axes;
        std::optional<analysis::DesignParameters> extracted() const
        {
            return cell ? std::optional<analysis::DesignParameters>(cell->extracted) : std::nullopt;
        }
    };

    void resolveInputs();
    void redesign();
    /// Pushes the design edits `edit` makes as `command` (one of the typed design commands).
    template <class Command, class... Arguments> bool pushEdit(const std::function<void(analysis::pipeline::DesignEdits&)>& edit,
                                                               Arguments&&... arguments);

    Document& m_document;
    AnalysisController& m_analysis;
    std::shared_ptr<const Prepared> m_prepared;
    TakePointer m_designed;
    double m_lastMilliseconds = 0.0;
    // extractedGains() for the latest boundaries, re-extracted when they or the preparation change
    mutable std::shared_ptr<const Prepared> m_extractedFrom;
    mutable std::vector<Eigen::Index> m_extractedFor;
    mutable analysis::GainSet m_extractedGains;
    mutable QString m_extractedFailure; ///< why m_extractedGains is empty, for m_extractedFor
    mutable QString m_extractionError;  ///< the last extractedGains() call's error, empty when none
    mutable double m_lastExtractionMilliseconds = 0.0;
};

} // namespace bunraku::app
