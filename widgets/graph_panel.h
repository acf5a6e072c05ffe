#pragma once
/// The graph grid with its controls: layout (all / one part / one DOF / single), the part and
/// DOF those layouts show, the two-take mode (overlay / side by side), the value scaling and the
/// thesis's ticks (10-unit value ticks, 2 s time ticks).

#include "widgets/graph_grid.h"

#include <QWidget>

class QCheckBox;
class QComboBox;

namespace bunraku::widgets {

class GraphPanel : public QWidget {
    Q_OBJECT
public:
    explicit GraphPanel(QWidget* parent = nullptr);

    GraphGrid* grid() const { return m_grid; }

    /// Sets both takes (B may be null) and refreshes the part and DOF choices.
    /// `identity` names the shown takes (GraphGrid::setTakes: other takes refit the time axis).
    void setTakes(std::shared_ptr<const analysis::Take> takeA, std::shared_ptr<const analysis::Take> takeB,
                  const QString& identity = {});
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

    GraphGrid* m_grid = nullptr;
    QComboBox* m_layout = nullptr;
    QComboBox* m_part = nullptr;
    QComboBox* m_dof = nullptr;
    QComboBox* m_mode = nullptr;
    QComboBox* m_scale = nullptr;
    QCheckBox* m_thesisTicks = nullptr;
};

} // namespace bunraku::widgets
