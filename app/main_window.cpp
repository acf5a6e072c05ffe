#include "app/main_window.h"

#include "app/analysis_controller.h"
#include "app/design_controller.h"
#include "app/design_panel.h"
#include "app/emotion_panel.h"
#include "app/file_controller.h"
#include "app/file_dialogs.h"
#include "app/focus_return.h"
#include "app/help_controller.h"
#include "app/multimodal_export_controller.h"
#include "app/image_file.h"
#include "app/normalise_panel.h"
#include "app/offscreen_view.h"
#include "app/phrase_marks.h"
#include "app/playback_controller.h"
#include "app/shortcuts_dialog.h"
#include "app/side_columns.h"
#include "app/video_export_dialog.h"
#include "app/view_video_controller.h"
#include "app/export_controller.h"
#include "app/viewport_panel.h"

#include "widgets/clock.h"
#include "widgets/corpus_browser.h"
#include "widgets/elided_label.h"
#include "widgets/graph_panel.h"
#include "widgets/inspector_widget.h"
#include "widgets/scrub_bar.h"
#include "widgets/timeline_widget.h"
#include "widgets/viewport_widget.h"

#include "analysis/core/puppet_layout.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QProgressDialog>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QTabBar>
#include <QUndoView>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace bunraku::app {
namespace {

const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");
constexpr int kLayoutVersion = 1;
/// How long an action's message stays in the status bar (Qt's own status tips go at once; a
/// message naming a written file needs the time to be read).
constexpr int kStatusTimeoutMs = 12000;

/// Corpus takes then derived takes, as the browser lists them; `ids` maps each entry's key (the
/// id's text) back to its id.
std::vector<widgets::BrowserEntry> browserEntries(const Document& document, QHash<QString, TakeId>& ids)
{
    std::vector<widgets::BrowserEntry> entries;
    ids.clear();
    const auto keyOf = [&ids](const TakeId& id) {
        QString key = id.toString();
        ids.insert(key, id);
        return key;
    };
    const auto& corpus = document.corpus();
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        const auto& take = corpus.takes[i];
        widgets::BrowserEntry entry;
        entry.id = keyOf(TakeId::corpus(i));
        entry.function = QString::fromStdString(take.labels.function.empty() ? "(no function)" : take.labels.function);
        entry.emotion = QString::fromStdString(take.labels.emotion.empty() ? "(no emotion)" : take.labels.emotion);
        entry.takeIndex = take.labels.takeIndex;
        entry.frames = int(take.frameCount());
        entries.push_back(entry);
    }
    for (const auto& derived : document.derivedTakes()) {
        widgets::BrowserEntry entry;
        entry.id = keyOf(derived.id);
        entry.label = derived.label;
        entry.frames = derived.take ? int(derived.take->frameCount()) : 0;
        entry.derived = true;
        entries.push_back(entry);
    }
    return entries;
}

/// `panel` in a scroll area: a dock holding it can be shorter or narrower than the panel's own
/// minimum (a 1280 x 720 screen) and scrolls instead of pushing other docks off the window.
QWidget* scrolled(QWidget* panel)
{
    auto* area = new QScrollArea;
    area->setObjectName(panel->objectName().isEmpty() ? QStringLiteral("panelScroll") : panel->objectName() + QStringLiteral("Scroll"));
    area->setFrameShape(QFrame::NoFrame);
    area->setWidgetResizable(true);
    area->setWidget(panel);
    return area;
}

} // namespace

MainWindow::MainWindow(QWidget* parent, std::shared_ptr<Executor> executor) : QMainWindow(parent), m_document(new Document(this))
{
    setObjectName("mainWindow");
    setAcceptDrops(true);
    setDockNestingEnabled(true);
    setDockOptions(AnimatedDocks | AllowNestedDocks | AllowTabbedDocks);
    m_files = new FileController(*m_document, this);
    m_exports = new ExportController(*m_document, this);
    m_files->projects().setViewStateHooks([this] { return viewState(); }, [this](const ViewState& state) { restoreViewState(state); });
    m_playback = new PlaybackController(*m_document, this);
    m_status = new widgets::ElidedLabel(this);
    m_status->setObjectName("statusMessage");
    m_statusTimer = new widgets::ClockTimer(this);
    m_statusTimer->setInterval(kStatusTimeoutMs);
    connect(m_statusTimer, &widgets::ClockTimer::timeout, this, [this] {
        if (m_status->text() == m_transientStatus) m_status->clear();
    });
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1000);
    m_progress->setMaximumWidth(180);
    m_progress->setVisible(false);
    m_stages = new QLabel(this);
    m_stages->setObjectName("stageStatus");
    // Which takes the views show, always in sight (the title bar may be hidden or cut).
    m_shownTakes = new QLabel(this);
    m_shownTakes->setObjectName("shownTakes");
    statusBar()->addWidget(m_status, 1);
    statusBar()->addPermanentWidget(m_shownTakes);
    statusBar()->addPermanentWidget(m_stages);
    statusBar()->addPermanentWidget(m_progress);
    createViews(std::move(executor));
    createMenus();
    connectDocument();

    connect(m_files, &FileController::statusMessage, this, &MainWindow::showStatus);
    connect(m_exports, &ExportController::statusMessage, this, &MainWindow::showStatus);
    connect(m_normalisePanel, &NormalisePanel::statusMessage, this, &MainWindow::showStatus);
    connect(m_emotionPanel, &EmotionPanel::statusMessage, this, &MainWindow::showStatus);
    new FocusReturn(this);
    m_columns = new SideColumns(this);
    // A wider window widens the 3D view first: it keeps at least a third of the width.
    m_columns->setFavoured(dock(QStringLiteral("viewDock")), 1.0 / 3.0);

    // The default size, within the screen (a 1366 x 768 laptop gets the whole screen).
    const QSize preferred(1500, 920);
    resize(screen() ? preferred.boundedTo(screen()->availableSize()) : preferred);
    m_defaultState = saveState(kLayoutVersion);
    updateTitle();
}

MainWindow::~MainWindow()
{
    // The document and its undo stack are children destroyed after this window's members: the
    // stack's destructor emits cleanChanged, which must not reach updateTitle on a half-gone window.
    m_document->undoStack()->disconnect(this);
    m_document->disconnect(this);
}

QDockWidget* MainWindow::addDock(QWidget* widget, const QString& title, const QString& objectName, Qt::DockWidgetArea area)
{
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(objectName);
    dock->setWidget(widget);
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetFloatable);
    addDockWidget(area, dock);
    m_docks.push_back(dock);
    return dock;
}

QDockWidget* MainWindow::dock(const QString& objectName) const
{
    for (auto* dock : m_docks)
        if (dock->objectName() == objectName) return dock;
    return nullptr;
}

void MainWindow::createViews(std::shared_ptr<Executor> executor)
{
    m_browser = new widgets::CorpusBrowser(this);
    m_inspector = new widgets::InspectorWidget(this);
    m_graphs = new widgets::GraphPanel(this);
    m_timeline = new widgets::TimelineWidget(this);
    m_analysis = new AnalysisController(*m_document, this, std::move(executor));
    // A kimono export simulates the cloth the 3D view shows (its Cloth Settings).
    m_exports->setClothParameters(m_analysis->clothParameters());
    connect(m_analysis, &AnalysisController::clothParametersChanged, m_exports, &ExportController::setClothParameters);
    m_viewportPanel = new ViewportPanel(*m_document, *m_analysis, this);
    m_design = new DesignController(*m_document, *m_analysis, this);
    m_designPanel = new DesignPanel(*m_document, *m_design, this);
    m_normalisePanel = new NormalisePanel(*m_document, *m_analysis, this);
    m_emotionPanel = new EmotionPanel(*m_document, *m_analysis, this);
    auto* history = new QUndoView(m_document->undoStack(), this);
    history->setEmptyLabel(tr("<opened>"));

    auto* corpusDock = addDock(m_browser, tr("Corpus"), "corpusDock", Qt::LeftDockWidgetArea);
    auto* inspectorDock = addDock(m_inspector, tr("Inspector"), "inspectorDock", Qt::LeftDockWidgetArea);
    auto* historyDock = addDock(history, tr("Undo History"), "historyDock", Qt::LeftDockWidgetArea);
    auto* graphsDock = addDock(m_graphs, tr("Graphs"), "graphsDock", Qt::RightDockWidgetArea);
    auto* viewDock = addDock(m_viewportPanel, tr("3D View"), "viewDock", Qt::RightDockWidgetArea);
    m_normalisePanel->setObjectName("normalisePanel");
    m_emotionPanel->setObjectName("emotionPanel");
    m_designPanel->setObjectName("designPanel");
    auto* normaliseDock = addDock(scrolled(m_normalisePanel), tr("Normalisation"), "normaliseDock", Qt::LeftDockWidgetArea);
    auto* emotionDock = addDock(scrolled(m_emotionPanel), tr("Emotion"), "emotionDock", Qt::LeftDockWidgetArea);
    auto* designDock = addDock(scrolled(m_designPanel), tr("Design"), "designDock", Qt::LeftDockWidgetArea);
    auto* timelineDock = addDock(m_timeline, tr("Timeline"), "timelineDock", Qt::BottomDockWidgetArea);
    splitDockWidget(viewDock, graphsDock, Qt::Horizontal);
    splitDockWidget(corpusDock, inspectorDock, Qt::Vertical);
    tabifyDockWidget(inspectorDock, normaliseDock);
    tabifyDockWidget(normaliseDock, emotionDock);
    tabifyDockWidget(emotionDock, designDock);
    // The undo history beside the corpus: four tabs below fit a narrow left column unelided.
    tabifyDockWidget(corpusDock, historyDock);
    corpusDock->raise();
    inspectorDock->raise();
    timelineDock->setFeatures(timelineDock->features() & ~QDockWidget::DockWidgetVerticalTitleBar);
    resizeDocks({corpusDock, viewDock, graphsDock}, {420, 460, 620}, Qt::Horizontal);
    resizeDocks({corpusDock, inspectorDock}, {260, 440}, Qt::Vertical);
    // One status entry per analysis stage: its progress while it runs, its error when it fails
    // (the panel showing the stage's result shows the error too).
    connect(&m_analysis->scheduler(), &StageScheduler::stateChanged, this, &MainWindow::showStageStatus);
    connect(&m_analysis->scheduler(), &StageScheduler::progressChanged, this, &MainWindow::showStageStatus);
    connect(&m_analysis->scheduler(), &StageScheduler::failed, this, [this](int slot, const QString& message) {
        m_status->setText(tr("%1 failed: %2").arg(AnalysisController::slotTitle(slot), message));
        m_failures[slot] = m_status->text();
    });
    // A stage that runs or succeeds again takes its failure out of the status bar.
    connect(&m_analysis->scheduler(), &StageScheduler::stateChanged, this, [this](int slot) {
        const auto failure = m_failures.find(slot);
        if (failure == m_failures.end() || m_analysis->scheduler().state(slot) == SlotState::Failed) return;
        if (m_status->text() == failure->second) m_status->clear();
        m_failures.erase(failure);
    });
}

void MainWindow::createMenus()
{
    auto* file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_files->corpora().openDemoAction());
    file->addAction(m_files->corpora().openCorpusAction());
    file->addAction(m_files->corpora().newCorpusAction());
    file->addMenu(m_files->recentMenu());
    file->addSeparator();
    file->addAction(m_files->projects().openProjectAction());
    file->addAction(m_files->projects().saveProjectAction());
    file->addAction(m_files->projects().saveProjectAsAction());
    file->addSeparator();
    file->addAction(m_files->imports().importAction());
    file->addAction(m_exports->exportAction(TakeSlot::A));
    file->addAction(m_exports->exportAction(TakeSlot::B));
    file->addAction(tr("Save &Screenshot..."), this, &MainWindow::chooseScreenshot);
    auto* report = file->addAction(tr("Export &Report..."), this, &MainWindow::chooseReport);
    report->setObjectName("exportReportAction");
    report->setToolTip(tr("The analysis report of the open corpus as one HTML file (figures and tables, the thesis's values beside)"));
    m_viewVideo = new ViewVideoController(*m_document, *m_playback, *m_viewportPanel, *m_files, this);
    connect(m_viewVideo, &ViewVideoController::message, this, &MainWindow::showStatus);
    file->addAction(m_viewVideo->action());
    m_multimodal = new MultimodalExportController(*m_document, *m_graphs, *m_viewportPanel, this);
    connect(m_multimodal, &MultimodalExportController::message, this, &MainWindow::showStatus);
    file->addAction(m_multimodal->action());
    file->addSeparator();
    auto* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    auto* edit = menuBar()->addMenu(tr("&Edit"));
    auto* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    auto* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    // Platform redo keys plus Ctrl+Shift+Z everywhere (on Linux it is already the platform key).
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    if (!redoKeys.contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z))) redoKeys << QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z);
    redo->setShortcuts(redoKeys);
    edit->addAction(undo);
    edit->addAction(redo);

    auto* playback = menuBar()->addMenu(tr("&Playback"));
    for (auto* action : {m_timeline->playAction(), m_timeline->stepBackAction(), m_timeline->stepForwardAction(),
                         m_timeline->homeAction(), m_timeline->endAction(), m_timeline->loopAction()})
        playback->addAction(action);

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    for (auto* dock : m_docks) m_viewMenu->addAction(dock->toggleViewAction());
    m_viewMenu->addSeparator();
    auto* camera = m_viewMenu->addMenu(tr("3D View &Camera"));
    for (auto* action : {m_viewportPanel->frameAllAction(), m_viewportPanel->frameSelectedAction(), m_viewportPanel->resetCameraAction()})
        camera->addAction(action);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(tr("&Reset Layout"), this, &MainWindow::resetLayout);

    auto* helpController = new HelpController(this);
    auto* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(helpController->userGuideAction());
    auto* shortcuts = help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showShortcuts);
    shortcuts->setObjectName("keyboardShortcutsAction");
    shortcuts->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Slash));
    help->addAction(helpController->aboutAction());
}

void MainWindow::connectDocument()
{
    connect(m_document, &Document::corpusChanged, this, [this] {
        refreshEntries();
        updateTitle();
    });
    connect(m_document, &Document::derivedTakesChanged, this, &MainWindow::refreshEntries);
    // A live take recomputed from other parameters or another take is renamed where it is listed.
    connect(m_document, &Document::takeLabelChanged, this, [this](const TakeId& id) {
        m_browser->setEntryLabel(id.toString(), m_document->takeLabel(id));
        updateTitle();
    });
    // ... and its frame count is the new take's.
    connect(m_document, &Document::takeChanged, this, [this](const TakeId& id) {
        if (const TakePointer take = m_document->take(id)) m_browser->setEntryFrames(id.toString(), int(take->frameCount()));
    });
    connect(m_document, &Document::selectionChanged, this, [this] { refreshTakes(); });
    connect(m_document, &Document::selectedTakeReplaced, this, [this] { refreshTakes(); });
    connect(m_document, &Document::currentTimeChanged, this, &MainWindow::refreshTime);
    connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    // During a drag the graphs hold their value ranges (autoscaled once when it ends).
    connect(m_document, &Document::interactionChanged, this, [this](bool active) {
        if (active)
            m_graphs->grid()->beginInteraction();
        else
            m_graphs->grid()->endInteraction();
    });

    connect(m_browser, &widgets::CorpusBrowser::takeChosen, this,
            [this](widgets::TakeSlot slot, const QString& key) {
                if (key.isEmpty() || m_browserIds.contains(key)) m_document->selectTake(TakeSlot(int(slot)), m_browserIds.value(key));
            });
    connect(m_graphs->grid(), &widgets::GraphGrid::timeScrubbed, m_document, &Document::setCurrentTime);
    connect(m_timeline, &widgets::TimelineWidget::timeScrubbed, m_document, &Document::setCurrentTime);
    connect(m_timeline, &widgets::TimelineWidget::playToggled, m_playback, &PlaybackController::setPlaying);
    connect(m_playback, &PlaybackController::playingChanged, m_timeline, &widgets::TimelineWidget::setPlaying);
    connect(m_timeline, &widgets::TimelineWidget::stepRequested, m_playback, &PlaybackController::step);
    connect(m_timeline, &widgets::TimelineWidget::homeRequested, m_playback, &PlaybackController::goToStart);
    connect(m_timeline, &widgets::TimelineWidget::endRequested, m_playback, &PlaybackController::goToEnd);
    connect(m_timeline, &widgets::TimelineWidget::loopToggled, m_playback, &PlaybackController::setLooping);
    connect(m_timeline, &widgets::TimelineWidget::speedChanged, m_playback, &PlaybackController::setSpeed);
    m_playback->setLooping(m_timeline->looping());
    // Dragging a phrase mark moves the design's boundary: one undo step per drag.
    auto* bar = m_timeline->scrubBar();
    connect(bar, &widgets::ScrubBar::boundaryDragStarted, m_document, &Document::beginInteraction);
    connect(bar, &widgets::ScrubBar::boundaryDragFinished, m_document, &Document::endInteraction);
    // Ticks are at take A's times (the designed take's through the warp): map back to functional frames.
    connect(bar, &widgets::ScrubBar::boundaryDragged, this, [this](int index, double seconds) {
        m_design->moveBoundary(index, m_design->functionalFrameAt(m_document->selectedId(TakeSlot::A), seconds));
    });
    connect(bar, &widgets::ScrubBar::boundaryAddRequested, this, [this](double seconds) {
        m_design->addBoundary(m_design->functionalFrameAt(m_document->selectedId(TakeSlot::A), seconds));
    });
    connect(bar, &widgets::ScrubBar::boundaryRemoveRequested, m_design, &DesignController::removeBoundary);
    connect(m_design, &DesignController::prepared, this, &MainWindow::refreshBoundaries);
    connect(m_design, &DesignController::designed, this, &MainWindow::refreshBoundaries);
    connect(m_viewportPanel, &ViewportPanel::partPicked, m_graphs, &widgets::GraphPanel::selectPart);
    connect(m_viewportPanel, &ViewportPanel::bonePicked, this, [this](int slot, const QString& joint, const QString& part) {
        // A take of a skeleton's joints has the joint as a part: its graphs follow the pick (a
        // puppet take's picked part came with partPicked).
        m_graphs->selectPart(joint);
        showStatus(part.isEmpty() ? tr("Bone %1 of take %2").arg(joint, slot == 0 ? QStringLiteral("A") : QStringLiteral("B"))
                                         : tr("Bone %1 of take %2 (drives the %3)").arg(joint, slot == 0 ? QStringLiteral("A") : QStringLiteral("B"), part));
    });
}

void MainWindow::showStatus(const QString& message)
{
    m_transientStatus = message;
    m_status->setText(message);
    m_status->setToolTip(m_status->shownText() == message ? QString() : message);
    m_statusTimer->start();
}

int MainWindow::statusTimeout() const { return m_statusTimer->interval(); }

void MainWindow::setStatusClock(widgets::Clock* clock) { m_statusTimer->setClock(clock); }

void MainWindow::refreshEntries()
{
    m_browser->setEntries(browserEntries(*m_document, m_browserIds));
    refreshTakes();
}

void MainWindow::refreshTakes()
{
    const TakePointer takeA = m_document->selectedTake(TakeSlot::A);
    const TakePointer takeB = m_document->selectedTake(TakeSlot::B);
    m_browser->setChosen(m_document->selectedId(TakeSlot::A).toString(), m_document->selectedId(TakeSlot::B).toString());
    // The ghost (a live take's original), and the thesis's per-channel result of a take shown as
    // one body: as the ghost when there is no other, else beside it; the caption says how far.
    const TakeId idA = m_document->selectedId(TakeSlot::A);
    const TakePointer ghost = m_document->ghostOf(idA);
    const TakePointer perChannel = m_document->perChannelGhostOf(idA);
    QString caption;
    if (const auto distance = m_document->perChannelDistanceOf(idA))
        caption = tr("%1: the thesis's per-channel result (each channel computed on its own), up to %2 cm (%3) and %4 deg from "
                     "the body shown, which is what the 3D view draws and every export writes")
                      .arg(ghost == perChannel ? tr("Grey dashes") : tr("Purple line"))
                      .arg(distance->maxPositionCm, 0, 'f', 1)
                      .arg(QString::fromStdString(distance->worstPart))
                      .arg(distance->maxAngleDeg, 0, 'f', 1) +
                  (ghost && ghost != perChannel ? tr(". Grey dashes: the take it was made from") : QString());
    m_graphs->setGhost(ghost);
    m_graphs->setPerChannelGhost(ghost == perChannel ? nullptr : perChannel, caption);
    m_graphs->setTakes(takeA, takeB, m_document->selectedId(TakeSlot::A).toString() + QLatin1Char('|') + m_document->selectedId(TakeSlot::B).toString());
    m_inspector->setTakes(takeA, takeB);
    m_timeline->setDuration(m_document->duration(), m_document->rateHz());
    refreshBoundaries();
    refreshTime(m_document->currentTime());
    updateTitle();
}

void MainWindow::refreshBoundaries()
{
    const TakeId idA = m_document->selectedId(TakeSlot::A);
    const TakePointer takeA = m_document->selectedTake(TakeSlot::A);
    const bool designed = m_design->showsBoundariesOn(idA);
    std::vector<double> boundaries;
    if (designed)
        boundaries = m_design->boundarySecondsOn(idA);
    else if (takeA && m_document->demoTruth())
        boundaries = phraseBoundarySeconds(*m_document->demoTruth(), *takeA);
    m_timeline->scrubBar()->setBoundariesEditable(designed);
    m_timeline->setBoundaries(std::move(boundaries));
}

void MainWindow::refreshTime(double seconds)
{
    m_graphs->grid()->setCursorTime(seconds);
    m_inspector->setTime(seconds);
    m_timeline->setTime(seconds);
}

void MainWindow::updateTitle()
{
    const QString source = m_document->corpusSource() == QStringLiteral("demo") ? tr("demo corpus")
                                                                               : QFileInfo(m_document->corpusSource()).fileName();
    QString shown = m_document->takeLabel(m_document->selectedId(TakeSlot::A));
    if (!m_document->selectedId(TakeSlot::B).isEmpty())
        shown += tr(" vs ") + m_document->takeLabel(m_document->selectedId(TakeSlot::B));
    // "demo corpus - greeting/none/2* - Bunraku Motion Workbench"; with no take shown, no empty
    // part ("no corpus* - ...").
    if (shown.isEmpty())
        setWindowTitle(tr("%1[*] - Bunraku Motion Workbench").arg(source.isEmpty() ? tr("no corpus") : source));
    else
        setWindowTitle(tr("%1 - %2[*] - Bunraku Motion Workbench").arg(source.isEmpty() ? tr("no corpus") : source, shown));
    // A long derived take's name is elided here (in full in the tool tip and the title).
    const auto named = [this](TakeSlot slot) {
        return fontMetrics().elidedText(m_document->takeLabel(m_document->selectedId(slot)), Qt::ElideRight, 320);
    };
    QString takes = tr("A: %1").arg(named(TakeSlot::A));
    if (!m_document->selectedId(TakeSlot::B).isEmpty()) takes += QStringLiteral("   ") + tr("B: %1").arg(named(TakeSlot::B));
    m_shownTakes->setText(takes);
    m_shownTakes->setToolTip(tr("The takes the 3D view, the graphs and the inspector show: %1").arg(shown));
    setWindowModified(!m_document->undoStack()->isClean());
}

void MainWindow::resetLayout()
{
    restoreState(m_defaultState, kLayoutVersion);
    for (auto* dock : m_docks) {
        dock->setFloating(false);
        dock->show();
    }
    m_columns->reset();
}

void MainWindow::restoreSavedLayout()
{
    const QSettings settings;
    if (settings.contains(kGeometryKey)) restoreGeometry(settings.value(kGeometryKey).toByteArray());
    if (settings.contains(kStateKey) && restoreState(settings.value(kStateKey).toByteArray(), kLayoutVersion))
        m_columns->adoptRestoredLayout();
}

void MainWindow::saveLayout() const
{
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState(kLayoutVersion));
}

QString MainWindow::stageStatusText() const { return m_stages->text(); }

void MainWindow::showStageStatus()
{
    const StageScheduler& scheduler = m_analysis->scheduler();
    QStringList parts;
    double least = 1.0;
    for (int slot : {AnalysisController::kPreprocessSlot, AnalysisController::kNormaliseSlot, AnalysisController::kDecomposeSlot,
                     AnalysisController::kAxesSlot, AnalysisController::kTakeAxisSlot, AnalysisController::kTakeAxisBSlot,
                     AnalysisController::kNormalisedBodySlot, AnalysisController::kWeightedSlot}) {
        if (scheduler.state(slot) == SlotState::Running) {
            parts << tr("%1 %2 %").arg(AnalysisController::slotTitle(slot)).arg(int(scheduler.progress(slot) * 100.0 + 0.5));
            least = std::min(least, scheduler.progress(slot));
        } else if (scheduler.state(slot) == SlotState::Failed) {
            parts << tr("%1 failed").arg(AnalysisController::slotTitle(slot));
        }
    }
    m_stages->setText(parts.join(QStringLiteral(" \u00b7 ")));
    m_stages->setToolTip(tr("Analysis stages running in the background (each recomputes only when its own inputs change)"));
    const bool running = scheduler.busy();
    m_progress->setVisible(running);
    if (running) m_progress->setValue(int(least * 1000));
}

bool MainWindow::exportReport(const QString& file)
{
    const auto status = m_analysis->exportReport(std::filesystem::path(file.toStdString()));
    if (!status) {
        showStatus(tr("Cannot export the report: %1").arg(QString::fromStdString(status.error().message)));
        return false;
    }
    showStatus(tr("Wrote the report %1").arg(file));
    return true;
}

void MainWindow::chooseReport()
{
    QString file = chooseSaveFile(this, FilePurpose::Report, tr("Export report"),
                                  suggestedFileName(*m_document, QStringLiteral("-report.html"), NameParts::Corpus), tr("HTML (*.html)"),
                                  m_files->projects().projectPath());
    if (file.isEmpty()) return;
    if (!file.endsWith(QStringLiteral(".html"), Qt::CaseInsensitive)) file += QStringLiteral(".html");
    if (!exportReport(file)) QMessageBox::warning(this, tr("Export Report"), m_status->text());
}

bool MainWindow::saveScreenshot(const QString& file, QWidget* widget)
{
    const QPixmap image = (widget ? widget : this)->grab();
    if (const auto saved = saveImageAtomically(image.toImage(), file); !saved) {
        showStatus(tr("Cannot write the screenshot %1").arg(QString::fromStdString(saved.error().message)));
        return false;
    }
    showStatus(tr("Saved screenshot %1").arg(file));
    return true;
}

int MainWindow::exportViewFrames(const QString& folder) { return m_viewVideo->exportFrames(folder); }

VideoExportResult MainWindow::exportViewVideo(const VideoExportOptions& options, const ExportProgress& progress)
{
    return m_viewVideo->exportVideo(options, progress);
}

void MainWindow::showShortcuts()
{
    ShortcutsDialog dialog(*this, this);
    dialog.exec();
}

void MainWindow::chooseScreenshot()
{
    QStringList views{tr("Whole window")};
    for (auto* dock : m_docks)
        if (dock->isVisible()) views << dock->windowTitle();
    QString file = chooseSaveFile(this, FilePurpose::Screenshot, tr("Save screenshot"), suggestedFileName(*m_document, QStringLiteral(".png")),
                                  tr("PNG images (*.png)"), m_files->projects().projectPath());
    if (file.isEmpty()) return;
    if (!file.endsWith(QStringLiteral(".png"), Qt::CaseInsensitive)) file += QStringLiteral(".png");
    // The view to grab: the dock that has focus, else the whole window.
    QWidget* target = nullptr;
    for (auto* dock : m_docks)
        if (dock->isVisible() && dock->isAncestorOf(QApplication::focusWidget())) target = dock->widget();
    saveScreenshot(file, target);
}

ViewState MainWindow::viewState() const
{
    ViewState state;
    state.graphLayout = int(m_graphs->grid()->graphLayout());
    state.twoTakeMode = int(m_graphs->grid()->twoTakeMode());
    state.valueScale = int(m_graphs->grid()->valueScale());
    state.angleDisplay = int(m_graphs->angleDisplay());
    state.thesisTicks = m_graphs->grid()->thesisTicks();
    state.part = m_graphs->selectedPart();
    state.dof = m_graphs->selectedDof();
    state.camera = m_viewportPanel->cameraState();
    state.shown = m_viewportPanel->shownObjects();
    state.figureA = m_viewportPanel->figureBox(0)->currentIndex();
    state.figureB = m_viewportPanel->figureBox(1)->currentIndex();
    state.cloth = m_viewportPanel->clothBox()->isChecked();
    state.clothParameters = m_analysis->clothParameters();
    state.weightEmotion = m_analysis->weightEmotion();
    if (!m_analysis->cellFunction().empty()) {
        state.cellFunction = QString::fromStdString(m_analysis->cellFunction());
        state.cellEmotion = QString::fromStdString(m_analysis->cellEmotion());
    }
    state.speed = m_timeline->speed();
    // The docks' places and sizes (QMainWindow::saveState), so the project reopens as laid out,
    // and the left column's width: a layout restored into a larger window gives that column the
    // difference unless told (SideColumns keeps this width instead).
    state.windowState = saveState(kLayoutVersion);
    state.leftWidth = m_columns->leftWidth();
    state.windowWidth = width();
    return state;
}

void MainWindow::restoreViewState(const ViewState& state)
{
    if (state.graphLayout) m_graphs->setGraphLayout(widgets::GraphLayout(*state.graphLayout));
    if (state.twoTakeMode) m_graphs->setTwoTakeMode(widgets::TwoTakeMode(*state.twoTakeMode));
    if (state.valueScale) m_graphs->setValueScale(widgets::ValueScale(*state.valueScale));
    if (state.thesisTicks) m_graphs->setThesisTicks(*state.thesisTicks);
    if (state.angleDisplay) m_graphs->setAngleDisplay(widgets::AngleDisplay(*state.angleDisplay));
    if (state.part) m_graphs->selectPart(*state.part);
    if (state.dof) m_graphs->selectDof(*state.dof);
    if (state.camera) m_viewportPanel->setCameraState(*state.camera);
    m_viewportPanel->setShownObjects(state.shown);
    // The 3D view's figure per take: puppet, skeleton, both or body (the boxes' order).
    if (state.figureA) m_viewportPanel->figureBox(0)->setCurrentIndex(*state.figureA);
    if (state.figureB) m_viewportPanel->figureBox(1)->setCurrentIndex(*state.figureB);
    // The kimono as cloth and its settings (checked by the project reader against their ranges).
    if (state.clothParameters) (void)m_analysis->setClothParameters(*state.clothParameters);
    if (state.cloth) m_viewportPanel->clothBox()->setChecked(*state.cloth);
    if (state.weightEmotion) m_analysis->setWeightEmotion(*state.weightEmotion);
    if (state.graphLayout) m_graphs->setGraphLayout(widgets::GraphLayout(*state.graphLayout));
    if (state.speed) m_timeline->setSpeed(*state.speed);
    // A layout that is not one of this layout version is ignored.
    if (state.windowState && restoreState(*state.windowState, kLayoutVersion))
        m_columns->adoptLayoutNow(state.leftWidth.value_or(0), state.windowWidth.value_or(0));
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_files->projects().maybeSave()) {
        event->ignore();
        return;
    }
    m_playback->setPlaying(false);
    saveLayout();
    m_files->projects().autosaveSession().removeOwn(); // saved, discarded or clean: nothing left to recover
    event->accept();
}

bool MainWindow::event(QEvent* event)
{
    // The tab bars of tabbed docks (made by the layout, also when docks are dragged together)
    // scroll instead of eliding their titles to "Nor..." in a narrow column.
    if (event->type() == QEvent::ChildPolished)
        if (auto* bar = qobject_cast<QTabBar*>(static_cast<QChildEvent*>(event)->child())) {
            bar->setElideMode(Qt::ElideNone);
            bar->setUsesScrollButtons(true);
        }
    return QMainWindow::event(event);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    QStringList paths;
    for (const QUrl& url : event->mimeData()->urls())
        if (url.isLocalFile()) paths << url.toLocalFile();
    event->acceptProposedAction();
    // After the drop has ended: opening may ask to save unsaved changes first.
    QTimer::singleShot(0, m_files, [files = m_files, paths] { files->openDroppedPaths(paths); });
}

} // namespace bunraku::app
