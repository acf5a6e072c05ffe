#pragma once
/// Dual quaternion skinning (Kavan et al. 2007): a rigid transform as a unit dual quaternion,
/// blended linearly and renormalised, so a vertex between two joints turning 180 degrees apart
/// about a bone (a twisted wrist) keeps its distance from the bone instead of collapsing onto it
/// as linear blending of matrices does. The GPU does the same in resources/shaders/skinned.vert.

#include "analysis/core/pose.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace bunraku::analysis {

struct DualQuaternion {
    Eigen::Vector4d real{0.0, 0.0, 0.0, 1.0}; ///< rotation quaternion (x, y, z, w)
    Eigen::Vector4d dual{0.0, 0.0, 0.0, 0.0}; ///< 0.5 * translation * real (x, y, z, w)

    static DualQuaternion fromRigid(const RigidTransform& a_T_b);
    /// The rigid transform of a (renormalised) dual quaternion.
    RigidTransform toRigid() const;
};

/// sum_i w_i q_i with every q_i's sign chosen to lie on the first's hemisphere, normalised.
DualQuaternion blendDualQuaternions(const DualQuaternion* q, const double* weights, int count);

} // namespace bunraku::analysis
