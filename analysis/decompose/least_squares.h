#pragma once
/// Function / emotion / fluctuation decomposition of a corpus by least squares (thesis 4.3.1,
/// eqs. 4.1-4.8): x_k^{ij}(t) = y^i(t) + z^{ij}(t) + eta_k^{ij}(t) with z^{i,neutral} = 0, so
/// y^i = mean_k x_k^{i,neutral}, z^{ij} = mean_k x_k^{ij} - y^i, eta = x - y - z; per channel.
/// The neutral emotion is Corpus::neutralEmotion (labels are data).
/// Orientations are decomposed on rotations (linear_corpus.h): the angle columns of every
/// component are rotation coordinates (degrees) about the function's per-frame mean part
/// orientation (Decomposition::charts), and a corpus whose takes all carry compatible skeletons
/// is decomposed joint by joint too (Decomposition::skeleton). emotion_weight.h turns
/// components back into takes with Euler angles and the full skeleton.

#include "analysis/core/angle_channels.h"
#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/decompose/linear_corpus.h"
#include "analysis/skeleton/skeleton_blend.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace bunraku::analysis {

/// y^i: one per function.
struct FunctionComponent {
    std::string function;
    Eigen::MatrixXd values; ///< frames x channels
};

/// z^{ij}: one per function x emotion cell (zero for the neutral emotion).
struct EmotionComponent {
    std::string function;
    std::string emotion;
    Eigen::MatrixXd values; ///< frames x channels
};

/// eta_k^{ij}: one per take, in corpus order.
struct FluctuationComponent {
    TakeLabels labels;
    Eigen::MatrixXd values; ///< frames x channels
};

/// The components of the takes' full skeletons: frames x skeleton coordinates
/// (skeleton_blend.h) about each function's chart.
struct SkeletalComponents {
    std::vector<SkeletonChart> charts;      ///< per function (Decomposition::functions order)
    std::vector<Eigen::MatrixXd> functions; ///< y^i per function
    std::vector<Eigen::MatrixXd> emotions;  ///< z^{ij} per cell (Decomposition::emotions order)
};

/// The components of a corpus; every matrix is frames x channels with the corpus's layout, the
/// angle columns of 6-DOF parts in rotation coordinates about the function's chart.
struct Decomposition {
    double rateHz = 5.0;
    std::vector<Channel> channels;
    std::string neutralEmotion;
    std::vector<FunctionComponent> functions;     ///< in Corpus::functions() order
    std::vector<EmotionComponent> emotions;       ///< function-major, Corpus::emotions() order, cells with takes only
    std::vector<FluctuationComponent> fluctuations;
    /// Mean of the takes of each cell, same order as `emotions` (x_mean^{ij}, eq. 4.22).
    std::vector<Eigen::MatrixXd> cellMeans;
    /// Per function: the per-frame mean orientation of each 6-DOF part over the function's
    /// takes, the chart of the components' angle columns (an empty chart without parts).
    std::vector<RotationChart> charts;
    /// Per function: Euler angles (a row of channels) whose branch written-back takes start on.
    std::vector<Eigen::RowVectorXd> angleBranches;
    /// The skeletons' components; empty unless every take carries a compatible skeleton.
    std::optional<SkeletalComponents> skeleton;

    const FunctionComponent* function(const std::string& name) const;
    const EmotionComponent* emotion(const std::string& function, const std::string& emotion) const;
    /// Index into `emotions`/`cellMeans`, -1 when absent.
    int cellIndex(const std::string& function, const std::string& emotion) const;
    Eigen::Index frameCount() const { return functions.empty() ? 0 : functions.front().values.rows(); }
};

/// The number of takes (fluctuations) of a cell of `decomposition`, 0 when absent.
int cellTakeCount(const Decomposition& decomposition, const std::string& function, const std::string& emotion);

/// The shared checks of every decomposition: a valid corpus, all takes with the same frame
/// count (pad or normalise first), and a neutral-emotion cell for every function.
Status checkDecomposable(const Corpus& corpus);

/// Least-squares decomposition (eqs. 4.4-4.8).
Result<Decomposition> decomposeLeastSquares(const Corpus& corpus);

/// Least squares on a corpus already in linear coordinates (lineariseCorpus of a corpus that
/// satisfies checkDecomposable): charts and skeletal components come from `linear`.
Decomposition decomposeLinear(const LinearCorpus& linear);

} // namespace bunraku::analysis
