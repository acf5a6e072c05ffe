#include "app/help_controller.h"

#include "app/about_dialog.h"
#include "app/installed_files.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QImage>
#include <QScreen>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QUrl>
#include <QVBoxLayout>

#include <algorithm>

namespace bunraku::app {
namespace {

/// Scales the document's images down to at most `maxWidth` pixels wide (the guide's screenshot
/// is a whole window), keeping their aspect ratio.
void fitImages(QTextDocument* document, int maxWidth)
{
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        for (auto fragment = block.begin(); !fragment.atEnd(); ++fragment) {
            const QTextFragment part = fragment.fragment();
            if (!part.isValid() || !part.charFormat().isImageFormat()) continue;
            QTextImageFormat image = part.charFormat().toImageFormat();
            const QImage picture = document->resource(QTextDocument::ImageResource, QUrl(image.name())).value<QImage>();
            if (picture.isNull() || picture.width() <= maxWidth) continue;
            image.setWidth(maxWidth);
            image.setHeight(double(maxWidth) * picture.height() / picture.width());
            QTextCursor cursor(document);
            cursor.setPosition(part.position());
            cursor.setPosition(part.position() + part.length(), QTextCursor::KeepAnchor);
            cursor.setCharFormat(image);
        }
    }
}

} // namespace

HelpController::HelpController(QWidget* window) : QObject(window), m_window(window)
{
    m_userGuide = new QAction(tr("&User Guide"), this);
    m_userGuide->setObjectName(QStringLiteral("userGuideAction"));
    m_userGuide->setShortcut(QKeySequence::HelpContents);
    if (userGuidePath().isEmpty()) {
        m_userGuide->setEnabled(false);
        m_userGuide->setToolTip(tr("The user guide is not installed (%1)").arg(expectedUserGuidePath()));
    }
    connect(m_userGuide, &QAction::triggered, this, [this] { showUserGuide(); });

    m_about = new QAction(tr("&About Bunraku Motion Workbench"), this);
    m_about->setObjectName(QStringLiteral("aboutAction"));
    m_about->setMenuRole(QAction::AboutRole);
    connect(m_about, &QAction::triggered, this, [this] { showAbout(); });
}

QSize HelpController::guideViewerSize(const QRect& area)
{
    const QSize preferred(900, 800);
    if (!area.isValid()) return preferred;
    // Room for a window manager's title bar and borders.
    constexpr int kFrameWidth = 16;
    constexpr int kFrameHeight = 48;
    return preferred.boundedTo(QSize(std::max(320, area.width() - kFrameWidth), std::max(240, area.height() - kFrameHeight)));
}

QDialog* HelpController::showUserGuide()
{
    const QString guide = userGuidePath();
    if (guide.isEmpty()) return nullptr;
    if (!m_guideViewer) {
        auto* viewer = new QDialog(m_window, Qt::Window);
        viewer->setObjectName(QStringLiteral("userGuideViewer"));
        viewer->setAttribute(Qt::WA_DeleteOnClose);
        viewer->setWindowTitle(tr("Bunraku Motion Workbench User Guide"));
        auto* browser = new QTextBrowser(viewer);
        browser->setObjectName(QStringLiteral("userGuideBrowser"));
        browser->setOpenExternalLinks(true);
        // Relative links and images (screenshot.png, FORMATS.md) resolve beside the guide.
        browser->setSearchPaths({QFileInfo(guide).absolutePath()});
        browser->setSource(QUrl::fromLocalFile(guide), QTextDocument::MarkdownResource);
        const QRect area = m_availableForTesting.isValid() ? m_availableForTesting
                           : m_window && m_window->screen()        ? m_window->screen()->availableGeometry()
                                                                   : QRect();
        const QSize size = guideViewerSize(area);
        fitImages(browser->document(), std::max(200, size.width() - 80));
        auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, viewer);
        connect(buttons, &QDialogButtonBox::rejected, viewer, &QDialog::close);
        auto* layout = new QVBoxLayout(viewer);
        layout->addWidget(browser);
        layout->addWidget(buttons);
        viewer->resize(size);
        // Centred in the screen area, its frame inside it.
        if (area.isValid()) viewer->move(area.center() - QPoint(size.width() / 2, size.height() / 2));
        m_guideViewer = viewer;
    }
    m_guideViewer->show();
    m_guideViewer->raise();
    m_guideViewer->activateWindow();
    return m_guideViewer;
}

QDialog* HelpController::showAbout()
{
    if (!m_aboutDialog) {
        auto* dialog = new AboutDialog(m_window);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        m_aboutDialog = dialog;
    }
    m_aboutDialog->show();
    m_aboutDialog->raise();
    m_aboutDialog->activateWindow();
    return m_aboutDialog;
}

} // namespace bunraku::app
