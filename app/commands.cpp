#include "app/commands.h"

#include <QCoreApplication>

namespace bunraku::app {

ParameterPart::ParameterPart(const AnalysisParameters& p, ParameterSections sections) : m_sections(sections)
{
    if (sections.testFlag(kPreprocessSection)) m_preprocess = p.preprocess;
    if (sections.testFlag(kNormaliseSection)) m_normalise = p.normalise;
    if (sections.testFlag(kDecomposeSection)) m_decompose = p.decompose;
    if (sections.testFlag(kFluctuationSection)) m_fluctuations = p.fluctuations;
    if (sections.testFlag(kAxisSection)) m_axis = p.axis;
    if (sections.testFlag(kWeightSection)) m_weight = p.design.emotionWeight;
    if (sections.testFlag(kWarpSection)) m_warp = p.design.warp;
    if (sections.testFlag(kGainSection)) m_gains = p.design.gains;
    if (sections.testFlag(kBoundarySection)) m_boundaries = p.design.boundaries;
}

void ParameterPart::applyTo(AnalysisParameters& p) const
{
    if (m_preprocess) p.preprocess = *m_preprocess;
    if (m_normalise) p.normalise = *m_normalise;
    if (m_decompose) p.decompose = *m_decompose;
    if (m_fluctuations) p.fluctuations = *m_fluctuations;
    if (m_axis) p.axis = *m_axis;
    if (m_sections.testFlag(kWeightSection)) p.design.emotionWeight = m_weight;
    if (m_sections.testFlag(kWarpSection)) p.design.warp = m_warp;
    if (m_sections.testFlag(kGainSection)) p.design.gains = m_gains;
    if (m_sections.testFlag(kBoundarySection)) p.design.boundaries = m_boundaries;
}

void ParameterPart::addMissing(const ParameterPart& other)
{
    const ParameterSections missing = other.m_sections & ~m_sections;
    if (!missing) return;
    // Both parts' values on one set of parameters, this one's last: its own sections stay.
    AnalysisParameters values;
    other.applyTo(values);
    applyTo(values);
    *this = ParameterPart(values, m_sections | missing);
}

bool ParameterPart::operator==(const ParameterPart& other) const
{
    if (m_sections != other.m_sections) return false;
    AnalysisParameters mine, theirs;
    applyTo(mine);
    other.applyTo(theirs);
    return !changedSections(mine, theirs);
}

ParameterCommand::ParameterCommand(Document* document, const AnalysisParameters& after, const QString& text, int id, int merging)
    : m_document(document),
      m_id(id),
      m_merging(merging),
      m_interaction(document->interactionId())
{
    const ParameterSections sections = changedSections(document->parameters(), after);
    m_before = ParameterPart(document->parameters(), sections);
    m_after = ParameterPart(after, sections);
    setText(text);
}

void ParameterCommand::apply(const ParameterPart& part)
{
    // The other sections are what they were when this command was done or undone (the stack's
    // order): only its own change is made.
    AnalysisParameters parameters = m_document->parameters();
    part.applyTo(parameters);
    m_document->applyParameters(parameters, {});
}

void ParameterCommand::undo() { apply(m_before); }

void ParameterCommand::redo() { apply(m_after); }

void ParameterCommand::setStep(const QString& control)
{
    m_stepControl = control;
    m_stepSeries = m_document->stepSeries();
    m_stepMilliseconds = m_document->clockMilliseconds();
}

bool ParameterCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const ParameterCommand*>(other);
    const bool sameDrag = (m_merging & InDrag) && m_interaction != 0 && next->m_interaction == m_interaction;
    const bool sameSteps = (m_merging & InSteps) && m_interaction == 0 && next->m_interaction == 0 && !m_stepControl.isEmpty() &&
                           next->m_stepControl == m_stepControl && next->m_stepSeries == m_stepSeries &&
                           next->m_stepMilliseconds >= m_stepMilliseconds &&
                           next->m_stepMilliseconds - m_stepMilliseconds <= kStepMergeMilliseconds;
    if (!sameDrag && !sameSteps) return false;
    // A section only the next step changed was, before this command, what the next one found.
    m_before.addMissing(next->m_before);
    ParameterPart after = next->m_after;
    after.addMissing(m_after);
    m_after = after;
    m_stepMilliseconds = next->m_stepMilliseconds;
    setText(next->text()); // "Set T_cmp to 30 frames": the value the merged steps ended at
    setObsolete(m_after == m_before);
    return true;
}

SetEmotionWeight::SetEmotionWeight(Document* document, AnalysisParameters after)
    : ParameterCommand(document, after,
                       QCoreApplication::translate("commands", "Set emotion weight a to %1").arg(after.design.emotionWeight, 0, 'f', 2),
                       kSetEmotionWeightId, InDrag | InSteps)
{
}

MoveWarpPoint::MoveWarpPoint(Document* document, AnalysisParameters after, const QString& text)
    : ParameterCommand(document, std::move(after), text.isEmpty() ? QCoreApplication::translate("commands", "Move warp point") : text,
                       kMoveWarpPointId, InDrag)
{
}

SetPhraseGain::SetPhraseGain(Document* document, AnalysisParameters after)
    : ParameterCommand(document, std::move(after), QCoreApplication::translate("commands", "Set phrase gain"), kSetPhraseGainId,
                       InDrag | InSteps)
{
}

MovePhraseBoundary::MovePhraseBoundary(Document* document, AnalysisParameters after)
    : ParameterCommand(document, std::move(after), QCoreApplication::translate("commands", "Move phrase boundary"),
                       kMovePhraseBoundaryId, InDrag)
{
}

AddPhraseBoundary::AddPhraseBoundary(Document* document, AnalysisParameters after)
    : ParameterCommand(document, std::move(after), QCoreApplication::translate("commands", "Add phrase boundary"), -1, Never)
{
}

RemovePhraseBoundary::RemovePhraseBoundary(Document* document, AnalysisParameters after)
    : ParameterCommand(document, std::move(after), QCoreApplication::translate("commands", "Remove phrase boundary"), -1, Never)
{
}

ImportTake::ImportTake(Document* document, TakePointer take, const QString& label, const QString& sourcePath,
                       std::shared_ptr<const analysis::io::ImportOptions> options)
    : m_document(document), m_take{document->nextImportedId(), label, std::move(take), sourcePath, TakeId(), std::move(options), nullptr, {}}
{
    setText(QCoreApplication::translate("commands", "Import %1").arg(label));
}

void ImportTake::redo()
{
    m_previousA = m_document->selectedId(TakeSlot::A);
    m_document->insertImportedTake(m_take, int(m_document->derivedTakes().size()), {});
    m_document->selectTake(TakeSlot::A, m_take.id);
}

void ImportTake::undo()
{
    m_document->removeImportedTake(m_take.id, {});
    m_document->selectTake(TakeSlot::A, m_previousA);
}

RemoveImportedTake::RemoveImportedTake(Document* document, const TakeId& id) : m_document(document)
{
    m_position = document->indexOfDerived(id);
    if (m_position >= 0) m_take = document->derivedTakes()[std::size_t(m_position)];
    setText(QCoreApplication::translate("commands", "Remove %1").arg(m_take.label));
}

void RemoveImportedTake::redo()
{
    if (m_position >= 0) m_document->removeImportedTake(m_take.id, {});
}

void RemoveImportedTake::undo()
{
    if (m_position >= 0) m_document->insertImportedTake(m_take, m_position, {});
}

AnalysisParameters editedParameters(const Document& document, const std::function<void(AnalysisParameters&)>& edit)
{
    AnalysisParameters parameters = document.parameters();
    edit(parameters);
    return parameters;
}

bool pushParameters(Document& document, ParameterCommand* command, const QString& step)
{
    if (!command->sections()) {
        delete command;
        return false;
    }
    if (!step.isEmpty()) command->setStep(step);
    document.undoStack()->push(command);
    return true;
}

bool changeStageParameters(Document& document, const std::function<void(AnalysisParameters&)>& edit, const QString& text,
                           const QString& stepControl)
{
    return pushParameters(document, new ChangeStageParameters(&document, editedParameters(document, edit), text), stepControl);
}

bool setEmotionWeight(Document& document, double weight)
{
    return pushParameters(document,
                          new SetEmotionWeight(&document, editedParameters(document, [weight](AnalysisParameters& p) {
                                                   p.design.emotionWeight = weight;
                                               })),
                          QStringLiteral("design.emotionWeight"));
}

} // namespace bunraku::app
