#pragma once
/// The File menu's corpora: open a corpus folder or the demo corpus, and make a corpus from take
/// files (File > New Corpus from Files..., as `bunraku corpus`). Long reads run off the GUI
/// thread behind a progress dialog that can cancel them; errors are told by the FileController.

#include "analysis/io/corpus_builder.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <vector>

class QAction;

namespace bunraku::app {

class Document;
class FileController;

class CorpusController : public QObject {
    Q_OBJECT
public:
    CorpusController(Document& document, FileController& files);

    // Operations without dialogs (each returns false and reports the error on failure).
    bool openDemoCorpus();
    bool openCorpusFolder(const QString& folder);
    /// Builds a corpus from take files (analysis/io/corpus_builder.h, as `bunraku corpus`),
    /// writes it to `folder` and opens it. With dialogs the work runs off the GUI thread behind a
    /// progress dialog that can cancel it; the notes (rates, neutral emotion) go to the status bar.
    bool createCorpusFromFiles(const std::vector<analysis::io::CorpusSource>& sources,
                               const analysis::io::CorpusBuildOptions& options, const QString& folder);
    /// File > New Corpus from Files: the dialog, then createCorpusFromFiles. `inputs` preset it.
    /// When the corpus cannot be made the dialog stays open with everything the user entered and
    /// the error (the row of the file it names selected). The corpus made is remembered as the
    /// folder of corpora (file_dialogs.h), where the next new corpus is suggested.
    void chooseFilesForCorpus(const QStringList& inputs = {});

    QAction* openCorpusAction() const { return m_openCorpus; }
    QAction* openDemoAction() const { return m_openDemo; }
    QAction* newCorpusAction() const { return m_newCorpus; }

signals:
    /// A corpus was opened in place of the document's (it is no longer the project's).
    void corpusOpened();

private:
    Document& m_document;
    FileController& m_files;
    QAction* m_openCorpus = nullptr;
    QAction* m_openDemo = nullptr;
    QAction* m_newCorpus = nullptr;
};

} // namespace bunraku::app
