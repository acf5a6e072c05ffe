#include "app/multimodal_frame.h"

#include <QFont>
#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace bunraku::app {
namespace {

constexpr int kMinimumSide = 64;

/// Column `column` of `columns` equal columns of `area` (the last one takes the remainder).
QRect cellOf(const QRect& area, int column, int columns, int row, int rows)
{
    const int x0 = area.left() + column * area.width() / columns;
    const int x1 = area.left() + (column + 1) * area.width() / columns;
    const int y0 = area.top() + row * area.height() / rows;
    const int y1 = area.top() + (row + 1) * area.height() / rows;
    return QRect(x0, y0, x1 - x0, y1 - y0);
}

/// Pixel size of the graph labels for a graph of height `height`.
int labelPixels(int height) { return std::clamp(height / 5, 8, 14); }

/// The plotting area inside a graph rectangle: room for the label above, value tick labels on
/// the left and time tick labels below when the graph is tall enough to hold them.
QRect plotOf(const QRect& graph)
{
    const int text = labelPixels(graph.height());
    const bool labels = graph.height() >= 48;
    const int left = labels ? 5 * text / 2 + 6 : 4;
    const int top = text + 4;
    const int bottom = labels ? text + 4 : 3;
    const QRect plot = graph.adjusted(left, top, -5, -bottom);
    return plot.width() >= 8 && plot.height() >= 4 ? plot : graph.adjusted(1, 1, -1, -1);
}

QString tickText(double value)
{
    if (std::fabs(value) < 1e-9) value = 0.0;
    return QString::number(value, 'g', 4);
}

} // namespace

std::vector<double> graphTicks(double lower, double upper, double step, int count)
{
    std::vector<double> ticks;
    if (!(upper > lower) || !std::isfinite(lower) || !std::isfinite(upper)) return ticks;
    if (!(step > 0.0)) {
        const double raw = (upper - lower) / std::max(1, count);
        const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
        const double fraction = raw / magnitude;
        step = (fraction < 1.5 ? 1.0 : fraction < 3.0 ? 2.0 : fraction < 7.0 ? 5.0 : 10.0) * magnitude;
    }
    const double first = std::ceil(lower / step - 1e-9) * step;
    for (int i = 0; first + i * step <= upper + 1e-9 * step && ticks.size() < 1000; ++i) {
        const double value = first + i * step;
        ticks.push_back(std::fabs(value) < 1e-9 * step ? 0.0 : value);
    }
    return ticks;
}

std::vector<double> valueAxisTicks(double lower, double upper, bool thesisTicks)
{
    auto ticks = graphTicks(lower, upper, thesisTicks ? 10.0 : 0.0, 3);
    if (ticks.size() < 2) ticks = graphTicks(lower, upper, 0.0, 3);
    return ticks;
}

MultimodalGeometry multimodalGeometry(const std::vector<analysis::Channel>& channels, bool twoTakes,
                                      const MultimodalOptions& options)
{
    MultimodalGeometry geometry;
    const QSize size = options.size;
    if (channels.empty() || size.width() < kMinimumSide || size.height() < kMinimumSide) return geometry;
    widgets::GraphLayoutOptions layout;
    layout.layout = options.layout;
    layout.twoTakeMode = widgets::TwoTakeMode::SideBySide;
    layout.hasTakeB = twoTakes;
    layout.selectedPart = options.part;
    layout.selectedDof = options.dof;
    geometry.cells = widgets::layoutGraphs(channels, layout);
    int rows = 1, columnsPerTake = 1;
    for (const auto& cell : geometry.cells) {
        rows = std::max(rows, cell.row + 1);
        if (cell.takes != widgets::GraphTakes::OnlyB) columnsPerTake = std::max(columnsPerTake, cell.column + 1);
    }
    const int width = size.width(), height = size.height();
    std::vector<QRect> areas; // one per take: where its graphs go
    if (!twoTakes) {
        if (columnsPerTake == 2) {
            // 24 graphs: two columns of 12 at the edges, the puppet between them
            const int column = width / 4;
            geometry.view = QRect(column, 0, width - 2 * column, height);
            areas = {QRect(0, 0, column, height), QRect(width - column, 0, column, height)};
        } else if (geometry.cells.size() > 1) {
            // 6 or 4 graphs: the right half of the screen
            geometry.view = QRect(0, 0, width / 2, height);
            areas = {QRect(width / 2, 0, width - width / 2, height)};
        } else {
            // one graph: along the bottom
            const int viewHeight = height * 7 / 10;
            geometry.view = QRect(0, 0, width, viewHeight);
            areas = {QRect(0, viewHeight, width, height - viewHeight)};
        }
    } else {
        // two takes: the puppets on top, each take's graphs stacked under its own puppet
        // the more rows of graphs, the more of the height they get (48: 60 %, 12: 50 %, 8: 45 %, 2: 30 %)
        const int percent = rows >= 12 ? 40 : rows >= 6 ? 50 : rows >= 2 ? 55 : 70;
        const int viewHeight = height * percent / 100;
        geometry.view = QRect(0, 0, width, viewHeight);
        areas = {QRect(0, viewHeight, width / 2, height - viewHeight),
                 QRect(width / 2, viewHeight, width - width / 2, height - viewHeight)};
    }
    for (const auto& cell : geometry.cells) {
        QRect graph;
        if (!twoTakes && columnsPerTake == 2) {
            graph = cellOf(areas[std::size_t(cell.column)], 0, 1, cell.row, rows);
        } else {
            const int take = cell.takes == widgets::GraphTakes::OnlyB ? 1 : 0;
            const int column = cell.column - take * columnsPerTake;
            graph = cellOf(areas[std::size_t(take)], column, columnsPerTake, cell.row, rows);
        }
        geometry.graphs.push_back(graph);
        geometry.plots.push_back(plotOf(graph));
    }
    return geometry;
}

analysis::Result<MultimodalFrame> MultimodalFrame::create(std::shared_ptr<const analysis::Take> takeA,
                                                          std::shared_ptr<const analysis::Take> takeB,
                                                          const MultimodalOptions& options)
{
    using analysis::ErrorCode;
    if (!takeA) return analysis::makeError(ErrorCode::InvalidArgument, "there is no take A to show");
    for (const auto* take : {takeA.get(), takeB.get()}) {
        if (!take) continue;
        if (take->frameCount() == 0 || take->channelCount() == 0)
            return analysis::makeError(ErrorCode::InvalidArgument, "take " + take->displayName() + " has no frames");
        if (!(take->rateHz > 0.0))
            return analysis::makeError(ErrorCode::InvalidArgument, "take " + take->displayName() + " has no frame rate");
    }
    if (options.size.width() < kMinimumSide || options.size.height() < kMinimumSide)
        return analysis::makeError(ErrorCode::InvalidArgument,
                                   std::to_string(options.size.width()) + "x" + std::to_string(options.size.height()) +
                                       " pixels is too small for the multimodal display (at least 64x64)");
    MultimodalFrame frame;
    frame.m_takes[0] = std::move(takeA);
    frame.m_takes[1] = std::move(takeB);
    frame.m_options = options;
    frame.m_geometry = multimodalGeometry(frame.m_takes[0]->channels, frame.m_takes[1] != nullptr, options);
    for (const auto& take : frame.m_takes)
        if (take) frame.m_duration = std::max(frame.m_duration, double(take->frameCount() - 1) / take->rateHz);
    if (!(frame.m_duration > 0.0)) frame.m_duration = 1.0 / frame.m_takes[0]->rateHz;
    for (const auto& cell : frame.m_geometry.cells) {
        Series series;
        series.slot = cell.takes == widgets::GraphTakes::OnlyB ? 1 : 0;
        const analysis::Take& take = *frame.m_takes[series.slot];
        const auto channel = take.channelIndex(cell.part, cell.dof);
        series.channel = channel ? *channel : -1;
        if (channel) {
            const auto column = take.values.col(*channel);
            double lower = column.minCoeff(), upper = column.maxCoeff();
            if (!std::isfinite(lower) || !std::isfinite(upper)) lower = upper = 0.0;
            const double pad = std::max(0.05 * (upper - lower), 1e-6 * std::max(1.0, std::fabs(upper)));
            series.lower = lower - (upper > lower ? pad : 1.0);
            series.upper = upper + (upper > lower ? pad : 1.0);
        }
        frame.m_series.push_back(series);
    }
    return frame;
}

QString MultimodalFrame::unitText(const Series& series) const
{
    const analysis::Take& take = *m_takes[series.slot];
    if (series.channel < 0 || series.channel >= Eigen::Index(take.channels.size())) return {};
    const std::string& unit = take.channels[std::size_t(series.channel)].unit;
    return unit.empty() ? QString() : QStringLiteral(" (") + QString::fromStdString(unit) + QLatin1Char(')');
}

int MultimodalFrame::cursorColumn(const QRect& plot, double seconds) const
{
    const double fraction = std::clamp(seconds / m_duration, 0.0, 1.0);
    return plot.left() + int(std::lround(fraction * double(plot.width() - 1)));
}

void MultimodalFrame::drawGraph(QPainter& painter, std::size_t index, double seconds) const
{
    const QRect& graph = m_geometry.graphs[index];
    const QRect& plot = m_geometry.plots[index];
    const auto& cell = m_geometry.cells[index];
    const Series& series = m_series[index];
    const QColor colour = series.slot == 0 ? m_colours.takeA : m_colours.takeB;
    const int text = labelPixels(graph.height());
    QFont font = painter.font();
    font.setPixelSize(text);
    painter.setFont(font);
    const bool labels = plot.top() - graph.top() > text && graph.height() >= 48;

    // value and time to pixels (the first and last pixel columns are t = 0 and the duration)
    const double span = series.upper - series.lower;
    const auto yOf = [&](double value) { return plot.bottom() - (value - series.lower) / span * double(plot.height() - 1); };
    const auto xOf = [&](double t) { return plot.left() + t / m_duration * double(plot.width() - 1); };

    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(m_colours.grid);
    const auto valueTicks = valueAxisTicks(series.lower, series.upper, m_options.thesisTicks);
    const auto timeTicks = graphTicks(0.0, m_duration, m_options.thesisTicks ? 2.0 : 0.0, 5);
    for (double v : valueTicks) painter.drawLine(QPointF(plot.left(), yOf(v)), QPointF(plot.right(), yOf(v)));
    for (double t : timeTicks) painter.drawLine(QPointF(xOf(t), plot.top()), QPointF(xOf(t), plot.bottom()));
    painter.setPen(m_colours.frame);
    painter.drawRect(plot.adjusted(0, 0, -1, -1));
    for (double v : valueTicks) painter.drawLine(QPointF(plot.left() - 3, yOf(v)), QPointF(plot.left(), yOf(v)));
    for (double t : timeTicks) painter.drawLine(QPointF(xOf(t), plot.bottom()), QPointF(xOf(t), plot.bottom() + 3));

    painter.setPen(m_colours.text);
    const QString takeName = m_takes[1] ? (series.slot == 0 ? QStringLiteral("A ") : QStringLiteral("B ")) : QString();
    painter.drawText(QRect(plot.left(), graph.top(), graph.right() - plot.left(), text + 3), Qt::AlignLeft | Qt::AlignVCenter,
                     takeName + QString::fromStdString(cell.part + "." + cell.dof) + unitText(series));
    if (labels) {
        const QFontMetrics metrics(font);
        // value labels at the lowest and highest tick, time labels at every other tick that fits
        if (!valueTicks.empty()) {
            for (double v : {valueTicks.front(), valueTicks.back()}) {
                const QRect box(graph.left(), int(std::lround(yOf(v))) - text / 2 - 1, plot.left() - graph.left() - 4, text + 2);
                painter.drawText(box, Qt::AlignRight | Qt::AlignVCenter, tickText(v));
            }
        }
        int lastRight = plot.left() - 1000;
        for (double t : timeTicks) {
            const QString label = tickText(t);
            const int w = metrics.horizontalAdvance(label);
            const int x = int(std::lround(xOf(t))) - w / 2;
            if (x <= lastRight + 4 || x + w > graph.right()) continue;
            painter.drawText(QRect(x, plot.bottom() + 3, w, text + 1), Qt::AlignCenter, label);
            lastRight = x + w;
        }
    }

    // the curve
    const analysis::Take& take = *m_takes[series.slot];
    if (series.channel >= 0) {
        painter.save();
        painter.setClipRect(plot);
        painter.setRenderHint(QPainter::Antialiasing, true);
        painter.setPen(QPen(colour, std::max(1.0, text / 9.0)));
        QPainterPath path;
        for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
            const QPointF point(xOf(double(f) / take.rateHz), yOf(take.values(f, series.channel)));
            if (f == 0) path.moveTo(point);
            else path.lineTo(point);
        }
        painter.drawPath(path);
        painter.restore();
    }

    // the time cursor: one exact pixel column
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(QPen(m_colours.cursor, 1.0));
    const int column = cursorColumn(plot, seconds);
    painter.drawLine(column, plot.top() + 1, column, plot.bottom() - 1);

    // the moving point: the take's value at the frame shown (nearest, clamped to the take)
    if (series.channel >= 0) {
        const Eigen::Index frame =
            std::clamp<Eigen::Index>(Eigen::Index(std::lround(seconds * take.rateHz)), 0, take.frameCount() - 1);
        const double t = std::min(double(frame) / take.rateHz, m_duration);
        const double radius = std::clamp(text / 3.5, 2.0, 5.0);
        painter.setRenderHint(QPainter::Antialiasing, true);
        painter.setPen(QPen(m_colours.text, 1.0));
        painter.setBrush(colour);
        painter.drawEllipse(QPointF(xOf(t), yOf(take.values(frame, series.channel))), radius, radius);
        painter.setBrush(Qt::NoBrush);
    }
}

QImage MultimodalFrame::compose(const QImage& view, double seconds) const
{
    QImage frame(m_options.size, QImage::Format_RGB32);
    frame.fill(m_colours.background);
    QPainter painter(&frame);
    if (!view.isNull() && !m_geometry.view.isEmpty()) {
        if (view.size() == m_geometry.view.size())
            painter.drawImage(m_geometry.view.topLeft(), view);
        else
            painter.drawImage(m_geometry.view, view.scaled(m_geometry.view.size(), Qt::IgnoreAspectRatio, Qt::SmoothTransformation));
    }
    for (std::size_t i = 0; i < m_geometry.graphs.size(); ++i) drawGraph(painter, i, seconds);
    painter.end();
    return frame;
}

analysis::Result<QImage> MultimodalFrame::render(const ViewImage& draw, double seconds) const
{
    auto view = draw(seconds, m_geometry.view.size());
    if (!view) return view.error();
    return compose(*view, seconds);
}

} // namespace bunraku::app
