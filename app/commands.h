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

/// Sets one parameter (generic change-value command). Pushed during a document interaction
/// (Document::beginInteraction, e.g. a slider or curve drag), consecutive changes of the same
/// key merge into one undo step that restores the value from before the drag.
class ChangeParameter : public QUndoCommand {
public:
    ChangeParameter(Document* document, QString key, QVariant value, const QString& text = {});

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
};

/// Adds a take read from a file under "Derived takes" and shows it as take A.
class ImportTake : public QUndoCommand {
public:
    ImportTake(Document* document, TakePointer take, const QString& label, const QString& sourcePath);

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

} // namespace bunraku::app
