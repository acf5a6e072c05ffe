#pragma once
/// "Recover unsaved work?": the autosaves left by workbenches that did not close normally, each
/// with when it was saved and what it holds. The user recovers one into this window, discards
/// the ones not wanted, or keeps them for later.

#include "app/autosave_session.h"

#include <QDialog>
#include <QVector>

#include <functional>

class QListWidget;
class QPushButton;

namespace bunraku::app {

class RecoveryDialog : public QDialog {
    Q_OBJECT
public:
    /// `discard` removes one orphan (returns false when it could not).
    RecoveryDialog(QVector<OrphanedAutosave> orphans, std::function<bool(const QString&)> discard, QWidget* parent = nullptr);

    /// The autosave chosen for recovery (after exec() returned Accepted).
    QString chosen() const { return m_chosen; }
    QListWidget* list() const { return m_list; }
    QPushButton* recoverButton() const { return m_recover; }
    QPushButton* discardButton() const { return m_discard; }
    QPushButton* laterButton() const { return m_later; }

private:
    void refreshButtons();

    QVector<OrphanedAutosave> m_orphans;
    std::function<bool(const QString&)> m_discardOne;
    QListWidget* m_list = nullptr;
    QPushButton* m_recover = nullptr;
    QPushButton* m_discard = nullptr;
    QPushButton* m_later = nullptr;
    QString m_chosen;
};

} // namespace bunraku::app
