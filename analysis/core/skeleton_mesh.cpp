#include "analysis/core/skeleton_mesh.h"

#include "analysis/core/skeleton.h"

#include <Eigen/Geometry>

#include <cmath>

namespace bunraku::analysis {

std::vector<int> SkeletonMesh::bonesUsed() const
{
    std::vector<char> used(bindPoses.size(), 0);
    for (std::size_t v = 0; v < joints.size() && v < weights.size(); ++v)
        for (int k = 0; k < 4; ++k)
            if (weights[v][k] > 0.0f && joints[v][std::size_t(k)] < used.size()) used[joints[v][std::size_t(k)]] = 1;
    std::vector<int> out;
    for (std::size_t j = 0; j < used.size(); ++j)
        if (used[j]) out.push_back(int(j));
    return out;
}

Status validateSkeletonMesh(const SkeletonMesh& mesh)
{
    const auto bad = [](const std::string& what) { return makeError(ErrorCode::InvalidArgument, "skeleton mesh: " + what); };
    const std::size_t n = mesh.positions.size();
    if (mesh.normals.size() != n || mesh.joints.size() != n || mesh.weights.size() != n)
        return bad("expected a normal, four joints and four weights per vertex");
    if (n > kMaxSkeletonMeshVertices) return bad("more than " + std::to_string(kMaxSkeletonMeshVertices) + " vertices");
    if (mesh.indices.size() % 3 != 0 || mesh.indices.size() / 3 > kMaxSkeletonMeshTriangles) return bad("expected whole triangles, at most " + std::to_string(kMaxSkeletonMeshTriangles));
    if (mesh.bindPoses.size() != mesh.jointNames.size()) return bad("expected a bind pose per joint");
    for (const std::uint32_t i : mesh.indices)
        if (i >= n) return bad("a triangle names vertex " + std::to_string(i) + " of " + std::to_string(n));
    for (std::size_t v = 0; v < n; ++v) {
        if (!mesh.positions[v].allFinite() || !mesh.normals[v].allFinite() || !mesh.weights[v].allFinite())
            return bad("vertex " + std::to_string(v) + " is not finite");
        if ((mesh.weights[v].array() < 0.0f).any() || std::abs(mesh.weights[v].sum() - 1.0f) > 1e-3f)
            return bad("the weights of vertex " + std::to_string(v) + " do not sum to 1");
        for (const std::uint16_t j : mesh.joints[v])
            if (j >= mesh.bindPoses.size()) return bad("vertex " + std::to_string(v) + " is weighted to joint " + std::to_string(j) + " of " + std::to_string(mesh.bindPoses.size()));
    }
    for (const RigidTransform& pose : mesh.bindPoses)
        if (!pose.translation.allFinite() || !pose.rotation.coeffs().allFinite() || std::abs(pose.rotation.norm() - 1.0) > 1e-6)
            return bad("a bind pose is not a rigid transform");
    return okStatus();
}

bool meshFitsSkeleton(const SkeletonMesh& mesh, const Skeleton& skeleton)
{
    if (mesh.jointNames.size() != skeleton.joints.size()) return false;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
        if (mesh.jointNames[j] != skeleton.joints[j].name) return false;
    return true;
}

std::vector<RigidTransform> skeletonMeshSkinning(const SkeletonMesh& mesh, const std::vector<RigidTransform>& world_T_joint)
{
    std::vector<RigidTransform> out(mesh.bindPoses.size());
    for (std::size_t j = 0; j < out.size() && j < world_T_joint.size(); ++j) out[j] = world_T_joint[j] * mesh.bindPoses[j].inverse();
    return out;
}

std::vector<Eigen::Vector3d> skinSkeletonMesh(const SkeletonMesh& mesh, const std::vector<RigidTransform>& world_T_joint)
{
    const auto skinning = skeletonMeshSkinning(mesh, world_T_joint);
    std::vector<Eigen::Matrix3d> rotations(skinning.size());
    for (std::size_t j = 0; j < skinning.size(); ++j) rotations[j] = skinning[j].rotation.toRotationMatrix();
    std::vector<Eigen::Vector3d> out(mesh.positions.size(), Eigen::Vector3d::Zero());
    for (std::size_t v = 0; v < out.size(); ++v) {
        const Eigen::Vector3d p = mesh.positions[v].cast<double>();
        for (int k = 0; k < 4; ++k) {
            const double w = mesh.weights[v][k];
            const std::size_t j = mesh.joints[v][std::size_t(k)];
            if (w == 0.0 || j >= skinning.size()) continue;
            out[v] += w * (rotations[j] * p + skinning[j].translation);
        }
    }
    return out;
}

SkeletonMesh transformedSkeletonMesh(const SkeletonMesh& mesh, const Eigen::Quaterniond& world_R_source, double scale)
{
    SkeletonMesh out = mesh;
    const Eigen::Matrix3f r = world_R_source.toRotationMatrix().cast<float>();
    for (Eigen::Vector3f& p : out.positions) p = r * (float(scale) * p);
    for (Eigen::Vector3f& n : out.normals) n = r * n;
    // world_T_joint' = T world_T_joint T^-1 with T = (R, scale): rotation R q R^-1, translation R scale t.
    for (RigidTransform& pose : out.bindPoses)
        pose = RigidTransform{(world_R_source * pose.rotation * world_R_source.conjugate()).normalized(), world_R_source * (scale * pose.translation)};
    return out;
}

} // namespace bunraku::analysis
