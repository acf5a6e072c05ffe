#pragma once
/// The undo commands: the only mutators of the document's undoable state (Tiled's
/// changevalue.h / changelayer.h). One class per verb-noun whose merging rule differs; each
/// holds the values of the sections it changes, before and after (ParameterPart: a warp drag
/// holds two warps, a weight step two numbers), and emits the document's typed signals.
///
/// Merging: inside a document interaction (Document::beginInteraction, a slider or curve drag)
/// consecutive commands of one class merge into one undo step back to the value before the
/// drag; outside one, a change marked as a step of a control (setStep: spin box arrows, keys,
/// wheel) merges with the previous step of the same control when it came within
/// kStepMergeMilliseconds (the document's clock) in the same step series
/// (Document::endStepSeries, called when the control loses the focus). A drag that returns to
/// its start becomes obsolete.

#include "app/document.h"

#include <QUndoCommand>

#include <functional>
#include <optional>
#include <vector>

namespace bunraku::app {

/// Command ids for QUndoCommand::id() (merging); -1: never merges.
enum CommandId {
    kChangeStageParametersId = 1,
    kSetEmotionWeightId,
    kMoveWarpPointId,
    kSetPhraseGainId,
    kMovePhraseBoundaryId,
};

/// Steps of one control merge while each comes within this many milliseconds of the previous.
inline constexpr qint64 kStepMergeMilliseconds = 1000;

/// The values of some sections of the parameters (ParameterSections), the others not held.
class ParameterPart {
public:
    ParameterPart() = default;
    /// `parameters`' values of `sections`.
    ParameterPart(const AnalysisParameters& parameters, ParameterSections sections);
    ParameterSections sections() const { return m_sections; }
    /// Sets the held sections of `parameters` to the held values.
    void applyTo(AnalysisParameters& parameters) const;
    /// Takes the sections of `other` this part does not hold.
    void addMissing(const ParameterPart& other);
    /// The same sections with the same values.
    bool operator==(const ParameterPart& other) const;

private:
    ParameterSections m_sections;
    std::optional<analysis::pipeline::PreprocessParameters> m_preprocess;
    std::optional<analysis::pipeline::NormaliseParameters> m_normalise;
    std::optional<analysis::pipeline::DecomposeParameters> m_decompose;
    std::optional<analysis::pipeline::FluctuationParameters> m_fluctuations;
    std::optional<analysis::pipeline::AxisParameters> m_axis;
    double m_weight = 0.0;
    std::optional<analysis::WarpCurve> m_warp;
    std::vector<analysis::pipeline::GainEdit> m_gains;
    analysis::pipeline::PhraseBoundaries m_boundaries;
};

/// Changes some sections of the analysis parameters; the base of every parameter command.
class ParameterCommand : public QUndoCommand {
public:
    void undo() override;
    void redo() override;
    int id() const override { return m_id; }
    bool mergeWith(const QUndoCommand* other) override;

    /// Marks the change as one step of `control` (a name unique to the control), made now.
    void setStep(const QString& control);
    /// The sections it changes (none: it changes nothing and is not pushed).
    ParameterSections sections() const { return m_after.sections(); }

protected:
    enum Merging { Never = 0, InDrag = 1, InSteps = 2 };
    /// Holds the sections in which `after` differs from the document's parameters now.
    ParameterCommand(Document* document, const AnalysisParameters& after, const QString& text, int id, int merging);

private:
    void apply(const ParameterPart& part);

    Document* m_document;
    ParameterPart m_before;
    ParameterPart m_after;
    int m_id;
    int m_merging;
    int m_interaction;
    QString m_stepControl; ///< empty: not a step
    int m_stepSeries = 0;
    qint64 m_stepMilliseconds = 0;
};

/// A stage's parameters (tau, T_cmp, scales, coupling, path, reference, method, M...): steps of
/// one control merge.
class ChangeStageParameters : public ParameterCommand {
public:
    ChangeStageParameters(Document* document, AnalysisParameters after, const QString& text)
        : ParameterCommand(document, std::move(after), text, kChangeStageParametersId, InSteps)
    {
    }
};

/// The emotion weight a (thesis eq. 4.45): a slider drag or its steps merge.
class SetEmotionWeight : public ParameterCommand {
public:
    SetEmotionWeight(Document* document, AnalysisParameters after);
};

/// The design's warp curve (a control point dragged, added or removed): a drag merges.
class MoveWarpPoint : public ParameterCommand {
public:
    MoveWarpPoint(Document* document, AnalysisParameters after, const QString& text = {});
};

/// One phrase gain (g0, g1): a slider drag or the steps of one cell's sliders merge.
class SetPhraseGain : public ParameterCommand {
public:
    SetPhraseGain(Document* document, AnalysisParameters after);
};

/// A phrase boundary dragged: a drag merges.
class MovePhraseBoundary : public ParameterCommand {
public:
    MovePhraseBoundary(Document* document, AnalysisParameters after);
};

/// A phrase boundary added with the gains that follow it: never merges.
class AddPhraseBoundary : public ParameterCommand {
public:
    AddPhraseBoundary(Document* document, AnalysisParameters after);
};

/// A phrase boundary removed with the gains that follow it: never merges.
class RemovePhraseBoundary : public ParameterCommand {
public:
    RemovePhraseBoundary(Document* document, AnalysisParameters after);
};

/// A design edit replaced at once (reset warp or gains or phrases, use the extracted gains or
/// warp): never merges.
class ReplaceDesignEdits : public ParameterCommand {
public:
    ReplaceDesignEdits(Document* document, AnalysisParameters after, const QString& text)
        : ParameterCommand(document, std::move(after), text, -1, Never)
    {
    }
};

/// Adds a take read from a file under "Derived takes" and shows it as take A.
class ImportTake : public QUndoCommand {
public:
    /// `options`: what the take was read with, kept for the project file (null: the defaults).
    ImportTake(Document* document, TakePointer take, const QString& label, const QString& sourcePath,
               std::shared_ptr<const analysis::io::ImportOptions> options = nullptr);

    void undo() override;
    void redo() override;
    const TakeId& takeId() const { return m_take.id; }

private:
    Document* m_document;
    DerivedTake m_take;
    TakeId m_previousA;
};

/// Removes an imported take (undo puts it back at its place).
class RemoveImportedTake : public QUndoCommand {
public:
    RemoveImportedTake(Document* document, const TakeId& id);

    void undo() override;
    void redo() override;

private:
    Document* m_document;
    DerivedTake m_take;
    int m_position = -1;
};

/// The document's parameters with `edit` applied.
AnalysisParameters editedParameters(const Document& document, const std::function<void(AnalysisParameters&)>& edit);

/// Pushes `command` (taking ownership) unless its parameters equal the document's; `step`
/// non-empty marks it as a step of that control. Returns true when pushed.
bool pushParameters(Document& document, ParameterCommand* command, const QString& step = {});

/// ChangeStageParameters with `edit` applied, as a step of `stepControl` when given.
bool changeStageParameters(Document& document, const std::function<void(AnalysisParameters&)>& edit, const QString& text,
                           const QString& stepControl = {});
/// SetEmotionWeight (a step of the weight control outside a drag).
bool setEmotionWeight(Document& document, double weight);

} // namespace bunraku::app
