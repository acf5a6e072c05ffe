#include "widgets/corpus_browser.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QMenu>
#include <QPushButton>
#include <QSet>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <map>

namespace bunraku::widgets {
namespace {

constexpr int kIdRole = Qt::UserRole + 1;
constexpr int kMarkColumn = 2;

QString branchKey(const QTreeWidgetItem* item)
{
    QString key;
    for (; item; item = item->parent()) key.prepend(item->text(0) + "/");
    return key;
}

} // namespace

CorpusBrowser::CorpusBrowser(QWidget* parent) : QWidget(parent), m_tree(new QTreeWidget(this))
{
    m_tree->setColumnCount(3);
    m_tree->setHeaderLabels({tr("Take"), tr("Frames"), tr("Shown")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_tree->header()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_tree->header()->setStretchLastSection(false);
    m_tree->setContextMenuPolicy(Qt::CustomContextMenu);
    m_tree->setObjectName("corpusTree");

    auto* showA = new QPushButton(tr("Show as A"), this);
    auto* showB = new QPushButton(tr("Show as B"), this);
    auto* clearB = new QPushButton(tr("Hide B"), this);
    showA->setToolTip(tr("Show the selected take as take A (double click does the same)"));
    showB->setToolTip(tr("Show the selected take as take B, to compare with A"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(showA);
    buttons->addWidget(showB);
    buttons->addWidget(clearB);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tree);
    layout->addLayout(buttons);

    connect(showA, &QPushButton::clicked, this, [this] { chooseCurrent(TakeSlot::A); });
    connect(showB, &QPushButton::clicked, this, [this] { chooseCurrent(TakeSlot::B); });
    connect(clearB, &QPushButton::clicked, this, [this] { emit takeChosen(TakeSlot::B, QString()); });
    connect(m_tree, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
        if (item && !item->data(0, kIdRole).toString().isEmpty()) chooseCurrent(TakeSlot::A);
    });
    connect(m_tree, &QTreeWidget::customContextMenuRequested, this, [this](const QPoint& position) {
        QTreeWidgetItem* item = m_tree->itemAt(position);
        if (!item || item->data(0, kIdRole).toString().isEmpty()) return;
        m_tree->setCurrentItem(item);
        QMenu menu(this);
        menu.addAction(tr("Show as A"), this, [this] { chooseCurrent(TakeSlot::A); });
        menu.addAction(tr("Show as B"), this, [this] { chooseCurrent(TakeSlot::B); });
        menu.exec(m_tree->viewport()->mapToGlobal(position));
    });
}

void CorpusBrowser::setEntries(const std::vector<BrowserEntry>& entries)
{
    QSet<QString> expanded;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it)
        if ((*it)->isExpanded()) expanded.insert(branchKey(*it));
    const bool firstFill = m_tree->topLevelItemCount() == 0;
    m_tree->clear();

    std::map<QString, QTreeWidgetItem*> branches;
    auto branch = [&](QTreeWidgetItem* parent, const QString& text) {
        const QString key = (parent ? branchKey(parent) : QString()) + text + "/";
        auto found = branches.find(key);
        if (found != branches.end()) return found->second;
        auto* item = parent ? new QTreeWidgetItem(parent, {text}) : new QTreeWidgetItem(m_tree, {text});
        item->setFlags(Qt::ItemIsEnabled);
        item->setExpanded(firstFill ? !parent : expanded.contains(key));
        branches[key] = item;
        return item;
    };
    for (const auto& entry : entries) {
        QTreeWidgetItem* parent = entry.derived ? branch(nullptr, tr("Derived takes"))
                                                : branch(branch(nullptr, entry.function), entry.emotion);
        const QString text = entry.derived ? entry.label : tr("take %1").arg(entry.takeIndex);
        auto* leaf = new QTreeWidgetItem(parent, {text, QString::number(entry.frames)});
        leaf->setData(0, kIdRole, entry.id);
        leaf->setToolTip(0, entry.derived ? entry.label : QStringLiteral("%1 / %2 / take %3").arg(entry.function, entry.emotion).arg(entry.takeIndex));
    }
    setChosen(m_chosen[0], m_chosen[1]);
}

void CorpusBrowser::setEntryLabel(const QString& id, const QString& label)
{
    if (QTreeWidgetItem* item = findLeaf(id)) {
        item->setText(0, label);
        item->setToolTip(0, label);
    }
}

void CorpusBrowser::setEntryFrames(const QString& id, int frames)
{
    if (QTreeWidgetItem* item = findLeaf(id)) item->setText(1, QString::number(frames));
}

int CorpusBrowser::entryFrames(const QString& id) const
{
    const QTreeWidgetItem* item = findLeaf(id);
    return item ? item->text(1).toInt() : -1;
}

QString CorpusBrowser::entryText(const QString& id) const
{
    const QTreeWidgetItem* item = findLeaf(id);
    return item ? item->text(0) : QString();
}

void CorpusBrowser::setChosen(const QString& idA, const QString& idB)
{
    m_chosen[0] = idA;
    m_chosen[1] = idB;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        const QString id = (*it)->data(0, kIdRole).toString();
        QString mark;
        if (!id.isEmpty() && id == idA) mark = QStringLiteral("A");
        if (!id.isEmpty() && id == idB) mark += mark.isEmpty() ? QStringLiteral("B") : QStringLiteral(" B");
        (*it)->setText(kMarkColumn, mark);
        QFont font = (*it)->font(0);
        font.setBold(!mark.isEmpty());
        (*it)->setFont(0, font);
    }
}

int CorpusBrowser::takeCount() const
{
    int count = 0;
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it)
        if (!(*it)->data(0, kIdRole).toString().isEmpty()) ++count;
    return count;
}

QString CorpusBrowser::currentId() const
{
    const QTreeWidgetItem* item = m_tree->currentItem();
    return item ? item->data(0, kIdRole).toString() : QString();
}

QTreeWidgetItem* CorpusBrowser::findLeaf(const QString& id) const
{
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it)
        if ((*it)->data(0, kIdRole).toString() == id) return *it;
    return nullptr;
}

bool CorpusBrowser::selectId(const QString& id)
{
    QTreeWidgetItem* item = findLeaf(id);
    if (!item) return false;
    for (auto* parent = item->parent(); parent; parent = parent->parent()) parent->setExpanded(true);
    m_tree->setCurrentItem(item);
    return true;
}

void CorpusBrowser::chooseCurrent(TakeSlot slot)
{
    const QString id = currentId();
    if (!id.isEmpty()) emit takeChosen(slot, id);
}

} // namespace bunraku::widgets
