#pragma once
/// One frame of the thesis's multimodal display (chapter 6.4-6.5) as a picture: the 3D view and
/// the graphs of the chosen layout composed in the thesis's arrangements, each graph with the
/// time cursor and a moving point at the current time.
///   one take  - 24 graphs: two columns of 12 at the left and right edges, the view between them;
///               6 (one part) or 4 (one DOF): the view in the left half, the graphs stacked in
///               the right half; 1 graph: the view above, the graph along the bottom.
///   two takes - the puppets side by side in the view on top (A left, B right as the camera sees
///               them), each take's graphs stacked under its puppet: 48 (2 columns of 12 per
///               take), 12 (6 per take), 8 (4 per take), 2 (one per take, side by side).
/// Graph ticks: automatic, or the thesis's (value ticks every 10 units, time ticks every 2 s,
/// 6.3.3). Drawn with QPainter into a QImage (no widgets, no OpenGL): the caller supplies the
/// view's image, so the workbench and `bunraku render --multimodal` compose the same frames.

#include "analysis/core/result.h"
#include "analysis/core/take.h"
#include "widgets/graph_layout.h"

#include <QColor>
#include <QImage>
#include <QRect>
#include <QSize>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bunraku::app {

struct MultimodalOptions {
    widgets::GraphLayout layout = widgets::GraphLayout::AllChannels;
    std::string part; ///< for OnePart and Single (the first part when empty)
    std::string dof;  ///< for OneDof and Single (the first DOF when empty)
    bool thesisTicks = true; ///< 10-unit value ticks and 2 s time ticks (thesis 6.3.3)
    QSize size{1920, 1080};  ///< the whole frame, pixels
};

/// The colours of the composed frame.
struct MultimodalColours {
    QColor takeA{0x1f, 0x77, 0xb4};
    QColor takeB{0xd9, 0x5f, 0x02};
    QColor cursor{0xe0, 0x00, 0x00}; ///< the time cursor (drawn 1 pixel wide, not antialiased)
    QColor background{0xff, 0xff, 0xff};
    QColor frame{0x80, 0x80, 0x80};
    QColor grid{0xe4, 0xe4, 0xe4};
    QColor text{0x30, 0x30, 0x30};
};

/// Where everything goes in a frame of `options.size`.
struct MultimodalGeometry {
    QRect view;                           ///< the 3D view
    std::vector<widgets::GraphCell> cells; ///< layoutGraphs (side by side for two takes)
    std::vector<QRect> graphs;            ///< one rectangle per cell (frame and labels included)
    std::vector<QRect> plots;             ///< the plotting area inside each graph rectangle
};

/// The arrangement for take A's channels (and B's when `twoTakes`). Empty view and no graphs
/// when the size is below 64 x 64 or there are no channels.
MultimodalGeometry multimodalGeometry(const std::vector<analysis::Channel>& channels, bool twoTakes,
                                      const MultimodalOptions& options);

/// Draws a 3D view image (the view rectangle's size) at a time.
using ViewImage = std::function<analysis::Result<QImage>(double seconds, QSize size)>;

/// The frames of one or two takes.
class MultimodalFrame {
public:
    /// takeB may be null. Errors: no take A, a take without frames or with a rate <= 0, a frame
    /// too small for the arrangement (below 64 x 64 pixels).
    static analysis::Result<MultimodalFrame> create(std::shared_ptr<const analysis::Take> takeA,
                                                    std::shared_ptr<const analysis::Take> takeB,
                                                    const MultimodalOptions& options);

    const MultimodalGeometry& geometry() const { return m_geometry; }
    const MultimodalOptions& options() const { return m_options; }
    const analysis::Take& takeA() const { return *m_takes[0]; }
    /// Take B, or null.
    const analysis::Take* takeB() const { return m_takes[1].get(); }
    /// The graphs' time axis: 0 .. the longer take's last frame, seconds.
    double duration() const { return m_duration; }
    /// The pixel column of the time cursor at `seconds` in plot rectangle `plot` (clamped).
    int cursorColumn(const QRect& plot, double seconds) const;

    /// The frame at `seconds`: `view` (scaled if it is not the view rectangle's size) and the graphs.
    QImage compose(const QImage& view, double seconds) const;
    /// compose() with the view drawn by `draw`; its error passes through.
    analysis::Result<QImage> render(const ViewImage& draw, double seconds) const;

private:
    MultimodalFrame() = default;
    void drawGraph(class QPainter& painter, std::size_t index, double seconds) const;

    std::shared_ptr<const analysis::Take> m_takes[2];
    MultimodalOptions m_options;
    MultimodalGeometry m_geometry;
    MultimodalColours m_colours;
    double m_duration = 0.0;
    /// Per graph: the take slot (0 = A, 1 = B), its channel and the value range drawn.
    struct Series {
        int slot = 0;
        Eigen::Index channel = 0;
        double lower = 0.0, upper = 1.0;
    };
    std::vector<Series> m_series;
    /// " (cm)", " (deg)": the unit of the series' channel, for its title; "" when it has none.
    QString unitText(const Series& series) const;
};

/// Ticks from `lower` to `upper`: multiples of `step` when step > 0, else about `count` round
/// values (1, 2 or 5 x 10^k apart).
std::vector<double> graphTicks(double lower, double upper, double step, int count = 4);

/// A graph's value ticks: every 10 units with the thesis's ticks (6.3.3), unless its range holds
/// fewer than two of them (a head moving 5 cm), then about 3 round values as without: every
/// graph keeps two value labels to read.
std::vector<double> valueAxisTicks(double lower, double upper, bool thesisTicks);

} // namespace bunraku::app
