#pragma once
/// The graph grid with its controls: layout (all / one part / one DOF / single), the part and
/// DOF those layouts show, the two-take mode (overlay / side by side), the value scaling and the
/// thesis's ticks (10-unit value ticks, 2 s time ticks), and the angles as Euler angles or rotation
/// coordinates.

#include "widgets/graph_grid.h"

#include <QWidget>

class QCheckBox;
class QLabel;
class QComboBox;

namespace bunraku::widgets {

/// How the graphs show the yaw, pitch and roll channels of 6-DOF parts.
enum class AngleDisplay {
    Euler,               ///< the take's Euler angles, as stored
    RotationCoordinates, ///< analysis::rotationCoordinateTake about take A's mean orientations
};

class GraphPanel : public QWidget {
    Q_OBJECT
public:
    explicit GraphPanel(QWidget* parent = nullptr);

    GraphGrid* grid() const { return m_grid; }

    /// Sets both takes (B may be null) and refreshes the part and DOF choices.
    /// `identity` names the shown takes (GraphGrid::setTakes: other takes refit the time axis).
    void setTakes(std::shared_ptr<const analysis::Take> takeA, std::shared_ptr<const analysis::Take> takeB,
                  const QString& identity = {});
    /// The take drawn faintly behind A (GraphGrid::setGhost), shown as the angles are.
    void setGhost(std::shared_ptr<const analysis::Take> ghost);
    /// The thesis's per-channel result drawn beside the ghost (GraphGrid::setPerChannelGhost) and
    /// `caption`, the line under the controls that says what the ghosts are and how far the
    /// per-channel result is from the body; an empty caption hides the line.
    void setPerChannelGhost(std::shared_ptr<const analysis::Take> take, const QString& caption);
    QString ghostCaption() const;
    /// The "Angles" choice: Euler angles, or rotation coordinates (which never wind or jump at
    /// gimbal); the same takes are shown again with the zoom kept.
    void setAngleDisplay(AngleDisplay display);
    AngleDisplay angleDisplay() const;
    /// What the grid draws as take A / B (the takes given, or their rotation-coordinate copies).
    std::shared_ptr<const analysis::Take> shownTakeA() const { return m_shownA; }
    std::shared_ptr<const analysis::Take> shownTakeB() const { return m_shownB; }
    void setGraphLayout(GraphLayout layout);
    void setTwoTakeMode(TwoTakeMode mode);
    void setValueScale(ValueScale scale);
    /// The "Thesis ticks" check box (GraphGrid::setThesisTicks).
    void setThesisTicks(bool on);
    /// Shows `part` in the one-part layout (e.g. a part clicked in the 3D view).
    void selectPart(const QString& part);
    /// Shows `dof` in the one-DOF and single layouts (a project's choice).
    void selectDof(const QString& dof);
    QString selectedPart() const;
    QString selectedDof() const;

private:
    void applySelection();
    /// The take as the angle choice shows it.
    std::shared_ptr<const analysis::Take> shown(const std::shared_ptr<const analysis::Take>& take) const;
    /// Passes the takes to the grid as the angle choice shows them.
    void showTakes(const QString& identity);
    /// Passes the per-channel result to the grid, converted (again if `changed`), with its
    /// caption; during a drag the grid holds it until the drag ends
    /// (GraphGrid::setPerChannelGhost), so it is converted only then.
    void showPerChannel(bool changed);

    GraphGrid* m_grid = nullptr;
    QComboBox* m_layout = nullptr;
    QComboBox* m_part = nullptr;
    QComboBox* m_dof = nullptr;
    QComboBox* m_mode = nullptr;
    QComboBox* m_scale = nullptr;
    QComboBox* m_angles = nullptr;
    QCheckBox* m_thesisTicks = nullptr;
    QLabel* m_ghostCaption = nullptr;
    QLabel* m_limitCaption = nullptr; ///< says how many graphs a take of very many channels leaves out
    std::shared_ptr<const analysis::Take> m_takeA, m_takeB, m_ghost, m_perChannel; ///< as given
    std::shared_ptr<const analysis::Take> m_shownA, m_shownB;         ///< as drawn
    QString m_caption;              ///< of the per-channel result, as given
    bool m_perChannelOwed = false;  ///< m_perChannel is still to be converted for the grid
};

} // namespace bunraku::widgets
