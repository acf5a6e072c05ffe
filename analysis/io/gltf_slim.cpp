#include "analysis/io/gltf_slim.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/scene_mesh.h"
#include "analysis/io/scene_take.h"
#include "analysis/io/text_scan.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>

namespace bunraku::analysis::io {

namespace {

namespace fs = std::filesystem;

std::string base64(std::string_view bytes)
{
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const unsigned b0 = std::uint8_t(bytes[i]), b1 = i + 1 < bytes.size() ? std::uint8_t(bytes[i + 1]) : 0u,
                       b2 = i + 2 < bytes.size() ? std::uint8_t(bytes[i + 2]) : 0u;
        out += table[b0 >> 2];
        out += table[((b0 & 3) << 4) | (b1 >> 4)];
        out += i + 1 < bytes.size() ? table[((b1 & 15) << 2) | (b2 >> 6)] : '=';
        out += i + 2 < bytes.size() ? table[b2 & 63] : '=';
    }
    return out;
}

} // namespace

Result<std::string> slimGltf(const std::string& bytes, GltfEncoding encoding, const fs::path* folder, const std::string& source, int& meshes,
                             FileSkins* skins)
{
    const bool binary = encoding == GltfEncoding::Binary;
    const auto bad = [&](const std::string& what) { return parseError(source, 0, "not a readable glTF file: " + what); };
    std::string_view json = bytes;
    std::string rest; // a binary file's chunks after the JSON
    if (binary) {
        auto u32 = [&](std::size_t at) {
            std::uint32_t v = 0;
            std::memcpy(&v, bytes.data() + at, 4);
            return v;
        };
        if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0) return bad("expected the glTF binary header");
        if (u32(4) != 2) return bad("expected glTF version 2");
        const std::uint32_t chunk = u32(12);
        if (u32(16) != 0x4E4F534Au || chunk > bytes.size() - 20) return bad("expected a JSON chunk inside the file");
        json = std::string_view(bytes).substr(20, chunk);
        rest = bytes.substr(20 + chunk);
    }
    nlohmann::json document = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
    if (document.is_discarded() || !document.is_object()) return bad("its JSON does not parse");
    meshes = document.contains("meshes") && document["meshes"].is_array() ? int(document["meshes"].size()) : 0;
    // Every buffer's bytes (for the skins): a binary file's BIN chunk, data URIs decoded, files
    // beside a text file read (and embedded as data URIs for assimp).
    std::vector<std::string> held;
    std::vector<std::string_view> buffers;
    if (document.contains("buffers") && document["buffers"].is_array()) {
        held.reserve(document["buffers"].size());
        for (auto& buffer : document["buffers"]) {
            buffers.emplace_back();
            if (!buffer.is_object()) continue;
            if (!buffer.contains("uri")) {
                // The binary chunk: its length, "BIN\0", then the bytes.
                if (binary && buffers.size() == 1 && rest.size() >= 8) {
                    std::uint32_t length = 0, type = 0;
                    std::memcpy(&length, rest.data(), 4);
                    std::memcpy(&type, rest.data() + 4, 4);
                    if (type == 0x004E4942u && length <= rest.size() - 8) buffers.back() = std::string_view(rest).substr(8, length);
                }
                continue;
            }
            if (!buffer["uri"].is_string()) continue;
            const std::string uri = buffer["uri"].get<std::string>();
            if (uri.rfind("data:", 0) == 0) {
                const std::size_t comma = uri.find(";base64,");
                if (!skins || comma == std::string::npos) continue;
                bool ok = false;
                held.push_back(decodeBase64(std::string_view(uri).substr(comma + 8), ok));
                if (ok) buffers.back() = held.back();
                continue;
            }
            if (binary) continue;
            if (!folder) return bad("its buffer '" + detail::quoted(uri) + "' is in another file");
            const fs::path relative(uri);
            if (relative.is_absolute() || uri.find("..") != std::string::npos || uri.find('%') != std::string::npos)
                return bad("its buffer " + detail::quoted(uri) + " is not a file beside it");
            auto data = readTextFile(*folder / relative, kMaxSceneFileBytes);
            if (!data) return data.error();
            buffer["uri"] = "data:application/octet-stream;base64," + base64(*data);
            held.push_back(std::move(*data));
            buffers.back() = held.back();
        }
    }
    if (skins) *skins = readGltfSkins(document, buffers);
    for (const char* key : {"meshes", "skins", "materials", "textures", "images", "samplers", "cameras"}) document.erase(key);
    if (document.contains("nodes") && document["nodes"].is_array())
        for (auto& node : document["nodes"])
            if (node.is_object())
                for (const char* key : {"mesh", "skin", "camera", "weights"}) node.erase(key);
    std::string text = document.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (!binary) return text;
    while (text.size() % 4 != 0) text += ' ';
    std::string out = "glTF";
    auto put = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    put(2);
    put(std::uint32_t(12 + 8 + text.size() + rest.size()));
    put(std::uint32_t(text.size()));
    put(0x4E4F534Au);
    out += text;
    out += rest;
    return out;
}

} // namespace bunraku::analysis::io
