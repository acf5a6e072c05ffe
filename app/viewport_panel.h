#pragma once
/// The 3D view dock: the renderer's ViewportWidget showing take A (and B side by side), with
/// toggles for the puppet, the motion axis, the orbits and the floor grid, and per take the
/// figure drawn (puppet, the performer's skeleton, or both). The motion axes are the
/// AnalysisController's (one scheduler job per take and axis parameters, take A's shared with
/// the graphable "axis" take): a take is shown at once and its axis added when computed, never
/// another take's; a click on a part selects its graphs.
/// A changed take (a designed take on every step of a warp drag) is shown at the next paint:
/// replacing the scene costs about one frame, so changes are not delayed.

#include "app/document.h"

#include "analysis/pipeline/stages.h"

#include <QWidget>

#include <vector>

class QCheckBox;
class QComboBox;

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
    /// Rebuilds the scene when an axis to draw is no longer the one drawn.
    void refreshAxes();
    void applyVisibility();

    Document& m_document;
    AnalysisController& m_analysis;
    widgets::ViewportWidget* m_viewport = nullptr;
    QCheckBox* m_puppet = nullptr;
    QCheckBox* m_axis = nullptr;
    QCheckBox* m_orbits = nullptr;
    QCheckBox* m_grid = nullptr;
    QComboBox* m_figures[2] = {nullptr, nullptr}; ///< puppet / skeleton / both, for take A and B
    std::vector<analysis::pipeline::Shared<analysis::pipeline::TakeAxis>> m_drawnAxes;
};

} // namespace bunraku::app
