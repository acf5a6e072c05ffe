#pragma once
/// The Khronos glTF validator (npm `gltf-validator`, installed globally by
/// scripts/install-deps.sh) as a peer of the .glb exports: tests/support/gltf_validate.js run by
/// node, its report parsed. A missing node or validator fails under CI=true and is reported as
/// skipped otherwise (tests/support/peer.h).
#include "tests/support/peer.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace bunraku::test {

/// "NODE_PATH=... node": the global npm modules on node's path.
inline std::string gltfValidatorNode() { return "NODE_PATH=\"$(npm root -g 2>/dev/null)\" node"; }

inline bool requireGltfValidator()
{
    const std::string probe = gltfValidatorNode() + " -e \"require('gltf-validator')\" >/dev/null 2>&1";
    return requirePeer(std::system(probe.c_str()) == 0, "the Khronos glTF validator (node and npm's gltf-validator)",
                       "npm install -g gltf-validator@2.0.0-dev.3.10 (scripts/install-deps.sh)");
}

/// The validator's report of `file` (its JSON: issues.numErrors, issues.messages, ...).
inline nlohmann::json validateGltf(const std::filesystem::path& file)
{
    const std::filesystem::path out = std::filesystem::path(file).replace_extension(".validator.json");
    const std::filesystem::path script = sourceDir() / "tests" / "support" / "gltf_validate.js";
    const std::string command = gltfValidatorNode() + " '" + script.string() + "' '" + file.string() + "' >'" + out.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(out);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    INFO("gltf-validator on " << file.string() << ":\n" << text.substr(0, 4000));
    REQUIRE(status == 0);
    return nlohmann::json::parse(text);
}

/// The validator's messages of `severity` (0 error, 1 warning, 2 info, 3 hint) as "CODE at POINTER: message" lines.
inline std::string gltfIssues(const nlohmann::json& report, int severity)
{
    std::string lines;
    for (const auto& message : report["issues"]["messages"])
        if (message.value("severity", -1) == severity)
            lines += message.value("code", std::string()) + " at " + message.value("pointer", std::string()) + ": " +
                     message.value("message", std::string()) + "\n";
    return lines;
}

} // namespace bunraku::test
