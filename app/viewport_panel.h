#pragma once
/// The 3D view dock: the renderer's ViewportWidget showing take A (and B side by side), with
/// toggles for the puppet, the motion axis, the orbits, the floor grid and the partner marker, per
/// take the figure drawn (puppet, the performer's skeleton, or both), and the camera actions
/// (viewport_panel_camera.cpp). The motion axes are computed in the background and added when
/// ready (for drawing only: the graphable "axis" take is the AnalysisController's); a click on a
/// part selects its graphs.
/// A changed take (a designed take on every step of a warp drag) is shown at the next paint:
/// replacing the scene costs about one frame, so changes are not delayed.

#include "app/document.h"

#include "analysis/core/pose.h"

#include <QWidget>

#include <utility>
#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QToolBar;

namespace bunraku::widgets {
class ViewportWidget;
}

namespace bunraku::app {

class Recomputer;

class ViewportPanel : public QWidget {
    Q_OBJECT
public:
    ViewportPanel(Document& document, QWidget* parent = nullptr);

    widgets::ViewportWidget* viewport() const { return m_viewport; }
    Recomputer* recomputer() const { return m_axes; }
    /// Camera actions (View > 3D View Camera and the view's tool bar): Frame All (F), Frame
    /// Selected (Shift+F: the part last clicked, else the figures at the current frame) and
    /// Reset Camera (Home with the 3D view focused).
    QAction* frameAllAction() const { return m_frameAll; }
    QAction* frameSelectedAction() const { return m_frameSelected; }
    QAction* resetCameraAction() const { return m_resetCamera; }
    /// The body part Frame Selected fits ("right_hand"; "" when none was clicked, or the
    /// background was).
    QString selectedPart() const { return m_selectedPart; }
    /// The camera as project view state ({"angle", "elevation", "distance", "target": [x, y, z],
    /// "fov"}), and back (ignored when malformed; project_file.cpp validates it).
    QVariantMap cameraState() const;
    void setCameraState(const QVariantMap& state);

signals:
    /// A part of the puppet was clicked (its name in the take's channels when it has one), or a
    /// bone of a skeleton that carries a part.
    void partPicked(const QString& part);
    /// A bone of a skeleton was clicked (take slot: 0 = A, 1 = B; joint; the part it carries or "").
    void bonePicked(int takeSlot, const QString& joint, const QString& part);

public:
    /// The figure shown for take A (0) or B (1): the combo box in the panel's tool row.
    QComboBox* figureBox(int slot) const { return m_figures[slot]; }

private:
    void rebuildScene();
    void applyVisibility();
    /// The camera actions, added to `bar` (viewport_panel_camera.cpp).
    void createCameraActions(QWidget* bar);

    Document& m_document;
    widgets::ViewportWidget* m_viewport = nullptr;
    Recomputer* m_axes = nullptr;
    QCheckBox* m_puppet = nullptr;
    QCheckBox* m_axis = nullptr;
    QCheckBox* m_orbits = nullptr;
    QCheckBox* m_grid = nullptr;
    QCheckBox* m_partner = nullptr;
    QAction* m_frameAll = nullptr;
    QAction* m_frameSelected = nullptr;
    QAction* m_resetCamera = nullptr;
    QString m_selectedPart;
    QComboBox* m_figures[2] = {nullptr, nullptr}; ///< puppet / skeleton / both, for take A and B
    quint64 m_sceneSerial = 0;
    /// The motion axis (world_T_axis per frame) of each take it was last computed for: a rebuilt
    /// scene keeps the axes of takes that did not change.
    std::vector<std::pair<TakePointer, std::vector<analysis::RigidTransform>>> m_knownAxes;
};

} // namespace bunraku::app
