#include "analysis/normalise/correspondence_path.h"

#include "analysis/normalise/distance_kernel.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <new>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace bunraku::analysis {

namespace detail {

void FreeWords::operator()(std::uint64_t* words) const { std::free(words); }

WordBuffer allocateWords(std::size_t count)
{
    constexpr std::size_t kHugePage = std::size_t(2) << 20;
    const std::size_t bytes = std::max<std::size_t>(count, 1) * sizeof(std::uint64_t);
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* memory = bytes < kHugePage ? std::malloc(bytes) : std::aligned_alloc(kHugePage, rounded);
    if (!memory) throw std::bad_alloc();
#ifdef __linux__
    if (bytes >= kHugePage) madvise(memory, rounded, MADV_HUGEPAGE);
#endif
    return WordBuffer(static_cast<std::uint64_t*>(memory));
}

} // namespace detail

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}

PathBuilder::PathBuilder(int searchBand, Eigen::Index referenceFrames, Eigen::Index sampleFrames, PathMethod method)
    : m_band(searchBand), m_referenceFrames(referenceFrames), m_sampleFrames(sampleFrames), m_method(method),
      m_optimal(method == PathMethod::Optimal)
{
    const bool optimal = m_optimal;
    assert(searchBand >= 0 && searchBand <= kMaxSearchBand);
    const std::size_t width = std::size_t(2 * searchBand + 1);
    if (optimal) {
        m_segment = detail::dpSegment(width);
        m_previous.assign(detail::kDpLanes * m_segment, kInfinity);
        m_current.assign(detail::kDpLanes * m_segment, kInfinity);
        m_segmentPrefix.assign(detail::kDpLanes * m_segment, kInfinity);
        m_nextSegmentPrefix.assign(detail::kDpLanes * m_segment, kInfinity);
        m_costs.assign(detail::kDpLanes * m_segment, kInfinity);
        m_words = detail::dpWords(m_segment);
        m_drops = detail::allocateWords(std::size_t(referenceFrames) * m_words);
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
    // sample frame firstSample - 1 + j', so u' <= u means j' <= j + 1. The previous row's prefix
    // minimum drops (first minimum on ties) are kept as bits for the back-pointers.
    std::copy_n(costRow, width, m_costs.begin());
    addOptimalRow({m_costs.data(), nullptr, nullptr}, lowColumn, highColumn);
}

void PathBuilder::addOptimalRow(const detail::DpCost& cost, Eigen::Index lowColumn, Eigen::Index highColumn)
{
    const auto width = std::size_t(2 * m_band + 1);
    if (m_row == 0)
        detail::dpFirstRow(cost, width, std::size_t(lowColumn), std::size_t(highColumn), m_current.data(), m_nextSegmentPrefix.data());
    else
        detail::dpRow(m_segmentPrefix.data(), cost, width, std::size_t(lowColumn), std::size_t(highColumn),
                      m_drops.get() + std::size_t(m_row - 1) * m_words,
                      m_row + 1 == m_referenceFrames ? m_current.data() : nullptr, m_nextSegmentPrefix.data());
    std::swap(m_previous, m_current);
    std::swap(m_segmentPrefix, m_nextSegmentPrefix);
    ++m_row;
}

Eigen::Index PathBuilder::slidingRowLength(int searchBand) { return Eigen::Index(detail::kDpLanes * detail::dpSegment(std::size_t(2 * searchBand + 1))); }

void PathBuilder::addRow(double* running, const double* entering, const double* leaving)
{
    const Eigen::Index width = 2 * m_band + 1;
    if (!m_optimal) {
        detail::windowSlide(running, entering, leaving, std::size_t(width));
        addRow(running);
        return;
    }
    assert(m_row < m_referenceFrames);
    const Eigen::Index firstSample = m_row - m_band;
    const Eigen::Index lowColumn = std::max<Eigen::Index>(0, -firstSample);
    const Eigen::Index highColumn = std::min<Eigen::Index>(width - 1, m_sampleFrames - 1 - firstSample);
    addOptimalRow({running, entering, leaving}, lowColumn, highColumn);
}

Eigen::VectorXi PathBuilder::finish(double* totalCost)
{
    assert(m_row == m_referenceFrames);
    if (!m_optimal) {
        if (totalCost) *totalCost = m_greedyCost;
        return m_greedy;
    }
    const Eigen::Index width = 2 * m_band + 1;
    const std::size_t last = std::size_t(m_referenceFrames - 1) * m_words;
    detail::dpDropBits(m_segmentPrefix.data(), std::size_t(width), m_drops.get() + last);
    Eigen::Index best = detail::lastDropAtOrBelow(m_drops.get() + last, std::size_t(width - 1), m_segment);
    const double bestCost = best >= 0 ? m_previous[detail::dpEntry(std::size_t(best), m_segment)] : kInfinity;
    Eigen::VectorXi path(m_referenceFrames);
    for (Eigen::Index t = m_referenceFrames - 1; t >= 0; --t) {
        assert(best >= 0);
        path[t] = int(t - m_band + best);
        if (t > 0)
            best = detail::lastDropAtOrBelow(m_drops.get() + std::size_t(t - 1) * m_words,
                                             std::size_t(std::min<Eigen::Index>(best + 1, width - 1)), m_segment);
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
