#pragma once
/// Help > Keyboard Shortcuts: every key of the window, read from its actions (so the list is
/// always what the keys do), plus the keys that act in one view only (Home in the 3D view, Delete
/// on a phrase tick) and the mouse in the graphs, the 3D view and the timeline. A filter field
/// narrows the list, as in Blender's keymap.

#include <QDialog>
#include <QString>

#include <vector>

class QLineEdit;
class QMainWindow;
class QTableWidget;

namespace bunraku::app {

struct ShortcutEntry {
    QString action; ///< "Play", "Frame All"
    QString keys;   ///< "Space", "Shift+F", "Ctrl+Z, Ctrl+Shift+Z"
    QString where;  ///< "everywhere", "3D view (focused)", "graphs (mouse)"
};

/// The window's actions with keys (menus, tool bars, the timeline), then the view-only keys and
/// the mouse. Keys in the platform's text ("Ctrl+Shift+Z").
std::vector<ShortcutEntry> windowShortcuts(const QMainWindow& window);

class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    explicit ShortcutsDialog(const QMainWindow& window, QWidget* parent = nullptr);

    QTableWidget* table() const { return m_table; }
    QLineEdit* filter() const { return m_filter; }
    /// The keys listed for `action` (the first row of that name), empty when not listed.
    QString keysOf(const QString& action) const;

private:
    void applyFilter(const QString& text);

    QLineEdit* m_filter = nullptr;
    QTableWidget* m_table = nullptr;
};

} // namespace bunraku::app
