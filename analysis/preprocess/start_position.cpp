#include "analysis/preprocess/start_position.h"

#include "analysis/core/puppet_layout.h"

#include <algorithm>
#include <optional>
#include <string>

namespace bunraku::analysis::preprocess {

const char* positionAlignmentName(PositionAlignment mode)
{
    return mode == PositionAlignment::PerPart ? "per-part" : "rigid";
}

bool parsePositionAlignment(const std::string& text, PositionAlignment& mode)
{
    if (text == "rigid") mode = PositionAlignment::Rigid;
    else if (text == "per-part") mode = PositionAlignment::PerPart;
    else return false;
    return true;
}

std::vector<Eigen::Vector3d> alignStartPosition(Take& take, const Take& reference, PositionAlignment mode)
{
    const auto parts = sixDofParts(take);
    std::vector<Eigen::Vector3d> offsets(parts.size(), Eigen::Vector3d::Zero());
    if (take.frameCount() == 0 || reference.frameCount() == 0) return offsets;
    // Per part: the reference's start minus the take's, where the reference has the part.
    std::vector<std::optional<Eigen::Vector3d>> differences(parts.size());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int matched = 0;
    const auto referenceParts = sixDofParts(reference);
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const auto r = std::find_if(referenceParts.begin(), referenceParts.end(),
                                    [&](const SixDofPart& part) { return part.part == parts[p].part; });
        if (r == referenceParts.end()) continue;
        const Eigen::Vector3d own = take.values.row(0).segment(parts[p].firstChannel, 3).transpose();
        const Eigen::Vector3d target = reference.values.row(0).segment(r->firstChannel, 3).transpose();
        differences[p] = target - own;
        sum += *differences[p];
        ++matched;
    }
    if (matched == 0) return offsets;
    const Eigen::Vector3d rigid = sum / double(matched);
    for (std::size_t p = 0; p < parts.size(); ++p) {
        if (mode == PositionAlignment::PerPart && !differences[p]) continue;
        offsets[p] = mode == PositionAlignment::Rigid ? rigid : *differences[p];
        take.values.middleCols(parts[p].firstChannel, 3).rowwise() += offsets[p].transpose();
    }
    // Points (the kimono's measured points) move with the body: the rigid offset; per part, their
    // own start difference where the reference has the point.
    const auto referencePoints = pointParts(reference);
    for (const SixDofPart& point : pointParts(take)) {
        Eigen::Vector3d offset = rigid;
        if (mode == PositionAlignment::PerPart) {
            const auto r = std::find_if(referencePoints.begin(), referencePoints.end(),
                                        [&](const SixDofPart& part) { return part.part == point.part; });
            if (r != referencePoints.end())
                offset = reference.values.row(0).segment(r->firstChannel, 3).transpose() -
                         take.values.row(0).segment(point.firstChannel, 3).transpose();
        }
        take.values.middleCols(point.firstChannel, 3).rowwise() += offset.transpose();
    }
    return offsets;
}

} // namespace bunraku::analysis::preprocess
