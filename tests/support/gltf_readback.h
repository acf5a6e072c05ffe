#pragma once
/// Reading our .glb exports back as a client would (tinygltf, the node hierarchy and the first
/// animation's samplers at a keyframe): a peer's forward kinematics of the file. Header-only;
/// link TinyGLTF::TinyGLTF.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <tiny_gltf.h>

#include <cstddef>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace bunraku::test {

/// A float accessor (tightly packed) as doubles.
inline std::vector<double> gltfFloats(const tinygltf::Model& model, int accessorIndex)
{
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(accessorIndex)];
    REQUIRE(accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT);
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
    const auto* data = reinterpret_cast<const float*>(model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset +
                                                      accessor.byteOffset);
    const std::size_t n = accessor.count * std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type)));
    return std::vector<double>(data, data + n);
}

/// World pose (metres, glTF axes) of every named node at keyframe `frame`.
inline std::map<std::string, Eigen::Isometry3d> gltfNodePoses(const tinygltf::Model& model, std::size_t frame)
{
    std::vector<Eigen::Quaterniond> rotation(model.nodes.size(), Eigen::Quaterniond::Identity());
    std::vector<Eigen::Vector3d> translation(model.nodes.size(), Eigen::Vector3d::Zero());
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const auto& node = model.nodes[n];
        if (node.rotation.size() == 4) rotation[n] = Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (node.translation.size() == 3) translation[n] = Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]);
    }
    const auto& animation = model.animations.front();
    for (const auto& channel : animation.channels) {
        const auto values = gltfFloats(model, animation.samplers[std::size_t(channel.sampler)].output);
        const auto n = std::size_t(channel.target_node);
        if (channel.target_path == "rotation")
            rotation[n] = Eigen::Quaterniond(values[4 * frame + 3], values[4 * frame], values[4 * frame + 1], values[4 * frame + 2]).normalized();
        else if (channel.target_path == "translation")
            translation[n] = Eigen::Vector3d(values[3 * frame], values[3 * frame + 1], values[3 * frame + 2]);
    }
    std::map<std::string, Eigen::Isometry3d> poses;
    std::function<void(int, const Eigen::Isometry3d&)> walk = [&](int n, const Eigen::Isometry3d& parent) {
        Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
        local.linear() = rotation[std::size_t(n)].toRotationMatrix();
        local.translation() = translation[std::size_t(n)];
        const Eigen::Isometry3d world = parent * local;
        poses[model.nodes[std::size_t(n)].name] = world;
        for (int child : model.nodes[std::size_t(n)].children) walk(child, world);
    };
    for (int root : model.scenes.front().nodes) walk(root, Eigen::Isometry3d::Identity());
    return poses;
}

/// World positions (metres, glTF axes) of every named node at keyframe `frame`.
inline std::map<std::string, Eigen::Vector3d> gltfNodePositions(const tinygltf::Model& model, std::size_t frame)
{
    std::map<std::string, Eigen::Vector3d> positions;
    for (const auto& [name, pose] : gltfNodePoses(model, frame)) positions[name] = pose.translation();
    return positions;
}

inline tinygltf::Model loadGlbBytes(const std::string& bytes)
{
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    const bool loaded = loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                    unsigned(bytes.size()));
    INFO(error << warning);
    REQUIRE(loaded);
    return model;
}

inline std::string readBinaryFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

} // namespace bunraku::test
