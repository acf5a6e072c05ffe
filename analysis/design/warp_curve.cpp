#include "analysis/design/warp_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bunraku::analysis {

Status validateWarpCurve(const WarpCurve& curve)
{
    if (curve.points.size() < 2) return makeError(ErrorCode::InvalidArgument, "a warp curve needs at least 2 control points");
    for (std::size_t i = 0; i < curve.points.size(); ++i) {
        const WarpPoint& p = curve.points[i];
        if (!std::isfinite(p.output) || !std::isfinite(p.source))
            return makeError(ErrorCode::InvalidArgument, "warp point " + std::to_string(i) + " is not finite");
        if (i > 0 && p.output <= curve.points[i - 1].output)
            return makeError(ErrorCode::InvalidArgument, "warp point " + std::to_string(i) + ": output frames must increase");
        if (i > 0 && p.source < curve.points[i - 1].source)
            return makeError(ErrorCode::InvalidArgument,
                             "warp point " + std::to_string(i) + ": source frames must not decrease (time cannot run backwards)");
    }
    return okStatus();
}

WarpCurve identityWarp(Eigen::Index frames, int spacing)
{
    Eigen::VectorXd samples = Eigen::VectorXd::LinSpaced(frames, 0.0, double(frames - 1));
    return warpCurveFromSamples(samples, spacing);
}

namespace {

/// Fritsch-Carlson tangents: averaged secants, zero at flat stretches and local extrema, then
/// shrunk interval by interval so that alpha^2 + beta^2 <= 9 (shrinking keeps earlier intervals valid).
std::vector<double> monotoneTangents(const std::vector<WarpPoint>& p)
{
    const std::size_t n = p.size();
    std::vector<double> secant(n > 1 ? n - 1 : 0), m(n, 0.0);
    for (std::size_t i = 0; i + 1 < n; ++i) secant[i] = (p[i + 1].source - p[i].source) / (p[i + 1].output - p[i].output);
    if (n < 2) return m;
    m[0] = secant[0];
    m[n - 1] = secant[n - 2];
    for (std::size_t i = 1; i + 1 < n; ++i)
        m[i] = (secant[i - 1] <= 0.0 || secant[i] <= 0.0) ? 0.0 : 0.5 * (secant[i - 1] + secant[i]);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        if (secant[i] <= 0.0) {
            m[i] = m[i + 1] = 0.0;
            continue;
        }
        const double a = m[i] / secant[i], b = m[i + 1] / secant[i];
        const double r = a * a + b * b;
        if (r > 9.0) {
            const double t = 3.0 / std::sqrt(r);
            m[i] = t * a * secant[i];
            m[i + 1] = t * b * secant[i];
        }
    }
    return m;
}

double evaluateWithTangents(const std::vector<WarpPoint>& p, const std::vector<double>& m, double x)
{
    if (p.empty()) return x;
    if (p.size() == 1 || x <= p.front().output) return p.front().source;
    if (x >= p.back().output) return p.back().source;
    const auto upper = std::upper_bound(p.begin(), p.end(), x, [](double v, const WarpPoint& q) { return v < q.output; });
    const std::size_t k = std::size_t(upper - p.begin()) - 1; // p[k].output <= x < p[k+1].output
    const double h = p[k + 1].output - p[k].output;
    const double s = (x - p[k].output) / h;
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p[k].source + (s3 - 2 * s2 + s) * h * m[k] + (-2 * s3 + 3 * s2) * p[k + 1].source +
           (s3 - s2) * h * m[k + 1];
}

} // namespace

double evaluateWarp(const WarpCurve& curve, double x)
{
    return evaluateWithTangents(curve.points, monotoneTangents(curve.points), x);
}

Eigen::VectorXd sampleWarp(const WarpCurve& curve)
{
    Eigen::Index frames = curve.outputFrames;
    if (frames <= 0 && !curve.points.empty()) frames = Eigen::Index(std::floor(curve.points.back().output)) + 1;
    Eigen::VectorXd samples(std::max<Eigen::Index>(frames, 0));
    const std::vector<double> tangents = monotoneTangents(curve.points);
    for (Eigen::Index f = 0; f < samples.size(); ++f) samples[f] = evaluateWithTangents(curve.points, tangents, double(f));
    // guard against rounding: never decreasing
    for (Eigen::Index f = 1; f < samples.size(); ++f) samples[f] = std::max(samples[f], samples[f - 1]);
    return samples;
}

double inverseWarp(const WarpCurve& curve, double source)
{
    if (!validateWarpCurve(curve).ok() || !std::isfinite(source)) return source;
    const std::vector<double> tangents = monotoneTangents(curve.points);
    double low = curve.points.front().output;
    double high = curve.points.back().output;
    if (evaluateWithTangents(curve.points, tangents, low) >= source) return low;
    if (evaluateWithTangents(curve.points, tangents, high) < source) return high;
    // invariant: f(low) < source <= f(high); 64 halvings reach double precision on any range
    for (int step = 0; step < 64 && high - low > 1e-9; ++step) {
        const double middle = 0.5 * (low + high);
        if (evaluateWithTangents(curve.points, tangents, middle) >= source)
            high = middle;
        else
            low = middle;
    }
    return high;
}

WarpCurve moveControlPoint(const WarpCurve& curve, std::size_t index, const WarpPoint& proposed, double minimumGap, WarpMove mode)
{
    WarpCurve moved = curve;
    if (index >= moved.points.size()) return moved;
    auto& p = moved.points;
    WarpPoint point = proposed;
    const bool first = index == 0, last = index + 1 == p.size();
    if (first || last) {
        point.output = p[index].output;
    } else {
        const double low = p[index - 1].output + minimumGap, high = p[index + 1].output - minimumGap;
        point.output = low <= high ? std::clamp(point.output, low, high) : 0.5 * (p[index - 1].output + p[index + 1].output);
    }
    if (mode == WarpMove::Push) {
        for (std::size_t j = 0; j < index; ++j) p[j].source = std::min(p[j].source, point.source);
        for (std::size_t j = index + 1; j < p.size(); ++j) p[j].source = std::max(p[j].source, point.source);
        p[index] = point;
        return moved;
    }
    const double lowSource = first ? -std::numeric_limits<double>::infinity() : p[index - 1].source;
    const double highSource = last ? std::numeric_limits<double>::infinity() : p[index + 1].source;
    point.source = std::clamp(point.source, lowSource, std::max(lowSource, highSource));
    p[index] = point;
    return moved;
}

WarpCurve warpCurveFromSamples(const Eigen::VectorXd& sourceOfOutput, int spacing)
{
    WarpCurve curve;
    curve.outputFrames = sourceOfOutput.size();
    const Eigen::Index last = sourceOfOutput.size() - 1;
    if (last < 0) return curve;
    spacing = std::max(1, spacing);
    double previous = -std::numeric_limits<double>::infinity();
    for (Eigen::Index f = 0; f <= last; f += spacing) {
        if (f != 0 && last - f < spacing / 2) break; // avoid a sliver before the last point
        previous = std::max(previous, sourceOfOutput[f]);
        curve.points.push_back({double(f), previous});
    }
    if (curve.points.empty() || curve.points.back().output < double(last))
        curve.points.push_back({double(last), std::max(previous, sourceOfOutput[last])});
    return curve;
}

} // namespace bunraku::analysis
