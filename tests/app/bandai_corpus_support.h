#pragma once
/// A corpus folder made from named shared Bandai files, as File > New Corpus from Files makes it,
/// for the app tests that open real takes in the workbench.

#include "tests/app/app_test_support.h"

#include "analysis/io/corpus_builder.h"
#include "analysis/io/corpus_io.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace bunraku::test {

/// Labels from "{function}_{emotion}_{take}", units guessed, written under the scratch folder
/// `scratch`; empty when the files are missing (skipped, or failed under CI=true). `allJoints`:
/// every joint a part (File > New Corpus's "all joints").
inline std::filesystem::path bandaiCorpusFolder(const std::vector<std::string>& names, const std::string& scratch,
                                                const std::string& name, bool allJoints = false)
{
    std::vector<std::filesystem::path> files;
    for (const auto& file : names) files.push_back(bandaiDir() / file);
    const bool present = std::all_of(files.begin(), files.end(), [](const auto& f) { return std::filesystem::exists(f); });
    if (!requireBandaiData(present)) return {};
    auto sources = analysis::io::labelTakeFiles(files, "{function}_{emotion}_{take}");
    REQUIRE(sources.ok());
    analysis::io::CorpusBuildOptions options;
    options.import.bvh.guessUnits = true;
    if (allJoints) options.import.bvhLayout = analysis::io::BvhTakeLayout::AllJoints;
    options.name = name;
    auto built = analysis::io::buildCorpus(*sources, options);
    REQUIRE(built.ok());
    const auto dir = scratchDir(scratch) / "corpus";
    REQUIRE(analysis::io::writeCorpus(built->corpus, dir).ok());
    return dir;
}

/// The five Bandai waves of one style: wave-right-hand_<style>_001.bvh ... _005.bvh.
inline std::vector<std::string> bandaiWaveNames(const std::string& style)
{
    std::vector<std::string> names;
    for (int k = 1; k <= 5; ++k) names.push_back("wave-right-hand_" + style + "_00" + std::to_string(k) + ".bvh");
    return names;
}

/// A shown window (demoWindow) that then opened the corpus folder `folder`; null when either failed.
inline std::unique_ptr<app::MainWindow> windowOnCorpus(const std::filesystem::path& folder)
{
    auto window = demoWindow();
    if (!window || !window->files().corpora().openCorpusFolder(QString::fromStdString(folder.string()))) return nullptr;
    return window;
}

} // namespace bunraku::test
