#pragma once
/// One dialog for several BVH files imported at once (bunraku-workbench f1.bvh ... f6.bvh, a
/// drop of several files): a table of the files with the joints the automatic part map found
/// for each (or that it found none) and the performer's height in metres, one Side and one
/// Units box for all, and per file a button that opens the joint dialog to choose its joints.
/// OK only when every file has its joints.

#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"

#include <QDialog>
#include <QStringList>

#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace bunraku::app {

class ImportTakesDialog : public QDialog {
    Q_OBJECT
public:
    /// `files` are read up to their first frame here (analysis::io::readBvhStart); a file that
    /// cannot be read shows its error in its row and keeps OK disabled.
    explicit ImportTakesDialog(const QStringList& files, QWidget* parent = nullptr);

    int fileCount() const { return int(m_rows.size()); }
    /// The import options of file `row`: its joints (the automatic map's, or chosen), the side
    /// and the units chosen for all.
    analysis::io::BvhImportOptions options(int row) const;
    /// Why OK is disabled, empty when it is not.
    QString problem() const { return m_problem; }
    QTableWidget* table() const { return m_table; }
    QComboBox* sideBox() const { return m_side; }
    QComboBox* unitsBox() const { return m_units; }
    /// Opens the joint dialog for file `row` (the row's Joints... button).
    void chooseJoints(int row);

private:
    struct Row {
        QString file;
        std::optional<analysis::io::BvhFile> start; ///< hierarchy and first frame
        QString readError;
        std::optional<analysis::io::JointMap> chosen; ///< from the joint dialog
        std::optional<analysis::io::JointMap> automatic;
        QString automaticError;
    };
    /// Maps every file again (side changed) and refreshes the table.
    void remap();
    void refresh();

    std::vector<Row> m_rows;
    QTableWidget* m_table = nullptr;
    QComboBox* m_side = nullptr;
    QComboBox* m_units = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_ok = nullptr;
    QString m_problem;
};

} // namespace bunraku::app
