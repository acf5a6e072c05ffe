#include "widgets/scale_error_plot.h"

#include <qcustomplot.h>

#include <QVBoxLayout>

#include <cmath>
#include <limits>

namespace bunraku::widgets {
namespace {

/// Colour-blind safe colours for the six axis DOF (Okabe-Ito); the mean is black.
const QColor kDofColours[] = {QColor(0xe6, 0x9f, 0x00), QColor(0x56, 0xb4, 0xe9), QColor(0x00, 0x9e, 0x73),
                              QColor(0xcc, 0x79, 0xa7), QColor(0x00, 0x72, 0xb2), QColor(0xd5, 0x5e, 0x00)};

} // namespace

ScaleErrorPlot::ScaleErrorPlot(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot(this))
{
    setObjectName("scaleErrorPlot");
    QFont small = font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() - 2.0));
    m_plot->xAxis->setLabel(tr("largest scale c"));
    m_plot->yAxis->setLabel(tr("rel. error (5.18)"));
    m_plot->xAxis->setLabelFont(small);
    m_plot->yAxis->setLabelFont(small);
    m_plot->xAxis->setTickLabelFont(small);
    m_plot->yAxis->setTickLabelFont(small);
    m_plot->setMinimumHeight(200);
    auto* title = new QCPTextElement(m_plot, tr("Approximation error per scale (thesis 5.4.1, Fig. 5.16)"), small);
    m_plot->plotLayout()->insertRow(0);
    m_plot->plotLayout()->addElement(0, 0, title);
    // The legend in its own row under the plot, four entries a line: inside the axes it hid the
    // curves of a narrow dock.
    m_plot->legend->setVisible(true);
    m_plot->legend->setFont(small);
    m_plot->axisRect()->insetLayout()->take(m_plot->legend);
    m_plot->plotLayout()->addElement(2, 0, m_plot->legend);
    m_plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    m_plot->legend->setWrap(4);
    m_plot->legend->setMargins(QMargins(2, 0, 2, 0));
    m_plot->plotLayout()->setRowStretchFactor(2, 0.001);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
}

void ScaleErrorPlot::setError(const analysis::ApproximationError& error, const std::vector<std::string>& dofNames,
                              const QString& title)
{
    m_plot->clearGraphs();
    if (auto* heading = qobject_cast<QCPTextElement*>(m_plot->plotLayout()->element(0, 0)))
        heading->setText(error.scales.empty() ? tr("Approximation error per scale (5.4.1): no emotional cell")
                                              : tr("Approximation error per scale (5.4.1, Fig. 5.16): %1").arg(title));
    QVector<double> scales;
    for (int c : error.scales) scales << double(c);
    for (Eigen::Index q = 0; q < error.relativeError.cols(); ++q) {
        QVector<double> values;
        bool finite = false;
        for (Eigen::Index c = 0; c < error.relativeError.rows(); ++c) {
            values << error.relativeError(c, q);
            finite = finite || std::isfinite(error.relativeError(c, q));
        }
        if (!finite) continue;
        auto* graph = m_plot->addGraph();
        graph->setData(scales, values, true);
        graph->setPen(QPen(kDofColours[q % 6], 1.5));
        graph->setName(q < Eigen::Index(dofNames.size()) ? QString::fromStdString(dofNames[std::size_t(q)])
                                                         : QStringLiteral("DOF %1").arg(q + 1));
    }
    if (!error.scales.empty()) {
        QVector<double> mean;
        for (Eigen::Index c = 0; c < error.meanRelativeError.size(); ++c) mean << error.meanRelativeError(c);
        auto* graph = m_plot->addGraph();
        graph->setData(scales, mean, true);
        graph->setPen(QPen(Qt::black, 2.5));
        graph->setName(tr("mean"));
    }
    m_plot->rescaleAxes();
    m_plot->yAxis->setRangeLower(0.0);
    m_plot->xAxis->setRange(0.5, std::max(1.5, double(error.scales.empty() ? 16 : error.scales.back()) + 0.5));
    m_plot->replot();
}

int ScaleErrorPlot::curveCount() const { return m_plot->graphCount(); }

double ScaleErrorPlot::value(int curve, int scale) const
{
    if (curve < 0 || curve >= m_plot->graphCount()) return std::numeric_limits<double>::quiet_NaN();
    const auto data = m_plot->graph(curve)->data();
    const auto found = data->findBegin(double(scale), false);
    if (found == data->constEnd() || found->key != double(scale)) return std::numeric_limits<double>::quiet_NaN();
    return found->value;
}

} // namespace bunraku::widgets
