#pragma once
/// Paths the tests read from: the source tree, the shared test data (../shared/data) and a
/// scratch folder per test under the build tree.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace bunraku::test {

inline std::filesystem::path sourceDir() { return BUNRAKU_SOURCE_DIR; }
inline std::filesystem::path sharedDataDir() { return std::filesystem::path(BUNRAKU_SHARED_DIR) / "data"; }
inline std::filesystem::path bandaiDir() { return sharedDataDir() / "bandai"; }

/// Where the tests' scratch folders are.
inline std::filesystem::path scratchRoot() { return std::filesystem::path(BUNRAKU_BINARY_DIR) / "test-scratch"; }

/// An empty folder under the build tree for one test's files.
inline std::filesystem::path scratchDir(const std::string& name)
{
    auto dir = scratchRoot() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// A file's bytes as they are on disk (empty when it cannot be read).
inline std::string fileBytes(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

} // namespace bunraku::test
