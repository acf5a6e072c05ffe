#pragma once
/// Emotional motion design by an emotion weight (thesis 4.5, eq. 4.45):
/// x^{ij}(t) = y^i(t) + a z^{ij}(t); a > 1 emphasises the emotion, 0 <= a < 1 damps it,
/// a = 1 gives the cell mean (least squares) and a = 0 the function component alone.

#include "analysis/core/result.h"
#include "analysis/core/take.h"
#include "analysis/decompose/least_squares.h"

#include <string>

namespace bunraku::analysis {

inline constexpr double kMinEmotionWeight = 0.0;
inline constexpr double kMaxEmotionWeight = 3.0;

/// A take with y^i + a z^{ij} for every channel, labelled function/emotion, take index 0 and
/// source "emotion weight a = ...". The sum is taken in the decomposition's coordinates
/// (rotation coordinates for angles) and written back as Euler angles, filtered and starting on
/// the function's branch (Decomposition::angleBranches); with skeletal components the take
/// carries the full skeleton y + a z joint by joint (each joint's rotation base * exp(y + a z)).
/// Errors: unknown function or cell (the message lists what exists), a outside [0, 3] or not
/// finite.
Result<Take> weightEmotion(const Decomposition& decomposition, const std::string& function, const std::string& emotion,
                           double weight);

/// The function component y^i as a take (Euler angles, the skeleton when decomposed), labelled
/// function/neutral emotion, take index 0, source "function component". NotFound for an
/// unknown function.
Result<Take> functionComponentTake(const Decomposition& decomposition, const std::string& function);

/// The allocation-free path for a live slider: writes y + a z into `out` (resized once to
/// frames x channels) in the decomposition's coordinates (angles as rotation coordinates:
/// eulerFromRotationCoordinates with the function's chart turns them into angles). `cell`
/// indexes Decomposition::emotions, `function` ::functions; the caller checked both and the
/// weight range (asserted).
void weightEmotionInto(const Decomposition& decomposition, int function, int cell, double weight, Eigen::MatrixXd& out);

} // namespace bunraku::analysis
