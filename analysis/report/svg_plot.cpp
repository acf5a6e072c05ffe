#include "analysis/report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace bunraku::analysis::report {
namespace {

std::string number(double value, int precision = 4)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    return text;
}

/// About `count` round tick values covering [low, high].
std::vector<double> niceTicks(double low, double high, int count)
{
    if (!(high > low)) return {low};
    const double raw = (high - low) / std::max(1, count);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (factor * magnitude >= raw) {
            step = factor * magnitude;
            break;
        }
    std::vector<double> ticks;
    for (double tick = std::ceil(low / step) * step; tick <= high + step * 1e-9 && ticks.size() < 50; tick += step)
        ticks.push_back(std::abs(tick) < step * 1e-9 ? 0.0 : tick);
    return ticks;
}

} // namespace

std::string paletteColour(std::size_t index)
{
    static const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
    return colours[index % 10];
}

std::string escapeXml(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string renderSvg(const SvgPlot& plot)
{
    const double left = 58, right = 12, top = plot.title.empty() ? 10 : 26, bottom = 40;
    const double innerWidth = plot.width - left - right, innerHeight = plot.height - top - bottom;
    auto yValue = [&](double y) { return plot.logY ? (y > 0 ? std::log10(y) : std::numeric_limits<double>::quiet_NaN()) : y; };
    double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin, yMin = xMin, yMax = -xMin;
    for (const auto& s : plot.series)
        for (Eigen::Index i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            const double y = yValue(s.y[i]);
            if (!std::isfinite(s.x[i]) || !std::isfinite(y)) continue;
            xMin = std::min(xMin, s.x[i]);
            xMax = std::max(xMax, s.x[i]);
            yMin = std::min(yMin, y);
            yMax = std::max(yMax, y);
        }
    if (!std::isfinite(xMin)) xMin = 0, xMax = 1, yMin = 0, yMax = 1;
    if (xMax <= xMin) xMax = xMin + 1;
    if (yMax <= yMin) yMin -= 0.5, yMax += 0.5;
    const double pad = 0.04 * (yMax - yMin);
    yMin -= pad;
    yMax += pad;
    auto px = [&](double x) { return left + (x - xMin) / (xMax - xMin) * innerWidth; };
    auto py = [&](double y) { return top + (1.0 - (y - yMin) / (yMax - yMin)) * innerHeight; };

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << plot.width << "\" height=\"" << plot.height
        << "\" viewBox=\"0 0 " << plot.width << ' ' << plot.height << "\" font-family=\"sans-serif\" font-size=\"10\">";
    svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>";
    if (!plot.title.empty())
        svg << "<text x=\"" << plot.width / 2 << "\" y=\"16\" text-anchor=\"middle\" font-size=\"12\">" << escapeXml(plot.title)
            << "</text>";
    svg << "<g stroke=\"#ddd\" stroke-width=\"0.6\">";
    const auto xTicks = niceTicks(xMin, xMax, 6), yTicks = niceTicks(yMin, yMax, 5);
    for (double t : xTicks) svg << "<line x1=\"" << px(t) << "\" y1=\"" << top << "\" x2=\"" << px(t) << "\" y2=\"" << top + innerHeight << "\"/>";
    for (double t : yTicks) svg << "<line x1=\"" << left << "\" y1=\"" << py(t) << "\" x2=\"" << left + innerWidth << "\" y2=\"" << py(t) << "\"/>";
    svg << "</g><rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << innerWidth << "\" height=\"" << innerHeight
        << "\" fill=\"none\" stroke=\"#444\"/>";
    for (double t : xTicks)
        svg << "<text x=\"" << px(t) << "\" y=\"" << top + innerHeight + 12 << "\" text-anchor=\"middle\">" << number(t) << "</text>";
    for (double t : yTicks)
        svg << "<text x=\"" << left - 4 << "\" y=\"" << py(t) + 3 << "\" text-anchor=\"end\">"
            << (plot.logY ? "1e" + number(t, 3) : number(t)) << "</text>";
    svg << "<text x=\"" << left + innerWidth / 2 << "\" y=\"" << plot.height - 6 << "\" text-anchor=\"middle\">"
        << escapeXml(plot.xLabel) << "</text>";
    svg << "<text transform=\"translate(12," << top + innerHeight / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
        << escapeXml(plot.yLabel) << "</text>";
    for (const auto& s : plot.series) {
        if (s.markers) {
            for (Eigen::Index i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
                const double y = yValue(s.y[i]);
                if (std::isfinite(s.x[i]) && std::isfinite(y))
                    svg << "<circle cx=\"" << number(px(s.x[i]), 6) << "\" cy=\"" << number(py(y), 6) << "\" r=\"" << 1.5 + s.width
                        << "\" fill=\"" << s.colour << "\"/>";
            }
            continue;
        }
        std::ostringstream points;
        bool open = false;
        auto flush = [&] {
            if (open) svg << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"" << s.width << "\""
                          << (s.dashed ? " stroke-dasharray=\"4 3\"" : "") << " points=\"" << points.str() << "\"/>";
            points.str("");
            open = false;
        };
        for (Eigen::Index i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            const double y = yValue(s.y[i]);
            if (!std::isfinite(s.x[i]) || !std::isfinite(y)) {
                flush();
                continue;
            }
            points << (open ? " " : "") << number(px(s.x[i]), 6) << ',' << number(py(y), 6);
            open = true;
        }
        flush();
    }
    double legendY = top + 10;
    // The legend's left edge: far enough in for its longest label (about 6 px a character).
    std::size_t longest = 0;
    for (const auto& s : plot.series) longest = std::max(longest, s.label.size());
    const double legendLeft = std::max(92.0, 6.0 * double(longest) + 24.0);
    for (const auto& s : plot.series) {
        if (s.label.empty()) continue;
        if (s.markers)
            svg << "<circle cx=\"" << left + innerWidth - legendLeft + 7 << "\" cy=\"" << legendY - 3 << "\" r=\"" << 1.5 + s.width << "\" fill=\"" << s.colour << "\"/>";
        else
            svg << "<line x1=\"" << left + innerWidth - legendLeft << "\" y1=\"" << legendY - 3 << "\" x2=\"" << left + innerWidth - legendLeft + 14 << "\" y2=\""
                << legendY - 3 << "\" stroke=\"" << s.colour << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"4 3\"" : "") << "/>";
        svg << "<text x=\"" << left + innerWidth - legendLeft + 18 << "\" y=\"" << legendY << "\">" << escapeXml(s.label) << "</text>";
        legendY += 12;
    }
    svg << "</svg>";
    return svg.str();
}

} // namespace bunraku::analysis::report
