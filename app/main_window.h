#pragma once
/// The workbench window: every view is a QDockWidget (movable, closable, restorable from the
/// View menu), the layout is saved between runs (QSettings) and "Reset layout" restores the
/// default. It composes widgets/ over the Document; the actions live in controllers
/// (FileController, PlaybackController) and undo commands.

#include "app/document.h"
#include "app/video_export.h"
#include "app/view_state.h"

#include <QHash>
#include <QMainWindow>

#include <map>
#include <memory>
#include <vector>

class QDockWidget;
class QLabel;
class QProgressBar;

namespace bunraku::widgets {
class Clock;
class ClockTimer;
class CorpusBrowser;
class ElidedLabel;
class GraphPanel;
class InspectorWidget;
class TimelineWidget;
} // namespace bunraku::widgets

namespace bunraku::app {

class AnalysisController;
class DesignController;
class DesignPanel;
class EmotionPanel;
class Executor;
class NormalisePanel;
class ExportController;
class FileController;
class MultimodalExportController;
class ViewVideoController;
class PlaybackController;
class SideColumns;
class ViewportPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// `executor` runs the analysis jobs (stage_scheduler.h); null: the thread pool. The monkey
    /// test (tests/monkey) passes a manual one, so that results arrive when its seed says.
    explicit MainWindow(QWidget* parent = nullptr, std::shared_ptr<Executor> executor = {});
    ~MainWindow() override;

    Document& document() { return *m_document; }
    FileController& files() { return *m_files; }
    ExportController& exports() { return *m_exports; }
    PlaybackController& playback() { return *m_playback; }
    widgets::GraphPanel* graphPanel() const { return m_graphs; }
    widgets::TimelineWidget* timeline() const { return m_timeline; }
    widgets::InspectorWidget* inspector() const { return m_inspector; }
    widgets::CorpusBrowser* browser() const { return m_browser; }
    /// The 3D view dock's content.
    ViewportPanel* viewportPanel() const { return m_viewportPanel; }
    AnalysisController& analysis() { return *m_analysis; }
    DesignController& design() { return *m_design; }
    DesignPanel* designPanel() const { return m_designPanel; }
    NormalisePanel* normalisePanel() const { return m_normalisePanel; }
    EmotionPanel* emotionPanel() const { return m_emotionPanel; }
    /// File > Export Multimodal Video...
    MultimodalExportController& multimodalExport() { return *m_multimodal; }
    const std::vector<QDockWidget*>& docks() const { return m_docks; }
    QDockWidget* dock(const QString& objectName) const;

    /// Shows every dock in its default place.
    void resetLayout();
    /// Restores the saved geometry and dock layout (QSettings), if any.
    void restoreSavedLayout();
    void saveLayout() const;
    /// The status bar's text of the analysis stages (running stages with their progress).
    QString stageStatusText() const;
    /// The status bar's names of the takes shown: "A: greeting/friendly/2", then
    /// "  B: ..." when B is shown; kept current as takes are chosen or renamed.
    QLabel* shownTakesLabel() const { return m_shownTakes; }
    /// The status bar's message line: one message at a time, a newer one replacing it; an
    /// action's message goes after statusTimeout() (a stage's failure stays until the stage runs
    /// again). Cut with an ellipsis at the window's edge, whole in its tool tip.
    widgets::ElidedLabel* statusLine() const { return m_status; }
    /// Shows an action's message (export, screenshot, a clamped value...) until the next one or
    /// the time out.
    void showStatus(const QString& message);
    /// Milliseconds an action's message stays.
    int statusTimeout() const;
    /// The clock the message's time-out runs on (the steady clock by default; tests inject a
    /// widgets::ManualClock).
    void setStatusClock(widgets::Clock* clock);
    /// File > Export Report: the analysis report of the open corpus (HTML) written to `file`;
    /// false (and a status message) on error.
    bool exportReport(const QString& file);

    /// Grabs `widget` (the whole window when null) into an image file (PNG by extension).
    bool saveScreenshot(const QString& file, QWidget* widget = nullptr);
    /// File > Export 3D View Video's exports (view_video_controller.h): every frame of take A as
    /// PNGs at the view's size, and a frame range as MP4 or PNGs at any size.
    int exportViewFrames(const QString& folder);
    VideoExportResult exportViewVideo(const VideoExportOptions& options, const ExportProgress& progress = {});

protected:
    bool event(QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    QDockWidget* addDock(QWidget* widget, const QString& title, const QString& objectName, Qt::DockWidgetArea area);
    void createViews(std::shared_ptr<Executor> executor);
    void createMenus();
    void connectDocument();
    void refreshEntries();
    void refreshTakes();
    /// The timeline's phrase marks: the design's (draggable) when take A is the functional take
    /// or the designed take, else the demo truth's.
    void refreshBoundaries();
    void refreshTime(double seconds);
    void updateTitle();
    void chooseScreenshot();
    void chooseReport();
    void showStageStatus();
    /// File > Export 3D View Video...: the dialog, the export, then a message on error.
    /// Help > Keyboard Shortcuts.
    void showShortcuts();
    ViewState viewState() const;
    void restoreViewState(const ViewState& state);

    Document* m_document = nullptr;
    FileController* m_files = nullptr;
    ExportController* m_exports = nullptr;
    PlaybackController* m_playback = nullptr;
    widgets::GraphPanel* m_graphs = nullptr;
    widgets::TimelineWidget* m_timeline = nullptr;
    widgets::InspectorWidget* m_inspector = nullptr;
    widgets::CorpusBrowser* m_browser = nullptr;
    /// The browser's entry keys (the ids' text) and the ids they stand for.
    QHash<QString, TakeId> m_browserIds;
    ViewportPanel* m_viewportPanel = nullptr;
    AnalysisController* m_analysis = nullptr;
    DesignController* m_design = nullptr;
    DesignPanel* m_designPanel = nullptr;
    NormalisePanel* m_normalisePanel = nullptr;
    EmotionPanel* m_emotionPanel = nullptr;
    MultimodalExportController* m_multimodal = nullptr;
    ViewVideoController* m_viewVideo = nullptr;
    std::vector<QDockWidget*> m_docks;
    QByteArray m_defaultState;
    QMenu* m_viewMenu = nullptr;
    QProgressBar* m_progress = nullptr;
    widgets::ElidedLabel* m_status = nullptr;
    widgets::ClockTimer* m_statusTimer = nullptr;
    QString m_transientStatus; ///< the action's message the timer clears (not a stage failure)
    QLabel* m_stages = nullptr;
    QLabel* m_shownTakes = nullptr;
    SideColumns* m_columns = nullptr;
    std::map<int, QString> m_failures; ///< per analysis slot: its failure shown in the status bar
};

} // namespace bunraku::app
