#pragma once
/// The performer's skeleton as solid geometry (issue: the full skeleton drawn): per joint, a
/// sphere at the joint and a capsule along each rigid bone to a child, in the joint's frame, so
/// a frame places each joint's mesh with its world_T_joint alone (as the puppet's parts). Sized
/// from the skeleton itself: a 170 cm performer and a 1 m puppet get bones in proportion.

#include "analysis/core/skeleton.h"
#include "render/mesh.h"

#include <string>
#include <vector>

namespace bunraku::render {

struct SkeletonStyle {
    float boneRadiusPerHeight = 0.02f; ///< bone radius as a fraction of the skeleton's height
    float jointRadiusScale = 1.3f;     ///< joint sphere radius / bone radius
    int segments = 12;                 ///< around each capsule and sphere
    glm::vec3 boneColour{0.86f, 0.82f, 0.72f};
};

/// Extent (cm) of the skeleton's joints along world z at the first frame; at least 1 cm.
float skeletonHeight(const analysis::SkeletalMotion& motion);

/// The radius (cm) of the joint spheres: the bones' radius times style.jointRadiusScale.
float skeletonJointRadius(const analysis::SkeletalMotion& motion, const SkeletonStyle& style = {});

/// A capsule of `radius` from the origin to (0, 0, length): a cylinder with hemispherical caps,
/// smooth normals.
Mesh capsuleMesh(float radius, float length, int segments = 16, int capStacks = 4);

/// Which puppet part ("head", "shoulder", "arm", "hand") a joint carries: the part bound to it
/// (Skeleton::parts), or "" when it carries none.
std::string jointPart(const analysis::Skeleton& skeleton, int joint);

/// Whether the bone from `joint` to its child `child` is drawn: the child's translation does
/// not change over the take (a rigid bone) and is longer than 1e-3 cm.
bool isRigidBone(const analysis::SkeletalMotion& motion, int child);

/// One triangle mesh per entry of Skeleton::joints (End Sites: empty), in that joint's frame:
/// its sphere and the capsules of its rigid bones. Bones of a joint that carries a puppet part
/// take that part's orbit colour (scene.h orbitColour of the first take), the others
/// `style.boneColour`.
std::vector<Mesh> buildSkeletonMeshes(const analysis::SkeletalMotion& motion, const SkeletonStyle& style = {});

} // namespace bunraku::render
