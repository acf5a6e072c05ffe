#pragma once
/// Thesis Fig. 5.16 in the Design dock: the relative error of eq. 5.18 between the wavelet
/// approximations of the functional and the phase-adjusted emotional axis, against the largest
/// scale c of the approximation (scales 1..c), one curve per axis DOF and their mean.

#include "analysis/design/approximation_error.h"

#include <QWidget>

#include <string>
#include <vector>

class QCustomPlot;

namespace bunraku::widgets {

class ScaleErrorPlot : public QWidget {
    Q_OBJECT
public:
    explicit ScaleErrorPlot(QWidget* parent = nullptr);

    /// The errors of one emotional cell (`title` names it) with the DOF names of its columns;
    /// an empty error shows "no emotional cell".
    void setError(const analysis::ApproximationError& error, const std::vector<std::string>& dofNames, const QString& title);

    /// Curves drawn: one per DOF with a finite error, then the mean (for tests).
    int curveCount() const;
    /// The y value of curve `curve` at scale `scale` (1-based), NaN when absent.
    double value(int curve, int scale) const;
    QCustomPlot* plot() const { return m_plot; }

private:
    QCustomPlot* m_plot = nullptr;
};

} // namespace bunraku::widgets
