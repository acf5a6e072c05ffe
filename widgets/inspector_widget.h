#pragma once
/// The values of every channel of take A and take B at the current time, one row per channel
/// (A's channels; B matched by name), with units.

#include "analysis/core/take.h"

#include <QWidget>

#include <memory>
#include <optional>

class QTableWidget;

namespace bunraku::widgets {

class InspectorWidget : public QWidget {
    Q_OBJECT
public:
    explicit InspectorWidget(QWidget* parent = nullptr);

    void setTakes(std::shared_ptr<const analysis::Take> takeA, std::shared_ptr<const analysis::Take> takeB);
    void setTime(double seconds);

    int rowCount() const;
    /// The value shown for row `row` of take A (slot 0) or B (slot 1); nullopt when blank.
    std::optional<double> shownValue(int row, int slot) const;

private:
    void refresh();

    QTableWidget* m_table = nullptr;
    std::shared_ptr<const analysis::Take> m_takes[2];
    double m_time = 0.0;
};

} // namespace bunraku::widgets
