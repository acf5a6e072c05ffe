#include "app/phrase_marks.h"

namespace bunraku::app {

std::vector<double> phraseBoundarySeconds(const analysis::synth::DemoGroundTruth& truth, const analysis::Take& take)
{
    const auto* takeTruth = truth.take(take.labels);
    const auto* cell = truth.cell(take.labels.function, take.labels.emotion);
    if (!takeTruth || !cell || take.rateHz <= 0.0) return {};
    const Eigen::VectorXd& toCell = takeTruth->takeToCell; // non-decreasing, take frame -> cell frame
    std::vector<double> seconds;
    for (std::size_t b = 1; b + 1 < cell->phraseBoundaries.size(); ++b) {
        const double u = cell->phraseBoundaries[b];
        for (Eigen::Index t = 0; t + 1 < toCell.size(); ++t) {
            if (toCell[t] <= u && u <= toCell[t + 1] && toCell[t + 1] > toCell[t]) {
                const double frame = double(t) + (u - toCell[t]) / (toCell[t + 1] - toCell[t]);
                seconds.push_back(frame / take.rateHz);
                break;
            }
        }
    }
    return seconds;
}

} // namespace bunraku::app
