#pragma once
/// Start-position alignment, thesis 2.2 step (4): "with the transmitter (the origin of the
/// coordinate system) as the centre, the start positions of the other motions were brought to
/// the reference's". The recorded puppet moves as one body: by default every take gets one rigid
/// translation, so the geometry between its parts (arm to hand, shoulder to head) is kept.

#include "analysis/core/take.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis::preprocess {

enum class PositionAlignment {
    /// One translation per take (default, the thesis's reading): the mean over the parts present
    /// in both takes of (reference start - take start), i.e. the take's start centroid moved onto
    /// the reference's (the least-squares translation). Inter-part vectors are unchanged.
    Rigid,
    /// Each 6-DOF part moved by its own offset so that every part starts exactly where the
    /// reference's does (the workbench's earlier behaviour): changes the geometry between parts.
    PerPart,
};

/// "rigid" / "per-part".
const char* positionAlignmentName(PositionAlignment mode);
/// Parses positionAlignmentName's text; false when unknown.
bool parsePositionAlignment(const std::string& text, PositionAlignment& mode);

/// Translates `take` so that its start position matches `reference`'s (parts matched by name;
/// parts the reference lacks move with the rest under Rigid and stay put under PerPart). Returns
/// the offset (cm) added to each 6-DOF part of `take`, in sixDofParts(take) order.
std::vector<Eigen::Vector3d> alignStartPosition(Take& take, const Take& reference, PositionAlignment mode);

} // namespace bunraku::analysis::preprocess
