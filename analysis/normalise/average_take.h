#pragma once
/// The average take of a cell (thesis 3.7): with one take as base, find in every other take the
/// frame corresponding to each base frame, average times and values, and resample the averaged
/// curve onto the base's frames. Used as a better reference ("5ave": all takes; "4ave": without
/// the outlier).

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/take.h"
#include "analysis/normalise/take_normalisation.h"

#include <vector>

namespace bunraku::analysis {

struct AverageOptions {
    int baseTake = 0;               ///< index into the takes (thesis: k = 1)
    std::vector<int> excludedTakes; ///< indices left out of the average (never the base)
    NormaliseOptions normalise;     ///< how takes are matched to the base
};

/// For each channel: t_bar(t_b) = mean_k t_k(t_b), x_bar(t_b) = mean_k x_k(t_k(t_b)) over the base
/// and the included takes; the curve (t_bar, x_bar) linearly interpolated at t = 0..T_base
/// (clamped at the ends). Angle channels are averaged as rotation coordinates about the base's
/// mean part orientations and written back Euler-filtered. When every member carries a
/// skeleton on the same joints, the average carries one too: per base frame each joint's mean
/// rotation (and mean root position) of the members at their body times
/// (TakeNormalisation::bodyTime), shown at the mean body time and resampled onto the base's
/// frames. Labels: the base's function/emotion, take index 0, source "average of takes ...".
/// InvalidArgument for a bad base or excluded index.
Result<Take> averageTake(const std::vector<const Take*>& takes, const AverageOptions& options = {},
                         const RunControl& control = {});

/// The same average from matchings already made: `toBase[k]` is takes[k] normalised to the base
/// take with options.normalise (normaliseTakes(*takes[options.baseTake], takes, options.normalise),
/// entries of the base and the excluded takes unused). A cell normalised to the base anyway (thesis
/// 3.6.1's suggested reference is the base of its 3.7 average) is not matched a second time.
/// Bit for bit averageTake(takes, options). InvalidArgument as averageTake, and when toBase does
/// not hold one normalisation per take on the base's frames.
Result<Take> averageTakeFrom(const std::vector<const Take*>& takes, const AverageOptions& options,
                             const std::vector<TakeNormalisation>& toBase);

} // namespace bunraku::analysis
