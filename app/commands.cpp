#include "app/commands.h"

#include <QCoreApplication>

namespace bunraku::app {

ChangeParameter::ChangeParameter(Document* document, QString key, QVariant value, const QString& text)
    : m_document(document),
      m_key(std::move(key)),
      m_before(document->parameter(m_key)),
      m_after(std::move(value)),
      m_interaction(document->interactionId())
{
    setText(text.isEmpty() ? QCoreApplication::translate("commands", "Change %1").arg(m_key) : text);
}

void ChangeParameter::undo() { m_document->applyParameter(m_key, m_before); }

void ChangeParameter::redo() { m_document->applyParameter(m_key, m_after); }

bool ChangeParameter::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const ChangeParameter*>(other);
    if (m_interaction == 0 || next->m_interaction != m_interaction || next->m_key != m_key) return false;
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

ImportTake::ImportTake(Document* document, TakePointer take, const QString& label, const QString& sourcePath)
    : m_document(document), m_take{document->nextImportedId(), label, std::move(take), sourcePath, QString()}
{
    setText(QCoreApplication::translate("commands", "Import %1").arg(label));
}

void ImportTake::redo()
{
    m_previousA = m_document->selectedId(TakeSlot::A);
    m_document->insertImportedTake(m_take, int(m_document->derivedTakes().size()));
    m_document->selectTake(TakeSlot::A, m_take.id);
}

void ImportTake::undo()
{
    m_document->removeImportedTake(m_take.id);
    m_document->selectTake(TakeSlot::A, m_previousA);
}

RemoveImportedTake::RemoveImportedTake(Document* document, const QString& id) : m_document(document)
{
    m_position = document->indexOfDerived(id);
    if (m_position >= 0) m_take = document->derivedTakes()[std::size_t(m_position)];
    setText(QCoreApplication::translate("commands", "Remove %1").arg(m_take.label));
}

void RemoveImportedTake::redo()
{
    if (m_position >= 0) m_document->removeImportedTake(m_take.id);
}

void RemoveImportedTake::undo()
{
    if (m_position >= 0) m_document->insertImportedTake(m_take, m_position);
}

bool changeParameter(Document& document, const QString& key, const QVariant& value, const QString& text)
{
    if (document.parameter(key) == value) return false;
    document.undoStack()->push(new ChangeParameter(&document, key, value, text));
    return true;
}

} // namespace bunraku::app
