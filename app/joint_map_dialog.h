#pragma once
/// Chooses which BVH joints become the puppet's head, shoulder, arm and hand: preset from the
/// automatic part map (analysis/io/bvh_joint_map.h; nothing preset for a part it cannot find),
/// the side of the limbs, a preview of the mapped puppet in its first pose (calibrated and
/// fitted as the import will do it), and OK only when every part has its own joint.

#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"

#include <QDialog>
#include <QImage>

#include <array>

class QComboBox;
class QLabel;
class QPushButton;

namespace bunraku::app {

class JointMapDialog : public QDialog {
    Q_OBJECT
public:
    /// `file` needs only its hierarchy and first frame (analysis::io::readBvhStart).
    JointMapDialog(const analysis::io::BvhFile& file, const QString& fileName, QWidget* parent = nullptr);

    analysis::io::JointMap jointMap() const;
    analysis::BodySide side() const;
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
    QLabel* m_message = nullptr;
    QLabel* m_image = nullptr;
    QPushButton* m_ok = nullptr;
    QString m_problem;
    QString m_note; ///< why the automatic map found nothing, when it did not
    QImage m_preview;
    bool m_applying = false;
};

} // namespace bunraku::app
