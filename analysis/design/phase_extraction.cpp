#include "analysis/design/phase_extraction.h"

#include <algorithm>
#include <cmath>

namespace bunraku::analysis {

Eigen::VectorXd invertMonotone(const Eigen::VectorXd& map, Eigen::Index targetFrames)
{
    Eigen::VectorXd inverse(std::max<Eigen::Index>(targetFrames, 0));
    const Eigen::Index n = map.size();
    if (n == 0) return Eigen::VectorXd::Zero(inverse.size());
    for (Eigen::Index v = 0; v < inverse.size(); ++v) {
        const double value = double(v);
        if (value <= map[0]) {
            inverse[v] = 0.0;
            continue;
        }
        if (value >= map[n - 1]) {
            // the first frame reaching the last value
            Eigen::Index s = n - 1;
            while (s > 0 && map[s - 1] >= map[n - 1]) --s;
            inverse[v] = double(s);
            continue;
        }
        const double* begin = map.data();
        const Eigen::Index hi = Eigen::Index(std::lower_bound(begin, begin + n, value) - begin); // map[hi] >= value
        const Eigen::Index lo = hi - 1;                                                          // map[lo] < value
        const double span = map[hi] - map[lo];
        inverse[v] = double(lo) + (span > 0 ? (value - map[lo]) / span : 0.0);
    }
    for (Eigen::Index v = 1; v < inverse.size(); ++v) inverse[v] = std::max(inverse[v], inverse[v - 1]);
    return inverse;
}

Eigen::MatrixXd resampleRows(const Eigen::MatrixXd& signal, const Eigen::VectorXd& at)
{
    Eigen::MatrixXd result(at.size(), signal.cols());
    const Eigen::Index last = signal.rows() - 1;
    for (Eigen::Index i = 0; i < at.size(); ++i) {
        const double t = std::clamp(at[i], 0.0, double(std::max<Eigen::Index>(last, 0)));
        const Eigen::Index k = std::min<Eigen::Index>(Eigen::Index(std::floor(t)), std::max<Eigen::Index>(last - 1, 0));
        const double w = last > 0 ? t - double(k) : 0.0;
        result.row(i) = (1.0 - w) * signal.row(k) + w * signal.row(std::min(k + 1, last));
    }
    return result;
}

Result<PhaseResult> extractPhase(const Eigen::MatrixXd& functional, const Eigen::MatrixXd& emotional,
                                 const PhaseOptions& options, const RunControl& control)
{
    Result<MatchResult> match = matchChannels(functional, emotional, options.match, control);
    if (!match) return match.error();
    PhaseResult phase;
    phase.correspondence = match->correspondence;
    phase.functionalToEmotional = match->smoothWarp;
    phase.cost = match->cost;
    phase.emotionalToFunctional = invertMonotone(phase.functionalToEmotional, emotional.rows());
    phase.curve = warpCurveFromSamples(phase.emotionalToFunctional, options.controlPointSpacing);
    return phase;
}

} // namespace bunraku::analysis
