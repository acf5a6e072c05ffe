#pragma once
/// The matching engine shared by the wavelet matcher and the amplitude baseline: per-frame
/// feature vectors of a reference and a sample, a window cost
/// cost(t_ref, t_smp) = sum_{s=-tau..tau} |f_ref(t_ref + s) - f_smp(t_smp + s)|^2 (thesis 3.5.2)
/// in the band |t_smp - t_ref| <= T_cmp, and a greedy or optimal non-decreasing path.
/// Each per-frame distance is computed once (on the band's diagonals) and the band is streamed
/// in tiles of reference frames: memory is O(frames x features) for feature-major copies,
/// O(frames x band) bits for the optimal path's back-pointers and O(tile x band) for the costs.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/normalise/wavelet_matching.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

/// frames x features, one row per frame (row-major so a frame's features are contiguous).
using FeatureMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
/// frames x features, column-major so each feature's series is contiguous (what the wavelet
/// transform writes, and what the optimal path reads a coupling set at a time).
using FeatureSeries = Eigen::MatrixXd;

struct FeatureMatchOptions {
    int tau = 4;
    int searchBand = 20;
    PathMethod path = PathMethod::Greedy;
};

/// Window indices beyond either end replicate the edge frame (the thesis leaves the ends
/// open; replicating keeps every window full without inventing motion). InvalidArgument for
/// tau < 0, searchBand outside 0..kMaxSearchBand, empty or mismatched features, a reference longer than
/// the sample plus the band (no admissible path); Cancelled via control.
Result<MatchResult> matchFeatures(const FeatureMatrix& reference, const FeatureMatrix& sample,
                                  const FeatureMatchOptions& options, const RunControl& control = {});
Result<MatchResult> matchFeatures(const FeatureSeries& reference, const FeatureSeries& sample,
                                  const FeatureMatchOptions& options, const RunControl& control = {});

/// 0 .. count - 1.
std::vector<Eigen::Index> allColumns(Eigen::Index count);

/// The same on the listed feature columns only (in that order), e.g. one coupling set's
/// columns of every channel's features, in either layout: the optimal path reads them in
/// place, the streamed paths copy them. InvalidArgument also for an empty list or a column out
/// of range.
Result<MatchResult> matchFeatures(const FeatureMatrix& reference, const FeatureMatrix& sample,
                                  const std::vector<Eigen::Index>& columns, const FeatureMatchOptions& options,
                                  const RunControl& control = {});
Result<MatchResult> matchFeatures(const FeatureSeries& reference, const FeatureSeries& sample,
                                  const std::vector<Eigen::Index>& columns, const FeatureMatchOptions& options,
                                  const RunControl& control = {});

} // namespace bunraku::analysis
