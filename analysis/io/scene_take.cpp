#include "analysis/io/scene_take.h"

#include "analysis/core/skeleton_mesh.h"
#include "analysis/core/take.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/fbx_connections.h"
#include "analysis/io/gltf_slim.h"
#include "analysis/io/scene_mesh.h"
#include "analysis/io/text_scan.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <cstdint>
#include <map>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>
#include <unordered_map>

namespace bunraku::analysis::io {

namespace {

namespace fs = std::filesystem;

constexpr const char* kHelperMarker = "_$AssimpFbx$_";
/// Joints that move less than this from their rest (the single-precision noise of assimp's
/// keys: 1e-7 of a 100 cm position) are still: no position channels, End Sites when leaves.
constexpr double kStillCm = 1e-4;
constexpr double kStillRadians = 1e-6;

std::string numberText(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

std::string lowerExtension(const fs::path& file)
{
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

std::optional<SceneFormat> formatOfExtension(const std::string& extension)
{
    if (extension == ".fbx") return SceneFormat::Fbx;
    if (extension == ".glb" || extension == ".gltf") return SceneFormat::Gltf;
    if (extension == ".dae") return SceneFormat::Collada;
    return std::nullopt;
}

const char* formatName(SceneFormat format)
{
    switch (format) {
    case SceneFormat::Fbx: return "FBX";
    case SceneFormat::Gltf: return "glTF";
    case SceneFormat::Collada: return "Collada";
    }
    return "scene";
}

/// assimp's messages may span lines: one line for ours.
std::string oneLine(std::string text)
{
    for (char& c : text)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    if (text.size() > 300) text = text.substr(0, 300) + "...";
    return text;
}

std::optional<double> metaNumber(const aiMetadata* meta, const char* key)
{
    if (!meta) return std::nullopt;
    for (unsigned i = 0; i < meta->mNumProperties; ++i) {
        if (std::string_view(meta->mKeys[i].C_Str()) != key) continue;
        const aiMetadataEntry& entry = meta->mValues[i];
        if (!entry.mData) return std::nullopt;
        switch (entry.mType) {
        case AI_BOOL: return *static_cast<const bool*>(entry.mData) ? 1.0 : 0.0;
        case AI_INT32: return double(*static_cast<const std::int32_t*>(entry.mData));
        case AI_UINT64: return double(*static_cast<const std::uint64_t*>(entry.mData));
        case AI_FLOAT: return double(*static_cast<const float*>(entry.mData));
        case AI_DOUBLE: return *static_cast<const double*>(entry.mData);
        default: return std::nullopt;
        }
    }
    return std::nullopt;
}

Eigen::Matrix4d toEigen(const aiMatrix4x4& m)
{
    Eigen::Matrix4d out;
    out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
    return out;
}

/// The rotation nearest a 3x3 block that may carry scale: columns normalised when they are
/// orthogonal (the usual case; single-precision keys leave 1e-7), else the polar factor by
/// Newton's iteration R <- (R + R^-T) / 2 (a few steps from a scaled rotation), the SVD when that
/// does not settle.
Eigen::Matrix3d rotationPart(const Eigen::Matrix3d& m, bool* scaled)
{
    const Eigen::Vector3d lengths = m.colwise().norm();
    if (scaled && (lengths - Eigen::Vector3d::Ones()).cwiseAbs().maxCoeff() > 1e-5) *scaled = true;
    if (lengths.minCoeff() > 1e-12) {
        Eigen::Matrix3d r = m * lengths.cwiseInverse().asDiagonal();
        if (r.determinant() > 0.0) {
            for (int step = 0; step < 20; ++step) {
                const double error = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
                if (error < 1e-12) return r;
                if (!(error < 0.5)) break;
                r = 0.5 * (r + r.inverse().transpose());
            }
        }
    }
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d u = svd.matrixU();
    if ((u * svd.matrixV().transpose()).determinant() < 0.0) u.col(2) = -u.col(2);
    return u * svd.matrixV().transpose();
}

/// (a, b, c) in radians with R = Rz(a) Rx(b) Ry(c), b in [-pi/2, pi/2]: the ZXY channels'
/// angles (0, 0, 0 for the identity).
Eigen::Vector3d zxyAngles(const Eigen::Matrix3d& r)
{
    const double b = std::asin(std::clamp(r(2, 1), -1.0, 1.0));
    if (std::abs(r(2, 1)) > 1.0 - 1e-12) return {std::atan2(r(1, 0), r(0, 0)), b, 0.0}; // gimbal lock: c folded into a
    return {std::atan2(-r(0, 1), r(1, 1)), b, std::atan2(-r(2, 0), r(2, 2))};
}

struct SceneNode {
    const aiNode* node = nullptr;
    int parent = -1;
    std::string name;
    Eigen::Matrix4d rest = Eigen::Matrix4d::Identity();
    const aiNodeAnim* channel = nullptr;
    bool helper = false;
    int owner = -1;  ///< the joint node a helper belongs to (-1 unknown)
    // The rest matrix's parts, for the components a channel does not key.
    Eigen::Vector3d restTranslation = Eigen::Vector3d::Zero();
    Eigen::Matrix3d restRotation = Eigen::Matrix3d::Identity();
    Eigen::Vector3d restScale = Eigen::Vector3d::Ones();
    // The keys last used (samples go forwards in time: the search starts there).
    unsigned positionKey = 0, rotationKey = 0, scalingKey = 0;
};

template <class Key>
Status checkKeys(const Key* keys, unsigned count, const std::string& source, const std::string& node)
{
    if (count > 0 && !keys) return parseError(source, 0, "animation channel of '" + node + "' has keys without values");
    for (unsigned k = 0; k < count; ++k) {
        if (!std::isfinite(keys[k].mTime)) return parseError(source, 0, "animation channel of '" + node + "' has a key time that is not a number");
        if (k > 0 && keys[k].mTime < keys[k - 1].mTime)
            return parseError(source, 0, "animation channel of '" + node + "' has key times out of order");
    }
    return okStatus();
}

/// Index of the last key at or before `ticks` (0 when before the first), with the weight of the
/// next; `cursor` is the previous answer, where the search starts when time goes forwards.
template <class Key>
std::pair<unsigned, double> bracket(const Key* keys, unsigned count, double ticks, unsigned& cursor)
{
    if (ticks <= keys[0].mTime) return {cursor = 0, 0.0};
    if (ticks >= keys[count - 1].mTime) return {cursor = count - 1, 0.0};
    unsigned low = cursor < count && keys[cursor].mTime <= ticks ? cursor : 0;
    if (low + 1 < count && keys[low + 1].mTime <= ticks) {
        if (low + 2 < count && keys[low + 2].mTime > ticks) {
            ++low;
        } else {
            const Key* upper = std::upper_bound(keys + low, keys + count, ticks, [](double t, const Key& key) { return t < key.mTime; });
            low = unsigned(upper - keys) - 1;
        }
    }
    cursor = low;
    const double span = keys[low + 1].mTime - keys[low].mTime;
    return {low, span > 0.0 ? (ticks - keys[low].mTime) / span : 0.0};
}

Eigen::Vector3d sampleVector(const aiVectorKey* keys, unsigned count, double ticks, unsigned& cursor)
{
    const auto [k, w] = bracket(keys, count, ticks, cursor);
    const Eigen::Vector3d a(keys[k].mValue.x, keys[k].mValue.y, keys[k].mValue.z);
    if (w == 0.0) return a;
    const Eigen::Vector3d b(keys[k + 1].mValue.x, keys[k + 1].mValue.y, keys[k + 1].mValue.z);
    return a + w * (b - a);
}

Eigen::Quaterniond sampleRotation(const aiQuatKey* keys, unsigned count, double ticks, unsigned& cursor)
{
    const auto [k, w] = bracket(keys, count, ticks, cursor);
    const Eigen::Quaterniond a(keys[k].mValue.w, keys[k].mValue.x, keys[k].mValue.y, keys[k].mValue.z);
    if (w == 0.0) return a.normalized();
    const Eigen::Quaterniond b(keys[k + 1].mValue.w, keys[k + 1].mValue.x, keys[k + 1].mValue.y, keys[k + 1].mValue.z);
    return a.normalized().slerp(w, b.normalized());
}

/// The node's local matrix at `ticks`: translation, rotation and scale from its keys where it
/// has them, else from its rest matrix.
Eigen::Matrix4d localMatrix(SceneNode& node, double ticks)
{
    const aiNodeAnim* c = node.channel;
    if (!c) return node.rest;
    Eigen::Vector3d translation = node.restTranslation;
    Eigen::Matrix3d rotation = node.restRotation;
    Eigen::Vector3d scale = node.restScale;
    if (c->mNumPositionKeys > 0) translation = sampleVector(c->mPositionKeys, c->mNumPositionKeys, ticks, node.positionKey);
    if (c->mNumRotationKeys > 0) rotation = sampleRotation(c->mRotationKeys, c->mNumRotationKeys, ticks, node.rotationKey).toRotationMatrix();
    if (c->mNumScalingKeys > 0) scale = sampleVector(c->mScalingKeys, c->mNumScalingKeys, ticks, node.scalingKey);
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = rotation * scale.asDiagonal();
    m.topRightCorner<3, 1>() = translation;
    return m;
}

/// The file's axes in BVH's: p_bvh = bvh_R_file p_file, for FBX from its axis settings
/// (UpAxis, FrontAxis, CoordAxis and their signs): up -> +Y, front -> +Z, coord -> +X.
struct AxisChange {
    Eigen::Matrix3d bvh_R_file = Eigen::Matrix3d::Identity();
    std::string upAxis = "+y";
};

std::string axisName(int axis, int sign) { return std::string(sign < 0 ? "-" : "+") + char('x' + axis); }

AxisChange fbxAxes(const aiMetadata* meta)
{
    AxisChange change;
    const auto up = metaNumber(meta, "UpAxis"), upSign = metaNumber(meta, "UpAxisSign");
    const auto front = metaNumber(meta, "FrontAxis"), frontSign = metaNumber(meta, "FrontAxisSign");
    const auto coord = metaNumber(meta, "CoordAxis"), coordSign = metaNumber(meta, "CoordAxisSign");
    if (!up || !front || !coord) return change;
    const int u = int(*up), f = int(*front), c = int(*coord);
    if (u < 0 || u > 2 || f < 0 || f > 2 || c < 0 || c > 2 || u == f || u == c || f == c) return change;
    const double su = upSign && *upSign < 0 ? -1.0 : 1.0, sf = frontSign && *frontSign < 0 ? -1.0 : 1.0,
                 sc = coordSign && *coordSign < 0 ? -1.0 : 1.0;
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    m(0, c) = sc;
    m(1, u) = su;
    m(2, f) = sf;
    change.bvh_R_file = m;
    change.upAxis = axisName(u, int(su));
    return change;
}

std::string unitName(double cmPerUnit)
{
    for (const auto& [value, name] : std::initializer_list<std::pair<double, const char*>>{{1.0, "cm"}, {100.0, "m"}, {0.1, "mm"}, {2.54, "in"}, {10.0, "dm"}, {30.48, "ft"}, {100000.0, "km"}})
        if (std::abs(cmPerUnit - value) <= 1e-6 * value) return name;
    return numberText(cmPerUnit) + " cm";
}

/// Every FBX time mode's rate (assimp's FrameRate metadata: FbxTime::EMode).
std::optional<double> fbxTimeModeRate(int mode, std::optional<double> custom)
{
    static const double rates[] = {0.0, 120.0, 100.0, 60.0, 50.0, 48.0, 30.0, 30.0, 29.97, 29.97, 25.0, 24.0, 1000.0, 23.976, 0.0, 96.0, 72.0, 59.94, 119.88};
    if (mode == 14) return custom && std::isfinite(*custom) && *custom > 0.0 ? custom : std::nullopt;
    if (mode > 0 && mode < int(std::size(rates)) && rates[mode] > 0.0) return rates[mode];
    return std::nullopt;
}

/// The global rest transform of the first node holding mesh `mesh` (assimp's offsets map from
/// that node's space), or nullopt when no node holds it.
std::optional<Eigen::Matrix4d> meshNodeGlobal(const aiScene& scene, unsigned mesh)
{
    std::vector<const aiNode*> stack{scene.mRootNode};
    for (std::size_t visited = 0; !stack.empty() && visited < 1000000; ++visited) {
        const aiNode* node = stack.back();
        stack.pop_back();
        if (!node) continue;
        for (unsigned k = 0; k < node->mNumMeshes && node->mMeshes; ++k) {
            if (node->mMeshes[k] != mesh) continue;
            Eigen::Matrix4d global = Eigen::Matrix4d::Identity();
            int depth = 0;
            for (const aiNode* at = node; at && depth < 100000; at = at->mParent, ++depth) global = toEigen(at->mTransformation) * global;
            if (!global.allFinite()) return std::nullopt;
            return global;
        }
        for (unsigned c = 0; c < node->mNumChildren && node->mChildren; ++c) stack.push_back(node->mChildren[c]);
    }
    return std::nullopt;
}

/// The skinned meshes assimp read (FBX, Collada): polygons fanned into triangles, every bone's
/// weights kept four per vertex; a mesh with inconsistent data is dropped with a note.
FileSkins skinsFromAssimp(const aiScene& scene)
{
    FileSkins out;
    std::size_t total = 0;
    for (unsigned m = 0; m < scene.mNumMeshes && scene.mMeshes; ++m) {
        const aiMesh* mesh = scene.mMeshes[m];
        if (!mesh) continue;
        if (mesh->mNumBones == 0 || !mesh->mBones) {
            ++out.unskinnedMeshes;
            continue;
        }
        std::string name = mesh->mName.C_Str();
        if (!detail::isUtf8(name)) name = detail::quoted(name);
        const std::string label = "mesh " + std::to_string(m) + (name.empty() ? "" : " '" + name + "'");
        const auto drop = [&](const std::string& why) { out.notes.push_back(label + " dropped: " + why); };
        const std::size_t n = mesh->mNumVertices;
        if (n == 0 || !mesh->mVertices) { drop("it has no vertices"); continue; }
        if (n > kMaxSkeletonMeshVertices - std::min(total, kMaxSkeletonMeshVertices)) { drop("more than " + std::to_string(kMaxSkeletonMeshVertices) + " vertices in all"); continue; }
        FileSkin skin;
        skin.name = name;
        skin.meshToWorld = meshNodeGlobal(scene, m);
        skin.positions.resize(n);
        skin.normals.assign(n, Eigen::Vector3f::Zero());
        bool finite = true;
        for (std::size_t v = 0; v < n; ++v) {
            skin.positions[v] = Eigen::Vector3f(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z);
            if (mesh->mNormals) skin.normals[v] = Eigen::Vector3f(mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z);
            finite = finite && skin.positions[v].allFinite();
            if (!skin.normals[v].allFinite()) skin.normals[v].setZero();
        }
        if (!finite) { drop("a vertex is not a number"); continue; }
        bool faces = true;
        for (unsigned f = 0; f < mesh->mNumFaces && mesh->mFaces && faces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices < 3 || !face.mIndices) continue; // points and lines
            for (unsigned k = 0; k < face.mNumIndices; ++k) faces = faces && face.mIndices[k] < n;
            for (unsigned k = 1; k + 1 < face.mNumIndices && faces; ++k)
                skin.indices.insert(skin.indices.end(), {face.mIndices[0], face.mIndices[k], face.mIndices[k + 1]});
            if (skin.indices.size() / 3 > kMaxSkeletonMeshTriangles) faces = false;
        }
        if (!faces) { drop("a face names a vertex it does not have, or more than " + std::to_string(kMaxSkeletonMeshTriangles) + " triangles"); continue; }
        resizeInfluences(skin, n);
        bool weights = true;
        for (unsigned b = 0; b < mesh->mNumBones && weights; ++b) {
            const aiBone* bone = mesh->mBones[b];
            if (!bone) continue;
            skin.boneNames.emplace_back(bone->mName.C_Str());
            skin.offsets.push_back(toEigen(bone->mOffsetMatrix));
            if (bone->mNumWeights > 0 && !bone->mWeights) weights = false;
            for (unsigned w = 0; w < bone->mNumWeights && weights; ++w) {
                const aiVertexWeight& weight = bone->mWeights[w];
                if (weight.mVertexId >= n || !std::isfinite(weight.mWeight)) weights = false;
                else addInfluence(skin, weight.mVertexId, int(skin.boneNames.size() - 1), weight.mWeight);
            }
        }
        if (!weights) { drop("a bone's weight names a vertex it does not have, or is not a number"); continue; }
        total += n;
        out.skins.push_back(std::move(skin));
    }
    return out;
}

/// What binding the file's meshes to the take's joints needs from the conversion.
struct SkinBinding {
    const std::unordered_map<std::string, int>* byName = nullptr;
    const std::vector<int>* jointOf = nullptr;        ///< per node, its joint or -1
    std::vector<Eigen::Matrix4d> restWorld;           ///< per node (joints and their ancestors), file
    std::vector<Eigen::Matrix4d> firstWorld;          ///< per node at frame 0, file
    std::vector<Eigen::Matrix3d> firstRotation;       ///< per joint at frame 0: BVH world_R_joint
    std::vector<Eigen::Vector3d> firstPosition;       ///< per joint at frame 0: BVH, cm
    Eigen::Matrix4d convert = Eigen::Matrix4d::Identity(); ///< file -> BVH axes and cm
    std::vector<std::string> jointNames;
};

/// The file's skinned meshes on the take's joints, in BVH's axes and cm (a vertex at
/// sum_k w_k A_j(t) bind_j^-1 v, A_j the joint's world pose as the take gives it): each bone's
/// offset brought to the joint's frame at the first frame, where the file's and the take's
/// poses are known together. Meshes that cannot be bound are dropped with a note.
std::shared_ptr<const SkeletonMesh> bindSkins(const FileSkins& file, const SkinBinding& binding, SceneTakeInfo& info)
{
    info.meshNotes.insert(info.meshNotes.end(), file.notes.begin(), file.notes.end());
    const std::size_t joints = binding.jointNames.size();
    if (file.skins.empty() || binding.firstRotation.size() != joints || binding.firstPosition.size() != joints) return nullptr;
    if (joints > 65535) {
        info.meshNotes.push_back("meshes dropped: the skeleton has more than 65535 joints");
        return nullptr;
    }
    auto out = std::make_shared<SkeletonMesh>();
    out->jointNames = binding.jointNames;
    out->bindPoses.assign(joints, RigidTransform{});
    std::vector<char> bound(joints, 0);
    std::vector<Eigen::Matrix4d> inverseBind(joints, Eigen::Matrix4d::Identity());
    const auto jointPose = [&](std::size_t j) {
        Eigen::Matrix4d a = Eigen::Matrix4d::Identity();
        a.topLeftCorner<3, 3>() = binding.firstRotation[j];
        a.topRightCorner<3, 1>() = binding.firstPosition[j];
        return a;
    };
    for (const FileSkin& skin : file.skins) {
        const std::string label = "mesh '" + skin.name + "'";
        const auto drop = [&](const std::string& why) { info.meshNotes.push_back(label + " dropped: " + why); };
        // The bones' joints; every weighted bone must be one.
        std::vector<int> jointOfBone(skin.boneNames.size(), -1);
        std::vector<char> weighted(skin.boneNames.size(), 0);
        for (std::size_t v = 0; v < skin.bones.size(); ++v)
            for (int k = 0; k < 4; ++k)
                if (skin.bones[v][std::size_t(k)] >= 0 && skin.weights[v][k] > 0.0f) weighted[std::size_t(skin.bones[v][std::size_t(k)])] = 1;
        std::string missing;
        int reference = -1;
        for (std::size_t b = 0; b < skin.boneNames.size(); ++b) {
            if (!weighted[b]) continue;
            const auto node = binding.byName->find(skin.boneNames[b]);
            const int joint = node == binding.byName->end() ? -1 : (*binding.jointOf)[std::size_t(node->second)];
            if (joint < 0) {
                if (missing.empty()) missing = skin.boneNames[b];
                continue;
            }
            jointOfBone[b] = joint;
            if (reference < 0) reference = int(b);
        }
        if (!missing.empty()) { drop("it is weighted to '" + (detail::isUtf8(missing) ? missing : detail::quoted(missing)) + "', which is not a joint of the take"); continue; }
        if (reference < 0) { drop("no vertex is weighted to a bone"); continue; }
        // The mesh's space in the bind pose: its node's (FBX, Collada), else where the reference
        // bone's rest and offset put it (glTF). Any invertible choice skins the same; this one
        // keeps the bind pose where the file's rest has it.
        const int referenceNode = binding.byName->at(skin.boneNames[std::size_t(reference)]);
        const Eigen::Matrix4d meshToWorld =
            binding.convert * (skin.meshToWorld ? *skin.meshToWorld : Eigen::Matrix4d(binding.restWorld[std::size_t(referenceNode)] * skin.offsets[std::size_t(reference)]));
        const Eigen::Matrix3d linear = meshToWorld.topLeftCorner<3, 3>();
        if (!meshToWorld.allFinite() || !(std::abs(linear.determinant()) > 1e-12)) { drop("its bind pose is degenerate"); continue; }
        const Eigen::Matrix4d worldToMesh = meshToWorld.inverse();
        // Each weighted bone's inverse bind in the joint's (world-aligned) frame.
        std::vector<std::pair<int, Eigen::Matrix4d>> binds;
        std::string problem;
        for (std::size_t b = 0; b < skin.boneNames.size() && problem.empty(); ++b) {
            if (jointOfBone[b] < 0) continue;
            const int node = binding.byName->at(skin.boneNames[b]);
            const Eigen::Matrix4d k = jointPose(std::size_t(jointOfBone[b])).inverse() * binding.convert * binding.firstWorld[std::size_t(node)] * skin.offsets[b] * worldToMesh;
            const Eigen::Matrix3d l = k.topLeftCorner<3, 3>();
            if (!k.allFinite() || (l.transpose() * l - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-3)
                problem = "its bind of '" + skin.boneNames[b] + "' is not rigid (scaled or sheared)";
            binds.emplace_back(jointOfBone[b], k);
        }
        if (!problem.empty()) { drop(problem); continue; }
        // A joint bound by an earlier mesh must be bound the same way.
        for (const auto& [joint, k] : binds)
            if (bound[std::size_t(joint)] && (k - inverseBind[std::size_t(joint)]).cwiseAbs().maxCoeff() > 1e-3)
                problem = "it is bound to '" + binding.jointNames[std::size_t(joint)] + "' in another pose than an earlier mesh";
        if (!problem.empty()) { drop(problem); continue; }
        for (const auto& [joint, k] : binds) {
            inverseBind[std::size_t(joint)] = k;
            bound[std::size_t(joint)] = 1;
        }
        // Vertices into the world (BVH axes, cm) of the bind pose; weights normalised.
        const std::size_t first = out->positions.size();
        const Eigen::Matrix3d normalMatrix = meshToWorld.topLeftCorner<3, 3>().inverse().transpose();
        std::size_t unweighted = 0;
        for (std::size_t v = 0; v < skin.positions.size(); ++v) {
            const Eigen::Vector3d p = (meshToWorld * skin.positions[v].cast<double>().homogeneous()).head<3>();
            Eigen::Vector3d n = normalMatrix * skin.normals[v].cast<double>();
            n = n.norm() > 1e-12 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
            std::array<std::pair<float, int>, 4> influences{};
            float sum = 0.0f;
            for (int k = 0; k < 4; ++k) {
                const int bone = skin.bones[v][std::size_t(k)];
                const float w = bone >= 0 ? skin.weights[v][k] : 0.0f;
                influences[std::size_t(k)] = {w > 0.0f ? w : 0.0f, bone >= 0 && w > 0.0f ? jointOfBone[std::size_t(bone)] : 0};
                sum += influences[std::size_t(k)].first;
            }
            if (!(sum > 0.0f)) { // follows the root, where the first frame has it
                ++unweighted;
                influences = {std::pair{1.0f, 0}, std::pair{0.0f, 0}, std::pair{0.0f, 0}, std::pair{0.0f, 0}};
                sum = 1.0f;
            }
            std::sort(influences.begin(), influences.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
            std::array<std::uint16_t, 4> ids{};
            Eigen::Vector4f weights;
            for (int k = 0; k < 4; ++k) {
                ids[std::size_t(k)] = std::uint16_t(influences[std::size_t(k)].second);
                weights[k] = influences[std::size_t(k)].first / sum;
            }
            out->positions.push_back(p.cast<float>());
            out->normals.push_back(n.cast<float>());
            out->joints.push_back(ids);
            out->weights.push_back(weights);
        }
        for (const std::uint32_t i : skin.indices) out->indices.push_back(std::uint32_t(first + i));
        // Normals the file did not give: the area-weighted mean of the triangles'.
        std::vector<Eigen::Vector3f> made(skin.positions.size(), Eigen::Vector3f::Zero());
        bool needed = false;
        for (std::size_t v = first; v < out->positions.size(); ++v) needed = needed || out->normals[v].isZero();
        if (needed) {
            for (std::size_t t = 0; t + 2 < skin.indices.size(); t += 3) {
                const std::uint32_t a = skin.indices[t], b = skin.indices[t + 1], c = skin.indices[t + 2];
                const Eigen::Vector3f face = (out->positions[first + b] - out->positions[first + a]).cross(out->positions[first + c] - out->positions[first + a]);
                made[a] += face, made[b] += face, made[c] += face;
            }
            for (std::size_t v = 0; v < made.size(); ++v)
                if (out->normals[first + v].isZero()) out->normals[first + v] = made[v].norm() > 0.0f ? made[v].normalized() : Eigen::Vector3f::UnitZ();
        }
        if (unweighted > 0) {
            info.meshNotes.push_back(label + ": " + std::to_string(unweighted) + " vertices without weights follow the root joint");
            if (!bound[0]) { // the root's bind: its pose at the first frame (those vertices stand as they were then)
                inverseBind[0] = jointPose(0).inverse();
                bound[0] = 1;
            }
        }
        if (skin.extraInfluences > 0)
            info.meshNotes.push_back(label + ": " + std::to_string(skin.extraInfluences) + " influences beyond a vertex's four largest dropped");
        ++out->fileMeshes;
    }
    if (out->positions.empty()) return nullptr;
    for (std::size_t j = 0; j < joints; ++j) {
        if (!bound[j]) continue;
        const Eigen::Matrix3d rotation = rotationPart(inverseBind[j].topLeftCorner<3, 3>(), nullptr);
        const RigidTransform inverse{Eigen::Quaterniond(rotation).normalized(), inverseBind[j].topRightCorner<3, 1>()};
        out->bindPoses[j] = inverse.inverse();
    }
    if (auto valid = validateSkeletonMesh(*out); !valid) {
        info.meshNotes.push_back("meshes dropped: " + valid.error().message);
        return nullptr;
    }
    info.meshVertices = out->vertexCount();
    info.meshTriangles = out->triangleCount();
    for (const int j : out->bonesUsed()) info.meshBones.push_back(binding.jointNames[std::size_t(j)]);
    return out;
}

Result<SceneTake> convertScene(const aiScene& scene, SceneFormat format, const std::string& source, const SceneTakeOptions& options,
                               const RunControl& control, const FileSkins* gltfSkins)
{
    SceneTake out;
    SceneTakeInfo& info = out.info;
    info.format = format;
    info.formatName = formatName(format);
    info.meshes = int(scene.mNumMeshes);
    for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
        const std::string name = scene.mAnimations && scene.mAnimations[a] ? scene.mAnimations[a]->mName.C_Str() : "";
        info.animations.push_back(detail::isUtf8(name) ? name : detail::quoted(name)); // shown and written as JSON
    }
    if (!scene.mRootNode) return parseError(source, 0, "the " + info.formatName + " file has no scene nodes");
    if (scene.mNumAnimations == 0 || !scene.mAnimations) {
        return makeError(ErrorCode::Unsupported, source + ": no animation in this " + info.formatName + " file (" + std::to_string(scene.mNumMeshes) +
                                                     " meshes, 0 animations): a take needs an animated skeleton");
    }

    // Which animation.
    int chosen = -1;
    if (options.animation.empty()) {
        chosen = 0;
    } else {
        for (unsigned a = 0; a < scene.mNumAnimations && chosen < 0; ++a)
            if (info.animations[a] == options.animation) chosen = int(a);
        if (chosen < 0 && std::all_of(options.animation.begin(), options.animation.end(), [](unsigned char c) { return std::isdigit(c); }) &&
            options.animation.size() < 9) {
            const int index = std::stoi(options.animation);
            if (index < int(scene.mNumAnimations)) chosen = index;
        }
        if (chosen < 0) {
            std::string names;
            for (unsigned a = 0; a < scene.mNumAnimations; ++a)
                names += (a ? ", " : "") + std::to_string(a) + " '" + info.animations[a] + "'";
            return makeError(ErrorCode::NotFound, source + ": no animation '" + options.animation + "' (expected a name or index of: " + names + ")");
        }
    }
    info.animation = chosen;
    const aiAnimation& animation = *scene.mAnimations[chosen];

    // The node tree, parents before children.
    std::vector<SceneNode> nodes;
    std::unordered_map<std::string, int> byName;
    std::vector<std::pair<const aiNode*, int>> stack{{scene.mRootNode, -1}};
    while (!stack.empty()) {
        const auto [node, parent] = stack.back();
        stack.pop_back();
        if (!node) continue;
        if (nodes.size() > 1000000) return parseError(source, 0, "more than a million scene nodes");
        SceneNode entry;
        entry.node = node;
        entry.parent = parent;
        entry.name = node->mName.C_Str();
        entry.rest = toEigen(node->mTransformation);
        if (!entry.rest.allFinite()) return parseError(source, 0, "node '" + entry.name + "' has a transform that is not a number");
        entry.restTranslation = entry.rest.topRightCorner<3, 1>();
        entry.restScale = entry.rest.topLeftCorner<3, 3>().colwise().norm().transpose();
        entry.restRotation = rotationPart(entry.rest.topLeftCorner<3, 3>(), nullptr);
        entry.helper = entry.name.find(kHelperMarker) != std::string::npos;
        const int index = int(nodes.size());
        byName.emplace(entry.name, index); // the first of equal names, as assimp's own lookups
        nodes.push_back(std::move(entry));
        if (node->mNumChildren > 0 && !node->mChildren) return parseError(source, 0, "node '" + nodes.back().name + "' lists children it does not have");
        for (unsigned c = node->mNumChildren; c-- > 0;) stack.push_back({node->mChildren[c], index});
    }
    // Helpers belong to the joint named before their marker.
    for (SceneNode& node : nodes) {
        if (!node.helper) continue;
        ++info.helperNodesFolded;
        const auto it = byName.find(node.name.substr(0, node.name.find(kHelperMarker)));
        if (it != byName.end()) node.owner = it->second;
    }

    // Channels onto nodes; the time span of all keys (ticks).
    double first = std::numeric_limits<double>::infinity(), last = -std::numeric_limits<double>::infinity();
    std::vector<double> keyTimes;
    bool anyKeyed = false;
    if (animation.mNumChannels > 0 && !animation.mChannels) return parseError(source, 0, "animation lists channels it does not have");
    for (unsigned c = 0; c < animation.mNumChannels; ++c) {
        const aiNodeAnim* channel = animation.mChannels[c];
        if (!channel) continue;
        const std::string name = channel->mNodeName.C_Str();
        const auto it = byName.find(name);
        if (it == byName.end()) continue;
        if (auto status = checkKeys(channel->mPositionKeys, channel->mNumPositionKeys, source, name); !status) return status.error();
        if (auto status = checkKeys(channel->mRotationKeys, channel->mNumRotationKeys, source, name); !status) return status.error();
        if (auto status = checkKeys(channel->mScalingKeys, channel->mNumScalingKeys, source, name); !status) return status.error();
        nodes[std::size_t(it->second)].channel = channel;
        auto span = [&](const auto* keys, unsigned count) {
            for (unsigned k = 0; k < count; ++k) {
                first = std::min(first, keys[k].mTime);
                last = std::max(last, keys[k].mTime);
                if (keyTimes.size() < 100000) keyTimes.push_back(keys[k].mTime);
                anyKeyed = true;
            }
        };
        span(channel->mPositionKeys, channel->mNumPositionKeys);
        span(channel->mRotationKeys, channel->mNumRotationKeys);
        span(channel->mScalingKeys, channel->mNumScalingKeys);
    }
    if (!anyKeyed)
        return makeError(ErrorCode::Unsupported, source + ": animation " + std::to_string(chosen) + " '" + info.animations[std::size_t(chosen)] +
                                                     "' moves no node of the " + info.formatName + " file: a take needs an animated skeleton");

    // A node is animated when it or one of its helper nodes has keys.
    std::vector<char> animated(nodes.size(), 0);
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (!nodes[n].channel) continue;
        if (!nodes[n].helper) animated[n] = 1;
        else if (nodes[n].owner >= 0) animated[std::size_t(nodes[n].owner)] = 1;
    }
    // The skeleton's root: the deepest common ancestor of the animated joints (non-helper nodes).
    auto depthOf = [&](int n) {
        int depth = 0;
        for (; n >= 0; n = nodes[std::size_t(n)].parent) ++depth;
        return depth;
    };
    int root = -1;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (!animated[n]) continue;
        if (root < 0) { root = int(n); continue; }
        int a = root, b = int(n);
        int da = depthOf(a), db = depthOf(b);
        while (da > db) { a = nodes[std::size_t(a)].parent; --da; }
        while (db > da) { b = nodes[std::size_t(b)].parent; --db; }
        while (a != b) { a = nodes[std::size_t(a)].parent; b = nodes[std::size_t(b)].parent; }
        root = a;
    }
    while (root >= 0 && nodes[std::size_t(root)].helper) root = nodes[std::size_t(root)].parent;
    if (root < 0)
        return makeError(ErrorCode::Unsupported, source + ": the animated nodes of the " + info.formatName + " file have no common joint");

    // Joints: the root and the non-helper nodes below it that are animated or lead to one, and
    // the leaves hanging from those without a mesh of their own (End Sites: Blender's "_end"
    // bones, Mixamo's HeadTop_End); parents first (the node order is).
    std::vector<char> animatedBelow(animated);
    for (std::size_t n = nodes.size(); n-- > 1;)
        if (animatedBelow[n] && nodes[n].parent >= 0) animatedBelow[std::size_t(nodes[n].parent)] = 1;
    std::vector<int> jointOf(nodes.size(), -1);
    std::vector<int> jointNodes;
    std::vector<int> jointParent;
    for (std::size_t n = std::size_t(root); n < nodes.size(); ++n) {
        if (nodes[n].helper) continue;
        int parent = nodes[n].parent;
        while (parent >= 0 && nodes[std::size_t(parent)].helper) parent = nodes[std::size_t(parent)].parent;
        int parentJoint = -1;
        if (int(n) != root) {
            if (parent < 0 || jointOf[std::size_t(parent)] < 0) continue; // not below the root
            if (!animatedBelow[n] && (!animatedBelow[std::size_t(parent)] || nodes[n].node->mNumMeshes > 0)) continue; // a mesh, a prop
            parentJoint = jointOf[std::size_t(parent)];
        }
        jointOf[n] = int(jointNodes.size());
        jointNodes.push_back(int(n));
        jointParent.push_back(parentJoint);
    }
    const int jointCount = int(jointNodes.size());
    // The nodes whose world matrices are needed: the joints and every ancestor of theirs.
    std::vector<char> needed(nodes.size(), 0);
    for (int n : jointNodes)
        for (int a = n; a >= 0 && !needed[std::size_t(a)]; a = nodes[std::size_t(a)].parent) needed[std::size_t(a)] = 1;

    // Units and axes into BVH's convention (y up, +Z forward, cm).
    AxisChange axes;
    double cmPerUnit = 100.0;
    if (format == SceneFormat::Fbx) {
        axes = fbxAxes(scene.mMetaData);
        const auto unit = metaNumber(scene.mMetaData, "UnitScaleFactor");
        cmPerUnit = unit && std::isfinite(*unit) && *unit > 0.0 && *unit < 1e7 ? *unit : 1.0;
        info.unit = unitName(cmPerUnit);
    } else if (format == SceneFormat::Gltf) {
        info.unit = "m";
    } else {
        // assimp turns a Collada scene into y up metres on its root node (<unit>, <up_axis>).
        const Eigen::Matrix3d rootLinear = nodes[0].rest.topLeftCorner<3, 3>();
        const double metresPerUnit = rootLinear.col(0).norm();
        info.cmPerUnit = metresPerUnit > 0.0 && std::isfinite(metresPerUnit) ? 100.0 * metresPerUnit : 100.0;
        info.unit = unitName(info.cmPerUnit);
        const Eigen::Vector3d up = rootLinear.transpose() * Eigen::Vector3d::UnitY();
        int axis = 0;
        up.cwiseAbs().maxCoeff(&axis);
        info.upAxis = axisName(axis, up[axis] < 0 ? -1 : 1);
    }
    if (info.upAxis.empty()) info.upAxis = axes.upAxis;
    if (format != SceneFormat::Collada) info.cmPerUnit = cmPerUnit;
    const Eigen::Matrix3d convert = cmPerUnit * axes.bvh_R_file;
    const Eigen::Matrix3d& axisTurn = axes.bvh_R_file;

    // The rate and the sample times.
    double ticksPerSecond = animation.mTicksPerSecond;
    if (!(std::isfinite(ticksPerSecond) && ticksPerSecond > 0.0)) ticksPerSecond = 1.0;
    const double spanSeconds = (last - first) / ticksPerSecond;
    if (!std::isfinite(spanSeconds) || spanSeconds < 0.0) return parseError(source, 0, "animation key times span no finite time");
    // `rate` is the take's (whole numbers of Hz snapped as BVH's are); samples are taken every
    // `step` seconds, the file's own frame time, so that they fall on its keys.
    double rate = 0.0, step = 0.0;
    if (format == SceneFormat::Fbx) {
        const auto mode = metaNumber(scene.mMetaData, "FrameRate");
        auto fileRate = mode ? fbxTimeModeRate(int(*mode), metaNumber(scene.mMetaData, "CustomFrameRate")) : std::nullopt;
        if (!fileRate && plausibleRate(ticksPerSecond)) fileRate = ticksPerSecond;
        if (fileRate && plausibleRate(*fileRate)) {
            step = 1.0 / *fileRate;
            rate = bvhRateHz(step);
            info.rateSource = "file";
        }
    }
    if (rate == 0.0 && keyTimes.size() > 1) {
        std::sort(keyTimes.begin(), keyTimes.end());
        // Keys of different channels at one time may differ in the last digits (float seconds or ms).
        keyTimes.erase(std::unique(keyTimes.begin(), keyTimes.end(), [&](double a, double b) { return (b - a) / ticksPerSecond < 1e-5; }), keyTimes.end());
        if (keyTimes.size() > 1) {
            // The mean spacing; uniform when every key is within 1/1000 of a step of its multiple.
            const double keyStep = (keyTimes.back() - keyTimes.front()) / ticksPerSecond / double(keyTimes.size() - 1);
            bool uniform = keyStep > 0.0;
            for (std::size_t k = 0; uniform && k < keyTimes.size(); ++k) {
                const double units = (keyTimes[k] - keyTimes[0]) / ticksPerSecond / keyStep;
                uniform = std::abs(units - double(k)) < 1e-3;
            }
            if (uniform && plausibleRate(1.0 / keyStep)) {
                step = keyStep;
                rate = bvhRateHz(step);
                info.rateSource = "keys";
            }
        }
    }
    if (rate == 0.0) {
        if (!plausibleRate(options.rateHz)) return makeError(ErrorCode::InvalidArgument, source + ": --rate " + numberText(options.rateHz) + ": " + rateExpectation());
        rate = options.rateHz;
        step = 1.0 / rate;
        info.rateSource = "option";
    }
    info.rateHz = rate;
    info.startTime = first / ticksPerSecond;
    const double frameSpan = spanSeconds / step;
    // A last key within 1/1000 of a frame of a sample time is sampled.
    const double frameCountEstimate = std::floor(frameSpan + 1e-3) + 1.0;
    if (!(frameCountEstimate * double(6 * std::max(jointCount, 1)) <= double(kMaxSceneSamples)))
        return makeError(ErrorCode::Unsupported, source + ": the animation's " + numberText(spanSeconds) + " s at " + numberText(rate) + " Hz for " +
                                                     std::to_string(jointCount) + " joints exceed the limit of " + std::to_string(kMaxSceneSamples) +
                                                     " sampled values");
    const Eigen::Index frames = Eigen::Index(frameCountEstimate);

    // assimp gives a joint with FBX pivots but only translation, rotation and scale keys one
    // channel of its whole local transform, pre- and post-rotation folded into its rotation
    // keys: its animated pose then hangs from the parent of its helper chain, the helpers'
    // static transforms skipped. When the helpers carry keys themselves, the chain is composed.
    std::vector<int> animatedParent(nodes.size(), -1);
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        animatedParent[n] = nodes[n].parent;
        if (!nodes[n].channel || nodes[n].helper) continue;
        int parent = nodes[n].parent;
        bool keyedHelper = false;
        while (parent >= 0 && nodes[std::size_t(parent)].helper && nodes[std::size_t(parent)].owner == int(n)) {
            keyedHelper = keyedHelper || nodes[std::size_t(parent)].channel != nullptr;
            parent = nodes[std::size_t(parent)].parent;
        }
        if (!keyedHelper) animatedParent[n] = parent;
    }

    // Rest and per-frame world poses, BVH axes and cm: rotation (polar part) and position.
    std::vector<Eigen::Matrix4d> world(nodes.size());
    std::vector<Eigen::Matrix3d> restRotation(static_cast<std::size_t>(jointCount));
    std::vector<Eigen::Vector3d> restPosition(static_cast<std::size_t>(jointCount));
    auto worldAt = [&](std::optional<double> ticks) {
        for (std::size_t n = 0; n < nodes.size(); ++n) {
            if (!needed[n]) continue;
            const Eigen::Matrix4d local = ticks ? localMatrix(nodes[n], *ticks) : nodes[n].rest;
            const int parent = ticks ? animatedParent[n] : nodes[n].parent;
            world[n] = parent >= 0 ? Eigen::Matrix4d(world[std::size_t(parent)] * local) : local;
        }
    };
    worldAt(std::nullopt);
    SkinBinding skinBinding;
    const FileSkins assimpSkins = gltfSkins ? FileSkins{} : skinsFromAssimp(scene);
    const FileSkins& fileSkins = gltfSkins ? *gltfSkins : assimpSkins;
    if (!fileSkins.skins.empty()) skinBinding.restWorld = world;
    bool scaled = false;
    for (int j = 0; j < jointCount; ++j) {
        const Eigen::Matrix4d& w = world[std::size_t(jointNodes[std::size_t(j)])];
        restRotation[std::size_t(j)] = axisTurn * rotationPart(w.topLeftCorner<3, 3>(), nullptr) * axisTurn.transpose();
        restPosition[std::size_t(j)] = convert * w.topRightCorner<3, 1>();
        if (!restPosition[std::size_t(j)].allFinite()) return parseError(source, 0, "joint '" + nodes[std::size_t(jointNodes[std::size_t(j)])].name + "' has no finite rest position");
    }

    // Sample every frame: world-aligned-at-rest frames (R_world R_rest^T), local rotations and
    // translations in the parent's frame.
    std::vector<Eigen::Quaterniond> localRotation(std::size_t(frames) * std::size_t(jointCount));
    Eigen::MatrixXd localTranslation(frames, 3 * jointCount);
    std::vector<Eigen::Matrix3d> frameRotation(static_cast<std::size_t>(jointCount));
    std::vector<Eigen::Vector3d> framePosition(static_cast<std::size_t>(jointCount));
    for (Eigen::Index f = 0; f < frames; ++f) {
        if ((f & 255) == 0) {
            if (control.cancelled()) return makeError(ErrorCode::Cancelled, source + ": reading cancelled");
            control.report(double(f) / double(frames));
        }
        worldAt(std::min(last, first + double(f) * step * ticksPerSecond));
        for (int j = 0; j < jointCount; ++j) {
            const Eigen::Matrix4d& w = world[std::size_t(jointNodes[std::size_t(j)])];
            frameRotation[std::size_t(j)] = axisTurn * rotationPart(w.topLeftCorner<3, 3>(), &scaled) * axisTurn.transpose() * restRotation[std::size_t(j)].transpose();
            framePosition[std::size_t(j)] = convert * w.topRightCorner<3, 1>();
            const int p = jointParent[std::size_t(j)];
            Eigen::Matrix3d local = frameRotation[std::size_t(j)];
            Eigen::Vector3d translation = framePosition[std::size_t(j)];
            if (p >= 0) {
                local = frameRotation[std::size_t(p)].transpose() * frameRotation[std::size_t(j)];
                translation = frameRotation[std::size_t(p)].transpose() * (framePosition[std::size_t(j)] - framePosition[std::size_t(p)]);
            }
            localRotation[std::size_t(f) * std::size_t(jointCount) + std::size_t(j)] = Eigen::Quaterniond(local).normalized();
            localTranslation.block<1, 3>(f, 3 * j) = translation.transpose();
        }
        if (!localTranslation.row(f).allFinite()) return parseError(source, 0, "the animation gives joint positions that are not numbers at frame " + std::to_string(f));
        if (f == 0 && !fileSkins.skins.empty()) {
            skinBinding.firstWorld = world;
            skinBinding.firstRotation = frameRotation;
            skinBinding.firstPosition = framePosition;
        }
    }
    info.scaleDropped = scaled;
    control.report(1.0);

    // Joint names as the skeleton needs them: UTF-8 text (they go into JSON files), non-empty and
    // unique; a file's other names get "joint N" or a suffix, and the error names the first.
    std::vector<std::string> jointNames(static_cast<std::size_t>(jointCount));
    {
        std::unordered_map<std::string, int> used;
        for (int j = 0; j < jointCount; ++j) {
            std::string name = nodes[std::size_t(jointNodes[std::size_t(j)])].name;
            if (!detail::isUtf8(name))
                return parseError(source, 0, "node name " + detail::quoted(name) + " is not UTF-8 text");
            if (name.empty()) name = "joint " + std::to_string(j);
            std::string unique = name;
            for (int k = 2; used.count(unique); ++k) unique = name + " " + std::to_string(k);
            used.emplace(unique, j);
            jointNames[std::size_t(j)] = unique;
        }
    }

    // The file's skinned meshes on these joints.
    if (!fileSkins.skins.empty() || !fileSkins.notes.empty()) {
        skinBinding.byName = &byName;
        skinBinding.jointOf = &jointOf;
        skinBinding.convert.topLeftCorner<3, 3>() = convert;
        skinBinding.jointNames = jointNames;
        if (skinBinding.firstWorld.empty()) skinBinding.firstWorld = skinBinding.restWorld; // no frames
        out.bvh.mesh = bindSkins(fileSkins, skinBinding, info);
    }

    // The BVH structure: offsets are the rest pose's, End Sites the leaves that never move.
    BvhFile& bvh = out.bvh;
    bvh.source = source;
    std::vector<int> childCount(std::size_t(jointCount), 0);
    for (int j = 1; j < jointCount; ++j) ++childCount[std::size_t(jointParent[std::size_t(j)])];
    auto varies = [&](int j, bool rotation) {
        for (Eigen::Index f = 1; f < frames; ++f) {
            if (rotation) {
                if (localRotation[std::size_t(f) * std::size_t(jointCount) + std::size_t(j)].angularDistance(localRotation[std::size_t(j)]) > kStillRadians) return true;
            } else if ((localTranslation.block<1, 3>(f, 3 * j) - localTranslation.block<1, 3>(0, 3 * j)).norm() > kStillCm) {
                return true;
            }
        }
        return false;
    };
    std::vector<int> firstColumn(std::size_t(jointCount), -1);
    std::vector<char> positions(std::size_t(jointCount), 0);
    int columns = 0;
    for (int j = 0; j < jointCount; ++j) {
        BvhJoint joint;
        joint.name = jointNames[std::size_t(j)];
        joint.parent = jointParent[std::size_t(j)];
        const Eigen::Vector3d offset = j == 0 ? restPosition[0] : Eigen::Vector3d(restPosition[std::size_t(j)] - restPosition[std::size_t(joint.parent)]);
        joint.offset = offset;
        const bool leaf = j > 0 && childCount[std::size_t(j)] == 0;
        const Eigen::Vector3d atStart = localTranslation.block<1, 3>(0, 3 * j).transpose();
        const bool moved = (atStart - offset).norm() > kStillCm || varies(j, false);
        const bool turned = localRotation[std::size_t(j)].angularDistance(Eigen::Quaterniond::Identity()) > kStillRadians || varies(j, true);
        if (leaf && !moved && !turned) {
            joint.endSite = true;
        } else {
            positions[std::size_t(j)] = j == 0 || moved;
            if (positions[std::size_t(j)]) joint.channels = {BvhChannel::Xposition, BvhChannel::Yposition, BvhChannel::Zposition};
            joint.channels.insert(joint.channels.end(), {BvhChannel::Zrotation, BvhChannel::Xrotation, BvhChannel::Yrotation});
            joint.firstChannel = columns;
            firstColumn[std::size_t(j)] = columns;
            columns += int(joint.channels.size());
        }
        bvh.skeleton.joints.push_back(std::move(joint));
    }
    bvh.skeleton.channelCount = columns;
    bvh.motion.frameTime = 1.0 / rate; // bvhRateHz gives `rate` back
    bvh.motion.values.resize(frames, columns);
    for (int j = 0; j < jointCount; ++j) {
        const int column = firstColumn[std::size_t(j)];
        if (column < 0) continue;
        int c = column;
        for (Eigen::Index f = 0; f < frames; ++f) {
            c = column;
            if (positions[std::size_t(j)]) {
                bvh.motion.values.block<1, 3>(f, c) = localTranslation.block<1, 3>(f, 3 * j);
                c += 3;
            }
            const Eigen::Vector3d angles = zxyAngles(localRotation[std::size_t(f) * std::size_t(jointCount) + std::size_t(j)].toRotationMatrix());
            bvh.motion.values.block<1, 3>(f, c) = (angles * (180.0 / std::numbers::pi)).transpose();
        }
    }
    return out;
}

Assimp::Importer& configure(Assimp::Importer& importer)
{
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, true);
    importer.SetPropertyBool(AI_CONFIG_FBX_CONVERT_TO_M, false);
    // Collada nodes by their names ("Hips"), not their ids ("Armature_Hips").
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_USE_COLLADA_NAMES, true);
    return importer;
}

Result<SceneFormat> formatOf(const std::string& extension, const std::string& source)
{
    const auto format = formatOfExtension(extension);
    if (!format) return makeError(ErrorCode::Unsupported, source + ": not a scene take file (expected .fbx, .glb, .gltf or .dae)");
    return *format;
}

Error assimpError(const std::string& source, SceneFormat format, const Assimp::Importer& importer)
{
    return makeError(ErrorCode::Parse, source + ": not a readable " + std::string(formatName(format)) + " file: " + oneLine(importer.GetErrorString()));
}

/// assimp 5.2 crashes (a null read) on a Collada array whose `count` is not a number (found by
/// fuzz_scene_take: `<float_array count="x">`): such files are refused before it reads them.
std::optional<Error> checkColladaArrayCounts(const std::string& bytes, const std::string& source)
{
    const auto isName = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
    for (std::size_t at = bytes.find("_array"); at != std::string::npos; at = bytes.find("_array", at + 6)) {
        const std::size_t open = bytes.rfind('<', at);
        if (open == std::string::npos || at - open > 16 || open + 1 == at) continue;
        bool element = true;
        for (std::size_t i = open + 1; i < at; ++i) element = element && isName(bytes[i]);
        const std::size_t end = bytes.find('>', at);
        if (!element || end == std::string::npos) continue;
        const std::string_view tag(bytes.data() + at + 6, end - at - 6);
        const std::size_t count = tag.find("count");
        if (count == std::string_view::npos) continue;
        std::size_t i = count + 5;
        while (i < tag.size() && (tag[i] == ' ' || tag[i] == '\t' || tag[i] == '\n' || tag[i] == '\r' || tag[i] == '=')) ++i;
        if (i >= tag.size() || (tag[i] != '"' && tag[i] != '\'')) continue;
        const std::size_t close = tag.find(tag[i], i + 1);
        const std::string_view value = tag.substr(i + 1, close == std::string_view::npos ? std::string_view::npos : close - i - 1);
        bool number = !value.empty() && value.size() <= 18;
        for (const char c : value) number = number && c >= '0' && c <= '9';
        if (!number)
            return makeError(ErrorCode::Parse, source + ": a Collada " + std::string(bytes, open + 1, at + 6 - open - 1) +
                                                   "'s count is not a whole number (expected digits, got \"" +
                                                   oneLine(std::string(value.substr(0, 20))) + "\")");
    }
    return std::nullopt;
}

/// The value of attribute `name` in the tag text `tag` (between its quotes), or empty.
std::string_view colladaAttribute(std::string_view tag, std::string_view name)
{
    for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + name.size())) {
        if (at > 0 && tag[at - 1] != ' ' && tag[at - 1] != '\t' && tag[at - 1] != '\n' && tag[at - 1] != '\r') continue;
        std::size_t i = at + name.size();
        while (i < tag.size() && (tag[i] == ' ' || tag[i] == '\t' || tag[i] == '\n' || tag[i] == '\r')) ++i;
        if (i >= tag.size() || tag[i] != '=') continue;
        ++i;
        while (i < tag.size() && (tag[i] == ' ' || tag[i] == '\t' || tag[i] == '\n' || tag[i] == '\r')) ++i;
        if (i >= tag.size() || (tag[i] != '"' && tag[i] != '\'')) continue;
        const std::size_t close = tag.find(tag[i], i + 1);
        if (close == std::string_view::npos) return {};
        return tag.substr(i + 1, close - i - 1);
    }
    return {};
}

/// A whole number of at most 18 digits, or nullopt.
std::optional<std::uint64_t> colladaNumber(std::string_view text)
{
    if (text.empty() || text.size() > 18) return std::nullopt;
    std::uint64_t value = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + std::uint64_t(c - '0');
    }
    return value;
}

/// assimp 5.2 reads an accessor's `count` x `stride` values (from `offset`) out of the array it
/// names without checking the array holds them (found by fuzz_scene_take: `<float_array
/// count="0">` under an accessor of 3 x 3 crashed `bunraku info` with a null read): every
/// accessor must fit its array's count, and every array's count must not exceed the values
/// written in it.
std::optional<Error> checkColladaAccessors(const std::string& bytes, const std::string& source)
{
    // The arrays: id -> count, each count checked against the values in the element.
    std::map<std::string, std::uint64_t, std::less<>> arrays;
    for (std::size_t at = bytes.find("_array"); at != std::string::npos; at = bytes.find("_array", at + 6)) {
        const std::size_t open = bytes.rfind('<', at);
        if (open == std::string::npos || at - open > 16 || open + 1 == at || bytes[open + 1] == '/') continue;
        const std::size_t end = bytes.find('>', at);
        if (end == std::string::npos) continue;
        const std::string_view tag(bytes.data() + at + 6, end - at - 6);
        const auto count = colladaNumber(colladaAttribute(tag, "count"));
        if (!count) continue; // checkColladaArrayCounts says why
        const std::string element = std::string(bytes, open + 1, at + 6 - open - 1);
        const std::size_t close = bytes.find("</" + element, end);
        if (close == std::string::npos) continue;
        std::uint64_t values = 0;
        bool inside = false;
        for (std::size_t i = end + 1; i < close; ++i) {
            const bool space = bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\n' || bytes[i] == '\r';
            if (!space && !inside) ++values;
            inside = !space;
        }
        if (*count > values)
            return makeError(ErrorCode::Parse, source + ": a Collada " + element + " says it holds " + std::to_string(*count) +
                                                   " values but holds " + std::to_string(values));
        const std::string_view id = colladaAttribute(tag, "id");
        if (!id.empty()) arrays[std::string(id)] = *count;
    }
    for (std::size_t at = bytes.find("<accessor"); at != std::string::npos; at = bytes.find("<accessor", at + 9)) {
        const std::size_t end = bytes.find('>', at);
        if (end == std::string::npos) break;
        const std::string_view tag(bytes.data() + at + 9, end - at - 9);
        std::string_view target = colladaAttribute(tag, "source");
        if (!target.empty() && target.front() == '#') target.remove_prefix(1);
        const auto array = arrays.find(target);
        if (array == arrays.end()) continue; // assimp reports an unknown source itself
        const auto count = colladaNumber(colladaAttribute(tag, "count"));
        const std::string_view strideText = colladaAttribute(tag, "stride");
        const std::string_view offsetText = colladaAttribute(tag, "offset");
        const auto stride = strideText.empty() ? std::optional<std::uint64_t>(1) : colladaNumber(strideText);
        const auto offset = offsetText.empty() ? std::optional<std::uint64_t>(0) : colladaNumber(offsetText);
        const std::uint64_t step = stride ? std::max<std::uint64_t>(*stride, 1) : 1;
        // count x stride + offset <= the array's count, without overflowing.
        const bool fits = count && stride && offset && *offset <= array->second && *count <= (array->second - *offset) / step;
        if (!fits)
            return makeError(ErrorCode::Parse, source + ": a Collada accessor reads past its array '" + oneLine(std::string(target.substr(0, 40))) +
                                                   "' (expected count x stride + offset within the array's " +
                                                   std::to_string(array->second) + " values)");
    }
    return std::nullopt;
}

/// assimp 5.2 reads a Collada index list (`<p>`, `<vcount>`, `<v>`, `<h>`) with a word that is no
/// number in it into gigabytes (found by fuzz_scene_take: `<p>0 St9exception1 2</p>` grew
/// `bunraku info` past 12 GB): such lists are refused before it reads them.
std::optional<Error> checkColladaIndexLists(const std::string& bytes, const std::string& source)
{
    for (const char* name : {"p", "vcount", "v", "h"}) {
        const std::string open = std::string("<") + name + ">";
        const std::string close = std::string("</") + name + ">";
        for (std::size_t at = bytes.find(open); at != std::string::npos; at = bytes.find(open, at + open.size())) {
            const std::size_t from = at + open.size();
            const std::size_t to = bytes.find(close, from);
            if (to == std::string::npos) break;
            for (std::size_t i = from; i < to; ++i) {
                const char c = bytes[i];
                if ((c >= '0' && c <= '9') || c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '-' || c == '+') continue;
                return makeError(ErrorCode::Parse, source + ": a Collada <" + name +
                                                       "> index list holds something that is not a whole number (expected digits and spaces)");
            }
        }
    }
    return std::nullopt;
}

/// Reads the bytes with assimp (glTF slimmed first) and converts the scene.
Result<SceneTake> readWithAssimp(const std::string& bytes, const std::string& extension, SceneFormat format, const std::string& source,
                                 const fs::path* folder, const SceneTakeOptions& options, const RunControl& control)
{
    if (bytes.empty()) return makeError(ErrorCode::Parse, source + ": empty file");
    // assimp follows FBX connections recursively: a cycle overflows its stack (fuzz_scene_take).
    if (format == SceneFormat::Fbx)
        if (auto error = checkFbxConnections(bytes, source)) return *error;
    if (format == SceneFormat::Collada)
        if (auto error = checkColladaArrayCounts(bytes, source)) return *error;
    if (format == SceneFormat::Collada)
        if (auto error = checkColladaIndexLists(bytes, source)) return *error;
    if (format == SceneFormat::Collada)
        if (auto error = checkColladaAccessors(bytes, source)) return *error;
    const std::string* input = &bytes;
    std::string slim;
    // assimp aborts on a model's KTime property, which it would keep as metadata: renamed to a
    // type it does not know, it is dropped (a take reads none of them; fuzz_scene_take).
    if (format == SceneFormat::Fbx) {
        const auto times = fbxModelTimeProperties(bytes);
        if (!times.empty()) {
            slim = bytes;
            for (const std::size_t at : times) slim[at + 4] = 'x'; // "KTime" -> "KTimx"
            input = &slim;
        }
    }
    int meshes = -1;
    FileSkins skins;
    if (format == SceneFormat::Gltf) {
        auto slimmed = slimGltf(bytes, extension == ".glb" ? GltfEncoding::Binary : GltfEncoding::Text, folder, source, meshes, &skins);
        if (!slimmed) return slimmed.error();
        slim = std::move(slimmed).value();
        input = &slim;
    }
    Assimp::Importer importer;
    configure(importer);
    const aiScene* scene = importer.ReadFileFromMemory(input->data(), input->size(), 0, extension.substr(1).c_str());
    if (!scene) return assimpError(source, format, importer);
    auto take = convertScene(*scene, format, source, options, control, format == SceneFormat::Gltf ? &skins : nullptr);
    if (take && meshes >= 0) take->info.meshes = meshes;
    return take;
}

} // namespace

bool isSceneTakeFile(const fs::path& file) { return formatOfExtension(lowerExtension(file)).has_value(); }

const std::vector<std::string>& sceneTakeExtensions()
{
    static const std::vector<std::string> extensions{".fbx", ".glb", ".gltf", ".dae"};
    return extensions;
}

Result<SceneTake> parseSceneTake(const std::string& bytes, const std::string& extension, const std::string& sourceName,
                                 const SceneTakeOptions& options, const RunControl& control)
{
    auto format = formatOf(extension, sourceName);
    if (!format) return format.error();
    return readWithAssimp(bytes, extension, *format, sourceName, nullptr, options, control);
}

Result<SceneTake> readSceneTake(const fs::path& file, const SceneTakeOptions& options, const RunControl& control)
{
    const std::string source = file.string();
    const std::string extension = lowerExtension(file);
    auto format = formatOf(extension, source);
    if (!format) return format.error();
    auto bytes = readTextFile(file, kMaxSceneFileBytes);
    if (!bytes) return bytes.error();
    // Text glTF may keep its buffers in files beside it.
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    return readWithAssimp(*bytes, extension, *format, source, &folder, options, control);
}

Result<std::vector<std::string>> listSceneAnimations(const fs::path& file)
{
    // Read as a take of its first animation (assimp reads them all): the names come with it. A
    // file without animation has none to list.
    auto take = readSceneTake(file);
    if (!take) {
        if (take.error().code == ErrorCode::Unsupported && take.error().message.find("no animation in this") != std::string::npos)
            return std::vector<std::string>{};
        return take.error();
    }
    return take->info.animations;
}

} // namespace bunraku::analysis::io
