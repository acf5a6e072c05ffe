#pragma once
/// The shared Bandai Namco BVH files (../shared/data/bandai, read in place, never copied), for
/// tests that need real motion capture. When they are missing the test fails under CI=true
/// and is reported as skipped otherwise (a WARN naming the folder), never passed silently.
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace bunraku::test {

/// Every .bvh file of the Bandai folder, sorted; empty (after failing or warning) when absent.
inline std::vector<std::filesystem::path> bandaiFilesOrSkip()
{
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    if (std::filesystem::is_directory(bandaiDir(), ec))
        for (const auto& entry : std::filesystem::directory_iterator(bandaiDir(), ec))
            if (entry.path().extension() == ".bvh") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    // Missing: fails under CI=true, reported as skipped otherwise (tests/support/peer.h).
    (void)requireBandaiData(!files.empty());
    return files;
}

} // namespace bunraku::test
