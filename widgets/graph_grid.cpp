#include "widgets/graph_grid.h"

#include "widgets/take_series.h"

#include <qcustomplot.h>

#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>

#include <algorithm>
#include <utility>
#include <cmath>
#include <map>

namespace bunraku::widgets {
namespace {

constexpr const char* kCursorLayer = "cursor";
constexpr const char* kLiveLayer = "live";

bool sameCells(const std::vector<GraphCell>& a, const std::vector<GraphCell>& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const GraphCell& x, const GraphCell& y) {
        return x.part == y.part && x.dof == y.dof && x.takes == y.takes && x.row == y.row && x.column == y.column;
    });
}

bool drawsSlot(GraphTakes takes, int slot)
{
    return takes == GraphTakes::AAndB || (slot == 0 ? takes == GraphTakes::OnlyA : takes == GraphTakes::OnlyB);
}

ValueRange merged(std::optional<ValueRange> a, const ValueRange& b)
{
    return a ? ValueRange{std::min(a->lower, b.lower), std::max(a->upper, b.upper)} : b;
}

std::pair<double, double> padded(const ValueRange& range)
{
    const double span = range.upper - range.lower;
    if (!(span > 1e-9)) return {range.lower - 1.0, range.upper + 1.0};
    return {range.lower - 0.08 * span, range.upper + 0.08 * span};
}

} // namespace

GraphGrid::GraphGrid(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot)
{
    // The plot fills the widget; when every graph at its readable height does not fit (24
    // graphs in a short dock), it scrolls instead of squeezing them into one another.
    m_scroll = new QScrollArea(this);
    m_scroll->setObjectName("graphScroll");
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setWidgetResizable(true);
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_scroll->setWidget(m_plot);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_scroll);
    // Graphs scrolled into view during a drag are drawn from then on (drawOnlyGraphsInView).
    connect(m_scroll->verticalScrollBar(), &QScrollBar::valueChanged, this, [this] {
        if (!m_interacting || !m_graphsOutOfViewHidden) return;
        updateCursorItems(); // the moving points of graphs now in view
        drawOnlyGraphsInView();
        m_plot->layer(kLiveLayer)->replot();
        m_plot->layer(kCursorLayer)->replot();
    });
    m_plot->setObjectName("graphPlot");
    // Paint buffers: [background grid main axes] [live] [cursor] [legend overlay].
    m_plot->addLayer(kLiveLayer, m_plot->layer("axes"), QCustomPlot::limAbove);
    m_plot->layer(kLiveLayer)->setMode(QCPLayer::lmBuffered);
    m_plot->addLayer(kCursorLayer, m_plot->layer(kLiveLayer), QCustomPlot::limAbove);
    m_plot->layer(kCursorLayer)->setMode(QCPLayer::lmBuffered);
    m_plot->setInteractions(QCP::iRangeZoom);
    m_plot->setNoAntialiasingOnDrag(true);
    m_plot->plotLayout()->clear();
    m_plot->plotLayout()->setRowSpacing(2);
    m_plot->plotLayout()->setColumnSpacing(6);
    connect(m_plot, &QCustomPlot::mousePress, this, &GraphGrid::onMousePress);
    connect(m_plot, &QCustomPlot::mouseMove, this, &GraphGrid::onMouseMove);
    connect(m_plot, &QCustomPlot::mouseRelease, this, &GraphGrid::onMouseRelease);
    connect(m_plot, &QCustomPlot::mouseDoubleClick, this, [this](QMouseEvent*) { resetTimeRange(); });
    // The layout is known only inside a replot: graphs that changed width are resampled there,
    // before anything is drawn.
    connect(m_plot, &QCustomPlot::afterLayout, this, [this] {
        resampleCurves(true);
        for (auto& graph : m_graphs) placeValueText(graph);
    });
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &ClockTimer::timeout, this, [this] {
        if (!interactionActive()) settleValueRanges();
    });
}

GraphGrid::~GraphGrid() = default;

const analysis::Take* GraphGrid::slotTake(int slot) const { return m_takes[slot].get(); }

void GraphGrid::setTakes(std::shared_ptr<const analysis::Take> takeA, std::shared_ptr<const analysis::Take> takeB,
                         const QString& identity)
{
    // Without an identity the takes are the same ones changed (only the first ones are "other").
    const bool firstTakes = !m_takes[0];
    const QString shown = identity.isEmpty() ? m_shownIdentity : identity;
    const bool otherTakes = firstTakes || shown != m_shownIdentity;
    // The whole take was in view: a new length of the same takes is followed.
    const double before = shownDuration();
    const bool wholeShown = m_rangeLower <= 1e-9 && std::abs(m_rangeUpper - before) <= 1e-6 * std::max(1.0, before);
    m_shownIdentity = shown;
    m_takes[0] = std::move(takeA);
    m_takes[1] = std::move(takeB);
    rebuild(false);
    const bool lengthChanged = std::abs(shownDuration() - before) > 1e-9;
    if (otherTakes) {
        m_followLength = false;
        resetTimeRange();
    } else if (lengthChanged && (wholeShown || m_followLength)) {
        if (interactionActive()) m_followLength = true; // refitted once the drag ends
        else resetTimeRange();
    }
}

double GraphGrid::shownDuration() const
{
    double duration = 0.0;
    for (const auto& take : m_takes)
        if (take) duration = std::max(duration, take->duration());
    for (const auto& ghost : m_ghosts)
        if (ghost) duration = std::max(duration, ghost->duration());
    return duration;
}

void GraphGrid::beginInteraction()
{
    m_interacting = true;
    // As QCustomPlot's own drags (setNoAntialiasingOnDrag): the curves redrawn on every step
    // are drawn without antialiasing, and smooth again in the full replot at the end.
    m_plot->setNotAntialiasedElements(QCP::aeAll);
}

void GraphGrid::setClock(Clock* clock)
{
    m_clock = clock ? clock : &steadyClock();
    m_settle.setClock(m_clock);
    m_lastDataMs.reset();
}

void GraphGrid::endInteraction()
{
    if (!m_interacting) return;
    m_interacting = false;
    m_plot->setNotAntialiasedElements(QCP::aeNone);
    if (std::exchange(m_graphsOutOfViewHidden, false)) {
        for (auto& graph : m_graphs) setGraphDrawn(graph, true);
        updateCursorItems(); // the moving points: shown where their take has a value
        m_rangesStale = true; // the full replot below draws them all
    }
    emit interactionEnded();
    if (m_perChannelPending) setPerChannelGhost(std::exchange(m_pendingPerChannel, nullptr));
    settleValueRanges();
    if (m_followLength) {
        m_followLength = false;
        resetTimeRange();
    }
}

void GraphGrid::settleValueRanges()
{
    m_settle.stop();
    if (!m_rangesStale) return;
    m_rangesStale = false;
    applyValueRanges();
    m_plot->replot();
}

void GraphGrid::setGhost(std::shared_ptr<const analysis::Take> ghost)
{
    if (ghost == m_ghosts[0]) return;
    m_ghosts[0] = std::move(ghost);
    rebuild();
}

void GraphGrid::setPerChannelGhost(std::shared_ptr<const analysis::Take> take)
{
    if (m_interacting) {
        // A drag step: the dots follow when the drag ends (a new take here would replot every
        // layer of every graph on every step).
        m_perChannelPending = take != m_ghosts[1];
        m_pendingPerChannel = m_perChannelPending ? std::move(take) : nullptr;
        return;
    }
    m_perChannelPending = false;
    m_pendingPerChannel.reset();
    if (take == m_ghosts[1]) return;
    m_ghosts[1] = std::move(take);
    rebuild();
}

void GraphGrid::setGraphLayout(GraphLayout layout)
{
    m_options.layout = layout;
    rebuild();
}

void GraphGrid::setTwoTakeMode(TwoTakeMode mode)
{
    m_options.twoTakeMode = mode;
    rebuild();
}

void GraphGrid::setValueScale(ValueScale scale)
{
    m_scale = scale;
    applyValueRanges();
    m_plot->replot();
}

void GraphGrid::setThesisTicks(bool on)
{
    if (on == m_thesisTicks) return;
    m_thesisTicks = on;
    applyTickers();
    m_plot->replot();
}

void GraphGrid::applyTickers()
{
    for (auto& graph : m_graphs) {
        // time: every 2 s (thesis 6.3.3), and by default multiples of 2 s when zoomed out
        auto time = QSharedPointer<QCPAxisTickerFixed>::create();
        time->setTickStep(2.0);
        time->setScaleStrategy(m_thesisTicks ? QCPAxisTickerFixed::ssNone : QCPAxisTickerFixed::ssMultiples);
        graph.rect->axis(QCPAxis::atBottom)->setTicker(time);
        if (m_thesisTicks) {
            auto value = QSharedPointer<QCPAxisTickerFixed>::create();
            value->setTickStep(10.0); // value ticks every 10 units (thesis 6.3.3)
            value->setScaleStrategy(QCPAxisTickerFixed::ssNone);
            graph.rect->axis(QCPAxis::atLeft)->setTicker(value);
        } else {
            auto value = QSharedPointer<QCPAxisTicker>::create();
            value->setTickCount(3);
            graph.rect->axis(QCPAxis::atLeft)->setTicker(value);
        }
    }
}

void GraphGrid::setSelectedChannel(const std::string& part, const std::string& dof)
{
    if (part == m_options.selectedPart && dof == m_options.selectedDof) return;
    m_options.selectedPart = part;
    m_options.selectedDof = dof;
    if (m_options.layout != GraphLayout::AllChannels) rebuild();
}

void GraphGrid::rebuild(bool allData)
{
    m_options.hasTakeB = m_takes[1] != nullptr;
    // At most kMaxGraphs: the first channels of the layout, for A and (side by side) for B alike.
    int total = 0;
    std::vector<GraphCell> cells = m_takes[0] ? layoutGraphs(m_takes[0]->channels, m_options, kMaxGraphs, &total) : std::vector<GraphCell>{};
    const int hidden = std::max(0, total - int(cells.size()));
    if (hidden != m_hiddenGraphs) {
        m_hiddenGraphs = hidden;
        emit graphsLimited(hidden, total);
    }
    std::vector<GraphCell> current;
    for (const auto& graph : m_graphs) current.push_back(graph.cell);
    // The ghosts are take A's (its source take, its per-channel result): drawn in the graphs of
    // A, never in B's column side by side.
    const auto firstOfA = std::find_if(m_graphs.begin(), m_graphs.end(), [](const Graph& graph) { return drawsSlot(graph.cell.takes, 0); });
    const bool sameStructure = !m_graphs.empty() && sameCells(cells, current) && firstOfA != m_graphs.end() &&
                               bool(m_ghosts[0]) == (firstOfA->ghosts[0] != nullptr) &&
                               bool(m_ghosts[1]) == (firstOfA->ghosts[1] != nullptr);

    if (!sameStructure) {
        m_plot->clearItems();
        m_plot->clearGraphs();
        m_plot->plotLayout()->clear();
        m_graphs.clear();
        int lastRow = 0;
        for (const auto& cell : cells) lastRow = std::max(lastRow, cell.row);
        m_plot->setMinimumHeight(cells.empty() ? 0 : (lastRow + 1) * kMinimumGraphHeight + 20);
        auto* margins = new QCPMarginGroup(m_plot);
        QFont tickFont = font();
        tickFont.setPointSizeF(std::max(6.0, tickFont.pointSizeF() - 2.0));
        for (const auto& cell : cells) {
            Graph graph;
            graph.cell = cell;
            graph.rect = new QCPAxisRect(m_plot, true);
            m_plot->plotLayout()->addElement(cell.row, cell.column, graph.rect);
            graph.rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
            graph.rect->setRangeZoom(Qt::Horizontal);
            graph.rect->setRangeDrag(Qt::Horizontal);
            graph.rect->setMinimumSize(60, 20);
            // Thin top and bottom margins (QCustomPlot's default is 15 px each): in a row of
            // kMinimumGraphHeight pixels the curve keeps most of the height. The bottom row's
            // time labels still get the margin they need.
            graph.rect->setMinimumMargins(QMargins(15, 6, 15, 4));
            auto* timeAxis = graph.rect->axis(QCPAxis::atBottom);
            auto* valueAxis = graph.rect->axis(QCPAxis::atLeft);
            graph.rect->axis(QCPAxis::atTop)->setVisible(false);
            graph.rect->axis(QCPAxis::atRight)->setVisible(false);
            timeAxis->setTickLabelFont(tickFont);
            valueAxis->setTickLabelFont(tickFont);
            valueAxis->setLabelFont(tickFont);
            valueAxis->setLabelPadding(1);
            // tick labels only under the bottom row; the tickers: applyTickers
            timeAxis->setTickLabels(cell.row == lastRow);
            timeAxis->setRange(m_rangeLower, m_rangeUpper);
            connect(timeAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
                    [this, rect = graph.rect](const QCPRange&) { propagateTimeRange(rect); });

            for (int g = 0; g < 2; ++g) {
                if (!m_ghosts[g] || !drawsSlot(cell.takes, 0)) continue;
                graph.ghosts[g] = m_plot->addGraph(timeAxis, valueAxis);
                graph.ghosts[g]->setPen(g == 0 ? QPen(m_colours.ghost, 1.0, Qt::DashLine) : QPen(m_colours.perChannel, 1.0, Qt::SolidLine));
            }
            for (int slot = 0; slot < 2; ++slot) {
                if (!drawsSlot(cell.takes, slot)) continue;
                graph.curves[slot] = m_plot->addGraph(timeAxis, valueAxis);
                graph.curves[slot]->setLayer(kLiveLayer);
                graph.curves[slot]->setPen(QPen(slot == 0 ? m_colours.takeA : m_colours.takeB, 1.0));
            }

            auto* name = new QCPItemText(m_plot);
            name->setClipToAxisRect(false);
            name->position->setType(QCPItemPosition::ptAxisRectRatio);
            name->position->setAxisRect(graph.rect);
            name->position->setCoords(0.01, 0.02);
            name->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
            name->setFont(tickFont);
            const QString label = QString::fromStdString(cell.part + "." + cell.dof);
            name->setText(cell.takes == GraphTakes::OnlyB ? label + " (B)" : label);
            graph.nameText = name;
            graph.nameAdvance = QFontMetrics(tickFont).horizontalAdvance(name->text());

            m_plot->setCurrentLayer(kCursorLayer);
            graph.cursor = new QCPItemStraightLine(m_plot);
            graph.cursor->setClipAxisRect(graph.rect);
            graph.cursor->setPen(QPen(QColor(0xc0, 0x20, 0x20), 1.0));
            for (auto* position : {graph.cursor->point1, graph.cursor->point2}) position->setAxes(timeAxis, valueAxis);
            for (int slot = 0; slot < 2; ++slot) {
                if (!graph.curves[slot]) continue;
                auto* point = new QCPItemTracer(m_plot);
                point->setClipAxisRect(graph.rect);
                point->position->setAxes(timeAxis, valueAxis);
                point->setStyle(QCPItemTracer::tsCircle);
                point->setSize(6.0);
                const QColor colour = slot == 0 ? m_colours.takeA : m_colours.takeB;
                point->setPen(QPen(colour.darker(130)));
                point->setBrush(colour);
                graph.points[slot] = point;
            }
            graph.valueText = new QCPItemText(m_plot);
            graph.valueText->setClipToAxisRect(false);
            graph.valueText->position->setType(QCPItemPosition::ptAxisRectRatio);
            graph.valueText->position->setAxisRect(graph.rect);
            graph.valueText->position->setCoords(0.99, 0.02);
            graph.valueText->setPositionAlignment(Qt::AlignRight | Qt::AlignTop);
            graph.valueText->setFont(tickFont);
            m_plot->setCurrentLayer("main");
            m_graphs.push_back(std::move(graph));
        }
        applyTickers();
        allData = true;
    }

    // Data: per curve, the channel of its take matched by name; only takes that changed.
    const bool changed[2] = {allData || m_plotted[0] != m_takes[0], allData || m_plotted[1] != m_takes[1]};
    for (int slot = 0; slot < 2; ++slot) m_plotted[slot] = m_takes[slot];
    for (auto& graph : m_graphs) {
        for (int slot = 0; slot < 2; ++slot) {
            if (!changed[slot]) continue;
            graph.channels[slot].reset();
            graph.envelopes[slot] = {};
            if (!graph.curves[slot]) continue;
            const analysis::Take* take = slotTake(slot);
            if (take) graph.channels[slot] = findChannel(*take, graph.cell.part, graph.cell.dof);
            if (take && graph.channels[slot]) graph.envelopes[slot] = SeriesEnvelope(m_takes[slot], *graph.channels[slot]);
        }
        if (changed[0] || changed[1]) {
            // The unit of the graph's channel (take A's, else B's): "cm", "deg".
            QString unit;
            for (int slot = 0; slot < 2 && unit.isEmpty(); ++slot)
                if (graph.channels[slot]) unit = QString::fromStdString(slotTake(slot)->channels[std::size_t(*graph.channels[slot])].unit);
            auto* valueAxis = graph.rect->axis(QCPAxis::atLeft);
            if (valueAxis->label() != unit) valueAxis->setLabel(unit);
        }
        for (int g = 0; g < 2; ++g) {
            if (!graph.ghosts[g] || !allData) continue;
            graph.ghostChannels[g] = findChannel(*m_ghosts[g], graph.cell.part, graph.cell.dof);
            graph.ghostEnvelopes[g] = graph.ghostChannels[g] ? SeriesEnvelope(m_ghosts[g], *graph.ghostChannels[g]) : SeriesEnvelope();
        }
        if (changed[0] || changed[1] || allData) sampleCurves(graph);
    }
    if (changed[0] || changed[1] || allData) ++m_samplings;
    updateCursorItems();
    if (!allData && !changed[0] && !changed[1]) {
        m_plot->layer(kCursorLayer)->replot(); // the same takes again: nothing to redraw
        return;
    }
    if (!allData) {
        const qint64 now = m_clock->milliseconds();
        const bool burst = m_lastDataMs && now - *m_lastDataMs < kSettleMs;
        m_lastDataMs = now;
        if (interactionActive() || burst) {
            // Only the curves of A and B changed and the value ranges are held: the axes,
            // ticks, labels and ghost in the layers below stay as they are.
            m_rangesStale = true;
            if (!interactionActive()) m_settle.start();
            else drawOnlyGraphsInView();
            m_plot->layer(kLiveLayer)->replot();
            m_plot->layer(kCursorLayer)->replot();
            return;
        }
    }
    m_rangesStale = false;
    m_settle.stop();
    applyValueRanges();
    m_plot->replot();
}

void GraphGrid::drawOnlyGraphsInView()
{
    // The curves and cursor items of the graphs scrolled out of sight are not drawn on a drag's
    // steps (96 graphs of a whole-body take fill several screens); endInteraction shows them.
    const QRect shown = m_plot->visibleRegion().boundingRect();
    for (auto& graph : m_graphs) {
        const bool inView = graph.rect->outerRect().intersects(shown);
        m_graphsOutOfViewHidden = m_graphsOutOfViewHidden || !inView;
        setGraphDrawn(graph, inView);
        for (auto* point : graph.points)
            if (point && !inView) point->setVisible(false);
    }
}

void GraphGrid::setGraphDrawn(Graph& graph, bool drawn)
{
    // The moving points are not here: updateCursorItems shows them where their take has a value.
    for (auto* layerable : std::initializer_list<QCPLayerable*>{graph.curves[0], graph.curves[1], graph.valueText, graph.cursor})
        if (layerable) layerable->setVisible(drawn);
}

void GraphGrid::applyValueRanges()
{
    auto graphRange = [](const Graph& graph) {
        std::optional<ValueRange> range;
        for (int slot = 0; slot < 2; ++slot)
            if (graph.curves[slot])
                if (auto r = graph.envelopes[slot].range()) range = merged(range, *r);
        for (int g = 0; g < 2; ++g)
            if (graph.ghosts[g])
                if (auto r = graph.ghostEnvelopes[g].range()) range = merged(range, *r);
        return range;
    };
    std::map<std::string, ValueRange> perDof;
    if (m_scale == ValueScale::PerDof) {
        for (const auto& graph : m_graphs)
            if (auto r = graphRange(graph)) {
                auto found = perDof.find(graph.cell.dof);
                perDof[graph.cell.dof] = found == perDof.end() ? *r : merged(found->second, *r);
            }
    }
    for (auto& graph : m_graphs) {
        std::optional<ValueRange> range = graphRange(graph);
        if (m_scale == ValueScale::PerDof && perDof.count(graph.cell.dof)) range = perDof[graph.cell.dof];
        const auto [lower, upper] = padded(range.value_or(ValueRange{0.0, 0.0}));
        graph.rect->axis(QCPAxis::atLeft)->setRange(lower, upper);
    }
}

void GraphGrid::sampleCurves(Graph& graph)
{
    // Before the first layout a new axis rect has no width yet: sample for a typical one, the
    // layout resamples at the real width before drawing.
    const int columns = graph.rect->width() > 1 ? graph.rect->width() : 800;
    graph.sampledColumns = graph.rect->width();
    for (int slot = 0; slot < 2; ++slot)
        if (graph.curves[slot]) graph.curves[slot]->data()->set(graph.envelopes[slot].sample(m_rangeLower, m_rangeUpper, columns), true);
    for (int g = 0; g < 2; ++g)
        if (graph.ghosts[g]) graph.ghosts[g]->data()->set(graph.ghostEnvelopes[g].sample(m_rangeLower, m_rangeUpper, columns), true);
}

void GraphGrid::resampleCurves(bool onlyResized)
{
    bool any = false;
    for (auto& graph : m_graphs) {
        if (onlyResized && graph.sampledColumns == graph.rect->width()) continue;
        sampleCurves(graph);
        any = true;
    }
    if (any) ++m_samplings;
}

void GraphGrid::updateCursorItems()
{
    for (auto& graph : m_graphs) {
        graph.cursor->point1->setCoords(m_cursorTime, 0.0);
        graph.cursor->point2->setCoords(m_cursorTime, 1.0);
        QStringList texts;
        for (int slot = 0; slot < 2; ++slot) {
            if (!graph.points[slot]) continue;
            std::optional<double> value;
            if (graph.channels[slot]) value = valueAt(*slotTake(slot), *graph.channels[slot], m_cursorTime);
            graph.points[slot]->setVisible(value.has_value());
            if (value) {
                graph.points[slot]->position->setCoords(m_cursorTime, *value);
                const bool both = graph.points[0] && graph.points[1];
                texts << (both ? QStringLiteral("%1 %2").arg(slot == 0 ? "A" : "B").arg(*value, 0, 'f', 1)
                               : QString::number(*value, 'f', 1));
            }
        }
        graph.valueText->setText(texts.join("  "));
        placeValueText(graph);
    }
}

void GraphGrid::placeValueText(Graph& graph) const
{
    if (!graph.valueText || !graph.nameText) return;
    const QFontMetrics metrics(graph.valueText->font());
    const int width = graph.rect->width(), height = graph.rect->height();
    const int needed = graph.nameAdvance + metrics.horizontalAdvance(graph.valueText->text()) + 16;
    if (needed <= width || height <= 0) {
        graph.valueText->position->setCoords(0.99, 0.02);
        graph.valueText->setPositionAlignment(Qt::AlignRight | Qt::AlignTop);
    } else {
        graph.valueText->position->setCoords(0.01, 0.02 + double(metrics.height() + 1) / double(height));
        graph.valueText->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
    }
}

void GraphGrid::setCursorTime(double seconds)
{
    // The same time again (the app passes it after new takes): setTakes placed the cursor's
    // points and values on the new data already.
    if (seconds == m_cursorTime) return;
    m_cursorTime = seconds;
    updateCursorItems();
    m_plot->layer(kCursorLayer)->replot();
}

void GraphGrid::setTimeRange(double lower, double upper)
{
    if (!(upper > lower)) return;
    m_rangeLower = lower;
    m_rangeUpper = upper;
    m_propagating = true;
    for (auto& graph : m_graphs) graph.rect->axis(QCPAxis::atBottom)->setRange(lower, upper);
    m_propagating = false;
    resampleCurves(false);
    m_plot->replot();
    emit timeRangeChanged(lower, upper);
}

std::pair<double, double> GraphGrid::timeRange() const { return {m_rangeLower, m_rangeUpper}; }

void GraphGrid::resetTimeRange()
{
    const double duration = shownDuration();
    setTimeRange(0.0, duration > 0.0 ? duration : 1.0);
}

void GraphGrid::propagateTimeRange(QCPAxisRect* source)
{
    if (m_propagating) return;
    const QCPRange range = source->axis(QCPAxis::atBottom)->range();
    m_rangeLower = range.lower;
    m_rangeUpper = range.upper;
    m_propagating = true;
    for (auto& graph : m_graphs)
        if (graph.rect != source) graph.rect->axis(QCPAxis::atBottom)->setRange(range);
    m_propagating = false;
    resampleCurves(false);
    emit timeRangeChanged(range.lower, range.upper);
}

const GraphCell& GraphGrid::graphCell(int graph) const { return m_graphs.at(std::size_t(graph)).cell; }

double GraphGrid::graphCursorTime(int graph) const { return m_graphs.at(std::size_t(graph)).cursor->point1->coords().x(); }

std::pair<QRectF, QRectF> GraphGrid::graphTextBoxes(int graph) const
{
    const Graph& g = m_graphs.at(std::size_t(graph));
    const auto box = [](const QCPItemText* text) {
        return QRectF(text->topLeft->pixelPosition(), text->bottomRight->pixelPosition()).normalized();
    };
    return {box(g.nameText), box(g.valueText)};
}

std::optional<double> GraphGrid::graphPointValue(int graph, int slot) const
{
    const auto* point = m_graphs.at(std::size_t(graph)).points[slot];
    if (!point || !point->visible()) return std::nullopt;
    return point->position->coords().y();
}

std::pair<double, double> GraphGrid::graphValueRange(int graph) const
{
    const QCPRange range = m_graphs.at(std::size_t(graph)).rect->axis(QCPAxis::atLeft)->range();
    return {range.lower, range.upper};
}

QRect GraphGrid::graphRect(int graph) const
{
    const QRect rect = m_graphs.at(std::size_t(graph)).rect->rect();
    return QRect(m_plot->mapTo(this, rect.topLeft()), rect.size());
}

QString GraphGrid::graphValueLabel(int graph) const { return m_graphs.at(std::size_t(graph)).rect->axis(QCPAxis::atLeft)->label(); }

void GraphGrid::onMousePress(QMouseEvent* event)
{
    const QPointF position = event->position();
    m_dragRect = m_plot->axisRectAt(position);
    if (!m_dragRect) return;
    auto* timeAxis = m_dragRect->axis(QCPAxis::atBottom);
    if (event->button() == Qt::MiddleButton || (event->button() == Qt::LeftButton && event->modifiers() & Qt::ShiftModifier)) {
        m_drag = Drag::Pan;
        m_panAnchor = timeAxis->pixelToCoord(position.x());
    } else if (event->button() == Qt::LeftButton) {
        m_drag = Drag::Scrub;
        emit timeScrubbed(timeAxis->pixelToCoord(position.x()));
    }
}

void GraphGrid::onMouseMove(QMouseEvent* event)
{
    if (m_drag == Drag::None || !m_dragRect) return;
    auto* timeAxis = m_dragRect->axis(QCPAxis::atBottom);
    const double key = timeAxis->pixelToCoord(event->position().x());
    if (m_drag == Drag::Scrub) {
        emit timeScrubbed(key);
    } else {
        const double shift = m_panAnchor - key;
        setTimeRange(m_rangeLower + shift, m_rangeUpper + shift);
    }
}

void GraphGrid::onMouseRelease(QMouseEvent*)
{
    m_drag = Drag::None;
    m_dragRect = nullptr;
}

} // namespace bunraku::widgets
