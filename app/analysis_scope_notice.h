#pragma once
/// The line at the top of the Normalisation, Emotion and Design docks while take A is a take
/// imported beside the corpus (File > Import Take, or files given on the command line): the
/// analyses run on the open corpus's cells, never on such a take, and this says so and how to
/// analyse one's own takes (File > New Corpus from Files). Hidden otherwise.

#include <QLabel>

namespace bunraku::app {

class Document;

class AnalysisScopeNotice : public QLabel {
    Q_OBJECT
public:
    AnalysisScopeNotice(const Document& document, QWidget* parent = nullptr);

    /// The text for the document's state ("" when take A is not an imported take).
    static QString textFor(const Document& document);

private:
    void refresh();

    const Document& m_document;
};

} // namespace bunraku::app
