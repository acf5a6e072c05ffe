#pragma once
/// Paths the tests read from: the source tree, the shared test data (../shared/data) and a
/// scratch folder per test under the build tree.
#include <filesystem>
#include <string>

namespace bunraku::test {

inline std::filesystem::path sourceDir() { return BUNRAKU_SOURCE_DIR; }
inline std::filesystem::path sharedDataDir() { return std::filesystem::path(BUNRAKU_SHARED_DIR) / "data"; }
inline std::filesystem::path bandaiDir() { return sharedDataDir() / "bandai"; }

/// An empty folder under the build tree for one test's files.
inline std::filesystem::path scratchDir(const std::string& name)
{
    auto dir = std::filesystem::path(BUNRAKU_BINARY_DIR) / "test-scratch" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace bunraku::test
