#pragma once
/// The linear space of the decomposition (thesis 4.3: x = y + z + eta per channel): positions
/// as they are, every 6-DOF part's orientation as rotation coordinates about its function's
/// per-frame mean orientation (analysis/core/angle_channels.h), and each take's full skeleton
/// (when every take carries a compatible one) as skeleton coordinates about the function's
/// per-frame mean joint rotations (analysis/skeleton/skeleton_blend.h). Means, differences and
/// weighted sums taken there come back as rotations for every part and joint, whatever Euler
/// branch or gimbal region the takes were written in.

#include "analysis/core/angle_channels.h"
#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/skeleton/skeleton_blend.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis {

struct LinearCorpus {
    /// The same takes and labels with values in rotation coordinates (and no skeletons).
    Corpus corpus;
    std::vector<std::string> functions;       ///< Corpus::functions() order
    std::vector<RotationChart> charts;        ///< per function: per-frame mean part orientations
    /// Per function: the first frame of its first neutral take (Euler angles), the branch the
    /// components' angles are written back on.
    std::vector<Eigen::RowVectorXd> angleBranches;
    /// Per take (corpus order): frames x skeleton coordinates; empty when the takes do not all
    /// carry compatible skeletons (the decomposition then has no skeletal components).
    std::vector<Eigen::MatrixXd> skeletonCoordinates;
    std::vector<SkeletonChart> skeletonCharts; ///< per function, when skeletonCoordinates is not empty
};

/// The corpus in linear coordinates. The corpus must satisfy checkDecomposable (equal lengths).
LinearCorpus lineariseCorpus(const Corpus& corpus);

/// Index of a function in LinearCorpus::functions, -1 when absent.
int functionIndex(const LinearCorpus& linear, const std::string& function);

} // namespace bunraku::analysis
