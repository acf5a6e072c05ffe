#pragma once
/// Help > About: the program's name and icon, its version and the commit it was built from, its
/// licence (GPL-3.0-or-later, no warranty) and the libraries it is built on with their versions
/// and licences (library_versions.h), in a table that can be copied into a bug report.

#include <QDialog>

class QTableWidget;

namespace bunraku::app {

class AboutDialog : public QDialog {
    Q_OBJECT
public:
    explicit AboutDialog(QWidget* parent = nullptr);

    /// Everything the dialog shows, as plain text (the Copy button puts it on the clipboard).
    QString plainText() const;

private:
    QString m_plainText;
    QTableWidget* m_libraries = nullptr;
};

} // namespace bunraku::app
