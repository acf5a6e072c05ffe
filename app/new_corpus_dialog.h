#pragma once
/// File > New Corpus from Files: take files or folders (picked or dropped), a file-name pattern
/// whose labels fill a table the user can correct (function, emotion, take), the part map of
/// each BVH file (automatic, or one map for all from the joint dialog), the side, the neutral
/// emotion, the rate and the output folder. The corpus itself is built by
/// analysis/io/corpus_builder.h, as `bunraku corpus` builds it.

#include "analysis/io/bvh.h"
#include "analysis/io/corpus_builder.h"

#include <QDialog>
#include <QStringList>

#include <filesystem>
#include <map>
#include <optional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace bunraku::app {

class NewCorpusDialog : public QDialog {
    Q_OBJECT
public:
    enum Column { FileColumn, FunctionColumn, EmotionColumn, TakeColumn, MapColumn, ColumnCount };

    explicit NewCorpusDialog(QWidget* parent = nullptr);

    /// Adds take files, or the take files directly inside folders (as dropped).
    void addInputs(const QStringList& paths);
    void setPattern(const QString& pattern);
    void setOutputFolder(const QString& folder);
    QString outputFolder() const;
    /// The files with the labels the table shows (corrections included).
    std::vector<analysis::io::CorpusSource> sources() const;
    analysis::io::CorpusBuildOptions buildOptions() const;
    /// Why the corpus cannot be made yet, empty when it can.
    QString problem() const { return m_problem; }

    QTableWidget* table() const { return m_table; }
    QLineEdit* jointsEdit() const { return m_joints; }
    QComboBox* sideBox() const { return m_side; }
    QComboBox* neutralBox() const { return m_neutral; }

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    /// Labels of the rows the user did not edit, from the pattern.
    void relabel();
    /// The part map column of every BVH row (the automatic map, or the joints given).
    void remap();
    /// Checks the table and options; updates the message and the Create button.
    void validate();
    void chooseJointMap();

    std::vector<std::filesystem::path> m_files;
    /// Per BVH file: its hierarchy and first frame, or why it cannot be read (read once).
    std::map<std::filesystem::path, std::pair<std::optional<analysis::io::BvhFile>, QString>> m_starts;
    QLineEdit* m_pattern = nullptr;
    QTableWidget* m_table = nullptr;
    QLineEdit* m_joints = nullptr;
    QComboBox* m_side = nullptr;
    QComboBox* m_neutral = nullptr;
    QDoubleSpinBox* m_rate = nullptr;
    QLineEdit* m_output = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_create = nullptr;
    QString m_problem;
    bool m_filling = false; ///< the table is being filled by code, not edited by the user
};

} // namespace bunraku::app
