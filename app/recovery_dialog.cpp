#include "app/recovery_dialog.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace bunraku::app {

RecoveryDialog::RecoveryDialog(QVector<OrphanedAutosave> orphans, std::function<bool(const QString&)> discard, QWidget* parent)
    : QDialog(parent), m_orphans(std::move(orphans)), m_discardOne(std::move(discard))
{
    setObjectName(QStringLiteral("recoveryDialog"));
    setWindowTitle(tr("Recover unsaved work?"));
    auto* layout = new QVBoxLayout(this);
    auto* text = new QLabel(tr("The workbench did not close normally, and this unsaved work was kept. Recover one into "
                               "this window, discard what you do not need, or keep it for later."),
                            this);
    text->setWordWrap(true);
    layout->addWidget(text);
    m_list = new QListWidget(this);
    for (const OrphanedAutosave& orphan : m_orphans) {
        auto* item = new QListWidgetItem(tr("%1 - %2").arg(QLocale().toString(orphan.saved, QLocale::ShortFormat), orphan.summary), m_list);
        item->setData(Qt::UserRole, orphan.path);
        item->setToolTip(orphan.path);
    }
    m_list->setCurrentRow(0);
    layout->addWidget(m_list);
    auto* buttons = new QDialogButtonBox(this);
    m_recover = buttons->addButton(tr("&Recover"), QDialogButtonBox::AcceptRole);
    m_discard = buttons->addButton(tr("&Discard"), QDialogButtonBox::DestructiveRole);
    m_later = buttons->addButton(tr("Keep for &Later"), QDialogButtonBox::RejectRole);
    layout->addWidget(buttons);
    connect(m_recover, &QPushButton::clicked, this, [this] {
        if (auto* item = m_list->currentItem()) {
            m_chosen = item->data(Qt::UserRole).toString();
            accept();
        }
    });
    connect(m_discard, &QPushButton::clicked, this, [this] {
        auto* item = m_list->currentItem();
        if (!item || !m_discardOne(item->data(Qt::UserRole).toString())) return;
        delete item;
        if (m_list->count() == 0) reject();
        refreshButtons();
    });
    connect(m_later, &QPushButton::clicked, this, &QDialog::reject);
    connect(m_list, &QListWidget::currentRowChanged, this, &RecoveryDialog::refreshButtons);
    refreshButtons();
}

void RecoveryDialog::refreshButtons()
{
    const bool chosen = m_list->currentItem() != nullptr;
    m_recover->setEnabled(chosen);
    m_discard->setEnabled(chosen);
}

} // namespace bunraku::app
