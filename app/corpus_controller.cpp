#include "app/corpus_controller.h"

#include "app/document.h"
#include "app/file_controller.h"
#include "app/file_dialogs.h"
#include "app/new_corpus_dialog.h"
#include "app/project_controller.h"

#include "analysis/io/corpus_io.h"
#include "analysis/synth/demo_corpus.h"

#include <QAction>
#include <QFileInfo>

#include <filesystem>

namespace bunraku::app {

CorpusController::CorpusController(Document& document, FileController& files) : QObject(&files), m_document(document), m_files(files)
{
    m_openCorpus = new QAction(tr("&Open Corpus Folder..."), this);
    m_openCorpus->setShortcut(QKeySequence::Open);
    m_openDemo = new QAction(tr("Open &Demo Corpus"), this);
    m_newCorpus = new QAction(tr("&New Corpus from Files..."), this);
    m_newCorpus->setToolTip(tr("Make a corpus of take files (BVH, CSV, FASTRAK): labels from their names, one part map, one rate"));
    connect(m_openDemo, &QAction::triggered, this, [this] {
        if (m_files.projects().maybeSave()) openDemoCorpus();
    });
    connect(m_openCorpus, &QAction::triggered, this, [this] {
        if (!m_files.projects().maybeSave()) return;
        const QString folder = chooseFolder(m_files.window(), FilePurpose::Corpus, tr("Open corpus folder"), m_files.projects().projectPath());
        if (!folder.isEmpty()) openCorpusFolder(folder);
    });
    connect(m_newCorpus, &QAction::triggered, this, [this] {
        if (m_files.projects().maybeSave()) chooseFilesForCorpus();
    });
}

bool CorpusController::openDemoCorpus()
{
    auto demo = analysis::synth::generateDemoCorpus();
    auto truth = std::make_shared<const analysis::synth::DemoGroundTruth>(std::move(demo.truth));
    // Shown first: the first take the generator did not turn about (its yaw channels wrap at
    // +-180 and the puppet faces away; such takes are there to exercise preprocessing).
    std::size_t first = 0;
    while (first + 1 < truth->takes.size() && truth->takes[first].yawWraps) ++first;
    m_document.setCorpus(std::move(demo.corpus), QStringLiteral("demo"), truth);
    if (first > 0) m_document.selectTake(TakeSlot::A, TakeId::corpus(first));
    emit corpusOpened();
    emit m_files.statusMessage(tr("Opened the demo corpus (%1 takes)").arg(m_document.corpus().takes.size()));
    return true;
}

bool CorpusController::openCorpusFolder(const QString& folder)
{
    analysis::Result<analysis::Corpus> corpus = analysis::makeError(analysis::ErrorCode::Cancelled, "not run");
    m_files.runTask(tr("Reading the corpus %1...").arg(QFileInfo(folder).fileName()),
                    [&](const analysis::RunControl& control) { corpus = analysis::io::readCorpus(toPath(folder), control); });
    if (!m_files.succeeded(corpus, tr("Opening %1 cancelled; nothing was changed").arg(folder), tr("Cannot open the corpus")))
        return false;
    const QString absolute = QFileInfo(folder).absoluteFilePath();
    m_document.setCorpus(std::move(corpus).value(), absolute);
    emit corpusOpened();
    m_files.addRecent(absolute);
    emit m_files.statusMessage(tr("Opened %1 (%2 takes)").arg(absolute).arg(m_document.corpus().takes.size()));
    return true;
}

bool CorpusController::createCorpusFromFiles(const std::vector<analysis::io::CorpusSource>& sources,
                                           const analysis::io::CorpusBuildOptions& options, const QString& folder)
{
    analysis::Result<analysis::io::CorpusBuild> result = analysis::makeError(analysis::ErrorCode::Cancelled, "not run");
    m_files.runTask(tr("Reading %n take file(s)...", nullptr, int(sources.size())),
                    [&](const analysis::RunControl& control) {
                        result = analysis::io::buildCorpus(sources, options, control);
                        if (!result) return;
                        if (auto written = analysis::io::writeCorpus(result->corpus, toPath(folder)); !written) result = written.error();
                    });
    if (!m_files.succeeded(result, tr("Making the corpus %1 cancelled; nothing was written").arg(folder), tr("Cannot make the corpus")))
        return false;
    if (!openCorpusFolder(folder)) return false;
    QStringList notes;
    for (const auto& note : result->notes) notes << QString::fromStdString(note);
    emit m_files.statusMessage(tr("Made the corpus %1 from %n file(s)", nullptr, int(sources.size())).arg(folder) +
                       (notes.isEmpty() ? QString() : QStringLiteral("; ") + notes.join(QStringLiteral("; "))));
    return true;
}

void CorpusController::chooseFilesForCorpus(const QStringList& inputs)
{
    NewCorpusDialog dialog(m_files.window());
    dialog.addInputs(inputs);
    dialog.setCreator([this](NewCorpusDialog& asking) {
        // The progress dialog over the new-corpus dialog; an error is shown in it, which stays open.
        return m_files.whileDialogAsks(&asking, [&] {
            const QString folder = asking.outputFolder();
            m_files.clearLastError();
            if (createCorpusFromFiles(asking.sources(), asking.buildOptions(), folder)) {
                rememberFolder(FilePurpose::Corpus, QFileInfo(folder).absoluteFilePath());
                rememberFolder(FilePurpose::NewCorpus, QFileInfo(folder).absoluteFilePath());
                return true;
            }
            asking.showCreateError(m_files.lastError().isEmpty() ? tr("cancelled; nothing was written") : m_files.lastError());
            return false;
        });
    });
    dialog.exec();
}

} // namespace bunraku::app
