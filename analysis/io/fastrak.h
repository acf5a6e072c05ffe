#pragma once
/// Polhemus FASTRAK ASCII records (station, x y z, azimuth elevation roll) to a 24-channel puppet
/// take. The supported variant and the z-down to z-up conversion are in docs/FORMATS.md.

#include "analysis/core/pose.h"
#include "analysis/core/take.h"

#include <array>
#include <filesystem>
#include <string>

namespace bunraku::analysis::io {

enum class FastrakUnits { Inches, Centimetres };

struct FastrakOptions {
    double rateHz = 5.0;               ///< thesis setup: 0.2 s per frame with 4 receivers
    FastrakUnits units = FastrakUnits::Centimetres;
    /// Station number (1-based) of head, shoulder, arm, hand.
    std::array<int, 4> stations{1, 2, 3, 4};
    TakeLabels labels;
};

/// FASTRAK frame (x forward, y right, z down) to workbench (x forward, y left, z up): a rotation
/// of 180 deg about x, C = diag(1, -1, -1). Positions p' = C p; orientations R' = C R C^T, which
/// in Z-Y'-X'' angles is (azimuth, elevation, roll) -> (-azimuth, -elevation, roll).
RigidTransform fastrakToWorkbench(const Eigen::Vector3d& positionCm, double azimuthDeg, double elevationDeg,
                                  double rollDeg);

Result<Take> parseFastrak(const std::string& text, const std::string& sourceName, const FastrakOptions& options = {});
Result<Take> readFastrak(const std::filesystem::path& file, const FastrakOptions& options = {});

} // namespace bunraku::analysis::io
