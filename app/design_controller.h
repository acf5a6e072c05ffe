#pragma once
/// Motion design (thesis 5.5) in the workbench: the functional take of take A's function is
/// prepared once in the background (its motion axis, relative motion and phrase boundaries, and
/// the phase and gains extracted from an emotional take of the same function); then every edit
/// of the warp curve or a phrase gain re-synthesises the designed take at once (designMotion
/// takes well under a millisecond) and publishes it as the live take "designed", with the
/// functional take as its ghost. Edits go through ChangeParameter (design.warp, design.gains);
/// a drag is one undo step.

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
    /// frames), clamped so it stays at least one frame after its predecessor and before its
    /// successor (boundaries keep their order and stay inside the take). Inside a document
    /// interaction (a drag) the moves merge into one undo step.
    void moveBoundary(int index, double frame);
    /// Back to the suggested boundaries.
    void resetBoundaries();

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
};

/// The warp parameter (QVariantList of [output, source]) as a curve; empty when unset.
analysis::WarpCurve warpFromVariant(const QVariant& value);
QVariant warpToVariant(const analysis::WarpCurve& curve);

} // namespace bunraku::app
