#include "app/about_dialog.h"

#include "app/build_info.h"
#include "app/installed_files.h"
#include "app/library_versions.h"

#include <QApplication>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace bunraku::app {
namespace {

QString fromView(std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); }

} // namespace

AboutDialog::AboutDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("aboutDialog"));
    setWindowTitle(tr("About Bunraku Motion Workbench"));

    const QString version = fromView(projectVersion());
    QString commit = fromView(buildCommit());
    if (!buildCommitDate().empty()) commit += QStringLiteral(" (%1)").arg(fromView(buildCommitDate()));

    auto* icon = new QLabel(this);
    icon->setPixmap(applicationIcon().pixmap(96, 96));
    icon->setAlignment(Qt::AlignTop);

    auto* text = new QLabel(this);
    text->setObjectName(QStringLiteral("aboutText"));
    text->setTextFormat(Qt::RichText);
    text->setOpenExternalLinks(true);
    text->setWordWrap(true);
    text->setTextInteractionFlags(Qt::TextBrowserInteraction);
    text->setText(tr("<h2>Bunraku Motion Workbench</h2>"
                     "<p>Version %1<br>Commit %2</p>"
                     "<p>Inspect, normalise, decompose and design expressive motion, after M. Hattori, "
                     "<i>Analysis of emotional expression in the performance motions of Bunraku puppets</i> "
                     "(Kobe University, 2000).</p>"
                     "<p>Copyright &copy; 2026 The Bunraku Motion Workbench authors.<br>"
                     "Licence: GNU General Public License, version 3 or (at your option) any later version "
                     "(%3). This program comes with ABSOLUTELY NO WARRANTY; see "
                     "<a href=\"https://www.gnu.org/licenses/gpl-3.0.html\">the licence</a>.</p>"
                     "<p>Built on:</p>")
                      .arg(version.toHtmlEscaped(), commit.toHtmlEscaped(), fromView(projectLicense())));

    const QList<LibraryVersion> libraries = libraryVersions();
    m_libraries = new QTableWidget(int(libraries.size()), 3, this);
    m_libraries->setObjectName(QStringLiteral("aboutLibraries"));
    m_libraries->setHorizontalHeaderLabels({tr("Library"), tr("Version"), tr("Licence")});
    m_libraries->verticalHeader()->hide();
    m_libraries->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_libraries->setSelectionMode(QAbstractItemView::NoSelection);
    m_libraries->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_libraries->horizontalHeader()->setStretchLastSection(true);

    m_plainText = QStringLiteral("Bunraku Motion Workbench %1\ncommit %2\nlicence %3\n").arg(version, commit, fromView(projectLicense()));
    for (int row = 0; row < libraries.size(); ++row) {
        const LibraryVersion& library = libraries[row];
        m_libraries->setItem(row, 0, new QTableWidgetItem(library.name));
        m_libraries->setItem(row, 1, new QTableWidgetItem(library.version));
        m_libraries->setItem(row, 2, new QTableWidgetItem(library.license));
        m_plainText += QStringLiteral("%1 %2 (%3)\n").arg(library.name, library.version, library.license);
    }
    m_libraries->resizeColumnsToContents();
    m_libraries->setMinimumHeight(m_libraries->horizontalHeader()->height() + 2 * m_libraries->frameWidth()
                                  + m_libraries->rowHeight(0) * int(libraries.size()));

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    auto* copy = buttons->addButton(tr("&Copy"), QDialogButtonBox::ActionRole);
    copy->setObjectName(QStringLiteral("aboutCopy"));
    connect(copy, &QPushButton::clicked, this, [this] { QApplication::clipboard()->setText(m_plainText); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* top = new QHBoxLayout;
    top->addWidget(icon);
    top->addWidget(text, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_libraries);
    layout->addWidget(buttons);
    resize(560, sizeHint().height());
}

QString AboutDialog::plainText() const { return m_plainText; }

} // namespace bunraku::app
