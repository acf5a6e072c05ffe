#pragma once
/// The 3D view dock: the renderer's ViewportWidget showing take A (and B side by side), with
/// toggles for the puppet, the motion axis, the orbits, the floor grid and the partner marker, per
/// take the figure drawn (puppet, the performer's skeleton, or both), and the camera actions
/// (viewport_panel_camera.cpp). The motion axes are the AnalysisController's (one scheduler job
/// per take and axis parameters, take A's shared with the graphable "axis" take): a take is shown
/// at once and its axis added when computed, never another take's; a click on a part selects its
/// graphs.
/// A changed take (a designed take on every step of a warp drag) is shown at the next paint:
/// replacing the scene costs about one frame, so changes are not delayed.

#include "app/document.h"
#include "app/view_state.h"

#include "analysis/core/skeleton_take.h"
#include "analysis/pipeline/stages.h"

#include <QWidget>

#include <array>
#include <iterator>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;

namespace bunraku::widgets {
class ViewportWidget;
}

namespace bunraku::app {

class AnalysisController;

class ViewportPanel : public QWidget {
    Q_OBJECT
public:
    ViewportPanel(Document& document, AnalysisController& analysis, QWidget* parent = nullptr);

    widgets::ViewportWidget* viewport() const { return m_viewport; }
    /// Per take in the scene (A, then B when shown): the motion axis drawn with it, null while
    /// that take's axis is being computed.
    const std::vector<analysis::pipeline::Shared<analysis::pipeline::TakeAxis>>& drawnAxes() const { return m_drawnAxes; }
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
    CameraState cameraState() const;
    void setCameraState(const CameraState& state);
    /// The boxes of what the view draws (Puppet, Axis, Orbits, Grid, Shadows, Partner) and
    /// Follow, as project view state, and back (the values a state holds; the others stay).
    ShownObjects shownObjects() const;
    void setShownObjects(const ShownObjects& shown);

signals:
    /// A part of the puppet was clicked (its name in the take's channels when it has one), or a
    /// bone of a skeleton that carries a part.
    void partPicked(const QString& part);
    /// A bone of a skeleton was clicked (take slot: 0 = A, 1 = B; joint; the part it carries or "").
    void bonePicked(int takeSlot, const QString& joint, const QString& part);

public:
    /// The figure shown for take A (0) or B (1): the combo box in the panel's tool row.
    QComboBox* figureBox(int slot) const { return m_figures[slot]; }
    /// "Cloth": the puppet dressed in its kimono simulated as cloth (AnalysisController's kimono
    /// jobs), off: the skinned kimono. "Cloth Settings..." opens the cloth's parameters.
    QCheckBox* clothBox() const { return m_cloth; }
    QAction* clothSettingsAction() const { return m_clothSettings; }
    /// Per take in the scene: the kimono drawn with it, null while it is being simulated (or
    /// with the Cloth box off).
    const std::vector<analysis::pipeline::Shared<analysis::KimonoSimulation>>& drawnKimonos() const { return m_drawnKimonos; }
    /// Opens the cloth settings dialog (modal); true when its values were applied.
    bool editClothSettings();
    /// A line under the tool bar, one sentence per shown take whose skeleton is drawn and differs
    /// from its 24 channels (a derived take: analysis::noticeableSkeletonGap), saying by how much;
    /// hidden when there is none.
    QLabel* skeletonGapLabel() const { return m_gapLabel; }

private:
    void rebuildScene();
    /// Rebuilds the scene when an axis or a kimono to draw is no longer the one drawn.
    void refreshAxes();
    void applyVisibility();
    /// Shows or hides the gap labels for the figures now chosen.
    void updateGapLabels();
    /// The camera actions, added to `bar` as buttons in its layout (viewport_panel_camera.cpp).
    void createCameraActions(QWidget* bar);
    /// The box of each kShownObjectKeys entry, in its order.
    std::array<QCheckBox*, std::size(kShownObjectKeys)> shownObjectBoxes() const;

    Document& m_document;
    AnalysisController& m_analysis;
    widgets::ViewportWidget* m_viewport = nullptr;
    QCheckBox* m_puppet = nullptr;
    QCheckBox* m_axis = nullptr;
    QCheckBox* m_orbits = nullptr;
    QCheckBox* m_grid = nullptr;
    QCheckBox* m_shadows = nullptr;
    QCheckBox* m_partner = nullptr;
    QCheckBox* m_follow = nullptr;
    QCheckBox* m_cloth = nullptr;
    QAction* m_clothSettings = nullptr;
    QAction* m_frameAll = nullptr;
    QAction* m_frameSelected = nullptr;
    QAction* m_resetCamera = nullptr;
    QString m_selectedPart;
    QComboBox* m_figures[2] = {nullptr, nullptr}; ///< puppet / skeleton / both, for take A and B
    QLabel* m_gapLabel = nullptr;
    /// The gap last computed per slot and the take it was computed for.
    struct GapMemo {
        std::weak_ptr<const analysis::Take> take;
        std::optional<analysis::SkeletonChannelGap> gap;
    };
    GapMemo m_gapMemo[2];
    /// The puppet fitted to each slot's take with a skeleton, kept while that take is shown.
    struct FittedBody {
        std::weak_ptr<const analysis::Take> take;
        std::shared_ptr<const analysis::BodyDescription> body;
    };
    FittedBody m_fittedBodies[2];
    std::vector<analysis::pipeline::Shared<analysis::pipeline::TakeAxis>> m_drawnAxes;
    std::vector<analysis::pipeline::Shared<analysis::KimonoSimulation>> m_drawnKimonos;
};

} // namespace bunraku::app
