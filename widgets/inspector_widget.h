#pragma once
/// The values of every channel of take A and take B at the current time, one row per channel
/// (A's channels; B matched by name), with units. Cheap per frame: fixed column widths (set
/// when the rows change), only cells whose text changes are touched, and nothing is drawn
/// while the inspector is hidden (it catches up when shown).

#include "analysis/core/take.h"

#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

class QTableWidget;

namespace bunraku::widgets {

class InspectorWidget : public QWidget {
    Q_OBJECT
public:
    explicit InspectorWidget(QWidget* parent = nullptr);

    void setTakes(std::shared_ptr<const analysis::Take> takeA, std::shared_ptr<const analysis::Take> takeB);
    void setTime(double seconds);

    int rowCount() const;
    /// The value of row `row` of take A (slot 0) or B (slot 1) at the current time, as the
    /// table shows it when visible; nullopt when blank.
    std::optional<double> shownValue(int row, int slot) const;

protected:
    void showEvent(QShowEvent* event) override;

private:
    void refresh();
    void showValues();

    QTableWidget* m_table = nullptr;
    std::shared_ptr<const analysis::Take> m_takes[2];
    std::vector<std::optional<double>> m_values[2]; ///< per row, at m_time
    double m_time = 0.0;
};

} // namespace bunraku::widgets
