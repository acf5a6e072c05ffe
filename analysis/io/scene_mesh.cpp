#include "analysis/io/scene_mesh.h"

#include "analysis/core/skeleton_mesh.h"
#include "analysis/io/text_scan.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

namespace bunraku::analysis::io {

void resizeInfluences(FileSkin& skin, std::size_t vertices)
{
    skin.bones.assign(vertices, {-1, -1, -1, -1});
    skin.weights.assign(vertices, Eigen::Vector4f::Zero());
}

void addInfluence(FileSkin& skin, std::size_t vertex, int bone, float weight)
{
    if (vertex >= skin.bones.size() || !(weight > 0.0f)) return;
    auto& bones = skin.bones[vertex];
    Eigen::Vector4f& weights = skin.weights[vertex];
    for (int k = 0; k < 4; ++k) {
        if (bones[std::size_t(k)] == bone) { // the same bone twice (split primitives): summed
            weights[k] += weight;
            return;
        }
    }
    int smallest = -1;
    for (int k = 0; k < 4 && smallest < 0; ++k)
        if (bones[std::size_t(k)] < 0) smallest = k;
    if (smallest < 0) { // full: the smallest goes when the new one is larger
        ++skin.extraInfluences;
        weights.minCoeff(&smallest);
        if (weights[smallest] >= weight) return;
    }
    bones[std::size_t(smallest)] = bone;
    weights[smallest] = weight;
}

std::string decodeBase64(std::string_view text, bool& ok)
{
    ok = true;
    std::string out;
    out.reserve(text.size() / 4 * 3);
    unsigned value = 0;
    int bits = 0;
    for (const char c : text) {
        int digit = -1;
        if (c >= 'A' && c <= 'Z') digit = c - 'A';
        else if (c >= 'a' && c <= 'z') digit = c - 'a' + 26;
        else if (c >= '0' && c <= '9') digit = c - '0' + 52;
        else if (c == '+' || c == '-') digit = 62;
        else if (c == '/' || c == '_') digit = 63;
        else if (c == '=') break;
        else if (c == '\n' || c == '\r' || c == ' ') continue;
        if (digit < 0) {
            ok = false;
            return {};
        }
        value = (value << 6) | unsigned(digit);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += char((value >> bits) & 0xFF);
        }
    }
    return out;
}

namespace {

using json = nlohmann::json;

/// An accessor's values as doubles (count x components), checked against its buffer view and
/// buffer; an error text when unusable.
struct AccessorRead {
    std::vector<double> values;
    std::size_t count = 0;
    std::string error;
};

int componentsOf(const std::string& type)
{
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    if (type == "MAT4") return 16;
    return 0;
}

int sizeOf(int componentType)
{
    switch (componentType) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
    }
}

std::optional<std::size_t> whole(const json& object, const char* key, std::size_t fallback)
{
    if (!object.contains(key)) return fallback;
    const json& value = object[key];
    if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<long long>() >= 0)) return std::nullopt;
    return std::size_t(value.get<unsigned long long>());
}

AccessorRead readAccessor(const json& document, const std::vector<std::string_view>& buffers, const json& indexValue, int components,
                          std::size_t maxCount)
{
    AccessorRead out;
    const auto fail = [&](std::string what) {
        out.error = std::move(what);
        out.values.clear();
        return out;
    };
    if (!indexValue.is_number_unsigned()) return fail("an accessor index that is not a whole number");
    const std::size_t index = indexValue.get<std::size_t>();
    const json& accessors = document.contains("accessors") ? document["accessors"] : json();
    if (!accessors.is_array() || index >= accessors.size() || !accessors[index].is_object()) return fail("accessor " + std::to_string(index) + " is missing");
    const json& accessor = accessors[index];
    const std::string where = "accessor " + std::to_string(index);
    if (accessor.contains("sparse")) return fail(where + " is sparse (not read)");
    if (!accessor.contains("type") || !accessor["type"].is_string() || componentsOf(accessor["type"].get<std::string>()) != components)
        return fail(where + " has the wrong type");
    const auto count = whole(accessor, "count", 0);
    const auto offset = whole(accessor, "byteOffset", 0);
    const int componentType = accessor.contains("componentType") && accessor["componentType"].is_number_integer() ? accessor["componentType"].get<int>() : 0;
    const int size = sizeOf(componentType);
    if (!count || !offset || size == 0) return fail(where + " has a bad count, offset or component type");
    if (*count > maxCount) return fail(where + " claims " + std::to_string(*count) + " values (more than " + std::to_string(maxCount) + ")");
    const bool normalized = accessor.contains("normalized") && accessor["normalized"].is_boolean() && accessor["normalized"].get<bool>();
    out.count = *count;
    if (*count == 0) return out;
    if (!accessor.contains("bufferView")) return fail(where + " has no buffer view");
    const json& views = document.contains("bufferViews") ? document["bufferViews"] : json();
    const auto viewIndex = whole(accessor, "bufferView", 0);
    if (!views.is_array() || !viewIndex || *viewIndex >= views.size() || !views[*viewIndex].is_object()) return fail(where + "'s buffer view is missing");
    const json& view = views[*viewIndex];
    const auto bufferIndex = whole(view, "buffer", ~std::size_t(0));
    const auto viewOffset = whole(view, "byteOffset", 0);
    const auto viewLength = whole(view, "byteLength", ~std::size_t(0));
    const std::size_t element = std::size_t(size) * std::size_t(components);
    const auto stride = whole(view, "byteStride", element);
    if (!bufferIndex || !viewOffset || !viewLength || !stride || *bufferIndex >= buffers.size()) return fail(where + "'s buffer view names no buffer");
    const std::string_view buffer = buffers[*bufferIndex];
    if (*viewOffset > buffer.size() || *viewLength > buffer.size() - *viewOffset) return fail(where + "'s buffer view reaches past its buffer");
    if (*stride < element || *stride > 252) return fail(where + "'s stride is smaller than its values");
    // offset + (count - 1) x stride + element <= length, without overflowing.
    if (*offset > *viewLength || element > *viewLength - *offset || (*count - 1) > (*viewLength - *offset - element) / *stride)
        return fail(where + " reads past its buffer view");
    const char* base = buffer.data() + *viewOffset + *offset;
    out.values.resize(*count * std::size_t(components));
    for (std::size_t i = 0; i < *count; ++i) {
        const char* at = base + i * *stride;
        for (int c = 0; c < components; ++c) {
            const char* p = at + c * size;
            double value = 0.0;
            switch (componentType) {
            case 5120: { std::int8_t v; std::memcpy(&v, p, 1); value = normalized ? std::max(double(v) / 127.0, -1.0) : double(v); break; }
            case 5121: { std::uint8_t v; std::memcpy(&v, p, 1); value = normalized ? double(v) / 255.0 : double(v); break; }
            case 5122: { std::int16_t v; std::memcpy(&v, p, 2); value = normalized ? std::max(double(v) / 32767.0, -1.0) : double(v); break; }
            case 5123: { std::uint16_t v; std::memcpy(&v, p, 2); value = normalized ? double(v) / 65535.0 : double(v); break; }
            case 5125: { std::uint32_t v; std::memcpy(&v, p, 4); value = double(v); break; }
            case 5126: { float v; std::memcpy(&v, p, 4); value = double(v); break; }
            }
            if (!std::isfinite(value)) return fail(where + " holds a value that is not a number");
            out.values[i * std::size_t(components) + std::size_t(c)] = value;
        }
    }
    return out;
}

std::string nodeName(const json& nodes, std::size_t index)
{
    if (index < nodes.size() && nodes[index].is_object() && nodes[index].contains("name") && nodes[index]["name"].is_string())
        return nodes[index]["name"].get<std::string>();
    return {};
}

/// One mesh node's skin, or a note.
std::optional<FileSkin> readSkinnedNode(const json& document, const std::vector<std::string_view>& buffers, std::size_t nodeIndex,
                                        std::string& note)
{
    const json& nodes = document["nodes"];
    const json& node = nodes[nodeIndex];
    FileSkin skin;
    skin.name = nodeName(nodes, nodeIndex);
    if (!detail::isUtf8(skin.name)) skin.name = "node " + std::to_string(nodeIndex);
    const std::string label = "the mesh of node " + std::to_string(nodeIndex) + (skin.name.empty() ? "" : " '" + skin.name + "'");
    const auto drop = [&](const std::string& why) {
        note = label + " dropped: " + why;
        return std::nullopt;
    };
    const auto meshIndex = whole(node, "mesh", ~std::size_t(0));
    const auto skinIndex = whole(node, "skin", ~std::size_t(0));
    const json& meshes = document["meshes"];
    const json& skins = document.contains("skins") ? document["skins"] : json();
    if (!meshIndex || !skinIndex || !meshes.is_array() || *meshIndex >= meshes.size() || !skins.is_array() || *skinIndex >= skins.size())
        return drop("its mesh or skin is missing");
    const json& skinJson = skins[*skinIndex];
    if (!skinJson.is_object() || !skinJson.contains("joints") || !skinJson["joints"].is_array() || skinJson["joints"].empty())
        return drop("its skin has no joints");
    const json& joints = skinJson["joints"];
    if (joints.size() > 65535) return drop("its skin has more than 65535 joints");
    for (const json& joint : joints) {
        if (!joint.is_number_unsigned() || joint.get<std::size_t>() >= nodes.size()) return drop("its skin names a joint that is no node");
        const std::string name = nodeName(nodes, joint.get<std::size_t>());
        if (name.empty() || !detail::isUtf8(name)) return drop("its skin has a joint without a name");
        skin.boneNames.push_back(name);
    }
    skin.offsets.assign(joints.size(), Eigen::Matrix4d::Identity());
    if (skinJson.contains("inverseBindMatrices")) {
        const AccessorRead matrices = readAccessor(document, buffers, skinJson["inverseBindMatrices"], 16, joints.size());
        if (!matrices.error.empty()) return drop(matrices.error);
        if (matrices.count != joints.size()) return drop("its skin has " + std::to_string(matrices.count) + " inverse bind matrices for " + std::to_string(joints.size()) + " joints");
        for (std::size_t b = 0; b < joints.size(); ++b)
            skin.offsets[b] = Eigen::Map<const Eigen::Matrix4d>(matrices.values.data() + 16 * b); // column-major, as glTF
    }
    const json& mesh = meshes[*meshIndex];
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) return drop("its mesh has no primitives");
    for (const json& primitive : mesh["primitives"]) {
        if (!primitive.is_object() || !primitive.contains("attributes") || !primitive["attributes"].is_object()) return drop("a primitive has no attributes");
        if (primitive.contains("mode") && !(primitive["mode"].is_number_integer() && primitive["mode"].get<int>() == 4)) return drop("a primitive is not triangles");
        const json& attributes = primitive["attributes"];
        if (!attributes.contains("POSITION") || !attributes.contains("JOINTS_0") || !attributes.contains("WEIGHTS_0"))
            return drop("a primitive has no POSITION, JOINTS_0 or WEIGHTS_0");
        const std::size_t room = kMaxSkeletonMeshVertices - std::min(kMaxSkeletonMeshVertices, skin.positions.size());
        const AccessorRead positions = readAccessor(document, buffers, attributes["POSITION"], 3, room);
        if (!positions.error.empty()) return drop(positions.error);
        const std::size_t n = positions.count;
        const AccessorRead jointsRead = readAccessor(document, buffers, attributes["JOINTS_0"], 4, n);
        if (!jointsRead.error.empty()) return drop(jointsRead.error);
        const AccessorRead weights = readAccessor(document, buffers, attributes["WEIGHTS_0"], 4, n);
        if (!weights.error.empty()) return drop(weights.error);
        if (jointsRead.count != n || weights.count != n) return drop("a primitive's joints or weights do not match its positions");
        AccessorRead normals;
        if (attributes.contains("NORMAL")) {
            normals = readAccessor(document, buffers, attributes["NORMAL"], 3, n);
            if (!normals.error.empty()) return drop(normals.error);
            if (normals.count != n) return drop("a primitive's normals do not match its positions");
        }
        if (attributes.contains("JOINTS_1")) note = label + ": influences beyond JOINTS_0/WEIGHTS_0 not read";
        const std::size_t first = skin.positions.size();
        skin.positions.resize(first + n);
        skin.bones.resize(first + n, {-1, -1, -1, -1});
        skin.weights.resize(first + n, Eigen::Vector4f::Zero());
        for (std::size_t v = 0; v < n; ++v) {
            skin.positions[first + v] = Eigen::Vector3d(positions.values[3 * v], positions.values[3 * v + 1], positions.values[3 * v + 2]).cast<float>();
            for (int k = 0; k < 4; ++k) {
                const double joint = jointsRead.values[4 * v + std::size_t(k)];
                const double weight = weights.values[4 * v + std::size_t(k)];
                if (!(weight > 0.0)) continue;
                if (!(joint >= 0.0 && joint < double(joints.size()))) return drop("vertex " + std::to_string(v) + " names joint " + std::to_string(long(joint)) + " of a skin of " + std::to_string(joints.size()));
                addInfluence(skin, first + v, int(joint), float(weight));
            }
        }
        skin.normals.resize(first + n, Eigen::Vector3f::Zero()); // zero: made from the triangles
        for (std::size_t v = 0; v < n && !normals.values.empty(); ++v)
            skin.normals[first + v] = Eigen::Vector3d(normals.values[3 * v], normals.values[3 * v + 1], normals.values[3 * v + 2]).cast<float>();
        if (primitive.contains("indices")) {
            const AccessorRead indices = readAccessor(document, buffers, primitive["indices"], 1, 3 * kMaxSkeletonMeshTriangles);
            if (!indices.error.empty()) return drop(indices.error);
            if (indices.count % 3 != 0) return drop("a primitive's index count is not a multiple of 3");
            for (const double i : indices.values) {
                if (!(i >= 0.0 && i < double(n))) return drop("a triangle names vertex " + std::to_string(long(i)) + " of " + std::to_string(n));
                skin.indices.push_back(std::uint32_t(first + std::size_t(i)));
            }
        } else {
            if (n % 3 != 0) return drop("a primitive's vertex count is not a multiple of 3");
            for (std::size_t i = 0; i < n; ++i) skin.indices.push_back(std::uint32_t(first + i));
        }
        if (skin.indices.size() / 3 > kMaxSkeletonMeshTriangles) return drop("more than " + std::to_string(kMaxSkeletonMeshTriangles) + " triangles");
    }
    if (skin.positions.empty()) return drop("it has no vertices");
    return skin;
}

} // namespace

FileSkins readGltfSkins(const nlohmann::json& document, const std::vector<std::string_view>& buffers)
{
    FileSkins out;
    if (!document.is_object() || !document.contains("nodes") || !document["nodes"].is_array() || !document.contains("meshes") || !document["meshes"].is_array())
        return out;
    const json& nodes = document["nodes"];
    std::size_t vertices = 0;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (!nodes[n].is_object() || !nodes[n].contains("mesh")) continue;
        if (!nodes[n].contains("skin")) {
            ++out.unskinnedMeshes;
            continue;
        }
        std::string note;
        auto skin = readSkinnedNode(document, buffers, n, note);
        if (!note.empty()) out.notes.push_back(note);
        if (!skin) continue;
        vertices += skin->positions.size();
        if (vertices > kMaxSkeletonMeshVertices) {
            out.notes.push_back("meshes beyond " + std::to_string(kMaxSkeletonMeshVertices) + " vertices dropped");
            break;
        }
        out.skins.push_back(std::move(*skin));
    }
    return out;
}

} // namespace bunraku::analysis::io
