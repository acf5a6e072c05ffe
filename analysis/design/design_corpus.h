#pragma once
/// The design experiment's cells on the synthetic corpus (thesis 5.5 with the means of 3.7):
/// the functional mean (the function's neutral takes) and the emotional mean (the cell's takes)
/// are either measured - the corpus preprocessed as thesis 2.2 and each cell's takes averaged by
/// the thesis 3.7 average take - or the ground truth's noiseless cell motions. For measured
/// means the ground truth also gives, per frame of each average take, the cell time it shows,
/// from which the true emotional -> functional correspondence of the two means follows.
/// How the average take's time base is mapped to cell time: docs/MOTION-AXIS.md.

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/design/design_experiment.h"
#include "analysis/normalise/average_take.h"
#include "analysis/preprocess/preprocess.h"
#include "analysis/synth/demo_corpus.h"

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace bunraku::analysis {

/// The thesis's settings for the average take (3.7 with 3.9's best): method2 coupling
/// (eq. 3.29), scales 1..16, tau = 4, T_cmp = 20, the optimal (least total cost) path.
AverageOptions designAverageOptions();

enum class DesignMeans {
    Measured, ///< preprocessed takes, averaged by averageTake (the thesis's pipeline)
    Truth,    ///< the ground truth's noiseless cell motions
};

struct DesignCorpusOptions {
    DesignMeans means = DesignMeans::Measured;
    preprocess::PreprocessOptions preprocess;
    AverageOptions average = designAverageOptions();
};

/// One mean (functional or emotional) and what the ground truth says about it.
struct DesignMean {
    Take take;                ///< the average take (frames x 24), or the truth cell motion
    /// Per frame of `take`: the cell time u (fractional frames of the cell's noiseless motion)
    /// it shows, by the ground truth (averageTakeCellTime); the identity for truth means.
    Eigen::VectorXd cellTime;
    /// eq. 5.18 form over the 24 channels of take vs the truth cell motion at cellTime, each
    /// channel's constant offset removed (the takes' position and heading offsets; the truth
    /// taken about its mean). 0 for truth means. A large value points at the averaging.
    double truthShapeError = std::numeric_limits<double>::quiet_NaN();
};

struct SyntheticDesignCell {
    DesignCell cell; ///< functional/emotional takes and trueEmotionalToFunctional
    DesignMean functionalMean;
    DesignMean emotionalMean;
};

/// Every function x emotion cell of the ground truth (neutral cells included) as a design cell.
/// `corpus` is the raw synthetic corpus (it is preprocessed here for measured means; unused for
/// truth means). NotFound when the corpus lacks a cell's takes or the truth a take;
/// errors of preprocessing and averaging pass through; Cancelled via control.
Result<std::vector<SyntheticDesignCell>> syntheticDesignCells(const Corpus& corpus, const synth::DemoGroundTruth& truth,
                                                              const DesignCorpusOptions& options = {},
                                                              const RunControl& control = {});

/// Cell time of each frame of an average take (thesis 3.7) from the members' cell times
/// (memberCellTime[k](t): the cell time that member k shows at its frame t, non-decreasing).
/// With ideal matching, member k's frame t_k(t_b) shows the base's cell time u_b(t_b); the
/// average places that moment at t_bar = mean_k t_k over the base and the included members, so
/// the average shows u_b(t_b) at t_bar(t_b): the curve (t_bar, u_b) is linearly interpolated
/// at t = 0..frames-1 (clamped), exactly as averageTake resamples a channel.
Eigen::VectorXd averageTakeCellTime(const std::vector<Eigen::VectorXd>& memberCellTime, const AverageOptions& options,
                                    Eigen::Index frames);

/// Where a non-decreasing sampled map f (frame -> value) first reaches `value`, linearly
/// interpolated between frames; 0 below f(0), the last frame above f(last).
double firstFrameReaching(const Eigen::VectorXd& map, double value);

} // namespace bunraku::analysis
