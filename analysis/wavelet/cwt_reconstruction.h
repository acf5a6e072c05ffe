#pragma once
/// Inverse continuous wavelet transform over a finite set of scales and the "approximation"
/// A(t) it leaves behind (thesis 5.3.2, eqs. 5.13/5.14): the part of x slower than the largest
/// scale, which the wavelet coefficients cannot represent.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/wavelet/cwt.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

/// x reconstructed from its coefficients at the given scales only (thesis eq. 5.13 with the
/// scale integral restricted to the scales, discretised with each scale's share of the scale
/// axis): the band-pass part of x the scales see. signal: samples; result: samples.
Result<Eigen::VectorXd> cwtReconstruction(const Eigen::VectorXd& signal, const std::vector<double>& scales,
                                          const CwtOptions& options = {}, const RunControl& control = {});

/// Each scale's term of cwtReconstruction separately (samples x scales, each scale with its share
/// of the scale axis among `scales`): their row sums are the reconstruction. For the integer
/// scales 1..c every share is 1, so the approximation of scales 1..k (k <= c) is x minus the
/// sum of the first k columns (thesis 5.4.1's per-scale approximations in one transform).
Result<Eigen::MatrixXd> cwtScaleContributions(const Eigen::VectorXd& signal, const std::vector<double>& scales,
                                              const CwtOptions& options = {}, const RunControl& control = {});

/// A(t) = x(t) - cwtReconstruction(x)(t): the approximation below the largest scale.
Result<Eigen::VectorXd> cwtApproximation(const Eigen::VectorXd& signal, const std::vector<double>& scales,
                                         const CwtOptions& options = {}, const RunControl& control = {});

} // namespace bunraku::analysis
