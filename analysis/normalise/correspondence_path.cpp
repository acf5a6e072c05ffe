#include "analysis/normalise/correspondence_path.h"

#include <cassert>
#include <cmath>

namespace bunraku::analysis {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}

PathBuilder::PathBuilder(int searchBand, Eigen::Index referenceFrames, Eigen::Index sampleFrames, PathMethod method)
    : m_band(searchBand), m_referenceFrames(referenceFrames), m_sampleFrames(sampleFrames), m_method(method),
      m_optimal(method == PathMethod::Optimal)
{
    const bool optimal = m_optimal;
    assert(searchBand >= 0 && searchBand <= 16000);
    const std::size_t width = std::size_t(2 * searchBand + 1);
    if (optimal) {
        m_previous.assign(width, kInfinity);
        m_current.assign(width, kInfinity);
        m_prefixMin.assign(width, kInfinity);
        m_prefixArg.assign(width, std::int16_t(-1));
        m_back.assign(std::size_t(referenceFrames) * width, std::int16_t(-1));
    } else {
        m_greedy = Eigen::VectorXi::Zero(referenceFrames);
    }
}

Eigen::Index PathBuilder::firstUsefulSample() const
{
    const Eigen::Index bandStart = std::max<Eigen::Index>(0, m_row - m_band);
    if (m_method != PathMethod::Greedy || m_row == 0) return bandStart;
    return std::max<Eigen::Index>(bandStart, m_greedy[m_row - 1]);
}

void PathBuilder::addRow(const double* costRow)
{
    assert(m_row < m_referenceFrames);
    const Eigen::Index width = 2 * m_band + 1;
    const Eigen::Index firstSample = m_row - m_band; // sample frame of column 0
    const Eigen::Index lowColumn = std::max<Eigen::Index>(0, -firstSample);
    const Eigen::Index highColumn = std::min<Eigen::Index>(width - 1, m_sampleFrames - 1 - firstSample);

    if (!m_optimal) {
        // Thesis 3.5.3: only sample frames at or after the previous choice; ties to the earliest.
        Eigen::Index from = lowColumn;
        if (m_row > 0 && m_method == PathMethod::Greedy) from = std::max<Eigen::Index>(from, m_greedy[m_row - 1] - firstSample);
        Eigen::Index best = -1;
        double bestCost = kInfinity;
        for (Eigen::Index j = from; j <= highColumn; ++j) {
            if (best < 0 || costRow[j] < bestCost) {
                best = j;
                bestCost = costRow[j];
            }
        }
        assert(best >= 0);
        m_greedy[m_row] = int(firstSample + best);
        m_greedyCost += bestCost;
        ++m_row;
        return;
    }

    // D(t, u) = cost(t, u) + min_{u' <= u} D(t - 1, u'); the previous row's column j' holds
    // sample frame firstSample - 1 + j', so u' <= u means j' <= j + 1.
    std::int16_t* back = m_back.data() + std::size_t(m_row) * std::size_t(width);
    std::fill(m_current.begin(), m_current.end(), kInfinity);
    if (m_row == 0) {
        for (Eigen::Index j = lowColumn; j <= highColumn; ++j) m_current[std::size_t(j)] = costRow[j];
    } else {
        // Prefix minimum of the previous row (first minimum on ties), then one pass.
        double runningMin = kInfinity;
        Eigen::Index runningArg = -1;
        for (Eigen::Index k = 0; k < width; ++k) {
            if (m_previous[std::size_t(k)] < runningMin) {
                runningMin = m_previous[std::size_t(k)];
                runningArg = k;
            }
            m_prefixMin[std::size_t(k)] = runningMin;
            m_prefixArg[std::size_t(k)] = std::int16_t(runningArg);
        }
        for (Eigen::Index j = lowColumn; j <= highColumn; ++j) {
            const std::size_t k = std::size_t(std::min<Eigen::Index>(j + 1, width - 1));
            m_current[std::size_t(j)] = costRow[j] + m_prefixMin[k];
            back[j] = m_prefixArg[k];
        }
    }
    std::swap(m_previous, m_current);
    ++m_row;
}

Eigen::VectorXi PathBuilder::finish(double* totalCost)
{
    assert(m_row == m_referenceFrames);
    if (!m_optimal) {
        if (totalCost) *totalCost = m_greedyCost;
        return m_greedy;
    }
    const Eigen::Index width = 2 * m_band + 1;
    Eigen::Index best = -1;
    double bestCost = kInfinity;
    for (Eigen::Index j = 0; j < width; ++j) {
        if (m_previous[std::size_t(j)] < bestCost) {
            bestCost = m_previous[std::size_t(j)];
            best = j;
        }
    }
    Eigen::VectorXi path(m_referenceFrames);
    for (Eigen::Index t = m_referenceFrames - 1; t >= 0; --t) {
        assert(best >= 0);
        path[t] = int(t - m_band + best);
        best = m_back[std::size_t(t) * std::size_t(width) + std::size_t(best)];
    }
    if (totalCost) *totalCost = bestCost;
    return path;
}

namespace {

Eigen::VectorXi runPath(const BandCost& band, PathMethod method)
{
    PathBuilder builder(band.searchBand, band.cost.rows(), band.sampleFrames, method);
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = band.cost;
    for (Eigen::Index t = 0; t < rows.rows(); ++t) builder.addRow(rows.row(t).data());
    return builder.finish();
}

} // namespace

Eigen::VectorXi greedyPath(const BandCost& band) { return runPath(band, PathMethod::Greedy); }
Eigen::VectorXi optimalPath(const BandCost& band) { return runPath(band, PathMethod::Optimal); }

double pathCost(const BandCost& band, const Eigen::VectorXi& path)
{
    if (path.size() != band.cost.rows()) return kInfinity;
    double sum = 0.0;
    for (Eigen::Index t = 0; t < path.size(); ++t) {
        const Eigen::Index column = path[t] - t + band.searchBand;
        if (path[t] < 0 || path[t] >= band.sampleFrames || column < 0 || column >= band.cost.cols()) return kInfinity;
        if (t > 0 && path[t] < path[t - 1]) return kInfinity;
        sum += band.cost(t, column);
    }
    return sum;
}

Eigen::VectorXd smoothWarp(const Eigen::VectorXi& correspondence)
{
    const Eigen::Index n = correspondence.size();
    Eigen::VectorXd warp(n);
    if (n == 0) return warp;
    // Centres of the runs of equal sample frames.
    std::vector<double> centre;
    std::vector<double> value;
    for (Eigen::Index start = 0; start < n;) {
        Eigen::Index end = start;
        while (end + 1 < n && correspondence[end + 1] == correspondence[start]) ++end;
        centre.push_back(0.5 * double(start + end));
        value.push_back(double(correspondence[start]));
        start = end + 1;
    }
    std::size_t k = 0;
    for (Eigen::Index t = 0; t < n; ++t) {
        const double x = double(t);
        while (k + 1 < centre.size() && centre[k + 1] <= x) ++k;
        if (x <= centre.front()) {
            warp[t] = value.front();
        } else if (k + 1 >= centre.size()) {
            warp[t] = value.back();
        } else {
            const double f = (x - centre[k]) / (centre[k + 1] - centre[k]);
            warp[t] = value[k] + f * (value[k + 1] - value[k]);
        }
    }
    return warp;
}

} // namespace bunraku::analysis
