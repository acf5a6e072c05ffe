#pragma once
/// The Help menu: **User Guide** (F1) shows the installed guide (docs/USER-GUIDE.md, installed as
/// PREFIX/share/bunraku/doc/USER-GUIDE.md) rendered from its Markdown in a viewer window, and
/// **About** shows the AboutDialog. When the guide is not installed the action says so and is
/// disabled, rather than opening an empty window.

#include <QObject>
#include <QPointer>
#include <QRect>
#include <QSize>

class QAction;
class QDialog;
class QWidget;

namespace bunraku::app {

class HelpController : public QObject {
    Q_OBJECT
public:
    explicit HelpController(QWidget* window);

    QAction* userGuideAction() const { return m_userGuide; }
    QAction* aboutAction() const { return m_about; }

    /// Shows the user guide (one viewer, raised when already open); nullptr when not installed.
    QDialog* showUserGuide();
    /// Shows the About dialog (modeless, one at a time).
    QDialog* showAbout();
    /// The screen area the guide viewer is fitted into (a 1366 x 768 laptop's, in tests); an
    /// invalid rectangle: the window's screen's available geometry.
    void setAvailableGeometryForTesting(const QRect& area) { m_availableForTesting = area; }
    /// The viewer's size on a screen whose available area is `area`: 900 x 800, smaller where
    /// the screen is (room left for the window frame).
    static QSize guideViewerSize(const QRect& area);

private:
    QWidget* m_window = nullptr;
    QAction* m_userGuide = nullptr;
    QAction* m_about = nullptr;
    QPointer<QDialog> m_guideViewer;
    QPointer<QDialog> m_aboutDialog;
    QRect m_availableForTesting;
};

} // namespace bunraku::app
