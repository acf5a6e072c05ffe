#pragma once
/// The corpus as a function x emotion x take tree, plus the derived takes (normalised, average,
/// components, weighted, designed, imported) under their own branch. The user chooses take A
/// and take B (double click: A; buttons or context menu: A or B); the tree marks them.

#include <QString>
#include <QWidget>

#include <vector>

class QTreeWidget;
class QTreeWidgetItem;

namespace bunraku::widgets {

/// One take as the browser lists it.
struct BrowserEntry {
    QString id;        ///< stable identifier the app resolves (never shown)
    QString function;  ///< corpus takes: function label; derived: empty
    QString emotion;   ///< corpus takes: emotion label
    int takeIndex = 0; ///< corpus takes: 1-based index in the cell
    QString label;     ///< derived takes: the name shown
    int frames = 0;
    bool derived = false;
};

enum class TakeSlot { A = 0, B = 1 };

class CorpusBrowser : public QWidget {
    Q_OBJECT
public:
    explicit CorpusBrowser(QWidget* parent = nullptr);

    /// Replaces the listed takes, keeping the expansion of branches that still exist.
    void setEntries(const std::vector<BrowserEntry>& entries);
    /// Renames the derived take `id` in place (selection and expansion kept).
    void setEntryLabel(const QString& id, const QString& label);
    /// Sets the frame count shown for `id` (a live take recomputed from another take).
    void setEntryFrames(const QString& id, int frames);
    /// The frame count shown for `id`, -1 when not listed.
    int entryFrames(const QString& id) const;
    /// The text the tree shows for `id`, empty when not listed.
    QString entryText(const QString& id) const;
    /// Marks which takes are A and B (empty id: none).
    void setChosen(const QString& idA, const QString& idB);

    /// The number of takes listed (leaves).
    int takeCount() const;
    /// The id of the selected leaf, or empty.
    QString currentId() const;
    /// Selects the leaf with `id` (for keyboard-free tests and restoring state).
    bool selectId(const QString& id);
    QTreeWidget* tree() const { return m_tree; }

signals:
    void takeChosen(bunraku::widgets::TakeSlot slot, const QString& id);

private:
    void chooseCurrent(TakeSlot slot);
    QTreeWidgetItem* findLeaf(const QString& id) const;

    QTreeWidget* m_tree = nullptr;
    QString m_chosen[2];
};

} // namespace bunraku::widgets
