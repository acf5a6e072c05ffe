#include "app/analysis_scope_notice.h"

#include "app/document.h"

#include <QFileInfo>

namespace bunraku::app {

AnalysisScopeNotice::AnalysisScopeNotice(const Document& document, QWidget* parent) : QLabel(parent), m_document(document)
{
    setObjectName("analysisScopeNotice");
    setWordWrap(true);
    setTextFormat(Qt::RichText);
    setStyleSheet(QStringLiteral("color: #b35900;"));
    connect(&document, &Document::selectionChanged, this, &AnalysisScopeNotice::refresh);
    connect(&document, &Document::corpusChanged, this, &AnalysisScopeNotice::refresh);
    connect(&document, &Document::derivedTakesChanged, this, &AnalysisScopeNotice::refresh);
    refresh();
}

QString AnalysisScopeNotice::textFor(const Document& document)
{
    const TakeId idA = document.selectedId(TakeSlot::A);
    for (const DerivedTake& derived : document.derivedTakes()) {
        if (derived.id != idA || derived.sourcePath.isEmpty()) continue;
        const QString corpus = document.corpusSource() == QStringLiteral("demo") ? tr("the demo corpus")
                                                                                 : QFileInfo(document.corpusSource()).fileName();
        return tr("Take A (%1) is imported beside the corpus, not part of it: this dock analyses the cells of %2 "
                  "(%3 takes). To analyse your own takes, make a corpus of them with <b>File &gt; New Corpus from Files</b>.")
            .arg(QFileInfo(derived.sourcePath).fileName().toHtmlEscaped(), corpus.toHtmlEscaped())
            .arg(document.corpus().takes.size());
    }
    return {};
}

void AnalysisScopeNotice::refresh()
{
    const QString text = textFor(m_document);
    setText(text);
    setVisible(!text.isEmpty());
}

} // namespace bunraku::app
