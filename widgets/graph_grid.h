#pragma once
/// The synchronised graphs of one or two takes (thesis digest section 6): value against time
/// per channel, each with a moving point and its value at the current time. All graphs live in
/// one QCustomPlot (one axis rect per graph). The time cursor, points and values sit on their own
/// buffered layer "cursor", so moving the time replots only that layer, never the curves. The
/// curves of takes A and B sit on the buffered layer "live" (the ghost, grid, axes and labels
/// below it): while the value ranges are held, new data for A or B (a designed take during a
/// warp drag) replots only that layer and the cursor layer. Ranges are held during an
/// interaction (beginInteraction/endInteraction) and for a burst of data changes less than
/// kSettleMs apart; they autoscale once when it ends (a full replot).
/// Zoom (wheel) and pan (middle or Shift+left drag) on time are shared by every graph; a left
/// press or drag in any graph scrubs (timeScrubbed); a double click resets the time range, and so
/// does showing other takes. Value axes carry the channels' units. Each graph keeps a readable
/// height (kMinimumGraphHeight): when the widget is shorter, the graphs scroll.
/// Curves hold only what their view needs (take_series.h SeriesEnvelope: at most 4 points a
/// pixel column, every frame when zoomed in): resampled when the time range or the graphs'
/// width changes, never when only the cursor moves, so an hour-long take draws like a short one.

#include "widgets/graph_layout.h"
#include "widgets/take_series.h"

#include "analysis/core/take.h"

#include <QColor>
#include <QTimer>

#include "widgets/clock.h"
#include <QWidget>

#include <array>
#include <memory>
#include <optional>
#include <vector>

class QCustomPlot;
class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;
class QCPItemTracer;
class QCPItemText;
class QMouseEvent;
class QScrollArea;

namespace bunraku::widgets {

/// How the value axes are scaled.
enum class ValueScale {
    PerGraph, ///< each graph fits its own data
    PerDof,   ///< graphs of the same DOF share one range (compare parts and takes)
};

/// The colours of take A, take B and the ghost (contrasting, colour-blind safe).
struct GraphColours {
    QColor takeA{0x1f, 0x77, 0xb4};
    QColor takeB{0xd9, 0x5f, 0x02};
    QColor ghost{0xa0, 0xa0, 0xa0};
    /// The thesis's per-channel result: purple, apart in hue from take A's blue and B's orange.
    QColor perChannel{0x7b, 0x32, 0x94};
};

class GraphGrid : public QWidget {
    Q_OBJECT
public:
    explicit GraphGrid(QWidget* parent = nullptr);
    ~GraphGrid() override;

    /// Take A (required for any graph) and take B (may be null). Rebuilds the graphs.
    /// `identity` names what is shown (the app passes the takes' ids; empty: the same takes as
    /// before, changed): when it changes, the time axis is refitted to the shown takes; while it
    /// stays (a live take recomputed, a designed take on every drag step) the zoom is kept, and
    /// a view showing the whole take follows a new length once no drag is under way.
    void setTakes(std::shared_ptr<const analysis::Take> takeA, std::shared_ptr<const analysis::Take> takeB,
                  const QString& identity = {});
    /// A take drawn faintly behind A (the original under a designed take); null hides it.
    void setGhost(std::shared_ptr<const analysis::Take> ghost);
    /// The thesis's per-channel result of a take shown as one body, drawn in orange behind A beside
    /// the ghost (a normalised take's ghost is its raw take); null hides it. During an interaction
    /// any change (a new one, or none) waits for endInteraction: a drag step redraws only the
    /// live curves, and a result that agrees with the body on some steps and not on others would
    /// rebuild every graph on each.
    void setPerChannelGhost(std::shared_ptr<const analysis::Take> take);
    /// The takes drawn as the ghost and as the per-channel result (as the angle display shows them).
    std::array<std::shared_ptr<const analysis::Take>, 2> ghostTakes() const { return {m_ghosts[0], m_ghosts[1]}; }
    void setGraphLayout(GraphLayout layout);
    void setTwoTakeMode(TwoTakeMode mode);
    void setValueScale(ValueScale scale);
    /// The thesis's ticks (6.3.3): value ticks every 10 units and time ticks every 2 s at any
    /// zoom. Off: about 3 value ticks per graph and time ticks at multiples of 2 s.
    void setThesisTicks(bool on);
    bool thesisTicks() const { return m_thesisTicks; }
    /// The part and DOF used by the OnePart, OneDof and Single layouts.
    void setSelectedChannel(const std::string& part, const std::string& dof);

    GraphLayout graphLayout() const { return m_options.layout; }
    TwoTakeMode twoTakeMode() const { return m_options.twoTakeMode; }
    ValueScale valueScale() const { return m_scale; }

    /// A drag that changes the takes' data on every step begins: until endInteraction, every
    /// graph keeps its value range, so new data of A or B replots only the "live" and "cursor"
    /// layers (not the axes, ticks and labels of every graph). Calls do not nest (like
    /// app::Document's): a second begin is ignored.
    void beginInteraction();
    /// The interaction ends: value ranges autoscale once (a full replot) if data changed.
    void endInteraction();
    bool interactionActive() const { return m_interacting; }
    /// Data changes closer together than this (ms) form a burst that holds the value ranges;
    /// this long after the last one, the ranges autoscale.
    static constexpr int kSettleMs = 250;
    /// The clock that tells a burst from isolated changes and times its end (null: the steady
    /// clock); tests inject a ManualClock.
    void setClock(Clock* clock);

    /// Moves the time cursor (seconds) and replots only the cursor layer.
    void setCursorTime(double seconds);
    double cursorTime() const { return m_cursorTime; }
    /// The shared visible time range, seconds.
    void setTimeRange(double lower, double upper);
    std::pair<double, double> timeRange() const;
    /// Shows the whole of the longer take.
    void resetTimeRange();
    /// The longest of the shown takes and the ghost, seconds.
    double shownDuration() const;
    /// The label of graph `graph`'s value axis (the channel's unit: "cm", "deg").
    QString graphValueLabel(int graph) const;

    int graphCount() const { return int(m_graphs.size()); }
    /// Most graphs the grid builds: a take of more channels than that shows its first
    /// kMaxGraphs (a take of 10,000 channels would build 10,000 plots, and QCustomPlot's layout
    /// work grows with their square); the 'one part' and 'single' layouts reach every channel.
    static constexpr int kMaxGraphs = 96;
    /// How many graphs the layout asks for beyond kMaxGraphs (0 normally).
    int hiddenGraphCount() const { return m_hiddenGraphs; }
    const GraphCell& graphCell(int graph) const;
    /// The time (seconds) at which graph `graph` draws its cursor line.
    double graphCursorTime(int graph) const;
    /// The value shown by graph `graph`'s moving point of take A (slot 0) or B (slot 1), or
    /// std::nullopt when that point is hidden (time outside the take, or no such curve).
    std::optional<double> graphPointValue(int graph, int slot) const;
    /// The boxes (pixels) of a graph's name and of its cursor values as drawn, and whether the
    /// values are empty.
    std::pair<QRectF, QRectF> graphTextBoxes(int graph) const;
    /// The value axis range of graph `graph`.
    std::pair<double, double> graphValueRange(int graph) const;
    /// The pixel rectangle of graph `graph` inside this widget (for tests and screenshots).
    QRect graphRect(int graph) const;

    QCustomPlot* plot() const { return m_plot; }
    /// The curve of take A (slot 0) or B (slot 1) in graph `graph`, null when it has none.
    QCPGraph* curve(int graph, int slot) const { return m_graphs.at(std::size_t(graph)).curves[slot]; }
    /// How many times the curves were resampled for a new view (time range, width or data).
    int samplingCount() const { return m_samplings; }
    /// The smallest height (pixels) of one row of graphs; below it the grid scrolls.
    static constexpr int kMinimumGraphHeight = 34;

signals:
    /// endInteraction: the drag is over (emitted before the held changes are shown).
    void interactionEnded();
    /// The user pressed or dragged at `seconds` in a graph.
    void timeScrubbed(double seconds);
    /// The grid was rebuilt with `hidden` graphs of the layout left out (kMaxGraphs), of `total`.
    void graphsLimited(int hidden, int total);
    /// The shared time range changed (zoom, pan or reset).
    void timeRangeChanged(double lower, double upper);

private:
    struct Graph {
        GraphCell cell;
        QCPAxisRect* rect = nullptr;
        QCPGraph* curves[2] = {nullptr, nullptr};
        QCPGraph* ghosts[2] = {nullptr, nullptr}; ///< the ghost, the per-channel result
        std::optional<Eigen::Index> channels[2];
        std::optional<Eigen::Index> ghostChannels[2];
        QCPItemStraightLine* cursor = nullptr;
        QCPItemTracer* points[2] = {nullptr, nullptr};
        QCPItemText* valueText = nullptr;
        QCPItemText* nameText = nullptr;
        int nameAdvance = 0; ///< pixels of nameText in the tick font (its text never changes)
        SeriesEnvelope envelopes[2]; ///< the curves' data at any zoom
        SeriesEnvelope ghostEnvelopes[2];
        int sampledColumns = 0; ///< the width the curves were last sampled for
    };

    /// Rebuilds the graphs when the layout changed, else updates the curves whose take changed
    /// (all of them when `allData`).
    void rebuild(bool allData = true);
    void applyValueRanges();
    /// Fills the curves of `graph` with the points of the current time range at its width.
    void sampleCurves(Graph& graph);
    /// Resamples every graph (a new time range), or only those whose width changed.
    void resampleCurves(bool onlyResized);
    /// The tickers of every graph for m_thesisTicks.
    void applyTickers();
    /// The cursor's values at the graph's top right, or under its name when both do not fit on
    /// one line beside each other (a narrow graph: 48 at 1366 pixels).
    void placeValueText(Graph& graph) const;
    /// Autoscales and replots if data changed while the ranges were held.
    void settleValueRanges();
    void updateCursorItems();
    /// During an interaction: hides the curves and cursor items of graphs out of the scroll
    /// area's view.
    void drawOnlyGraphsInView();
    /// Shows or hides a graph's curves, cursor line and value text (not its moving points).
    static void setGraphDrawn(Graph& graph, bool drawn);
    void onMousePress(QMouseEvent* event);
    void onMouseMove(QMouseEvent* event);
    void onMouseRelease(QMouseEvent* event);
    void propagateTimeRange(QCPAxisRect* source);
    const analysis::Take* slotTake(int slot) const;

    QCustomPlot* m_plot = nullptr;
    QScrollArea* m_scroll = nullptr;
    std::shared_ptr<const analysis::Take> m_takes[2];
    std::shared_ptr<const analysis::Take> m_ghosts[2]; ///< the ghost, the per-channel result
    std::shared_ptr<const analysis::Take> m_pendingPerChannel; ///< given during an interaction
    bool m_graphsOutOfViewHidden = false; ///< drawOnlyGraphsInView hid some graphs' curves
    bool m_perChannelPending = false;                          ///< m_pendingPerChannel is to be shown
    std::shared_ptr<const analysis::Take> m_plotted[2]; ///< the takes whose data the curves hold
    bool m_interacting = false;
    bool m_rangesStale = false; ///< data changed while the ranges were held
    Clock* m_clock = &steadyClock();
    std::optional<qint64> m_lastDataMs; ///< when A's or B's data last changed (m_clock)
    ClockTimer m_settle;                ///< autoscales after a burst of data changes
    GraphLayoutOptions m_options;
    ValueScale m_scale = ValueScale::PerGraph;
    bool m_thesisTicks = false;
    GraphColours m_colours;
    std::vector<Graph> m_graphs;
    int m_hiddenGraphs = 0;
    double m_cursorTime = 0.0;
    double m_rangeLower = 0.0;
    double m_rangeUpper = 1.0;
    bool m_propagating = false;
    int m_samplings = 0;
    QString m_shownIdentity; ///< what setTakes last showed (its identity)
    bool m_followLength = false; ///< the whole take was shown when a drag changed its length
    enum class Drag { None, Scrub, Pan } m_drag = Drag::None;
    QCPAxisRect* m_dragRect = nullptr;
    double m_panAnchor = 0.0;
};

} // namespace bunraku::widgets
