#pragma once
/// How deep the cloth's free particles lie inside the body's capsules at one frame (the check of
/// the kimono tests: at most 0.5 cm).
#include "analysis/cloth/kimono_cloth.h"

#include <algorithm>
#include <array>
#include <vector>

namespace bunraku::test {

/// cm: the deepest free particle of `x` inside a capsule of `colliders` posed by `holders`
/// (0 when none is inside).
inline double deepestInsideBody(const analysis::KimonoCloth& cloth, const std::vector<Eigen::Vector3d>& x,
                                const std::vector<analysis::ClothCollider>& colliders,
                                const std::array<analysis::RigidTransform, 3>& holders)
{
    double deepest = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (cloth.pinned[i]) continue;
        for (const analysis::ClothCollider& c : colliders) {
            const analysis::RigidTransform& pose = holders[c.holder];
            const Eigen::Vector3d a = pose.apply(c.a), b = pose.apply(c.b);
            const Eigen::Vector3d ab = b - a;
            const double t = std::clamp((x[i] - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            deepest = std::max(deepest, c.radius - (x[i] - (a + t * ab)).norm());
        }
    }
    return deepest;
}

} // namespace bunraku::test
