#pragma once
/// Chooses which BVH joints become the puppet's head, shoulder, arm and hand: preset from the
/// automatic part map (analysis/io/bvh_joint_map.h; nothing preset for a part it cannot find),
/// the side of the limbs, the file's length unit (guessed, or chosen: cm, m, mm, inches) with the
/// performer's height it gives in metres, a preview of the mapped puppet in its first pose
/// (calibrated and fitted as the import will do it), and OK only when every part has its own
/// joint.

#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"

#include <QDialog>
#include <QImage>

#include <array>
#include <optional>

class QComboBox;
class QLabel;
class QPushButton;

namespace bunraku::app {

/// The Units box of the import dialogs (this one and New Corpus from Files): Guess, then
/// centimetres, metres, millimetres and inches with their centimetres per unit as item data.
QComboBox* makeUnitsBox(QWidget* parent);
/// Applies a Units box's choice to import options: guessUnits for Guess, else unitScale.
void applyUnitsChoice(const QComboBox& units, analysis::io::BvhImportOptions& options);

class JointMapDialog : public QDialog {
    Q_OBJECT
public:
    /// `file` needs only its hierarchy and first frame (analysis::io::readBvhStart).
    JointMapDialog(const analysis::io::BvhFile& file, const QString& fileName, QWidget* parent = nullptr);

    analysis::io::JointMap jointMap() const;
    analysis::BodySide side() const;
    /// The unit chosen: nullopt for "Guess" (the import guesses, analysis::io::guessBvhUnits),
    /// else centimetres per file unit (1, 100, 0.1, 2.54).
    std::optional<double> cmPerUnit() const;
    /// Applies the choice to import options (guessUnits, or unitScale).
    void applyUnits(analysis::io::BvhImportOptions& options) const;
    QComboBox* unitsBox() const { return m_units; }
    /// "1.72 m tall (guessed: centimetres)" and, for a height that reads as well in inches, a hint.
    QString heightText() const;
    /// "head=...,shoulder=...,arm=...,hand=..." as the CLI's --joints takes it.
    QString jointMapText() const;
    /// Why OK is disabled (a part without a joint, one joint for two parts), empty when it is not.
    QString problem() const { return m_problem; }
    /// The last preview drawn (null when the map is not valid or nothing can be drawn).
    QImage preview() const { return m_preview; }

    QComboBox* partBox(int part) const { return m_parts[std::size_t(part)]; }
    QComboBox* sideBox() const { return m_side; }

private:
    /// Presets the parts from the automatic map of the chosen side.
    void applyAutomaticMap();
    /// Checks the choice, updates OK, the message and the preview.
    void update();

    analysis::io::BvhFile m_file;
    std::array<QComboBox*, 4> m_parts{};
    std::array<QLabel*, 4> m_found{};
    QComboBox* m_side = nullptr;
    QComboBox* m_units = nullptr;
    QLabel* m_height = nullptr;
    QLabel* m_message = nullptr;
    QLabel* m_image = nullptr;
    QPushButton* m_ok = nullptr;
    QString m_problem;
    QString m_note; ///< why the automatic map found nothing, when it did not
    QImage m_preview;
    bool m_applying = false;
};

} // namespace bunraku::app
