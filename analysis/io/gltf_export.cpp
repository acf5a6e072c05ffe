#include "analysis/io/gltf_export.h"

#include "analysis/io/atomic_file.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>
#include <limits>
#include <sstream>

namespace bunraku::analysis::io {

namespace {

constexpr double kMetresPerCm = 0.01;

/// One binary buffer with a view and an accessor per array.
class BufferBuilder {
public:
    explicit BufferBuilder(tinygltf::Model& model) : m_model(model) {}

    /// Appends `count` elements of `components` floats; returns the accessor's index.
    int addFloats(const std::vector<float>& values, int components, int type, int target, bool withBounds)
    {
        const int view = addView(values.data(), values.size() * sizeof(float), target);
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = values.size() / std::size_t(components);
        accessor.type = type;
        if (withBounds) {
            accessor.minValues.assign(std::size_t(components), std::numeric_limits<double>::max());
            accessor.maxValues.assign(std::size_t(components), std::numeric_limits<double>::lowest());
            for (std::size_t i = 0; i < values.size(); ++i) {
                const std::size_t c = i % std::size_t(components);
                accessor.minValues[c] = std::min(accessor.minValues[c], double(values[i]));
                accessor.maxValues[c] = std::max(accessor.maxValues[c], double(values[i]));
            }
        }
        m_model.accessors.push_back(accessor);
        return int(m_model.accessors.size()) - 1;
    }

    int addJointIndices(const std::vector<std::uint16_t>& values)
    {
        const int view = addView(values.data(), values.size() * sizeof(std::uint16_t), TINYGLTF_TARGET_ARRAY_BUFFER);
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        accessor.count = values.size() / 4;
        accessor.type = TINYGLTF_TYPE_VEC4;
        m_model.accessors.push_back(accessor);
        return int(m_model.accessors.size()) - 1;
    }

    int addIndices(const std::vector<std::uint32_t>& values)
    {
        const int view = addView(values.data(), values.size() * sizeof(std::uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        accessor.count = values.size();
        accessor.type = TINYGLTF_TYPE_SCALAR;
        m_model.accessors.push_back(accessor);
        return int(m_model.accessors.size()) - 1;
    }

    void finish()
    {
        tinygltf::Buffer buffer;
        buffer.data = std::move(m_bytes);
        m_model.buffers.push_back(std::move(buffer));
    }

private:
    int addView(const void* data, std::size_t bytes, int target)
    {
        while (m_bytes.size() % 4 != 0) m_bytes.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = m_bytes.size();
        view.byteLength = bytes;
        view.target = target;
        const std::size_t start = m_bytes.size();
        m_bytes.resize(start + bytes);
        if (bytes > 0) std::memcpy(m_bytes.data() + start, data, bytes);
        m_model.bufferViews.push_back(view);
        return int(m_model.bufferViews.size()) - 1;
    }

    tinygltf::Model& m_model;
    std::vector<unsigned char> m_bytes;
};

/// A pose in glTF's axes and metres.
RigidTransform toGltf(const RigidTransform& pose, const Eigen::Quaterniond& g)
{
    return RigidTransform{(g * pose.rotation * g.conjugate()).normalized(), g * (kMetresPerCm * pose.translation)};
}

std::vector<double> quaternionXyzw(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }

Status checkMeshes(const Skeleton& skeleton, const std::vector<JointMesh>& meshes)
{
    const std::string name = skeleton.name.empty() ? std::string("skeleton") : skeleton.name;
    std::size_t triangles = 0;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const JointMesh& mesh = meshes[m];
        const std::string where = name + ": glTF mesh " + std::to_string(m);
        if (mesh.joint < 0 || mesh.joint >= int(skeleton.joints.size()))
            return makeError(ErrorCode::InvalidArgument, where + " is bound to no joint of the skeleton");
        if (skeleton.joints[std::size_t(mesh.joint)].endSite)
            return makeError(ErrorCode::InvalidArgument, where + " is bound to the End Site '" + skeleton.joints[std::size_t(mesh.joint)].name + "'");
        if (mesh.normals.size() != mesh.positions.size() || mesh.colours.size() != mesh.positions.size() || mesh.indices.size() % 3 != 0)
            return makeError(ErrorCode::InvalidArgument, where + ": positions, normals and colours differ in count, or the indices are not triangles");
        for (std::uint32_t index : mesh.indices)
            if (index >= mesh.positions.size()) return makeError(ErrorCode::InvalidArgument, where + ": an index is out of range");
        triangles += mesh.indices.size() / 3;
    }
    if (triangles == 0) return makeError(ErrorCode::InvalidArgument, name + ": a glTF skin needs a mesh, and no triangles were given");
    return okStatus();
}

Status checkSkinnedMesh(const Skeleton& skeleton, const SkinnedMesh& mesh)
{
    const std::string where = (skeleton.name.empty() ? std::string("skeleton") : skeleton.name) + ": glTF skinned mesh";
    const std::size_t n = mesh.positions.size();
    if (mesh.normals.size() != n || mesh.colours.size() != n || mesh.joints.size() != n || mesh.weights.size() != n)
        return makeError(ErrorCode::InvalidArgument, where + ": positions, normals, colours, joints and weights differ in count");
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
        return makeError(ErrorCode::InvalidArgument, where + ": a glTF skin needs triangles (3 indices each), and none were given");
    if (mesh.bindPoses.size() != skeleton.joints.size())
        return makeError(ErrorCode::InvalidArgument, where + ": expected one bind pose per joint (" + std::to_string(skeleton.joints.size()) +
                                                         "), got " + std::to_string(mesh.bindPoses.size()));
    if (n > std::size_t(std::numeric_limits<std::uint32_t>::max()))
        return makeError(ErrorCode::InvalidArgument, where + ": too many vertices");
    for (std::uint32_t index : mesh.indices)
        if (index >= n) return makeError(ErrorCode::InvalidArgument, where + ": an index is out of range");
    for (std::size_t v = 0; v < n; ++v) {
        float sum = 0.0f;
        for (int k = 0; k < 4; ++k) {
            const int j = mesh.joints[v][std::size_t(k)];
            const float w = mesh.weights[v][k];
            if (!std::isfinite(w) || w < 0.0f)
                return makeError(ErrorCode::InvalidArgument, where + ": vertex " + std::to_string(v) + " has a negative or non-finite weight");
            if (w == 0.0f) continue;
            if (j < 0 || j >= int(skeleton.joints.size()) || skeleton.joints[std::size_t(j)].endSite)
                return makeError(ErrorCode::InvalidArgument, where + ": vertex " + std::to_string(v) + " is weighted to no joint of the skeleton");
            sum += w;
        }
        if (!(sum > 0.0f)) return makeError(ErrorCode::InvalidArgument, where + ": vertex " + std::to_string(v) + " has no weight");
    }
    return okStatus();
}

} // namespace

Status validateMorphAnimatedMesh(const MorphAnimatedMesh& mesh)
{
    const std::string where = "glTF animated mesh '" + mesh.name + "'";
    const std::size_t keys = mesh.keyPositions.size();
    if (keys == 0 || mesh.keyTimes.size() != keys)
        return makeError(ErrorCode::InvalidArgument, where + ": expected at least one key and one time per key, got " + std::to_string(keys) +
                                                         " keys and " + std::to_string(mesh.keyTimes.size()) + " times");
    const std::size_t n = mesh.normals.size();
    if (n == 0 || mesh.colours.size() != n)
        return makeError(ErrorCode::InvalidArgument, where + ": normals and colours differ in count, or there are no vertices");
    if (n > std::size_t(std::numeric_limits<std::uint32_t>::max())) return makeError(ErrorCode::InvalidArgument, where + ": too many vertices");
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
        return makeError(ErrorCode::InvalidArgument, where + ": expected triangles (3 indices each)");
    for (std::uint32_t index : mesh.indices)
        if (index >= n) return makeError(ErrorCode::InvalidArgument, where + ": an index is out of range");
    for (std::size_t k = 0; k < keys; ++k) {
        const double t = mesh.keyTimes[k];
        if (!std::isfinite(t) || t < 0.0 || (k > 0 && !(float(t) > float(mesh.keyTimes[k - 1]))))
            return makeError(ErrorCode::InvalidArgument, where + ": key " + std::to_string(k) + "'s time is not finite, negative or not after the key before");
        if (mesh.keyPositions[k].size() != n)
            return makeError(ErrorCode::InvalidArgument, where + ": key " + std::to_string(k) + " has " + std::to_string(mesh.keyPositions[k].size()) +
                                                             " vertices, expected " + std::to_string(n));
        for (const Eigen::Vector3f& p : mesh.keyPositions[k])
            if (!p.allFinite()) return makeError(ErrorCode::InvalidArgument, where + ": key " + std::to_string(k) + " has a non-finite position");
    }
    return okStatus();
}

Result<SkinnedMesh> rigidlySkinnedMesh(const SkeletalMotion& motion, const std::vector<JointMesh>& meshes)
{
    if (auto valid = validateSkeletalMotion(motion); !valid) return valid.error();
    if (motion.frameCount() < 1) return makeError(ErrorCode::InvalidArgument, motion.skeleton->name + ": glTF export needs at least one frame");
    if (auto ok = checkMeshes(*motion.skeleton, meshes); !ok) return ok.error();
    SkinnedMesh out;
    out.bindPoses = motion.worldPoses(0);
    for (const JointMesh& mesh : meshes) {
        const RigidTransform& bind = out.bindPoses[std::size_t(mesh.joint)];
        const auto base = std::uint32_t(out.positions.size());
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            out.positions.push_back(bind.apply(mesh.positions[v].cast<double>()).cast<float>());
            out.normals.push_back((bind.rotation * mesh.normals[v].cast<double>()).normalized().cast<float>());
            out.colours.push_back(mesh.colours[v]);
            out.joints.push_back({mesh.joint, 0, 0, 0});
            out.weights.emplace_back(1.0f, 0.0f, 0.0f, 0.0f);
        }
        for (std::uint32_t index : mesh.indices) out.indices.push_back(base + index);
    }
    return out;
}

Eigen::Quaterniond gltfAxisChange()
{
    Eigen::Matrix3d gltf_R_world;
    gltf_R_world << 0, 1, 0, //
        0, 0, 1,             //
        1, 0, 0;
    return Eigen::Quaterniond(gltf_R_world);
}

Result<std::string> skeletalMotionToGlb(const SkeletalMotion& motion, double rateHz, const std::vector<JointMesh>& meshes,
                                        const GltfExportOptions& options)
{
    if (auto valid = validateSkeletalMotion(motion); !valid) return valid.error();
    if (!plausibleRate(rateHz)) return makeError(ErrorCode::InvalidArgument, "glTF export: " + rateExpectation());
    auto mesh = rigidlySkinnedMesh(motion, meshes);
    if (!mesh) return mesh.error();
    return skinnedMotionToGlb(motion, rateHz, *mesh, options);
}

Result<std::string> skinnedMotionToGlb(const SkeletalMotion& motion, double rateHz, const SkinnedMesh& skinned,
                                       const GltfExportOptions& options)
{
    if (auto valid = validateSkeletalMotion(motion); !valid) return valid.error();
    if (!plausibleRate(rateHz)) return makeError(ErrorCode::InvalidArgument, "glTF export: " + rateExpectation());
    const Skeleton& skeleton = *motion.skeleton;
    const Eigen::Index frames = motion.frameCount();
    if (frames < 1) return makeError(ErrorCode::InvalidArgument, skeleton.name + ": glTF export needs at least one frame");
    if (auto ok = checkSkinnedMesh(skeleton, skinned); !ok) return ok.error();
    if (options.animatedMesh)
        if (auto ok = validateMorphAnimatedMesh(*options.animatedMesh); !ok) return ok.error();
    const Eigen::Quaterniond g = gltfAxisChange();

    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = options.generator;
    BufferBuilder buffer(model);

    // Joints: one node each (End Sites left out), in skeleton order, which is also the skin's order.
    const std::size_t slots = skeleton.joints.size();
    std::vector<int> nodeOf(slots, -1);
    std::vector<int> skinJoints;
    for (std::size_t j = 0; j < slots; ++j) {
        const SkeletonJoint& joint = skeleton.joints[j];
        if (joint.endSite) continue;
        tinygltf::Node node;
        node.name = joint.name;
        const RigidTransform local = toGltf(motion.localPose(0, int(j)), g);
        node.rotation = quaternionXyzw(local.rotation);
        node.translation = {local.translation.x(), local.translation.y(), local.translation.z()};
        nodeOf[j] = int(model.nodes.size());
        skinJoints.push_back(nodeOf[j]);
        model.nodes.push_back(std::move(node));
        if (joint.parent >= 0) model.nodes[std::size_t(nodeOf[std::size_t(joint.parent)])].children.push_back(nodeOf[j]);
    }
    std::vector<int> skinIndexOfNode(model.nodes.size(), -1);
    for (std::size_t k = 0; k < skinJoints.size(); ++k) skinIndexOfNode[std::size_t(skinJoints[k])] = int(k);

    // Inverse bind matrices: the mesh's bind poses.
    std::vector<float> inverseBind;
    for (std::size_t j = 0; j < slots; ++j) {
        if (nodeOf[j] < 0) continue;
        const Eigen::Matrix4d m = toGltf(skinned.bindPoses[j], g).inverse().isometry().matrix();
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row) inverseBind.push_back(float(m(row, column)));
    }

    // The mesh in its bind pose; each vertex's influences by decreasing weight, renormalised
    // (unused slots: joint 0, weight 0).
    std::vector<float> positions, normals, colours, weights;
    std::vector<std::uint16_t> jointIndices;
    const std::size_t vertices = skinned.positions.size();
    positions.reserve(3 * vertices);
    normals.reserve(3 * vertices);
    colours.reserve(3 * vertices);
    weights.reserve(4 * vertices);
    jointIndices.reserve(4 * vertices);
    for (std::size_t v = 0; v < vertices; ++v) {
        const Eigen::Vector3d p = g * (kMetresPerCm * skinned.positions[v].cast<double>());
        const Eigen::Vector3d n = (g * skinned.normals[v].cast<double>()).normalized();
        for (int a = 0; a < 3; ++a) {
            positions.push_back(float(p[a]));
            normals.push_back(float(n[a]));
            colours.push_back(std::clamp(skinned.colours[v][a], 0.0f, 1.0f));
        }
        std::array<std::pair<float, int>, 4> influences{};
        double sum = 0.0;
        for (int k = 0; k < 4; ++k) {
            const float w = skinned.weights[v][k];
            influences[std::size_t(k)] = {w, w > 0.0f ? skinIndexOfNode[std::size_t(nodeOf[std::size_t(skinned.joints[v][std::size_t(k)])])] : 0};
            sum += double(w);
        }
        // The same joint twice (weights split) counts once.
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b)
                if (influences[std::size_t(a)].first > 0.0f && influences[std::size_t(b)].first > 0.0f &&
                    influences[std::size_t(a)].second == influences[std::size_t(b)].second) {
                    influences[std::size_t(a)].first += influences[std::size_t(b)].first;
                    influences[std::size_t(b)] = {0.0f, 0};
                }
        std::stable_sort(influences.begin(), influences.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        float written = 0.0f;
        for (int k = 0; k < 4; ++k) {
            auto& [w, joint] = influences[std::size_t(k)];
            if (w <= 0.0f) joint = 0;
            w = k == 0 ? 0.0f : float(double(w) / sum);
            written += w;
        }
        influences[0].first = 1.0f - written; // the largest absorbs the rounding: the sum is 1 in float
        for (const auto& [w, joint] : influences) {
            weights.push_back(w);
            jointIndices.push_back(std::uint16_t(joint));
        }
    }
    const std::vector<std::uint32_t>& indices = skinned.indices;
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = buffer.addFloats(positions, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
    primitive.attributes["NORMAL"] = buffer.addFloats(normals, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    primitive.attributes["COLOR_0"] = buffer.addFloats(colours, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    primitive.attributes["JOINTS_0"] = buffer.addJointIndices(jointIndices);
    primitive.attributes["WEIGHTS_0"] = buffer.addFloats(weights, 4, TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    primitive.indices = buffer.addIndices(indices);
    primitive.material = 0;
    tinygltf::Material material;
    material.name = "figure";
    material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.8;
    material.doubleSided = true;
    model.materials.push_back(material);
    tinygltf::Mesh mesh;
    mesh.name = options.name;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);

    tinygltf::Skin skin;
    skin.name = skeleton.name;
    skin.joints = skinJoints;
    skin.inverseBindMatrices = buffer.addFloats(inverseBind, 16, TINYGLTF_TYPE_MAT4, -1, false);
    model.skins.push_back(skin);

    tinygltf::Node meshNode;
    meshNode.name = options.name;
    meshNode.mesh = 0;
    meshNode.skin = 0;
    const int meshNodeIndex = int(model.nodes.size());
    model.nodes.push_back(meshNode);

    // The animation: every joint's rotation (signs kept continuous), the moving translations.
    std::vector<float> times(static_cast<std::size_t>(frames));
    for (Eigen::Index f = 0; f < frames; ++f) times[std::size_t(f)] = float(double(f) / rateHz);
    const int input = buffer.addFloats(times, 1, TINYGLTF_TYPE_SCALAR, -1, true);
    tinygltf::Animation animation;
    animation.name = options.name;
    std::vector<bool> moving(slots, false);
    for (int j : motion.movingJoints) moving[std::size_t(j)] = true;
    const auto addChannel = [&](int node, const char* path, const std::vector<float>& values, int type) {
        tinygltf::AnimationSampler sampler;
        sampler.input = input;
        sampler.output = buffer.addFloats(values, type == TINYGLTF_TYPE_VEC4 ? 4 : 3, type, -1, false);
        sampler.interpolation = "LINEAR";
        animation.samplers.push_back(sampler);
        tinygltf::AnimationChannel channel;
        channel.sampler = int(animation.samplers.size()) - 1;
        channel.target_node = node;
        channel.target_path = path;
        animation.channels.push_back(channel);
    };
    for (std::size_t j = 0; j < slots; ++j) {
        if (nodeOf[j] < 0) continue;
        std::vector<float> rotations;
        rotations.reserve(std::size_t(4 * frames));
        Eigen::Quaterniond previous = Eigen::Quaterniond::Identity();
        for (Eigen::Index f = 0; f < frames; ++f) {
            Eigen::Quaterniond q = toGltf(motion.localPose(f, int(j)), g).rotation;
            if (f > 0 && q.dot(previous) < 0.0) q.coeffs() = -q.coeffs();
            previous = q;
            for (double c : quaternionXyzw(q)) rotations.push_back(float(c));
        }
        addChannel(nodeOf[j], "rotation", rotations, TINYGLTF_TYPE_VEC4);
        if (!moving[j]) continue;
        std::vector<float> translations;
        translations.reserve(std::size_t(3 * frames));
        for (Eigen::Index f = 0; f < frames; ++f) {
            const Eigen::Vector3d t = g * (kMetresPerCm * motion.translation(f, int(j)));
            for (int a = 0; a < 3; ++a) translations.push_back(float(t[a]));
        }
        addChannel(nodeOf[j], "translation", translations, TINYGLTF_TYPE_VEC3);
    }
    int animatedNodeIndex = -1;
    if (options.animatedMesh) {
        // The first key is the mesh, every later key a morph target (POSITION displacements from
        // the first); the weights give key k's target 1 at its time and the others 0.
        const MorphAnimatedMesh& animated = *options.animatedMesh;
        const std::size_t keys = animated.keyPositions.size();
        const std::size_t clothVertices = animated.normals.size();
        const auto inFile = [&](const Eigen::Vector3f& p) { return g * (kMetresPerCm * p.cast<double>()); };
        std::vector<float> base, baseNormals, baseColours;
        base.reserve(3 * clothVertices);
        std::vector<Eigen::Vector3d> first(clothVertices);
        for (std::size_t v = 0; v < clothVertices; ++v) {
            first[v] = inFile(animated.keyPositions[0][v]);
            const Eigen::Vector3d n = (g * animated.normals[v].cast<double>()).normalized();
            for (int a = 0; a < 3; ++a) {
                base.push_back(float(first[v][a]));
                baseNormals.push_back(float(n[a]));
                baseColours.push_back(std::clamp(animated.colours[v][a], 0.0f, 1.0f));
            }
        }
        tinygltf::Primitive morphing;
        morphing.mode = TINYGLTF_MODE_TRIANGLES;
        morphing.attributes["POSITION"] = buffer.addFloats(base, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
        morphing.attributes["NORMAL"] = buffer.addFloats(baseNormals, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
        morphing.attributes["COLOR_0"] = buffer.addFloats(baseColours, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
        morphing.indices = buffer.addIndices(animated.indices);
        morphing.material = 0;
        tinygltf::Value::Array targetNames;
        std::vector<float> displacement(3 * clothVertices);
        for (std::size_t k = 1; k < keys; ++k) {
            for (std::size_t v = 0; v < clothVertices; ++v) {
                // The displacement from the base as stored (float), so base + displacement is the
                // key's position to float rounding.
                const Eigen::Vector3d p = inFile(animated.keyPositions[k][v]);
                for (int a = 0; a < 3; ++a) displacement[3 * v + std::size_t(a)] = float(p[a]) - base[3 * v + std::size_t(a)];
            }
            morphing.targets.push_back({{"POSITION", buffer.addFloats(displacement, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true)}});
            char targetName[48];
            std::snprintf(targetName, sizeof targetName, "t %.4f s", animated.keyTimes[k]);
            targetNames.emplace_back(std::string(targetName));
        }
        tinygltf::Mesh morphMesh;
        morphMesh.name = animated.name;
        morphMesh.primitives.push_back(morphing);
        if (keys > 1) {
            morphMesh.weights.assign(keys - 1, 0.0);
            // Blender names its shape keys after these (glTF's convention for target names).
            morphMesh.extras = tinygltf::Value(tinygltf::Value::Object{{"targetNames", tinygltf::Value(targetNames)}});
        }
        model.meshes.push_back(morphMesh);
        tinygltf::Node animatedNode;
        animatedNode.name = animated.name;
        animatedNode.mesh = int(model.meshes.size()) - 1;
        animatedNodeIndex = int(model.nodes.size());
        model.nodes.push_back(animatedNode);
        if (keys > 1) {
            std::vector<float> keyTimes(keys);
            for (std::size_t k = 0; k < keys; ++k) keyTimes[k] = float(animated.keyTimes[k]);
            std::vector<float> keyWeights(keys * (keys - 1), 0.0f);
            for (std::size_t k = 1; k < keys; ++k) keyWeights[k * (keys - 1) + (k - 1)] = 1.0f;
            tinygltf::AnimationSampler sampler;
            sampler.input = buffer.addFloats(keyTimes, 1, TINYGLTF_TYPE_SCALAR, -1, true);
            sampler.output = buffer.addFloats(keyWeights, 1, TINYGLTF_TYPE_SCALAR, -1, false);
            sampler.interpolation = "LINEAR";
            animation.samplers.push_back(sampler);
            tinygltf::AnimationChannel channel;
            channel.sampler = int(animation.samplers.size()) - 1;
            channel.target_node = animatedNodeIndex;
            channel.target_path = "weights";
            animation.channels.push_back(channel);
        }
    }
    if (!options.description.empty())
        animation.extras = tinygltf::Value(tinygltf::Value::Object{{"description", tinygltf::Value(options.description)}});
    model.animations.push_back(animation);
    buffer.finish();

    tinygltf::Scene scene;
    scene.name = options.name;
    for (std::size_t j = 0; j < slots; ++j)
        if (nodeOf[j] >= 0 && skeleton.joints[j].parent < 0) scene.nodes.push_back(nodeOf[j]);
    scene.nodes.push_back(meshNodeIndex);
    if (animatedNodeIndex >= 0) scene.nodes.push_back(animatedNodeIndex);
    if (!options.description.empty())
        scene.extras = tinygltf::Value(tinygltf::Value::Object{{"description", tinygltf::Value(options.description)}});
    model.scenes.push_back(scene);
    model.defaultScene = 0;

    std::ostringstream stream;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, stream, false, true))
        return makeError(ErrorCode::Io, skeleton.name + ": the glTF writer failed");
    return stream.str();
}

Status writeSkinnedGlb(const SkeletalMotion& motion, double rateHz, const SkinnedMesh& mesh, const std::filesystem::path& file,
                       const GltfExportOptions& options)
{
    auto bytes = skinnedMotionToGlb(motion, rateHz, mesh, options);
    if (!bytes) return makeError(bytes.error().code, file.string() + ": " + bytes.error().message);
    return writeFileAtomically(file, *bytes);
}

Status writeSkeletalGlb(const SkeletalMotion& motion, double rateHz, const std::vector<JointMesh>& meshes,
                        const std::filesystem::path& file, const GltfExportOptions& options)
{
    auto bytes = skeletalMotionToGlb(motion, rateHz, meshes, options);
    if (!bytes) return makeError(bytes.error().code, file.string() + ": " + bytes.error().message);
    return writeFileAtomically(file, *bytes);
}

} // namespace bunraku::analysis::io
