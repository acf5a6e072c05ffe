#pragma once
/// The undo commands: the only mutators of the document's undoable state (Tiled's
/// changevalue.h / changelayer.h). Verb-noun names; each emits the document's typed signals
/// through the Document mutators.

#include "app/document.h"

#include <QUndoCommand>
#include <QVariant>

namespace bunraku::app {

/// Command ids for QUndoCommand::id() (merging).
enum CommandId { kChangeParameterId = 1 };

/// Steps of one control merge while each comes within this many milliseconds of the previous.
inline constexpr qint64 kStepMergeMilliseconds = 1000;

/// Sets one parameter (generic change-value command). Pushed during a document interaction
/// (Document::beginInteraction, e.g. a slider or curve drag), consecutive changes of the same
/// key merge into one undo step that restores the value from before the drag. Outside an
/// interaction, a change marked as a step of a control (setStep) merges with the previous step
/// of the same control and key when it came within kStepMergeMilliseconds and in the same step
/// series (Document::endStepSeries, called when the control loses the focus).
class ChangeParameter : public QUndoCommand {
public:
    ChangeParameter(Document* document, QString key, QVariant value, const QString& text = {});

    /// Marks the change as one step of `control` (any name unique to the control; non-empty),
    /// made now.
    void setStep(const QString& control);

    void undo() override;
    void redo() override;
    int id() const override { return kChangeParameterId; }
    bool mergeWith(const QUndoCommand* other) override;

    const QString& key() const { return m_key; }

private:
    Document* m_document;
    QString m_key;
    QVariant m_before;
    QVariant m_after;
    int m_interaction;
    QString m_stepControl; ///< empty: not a step
    int m_stepSeries = 0;
    qint64 m_stepMilliseconds = 0; ///< steady clock time of the latest merged step
};

/// Sets several parameters as one undo step (phrase boundaries with the gains that follow them);
/// redo applies them in key order, undo restores every value from before.
class ChangeParameters : public QUndoCommand {
public:
    ChangeParameters(Document* document, QVariantMap values, const QString& text);

    void undo() override;
    void redo() override;

private:
    Document* m_document;
    QVariantMap m_before;
    QVariantMap m_after;
};

/// Adds a take read from a file under "Derived takes" and shows it as take A.
class ImportTake : public QUndoCommand {
public:
    /// `options`: what the take was read with, kept for the project file (null: the defaults).
    ImportTake(Document* document, TakePointer take, const QString& label, const QString& sourcePath,
               std::shared_ptr<const analysis::io::ImportOptions> options = nullptr);

    void undo() override;
    void redo() override;
    const QString& takeId() const { return m_take.id; }

private:
    Document* m_document;
    DerivedTake m_take;
    QString m_previousA;
};

/// Removes an imported take (undo puts it back at its place).
class RemoveImportedTake : public QUndoCommand {
public:
    RemoveImportedTake(Document* document, const QString& id);

    void undo() override;
    void redo() override;

private:
    Document* m_document;
    DerivedTake m_take;
    int m_position = -1;
};

/// Pushes ChangeParameter unless the value is unchanged. Returns true when pushed.
bool changeParameter(Document& document, const QString& key, const QVariant& value, const QString& text = {});
/// Pushes ChangeParameter marked as a step of `control` (default: the key), so consecutive
/// spin box or slider steps become one undo step. Returns true when pushed.
bool stepParameter(Document& document, const QString& key, const QVariant& value, const QString& text = {},
                   const QString& control = {});
/// Pushes ChangeParameters for the values that differ from the document's. Returns true when pushed.
bool changeParameters(Document& document, const QVariantMap& values, const QString& text);

} // namespace bunraku::app
