#pragma once
/// A performer's body on the floor: where a derived take (a weighted one, x = y + a z on the
/// body's rotations) would crouch deeper than any of its inputs or push its feet through the
/// floor, the pelvis is held at a given height and the legs bend (two-bone inverse kinematics at
/// hip and knee, each foot keeping its orientation) so that the lowest point of the body is at a
/// given height. Segment lengths stay as they are (only rotations and the roots' translation
/// change). docs/NORMALISATION.md, "On the floor".

#include "analysis/core/skeleton.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace bunraku::analysis {

/// One leg of a skeleton: the joints that turn to place its foot. The knee is the hip's child,
/// the ankle the knee's; the thigh and the shin are the chain's longest pair of consecutive bones.
struct LegJoints {
    int hip = -1;
    int knee = -1;
    int ankle = -1;
};

/// The pelvis (the first joint from the root where the legs branch) and the legs below it, read
/// at the motion's first frame: the pelvis's child chains that reach within 10 % of the body's
/// height from its lowest point. pelvis -1 and no legs for a skeleton of one chain.
struct LegLayout {
    int pelvis = -1;
    std::vector<LegJoints> legs;
};
LegLayout findLegs(const SkeletalMotion& motion);

/// Per frame: the lowest point of the body (every joint and End Site but the roots), cm.
Eigen::VectorXd lowestPoints(const SkeletalMotion& motion);
/// Per frame: the height of `joint`, cm.
Eigen::VectorXd jointHeights(const SkeletalMotion& motion, int joint);

/// `motion` with, per frame f, its roots moved vertically so that the pelvis is at
/// pelvisHeight(f), then its legs bent so that its lowest point is at lowestPoint(f): every foot
/// moves by the same height (a lifted foot stays lifted), and where the lowest foot's leg cannot
/// stretch that far the other feet go on down until one is there; a foot further out than the
/// stretched leg reaches at that height comes in under the hip. Where no leg reaches or the
/// lowest point is not on a leg, the roots move again so that the lowest point is where it
/// should be: no foot below the floor comes first. Without legs,
/// only the vertical move that puts the lowest point at lowestPoint(f). Null when `motion` has no
/// skeleton or the heights do not have one value per frame.
std::shared_ptr<const SkeletalMotion> groundBody(const SkeletalMotion& motion, const Eigen::VectorXd& pelvisHeight,
                                                 const Eigen::VectorXd& lowestPoint);

} // namespace bunraku::analysis
