#pragma once
/// Line charts as self-contained SVG text (no script, no external resource): the figures of the
/// analysis report. Axes with "nice" ticks, one polyline per series, an optional legend.

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis::report {

struct SvgSeries {
    std::string label;   ///< legend text (empty: not in the legend)
    Eigen::VectorXd x;
    Eigen::VectorXd y;   ///< same length as x; non-finite points break the line
    std::string colour;  ///< CSS colour, e.g. "#1f77b4"
    bool dashed = false;
    double width = 1.2;
    bool markers = false; ///< a dot at each point instead of a line (a scatter plot)
};

struct SvgPlot {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    int width = 420;
    int height = 260;
    bool logY = false; ///< log10 axis (non-positive values dropped)
    std::vector<SvgSeries> series;
};

/// The chart as an <svg> element (UTF-8, XML-escaped labels).
std::string renderSvg(const SvgPlot& plot);

/// A colour of a fixed palette of 10 (index taken modulo 10).
std::string paletteColour(std::size_t index);

/// `text` with &, <, >, " and ' escaped for HTML and XML.
std::string escapeXml(const std::string& text);

} // namespace bunraku::analysis::report
