#pragma once
/// The workbench's model: the open corpus, the takes derived from it (imported takes, and the
/// live results of normalisation, decomposition and design), the choice of take A and B, the
/// current time, the analysis parameters and the undo stack (Tiled's document.h).
///
/// Undoable state (the typed analysis parameters, imported takes) changes only through the
/// commands in app/commands.h, which emit the typed change signals below. View state
/// (selection, time) is set directly. Derived results ("live/..." takes) are published by the
/// AnalysisController alone - views only read them - and are never on the undo stack.

#include "analysis/core/corpus.h"
#include "analysis/core/skeleton_take.h"
#include "analysis/core/take.h"
#include "analysis/pipeline/stage_parameters.h"
#include "analysis/synth/demo_corpus.h"
#include "app/take_id.h"

#include <QObject>
#include <QString>
#include <QUndoStack>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace bunraku::analysis::io {
struct ImportOptions;
}

namespace bunraku::app {

/// The two shown takes (the corpus browser's slots map onto these).
enum class TakeSlot { A = 0, B = 1 };
using TakePointer = std::shared_ptr<const analysis::Take>;
using AnalysisParameters = analysis::pipeline::ChainParameters;

/// Which parts of the parameters a change touched (Document::parametersChanged).
enum ParameterSection : int {
    kPreprocessSection = 1,
    kNormaliseSection = 2,
    kDecomposeSection = 4,
    kFluctuationSection = 8,
    kAxisSection = 16,
    kWeightSection = 32,
    kWarpSection = 64,
    kGainSection = 128,
    kBoundarySection = 256,
    kDesignSections = kWeightSection | kWarpSection | kGainSection | kBoundarySection,
};
Q_DECLARE_FLAGS(ParameterSections, ParameterSection)
Q_DECLARE_OPERATORS_FOR_FLAGS(ParameterSections)
/// The sections in which `a` and `b` differ.
ParameterSections changedSections(const AnalysisParameters& a, const AnalysisParameters& b);

/// A take listed under "Derived takes": imported files and live analysis results.
struct DerivedTake {
    TakeId id;     ///< an imported take or a live result
    QString label; ///< shown in the corpus browser
    TakePointer take;
    QString sourcePath; ///< imported takes: the file; empty for live results
    TakeId ghostId;     ///< live results: the take drawn faintly behind it (its original)
    /// imported takes: the options they were read with (stored in projects); null for defaults
    std::shared_ptr<const analysis::io::ImportOptions> importOptions;
    /// live results shown as one body (analysis::bodyMotion): the thesis's per-channel result, drawn
    /// as the ghost when there is no ghostId (beside it otherwise); null when the take's channels
    /// are its body's.
    TakePointer perChannelGhost;
    /// How far the body is from perChannelGhost (meaningful when it is set).
    analysis::PerChannelDistance perChannelDistance;
};

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    /// Replaces the corpus (source: "demo" or the folder read); clears derived takes, the undo
    /// stack and the selection, then shows the first take as A. `truth` is the demo corpus's
    /// ground truth (phrase boundaries), null for other corpora.
    void setCorpus(analysis::Corpus corpus, const QString& source,
                   std::shared_ptr<const analysis::synth::DemoGroundTruth> truth = nullptr);
    /// The demo corpus's ground truth, null for other corpora.
    const analysis::synth::DemoGroundTruth* demoTruth() const { return m_truth.get(); }
    const analysis::Corpus& corpus() const { return *m_corpus; }
    /// The corpus, shared (analysis jobs keep it alive while they run).
    std::shared_ptr<const analysis::Corpus> sharedCorpus() const { return m_corpus; }
    QString corpusSource() const { return m_corpusSource; }

    /// The take with `id` (corpus or derived), null when unknown.
    TakePointer take(const TakeId& id) const;
    /// The label the user sees for `id` (a live result's recipe: "designed from bow functional
    /// (warp: 15 of 18 points moved; ...)").
    QString takeLabel(const TakeId& id) const;
    /// A short name for `id` that stays while the take is edited, for file names and the names
    /// inside exported files: a corpus take's "greeting/friendly/2", an imported take's label, a
    /// live result's kind after its function ("bow designed", or "designed" without one).
    QString takeName(const TakeId& id) const;
    const std::vector<DerivedTake>& derivedTakes() const { return m_derived; }

    /// Shows the take `id` (empty: none, allowed for B only) in `slot`. View state.
    void selectTake(TakeSlot slot, const TakeId& id);
    TakeId selectedId(TakeSlot slot) const { return m_selected[int(slot)]; }
    TakePointer selectedTake(TakeSlot slot) const { return take(m_selected[int(slot)]); }

    /// Seconds; clamped to [0, duration()].
    void setCurrentTime(double seconds);
    double currentTime() const { return m_time; }
    /// The longer of the shown takes, seconds.
    double duration() const;
    /// The frame rate of take A (Hz), 5 when none.
    double rateHz() const;

    /// The analysis parameters (every stage's, and the design edits).
    const AnalysisParameters& parameters() const { return m_parameters; }

    /// Publishes a live analysis result as TakeId::live(name) (replacing the previous one; null
    /// removes it). For the AnalysisController only; not undoable: results are recomputed from
    /// the parameters. A result with a skeleton is published as its body moves
    /// (analysis::bodyMotion: one motion for the figure, the graphs and exports), its per-channel
    /// result kept as perChannelGhost.
    /// Returns the take as published (null when removed).
    TakePointer setLiveTake(const QString& name, const QString& label, TakePointer take, const TakeId& ghostId = {});
    /// setLiveTake with the body already computed (analysis::bodyMotion, off the GUI thread for a
    /// long take): `body.take` is published, `body.perChannel` kept as its per-channel ghost.
    TakePointer setLiveBody(const QString& name, const QString& label, analysis::BodyMotion body, const TakeId& ghostId = {});
    /// The take drawn as a ghost behind `id` (a live result's original, else its per-channel
    /// result), null when none.
    TakePointer ghostOf(const TakeId& id) const;
    /// A live result's per-channel (thesis) result when it is shown as its body, null otherwise.
    TakePointer perChannelGhostOf(const TakeId& id) const;
    /// How far that per-channel result is from the body shown (nothing without one).
    std::optional<analysis::PerChannelDistance> perChannelDistanceOf(const TakeId& id) const;

    /// Replaces every parameter (loading a project): not undoable, clears the undo stack.
    void restoreParameters(const AnalysisParameters& values);

    QUndoStack* undoStack() { return &m_undo; }
    /// Increases with every change of the model's inputs (corpus, parameters, imports); results
    /// computed from an older version are stale.
    quint64 version() const { return m_version; }

    /// A slider or curve drag: commands pushed between beginInteraction() and
    /// endInteraction() with the same key merge into one undo step.
    void beginInteraction();
    void endInteraction();
    /// The current interaction's id, 0 when none.
    int interactionId() const { return m_interaction; }
    /// Steps of one control (spin box arrows, keys, wheel) merge into one undo step while they
    /// follow each other quickly (app/commands.h stepParameter); a control that loses the focus
    /// ends the series, so the next step starts a new undo step.
    void endStepSeries() { ++m_stepSeries; }
    /// The current step series, increased by endStepSeries().
    int stepSeries() const { return m_stepSeries; }
    /// Milliseconds of a monotonic clock for step merging (default std::chrono::steady_clock;
    /// tests set their own, so no test depends on wall-clock windows).
    qint64 clockMilliseconds() const;
    void setClock(std::function<qint64()> clock) { m_clock = std::move(clock); }

    /// Opening a project: its imported takes (appended with one derivedTakesChanged: one rebuild
    /// of the corpus browser for 10,000 takes, not one per take) and every parameter
    /// (restoreParameters). Not undoable, clears the undo stack.
    void restoreProject(std::vector<DerivedTake> imported, const AnalysisParameters& parameters);

    /// What only the undo commands of app/commands.h can make: the mutators below take one, so
    /// every undoable change goes through a command.
    class CommandKey {
        CommandKey() = default;
        friend class ParameterCommand;
        friend class ImportTake;
        friend class RemoveImportedTake;
    };
    // --- mutators for commands only (app/commands.cpp) ---
    void applyParameters(const AnalysisParameters& values, CommandKey);
    void insertImportedTake(const DerivedTake& take, int position, CommandKey);
    void removeImportedTake(const TakeId& id, CommandKey);
    int indexOfDerived(const TakeId& id) const;
    /// The next unused imported take's id.
    TakeId nextImportedId();

signals:
    void corpusChanged();
    void derivedTakesChanged();
    /// The content of take `id` changed (a live result was recomputed).
    void takeChanged(const bunraku::app::TakeId& id);
    /// The label of derived take `id` changed (a live result computed from other parameters or
    /// another take).
    void takeLabelChanged(const bunraku::app::TakeId& id);
    /// Another take is chosen for `slot`.
    void selectionChanged(bunraku::app::TakeSlot slot);
    /// The take shown in `slot` was replaced by new content under the same id (a live result
    /// recomputed: every step of a design drag). Not a new choice: what depends only on which
    /// take is shown (its cell, the browser) stays; what depends on its values follows.
    void selectedTakeReplaced(bunraku::app::TakeSlot slot);
    void currentTimeChanged(double seconds);
    /// Parameters changed in `sections`.
    void parametersChanged(bunraku::app::ParameterSections sections);
    /// An interaction (a drag) began (true) or ended (false): views may hold their ranges.
    void interactionChanged(bool active);

private:
    TakePointer publishLive(const QString& name, const QString& label, TakePointer take, TakePointer perChannelGhost,
                            const analysis::PerChannelDistance& distance, const TakeId& ghostId);

    std::shared_ptr<const analysis::Corpus> m_corpus;
    QString m_corpusSource;
    std::shared_ptr<const analysis::synth::DemoGroundTruth> m_truth;
    std::vector<DerivedTake> m_derived;
    TakeId m_selected[2];
    double m_time = 0.0;
    AnalysisParameters m_parameters;
    std::function<qint64()> m_clock;
    QUndoStack m_undo;
    quint64 m_version = 1;
    int m_interaction = 0;
    int m_interactionSerial = 0;
    int m_stepSeries = 0;
    int m_importSerial = 0;
};

} // namespace bunraku::app
