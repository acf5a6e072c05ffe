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

void ChangeParameter::setStep(const QString& control)
{
    m_stepControl = control;
    m_stepSeries = m_document->stepSeries();
    m_stepMilliseconds = m_document->clock().milliseconds();
}

bool ChangeParameter::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const ChangeParameter*>(other);
    if (next->m_key != m_key) return false;
    const bool sameInteraction = m_interaction != 0 && next->m_interaction == m_interaction;
    const bool sameSteps = m_interaction == 0 && next->m_interaction == 0 && !m_stepControl.isEmpty() &&
                           next->m_stepControl == m_stepControl && next->m_stepSeries == m_stepSeries &&
                           next->m_stepMilliseconds >= m_stepMilliseconds &&
                           next->m_stepMilliseconds - m_stepMilliseconds <= kStepMergeMilliseconds;
    if (!sameInteraction && !sameSteps) return false;
    m_after = next->m_after;
    m_stepMilliseconds = next->m_stepMilliseconds;
    setObsolete(m_after == m_before);
    return true;
}

ChangeParameters::ChangeParameters(Document* document, QVariantMap values, const QString& text)
    : m_document(document), m_after(std::move(values))
{
    for (auto it = m_after.begin(); it != m_after.end(); ++it) m_before.insert(it.key(), document->parameter(it.key()));
    setText(text);
}

void ChangeParameters::redo()
{
    for (auto it = m_after.begin(); it != m_after.end(); ++it) m_document->applyParameter(it.key(), it.value());
}

void ChangeParameters::undo()
{
    for (auto it = m_before.begin(); it != m_before.end(); ++it) m_document->applyParameter(it.key(), it.value());
}

ImportTake::ImportTake(Document* document, TakePointer take, const QString& label, const QString& sourcePath,
                       std::shared_ptr<const analysis::io::ImportOptions> options)
    : m_document(document), m_take{document->nextImportedId(), label, std::move(take), sourcePath, QString(), std::move(options)}
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

bool stepParameter(Document& document, const QString& key, const QVariant& value, const QString& text, const QString& control)
{
    if (document.parameter(key) == value) return false;
    auto* command = new ChangeParameter(&document, key, value, text);
    command->setStep(control.isEmpty() ? key : control);
    document.undoStack()->push(command);
    return true;
}

bool changeParameters(Document& document, const QVariantMap& values, const QString& text)
{
    QVariantMap changed;
    for (auto it = values.begin(); it != values.end(); ++it)
        if (document.parameter(it.key()) != it.value()) changed.insert(it.key(), it.value());
    if (changed.isEmpty()) return false;
    document.undoStack()->push(new ChangeParameters(&document, changed, text));
    return true;
}

} // namespace bunraku::app
