#pragma once
/// Correspondence paths through a banded cost: for every reference frame t_ref one sample frame
/// t_smp in t_ref +- T_cmp, never running backwards (thesis 3.5.3). Greedy is the thesis's scan;
/// Optimal is dynamic programming over the same band and constraint.

#include "analysis/core/result.h"
#include "analysis/normalise/wavelet_matching.h"

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace bunraku::analysis {

namespace detail {
struct DpCost;

struct FreeWords {
    void operator()(std::uint64_t* words) const;
};
/// Uninitialised words; large buffers on transparent huge pages where the system offers them
/// (one page fault per 2 MB instead of per 4 kB).
using WordBuffer = std::unique_ptr<std::uint64_t[], FreeWords>;
WordBuffer allocateWords(std::size_t count);
}

/// Window costs in the band: row t_ref, column j <-> sample frame t_ref - searchBand + j.
/// Cells whose sample frame lies outside 0..sampleFrames-1 are ignored.
struct BandCost {
    Eigen::MatrixXd cost; ///< reference frames x (2 * searchBand + 1)
    int searchBand = 20;
    Eigen::Index sampleFrames = 0;
};

/// Feeds band rows one at a time (so long takes never hold the whole band) and keeps what the
/// chosen PathMethod needs: the choices so far (greedy, independent) or, for optimal, one bit
/// per band cell - where each row's prefix minimum drops, which is enough to walk the
/// back-pointers (ceil((2 T_cmp + 1) / 64) x 8 bytes a frame). Rows must have 2 * searchBand + 1
/// entries.
class PathBuilder {
public:
    PathBuilder(int searchBand, Eigen::Index referenceFrames, Eigen::Index sampleFrames, PathMethod method);
    /// The lowest sample frame the next row may choose (greedy: the previous choice) - lets the
    /// caller skip computing costs left of it. Always within the band.
    Eigen::Index firstUsefulSample() const;
    /// Adds row t_ref (= number of rows added so far).
    void addRow(const double* costRow);
    /// Slides window sums one row on, running = (running + entering) - leaving, and adds them as
    /// row t_ref: the same as detail::windowSlide then addRow(running), in one pass for the
    /// optimal path. The three rows hold slidingRowLength(searchBand) entries, those past
    /// 2 searchBand + 1 +infinity in `running` and 0 in the others.
    void addRow(double* running, const double* entering, const double* leaving);
    static Eigen::Index slidingRowLength(int searchBand);
    /// The path and its summed cost; call after every reference frame was added.
    Eigen::VectorXi finish(double* totalCost = nullptr);

private:
    void addOptimalRow(const detail::DpCost& cost, Eigen::Index lowColumn, Eigen::Index highColumn);

    int m_band;
    Eigen::Index m_referenceFrames;
    Eigen::Index m_sampleFrames;
    PathMethod m_method;
    bool m_optimal;
    Eigen::Index m_row = 0;
    // greedy and independent
    Eigen::VectorXi m_greedy;
    double m_greedyCost = 0;
    // optimal: rows interleaved (detail::dpEntry), kDpLanes m_segment entries each
    std::size_t m_segment = 0;
    std::vector<double> m_previous, m_current;             // D of the last row and the next
    std::vector<double> m_segmentPrefix, m_nextSegmentPrefix; // their prefix minima within each segment
    std::vector<double> m_costs;                             // a cost row padded to kDpLanes m_segment entries
    std::size_t m_words = 0;            // 64-bit words of drop bits per row
    detail::WordBuffer m_drops;         // row t: where the prefix minimum of row t drops
};

/// Thesis 3.5.3: for t_ref = 0, 1, ... choose the cheapest t_smp >= the previous choice (ties to
/// the earliest). Reproduces the plateaus-then-jump of Table 3.3.
Eigen::VectorXi greedyPath(const BandCost& band);
/// The non-decreasing path in the band minimising the summed cost (ties to the earliest).
Eigen::VectorXi optimalPath(const BandCost& band);
/// Summed cost of a path through the band (infinity when it leaves the band or the sample).
double pathCost(const BandCost& band, const Eigen::VectorXi& path);

/// A sub-frame monotone warp from an integer correspondence: each plateau (several t_ref on one
/// t_smp) and each jump is spread linearly between the midpoints of consecutive runs, so the
/// warp is non-decreasing and passes through every run's centre. Frames, same length.
Eigen::VectorXd smoothWarp(const Eigen::VectorXi& correspondence);

} // namespace bunraku::analysis
