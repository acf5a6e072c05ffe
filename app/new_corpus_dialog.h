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
#include <functional>
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
    /// Removes the selected rows (the Remove button, the Delete key, the table's context menu).
    void removeSelectedRows();
    /// Makes the corpus when Create Corpus is pressed: true closes the dialog; false keeps it
    /// open with everything as the user left it, showing `lastError` (see showCreateError).
    /// Without a creator Create Corpus accepts the dialog.
    void setCreator(std::function<bool(NewCorpusDialog&)> creator) { m_creator = std::move(creator); }
    /// Shows why the corpus could not be made, and selects the row of the file it names.
    void showCreateError(const QString& message);
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
    /// The animation read from FBX, glTF and Collada files (name or index; empty: the first).
    QLineEdit* animationEdit() const { return m_animation; }
    QComboBox* sideBox() const { return m_side; }
    /// The puppet's four parts (0, default) or every joint of the skeleton (1).
    QComboBox* channelsBox() const { return m_channels; }
    QComboBox* unitsBox() const { return m_units; }
    QComboBox* neutralBox() const { return m_neutral; }
    QPushButton* removeButton() const { return m_remove; }
    QPushButton* createButton() const { return m_create; }
    QString messageText() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
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
    /// Per BVH file: its hierarchy and first frame, or why it cannot be read (read once); per
    /// FBX, glTF or Collada file its converted skeleton and motion (read again when the
    /// animation changes).
    std::map<std::filesystem::path, std::pair<std::optional<analysis::io::BvhFile>, QString>> m_starts;
    /// Per FBX, glTF or Collada file: its animations and the one read, for the part map column.
    std::map<std::filesystem::path, QString> m_animationNotes;
    QLineEdit* m_pattern = nullptr;
    QTableWidget* m_table = nullptr;
    QLineEdit* m_joints = nullptr;
    QLineEdit* m_animation = nullptr;
    QComboBox* m_channels = nullptr;
    QComboBox* m_side = nullptr;
    QComboBox* m_units = nullptr;
    QComboBox* m_neutral = nullptr;
    QDoubleSpinBox* m_rate = nullptr;
    QLineEdit* m_output = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_create = nullptr;
    QPushButton* m_remove = nullptr;
    std::function<bool(NewCorpusDialog&)> m_creator;
    QString m_problem;
    bool m_filling = false; ///< the table is being filled by code, not edited by the user
};

} // namespace bunraku::app
