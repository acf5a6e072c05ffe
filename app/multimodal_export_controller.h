#pragma once
/// File > Export Multimodal Video...: the takes shown (A, and B beside it), the 3D view's camera
/// and objects, and the graph dock's layout, part, DOF and ticks, composed frame by frame
/// (MultimodalFrame) and written by the video export (exportMultimodalVideo) with a progress
/// dialog and Cancel. The 3D view is drawn offscreen at the arrangement's size.

#include "app/multimodal_export_dialog.h"

#include <QObject>

class QAction;
class QWidget;

namespace bunraku::widgets {
class GraphPanel;
}

namespace bunraku::app {

class Document;
class ViewportPanel;

class MultimodalExportController : public QObject {
    Q_OBJECT
public:
    MultimodalExportController(Document& document, widgets::GraphPanel& graphs, ViewportPanel& viewport, QWidget* window);

    /// "Export &Multimodal Video...", for the File menu.
    QAction* action() const { return m_action; }

    /// The graph dock's choices (layout, part, DOF, thesis ticks) at `size`.
    MultimodalOptions graphDockLayout(QSize size = {1920, 1080}) const;

    /// Exports take A's frames (and B's beside them) with `layout`; without `progress` a modal
    /// progress dialog with Cancel. Reports the outcome through message().
    VideoExportResult exportVideo(const MultimodalOptions& layout, const VideoExportOptions& options,
                                  const ExportProgress& progress = {});

signals:
    /// A line for the status bar.
    void message(const QString& text);

private:
    void choose();

    Document& m_document;
    widgets::GraphPanel& m_graphs;
    ViewportPanel& m_viewport;
    QWidget* m_window = nullptr;
    QAction* m_action = nullptr;
};

} // namespace bunraku::app
