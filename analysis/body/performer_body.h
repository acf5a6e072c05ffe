#pragma once
/// The performer's body: a smooth, neutral mannequin built on a skeleton's own bone lengths and
/// skinned to its joints, the 3D view's "Body" figure for a take with a skeleton.
///
/// How it is made (all from the skeleton, any family): the body is built in the take's first
/// pose with each arm turned about its upper arm to hang 40 deg below the horizontal, away from
/// the trunk, and each leg about its thigh to point down (no limb touching the trunk: a surface
/// built with an arm against the side would tear when the arm rises; a rest pose with every
/// rotation zero is no pose at all for skeletons whose bones lie along x). Each bone is one
/// segment. The trunk is the chain from the root to the head (the joint bound to the head part,
/// else one named "head", else the highest): from the pelvis (its lowest joint with more than one
/// child; a root on the floor below it carries nothing) up to the branch of the arms its bones are
/// thick (7.5 % of the height), above it the neck is slim (3 %), and the head is a sphere (6.2 %)
/// over its bone. Every other bone belongs to a limb
/// and is a capsule of radius 20 % of its length, kept within 2 % to 5 % of the height and
/// tapering by 0.9 per bone down the limb (to no less than 1.5 %). The capsules are joined by a smooth union (2 % of
/// the height) and polygonised by surface nets at 1/120 of the height, so the surface is one
/// closed piece. Each vertex is skinned to the up to four joints whose segments are nearest
/// (weights falling off exponentially with the distance beyond the nearest, over 1.2 % of the
/// height), blended on the GPU by dual quaternions as the puppet is.

#include "analysis/body/puppet_model.h"
#include "analysis/core/result.h"
#include "analysis/core/skeleton.h"
#include "analysis/core/skeleton_mesh.h"

#include <vector>

namespace bunraku::analysis {

/// Most joints a body can be skinned to (the renderer's uniform budget); a larger skeleton has
/// no body (its capsules are drawn).
inline constexpr int kMaxBodyJoints = 100;

struct PerformerBody {
    /// The surface: `joints` index Skeleton::joints; regions none; paint positions unused.
    PuppetMesh mesh;
    /// model_T_joint in the pose the body was built in, one per Skeleton::joints (End Sites
    /// included).
    std::vector<RigidTransform> bindPoses;
    float height = 0.0f; ///< cm, the skeleton's height in that pose
};

/// The body of `motion`'s skeleton (its bones as they are at the first frame). Errors for a
/// skeleton of more than kMaxBodyJoints joints or of no extent.
Result<PerformerBody> performerBody(const SkeletalMotion& motion);

/// The file's own mesh (Skeleton::mesh) as a body the renderer draws as it draws the performer's
/// (the "File's mesh" figure, blended linearly as the file means it): one clay colour. Errors for
/// a mesh of more than kMaxBodyJoints joints (its skeleton's), or one made for other joints.
Result<PerformerBody> skeletonMeshBody(const SkeletonMesh& mesh, const Skeleton& skeleton);

/// The joints' skinning transforms world_T_joint * inverse(bind) of `body` at the given joint
/// poses (one per joint), as what the renderer blends.
std::vector<RigidTransform> bodySkinningTransforms(const PerformerBody& body, const std::vector<RigidTransform>& world_T_joint);

} // namespace bunraku::analysis
