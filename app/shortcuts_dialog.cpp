#include "app/shortcuts_dialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QCoreApplication>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSet>
#include <QTableWidget>
#include <QVBoxLayout>

namespace bunraku::app {

namespace {

/// The action's text without mnemonics and without the text after a tab (shown as its key).
QString plainText(const QAction* action)
{
    QString text = action->text().section(QLatin1Char('\t'), 0, 0);
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    text.replace(QStringLiteral("&&"), QStringLiteral("&"));
    if (text.endsWith(QStringLiteral("..."))) text.chop(3);
    return text.trimmed();
}

void collect(const QList<QAction*>& actions, std::vector<ShortcutEntry>& entries, QSet<const QAction*>& seen)
{
    for (const QAction* action : actions) {
        if (!action || seen.contains(action)) continue;
        seen.insert(action);
        if (action->menu()) collect(action->menu()->actions(), entries, seen);
        QStringList keys;
        for (const QKeySequence& key : action->shortcuts()) keys << key.toString(QKeySequence::NativeText);
        const QString shown = action->text().section(QLatin1Char('\t'), 1); // a key named in the text
        if (keys.isEmpty() && shown.isEmpty()) continue;
        entries.push_back({plainText(action), keys.isEmpty() ? shown : keys.join(QStringLiteral(", ")),
                           keys.isEmpty() ? QCoreApplication::translate("ShortcutsDialog", "see the key") :
                                            QCoreApplication::translate("ShortcutsDialog", "everywhere but while typing")});
    }
}

} // namespace

std::vector<ShortcutEntry> windowShortcuts(const QMainWindow& window)
{
    const auto tr = [](const char* text) { return QCoreApplication::translate("ShortcutsDialog", text); };
    std::vector<ShortcutEntry> entries;
    QSet<const QAction*> seen;
    if (window.menuBar()) collect(window.menuBar()->actions(), entries, seen);
    // Actions of the views that are in no menu.
    for (const QAction* action : window.findChildren<QAction*>())
        if (!action->shortcuts().isEmpty() && action->shortcutContext() == Qt::WindowShortcut) collect({const_cast<QAction*>(action)}, entries, seen);
    for (ShortcutEntry& entry : entries)
        if (entry.where == tr("see the key")) entry.where = tr("3D view (focused)");
    const std::vector<ShortcutEntry> views{
        {tr("Remove the selected phrase boundary"), tr("Delete, Backspace"), tr("timeline (focused)")},
        {tr("Orbit the camera"), tr("Left drag"), tr("3D view (mouse)")},
        {tr("Pan the camera"), tr("Right or middle drag"), tr("3D view (mouse)")},
        {tr("Zoom the camera"), tr("Wheel"), tr("3D view (mouse)")},
        {tr("Show a part's graphs"), tr("Click a part"), tr("3D view (mouse)")},
        {tr("Move the time"), tr("Press or drag"), tr("graphs, timeline (mouse)")},
        {tr("Zoom time"), tr("Wheel"), tr("graphs (mouse)")},
        {tr("Pan time"), tr("Shift+drag, middle drag"), tr("graphs (mouse)")},
        {tr("Show the whole take"), tr("Double click"), tr("graphs (mouse)")},
        {tr("Move a phrase boundary"), tr("Drag an orange tick"), tr("timeline (mouse)")},
        {tr("Add a phrase boundary"), tr("Double click"), tr("timeline (mouse)")},
        {tr("Move a warp point (it stops at its neighbours)"), tr("Drag a point"), tr("Design warp curve (mouse)")},
        {tr("Move a warp point pushing the points it meets"), tr("Shift+drag a point"), tr("Design warp curve (mouse)")},
        {tr("Show as A"), tr("Double click"), tr("corpus (mouse)")},
    };
    entries.insert(entries.end(), views.begin(), views.end());
    return entries;
}

ShortcutsDialog::ShortcutsDialog(const QMainWindow& window, QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Keyboard Shortcuts"));
    setObjectName("shortcutsDialog");
    m_filter = new QLineEdit(this);
    m_filter->setObjectName("shortcutFilter");
    m_filter->setPlaceholderText(tr("Filter by action or key"));
    m_filter->setClearButtonEnabled(true);
    m_table = new QTableWidget(this);
    m_table->setObjectName("shortcutTable");
    m_table->setColumnCount(3);
    m_table->setHorizontalHeaderLabels({tr("Action"), tr("Keys"), tr("Where")});
    m_table->verticalHeader()->setVisible(false);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    const auto entries = windowShortcuts(window);
    m_table->setRowCount(int(entries.size()));
    for (int row = 0; row < int(entries.size()); ++row) {
        const ShortcutEntry& entry = entries[std::size_t(row)];
        m_table->setItem(row, 0, new QTableWidgetItem(entry.action));
        m_table->setItem(row, 1, new QTableWidgetItem(entry.keys));
        m_table->setItem(row, 2, new QTableWidgetItem(entry.where));
    }
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    auto* note = new QLabel(tr("Window keys work wherever the focus is, except while you type in a text field; after a "
                               "control is set the focus returns to the window."),
                            this);
    note->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_filter);
    layout->addWidget(m_table, 1);
    layout->addWidget(note);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_filter, &QLineEdit::textChanged, this, &ShortcutsDialog::applyFilter);
    resize(560, 520);
}

QString ShortcutsDialog::keysOf(const QString& action) const
{
    for (int row = 0; row < m_table->rowCount(); ++row)
        if (m_table->item(row, 0)->text() == action) return m_table->item(row, 1)->text();
    return {};
}

void ShortcutsDialog::applyFilter(const QString& text)
{
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const bool shown = text.isEmpty() || m_table->item(row, 0)->text().contains(text, Qt::CaseInsensitive) ||
                           m_table->item(row, 1)->text().contains(text, Qt::CaseInsensitive);
        m_table->setRowHidden(row, !shown);
    }
}

} // namespace bunraku::app
