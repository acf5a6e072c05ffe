#pragma once
/// Motion design (thesis 5.5) in the workbench: the functional take of take A's function is
/// prepared once in the background (its motion axis, relative motion and phrase boundaries, and
/// the phase and gains extracted from an emotional take of the same function); then every edit
/// of the warp curve or a phrase gain re-synthesises the designed take at once (designMotion
/// takes well under a millisecond) and publishes it as the live take "designed", with the
/// functional take as its ghost. Edits go through ChangeParameter (design.warp, design.gains);
/// a drag is one undo step. Phrase boundaries are added and removed one at a time, each one undo
/// step together with the gain edits that follow the new phrase structure (a split phrase's
/// gains are copied to both halves; two merged phrases keep the gains of the longer one, the
/// left one on a tie). The extracted gains follow the boundaries in use: the extraction's
/// phase is kept and the gains are re-extracted per phrase (extractGainsForBoundaries, a few
/// microseconds for the demo takes, so on the GUI thread and cached).
///
/// design.boundaries holds the inner boundaries (functional frames); the structure with no
/// inner boundary at all is stored as {0}, since the empty list means "suggested".

#include "app/document.h"
#include "app/recomputer.h"

#include "analysis/design/motion_design.h"

#include <QObject>

#include <memory>

namespace bunraku::app {

class DesignController : public QObject {
    Q_OBJECT
public:
    explicit DesignController(Document& document, QObject* parent = nullptr);

    Recomputer* recomputer() const { return m_recomputer; }
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
    std::vector<double> boundarySecondsOn(const QString& takeId) const;
    /// The functional frame shown at `seconds` of the take `takeId`: seconds * rate, through the
    /// warp on the designed take.
    double functionalFrameAt(const QString& takeId, double seconds) const;
    /// The index (among the inner ones) of the inner boundary nearest to functional frame
    /// `frame`, -1 when there is none.
    int nearestBoundary(double frame) const;
    /// The extracted correspondence (emotional frame -> functional frame), empty when unknown.
    Eigen::VectorXd extractedWarp() const;
    /// The extracted control points, empty when unknown.
    analysis::WarpCurve extractedCurve() const;
    QString sourceId() const { return m_sourceId; }
    QString targetId() const { return m_targetId; }
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
        std::shared_ptr<const analysis::DesignBasis> basis;
        std::vector<Eigen::Index> boundaries;
        std::optional<analysis::DesignParameters> extracted;
        QString sourceId;
        QString targetId;
    };

    void resolveInputs();
    Job snapshot();
    void accept(const JobOutput& output);
    void redesign();

    Document& m_document;
    Recomputer* m_recomputer = nullptr;
    std::shared_ptr<const Prepared> m_prepared;
    QString m_sourceId;
    QString m_targetId;
    quint64 m_inputSerial = 0;
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

/// The warp parameter (QVariantList of [output, source]) as a curve; empty when unset.
analysis::WarpCurve warpFromVariant(const QVariant& value);
QVariant warpToVariant(const analysis::WarpCurve& curve);

} // namespace bunraku::app
