// docs/TUTORIAL.md's Mixamo FBX section ("9. A Mixamo FBX take"), run as written: Blender 3.4
// makes Mixamo-style FBX takes from six Bandai waves (tests/cli/blender_mixamo.py: Mixamo's
// bone names, binary FBX, every frame keyed), then the section's ```sh tutorial-mixamo commands
// run in order in a scratch folder and every output is checked against what the page says and
// against the source BVH takes. Kept apart from the tutorial's main thread (```sh tutorial,
// tests/cli/tutorial_test.cpp), which the clean-root package check also runs in a root without
// Blender. Without Blender or the Bandai files the case fails under CI=true and is reported as
// skipped otherwise.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/cli/tutorial_script.h"
#include "tests/support/peer.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include "analysis/core/corpus.h"
#include "analysis/core/skeleton.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/take_reader.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <map>

using namespace bunraku;
using bunraku::test::readTextFile;

namespace {

namespace fs = std::filesystem;

/// Bandai's joints by their Mixamo names in the files tests/cli/blender_mixamo.py makes.
const std::map<std::string, std::string>& bandaiNames()
{
    static const std::map<std::string, std::string> names = [] {
        std::map<std::string, std::string> m{{"mixamorig:Hips", "Hips"},
                                             {"mixamorig:Spine", "Spine"},
                                             {"mixamorig:Spine2", "Chest"},
                                             {"mixamorig:Neck", "Neck"},
                                             {"mixamorig:Head", "Head"}};
        for (const auto& [bandai, side] : {std::pair{"L", "Left"}, std::pair{"R", "Right"}}) {
            const std::string s = side, b = bandai;
            m["mixamorig:" + s + "Shoulder"] = "Shoulder_" + b;
            m["mixamorig:" + s + "Arm"] = "UpperArm_" + b;
            m["mixamorig:" + s + "ForeArm"] = "LowerArm_" + b;
            m["mixamorig:" + s + "Hand"] = "Hand_" + b;
            m["mixamorig:" + s + "UpLeg"] = "UpperLeg_" + b;
            m["mixamorig:" + s + "Leg"] = "LowerLeg_" + b;
            m["mixamorig:" + s + "Foot"] = "Foot_" + b;
            m["mixamorig:" + s + "ToeBase"] = "Toes_" + b;
        }
        return m;
    }();
    return names;
}

/// Joint name -> world position (cm) at `frame`, End Sites left out.
std::map<std::string, Eigen::Vector3d> jointPositions(const analysis::SkeletalMotion& motion, Eigen::Index frame)
{
    std::map<std::string, Eigen::Vector3d> positions;
    const auto poses = motion.worldPoses(frame);
    for (std::size_t j = 0; j < poses.size(); ++j)
        if (!motion.skeleton->joints[j].endSite) positions[motion.skeleton->joints[j].name] = poses[j].translation;
    return positions;
}

} // namespace

TEST_CASE("the tutorial's Mixamo FBX section runs on FBX takes Blender makes from the Bandai waves", "[cli][tutorial][blender][scene]")
{
    std::vector<std::string> sources;
    for (const char* emotion : {"normal", "exhausted"})
        for (int take = 1; take <= 3; ++take) sources.push_back(std::string("wave-right-hand_") + emotion + "_00" + std::to_string(take) + ".bvh");
    bool all = true;
    for (const auto& name : sources) all = all && fs::exists(test::bandaiDir() / name);
    if (!test::requireBandaiData(all)) return;
    if (!test::requirePeer(std::system("command -v blender >/dev/null 2>&1") == 0, "blender (Debian's Blender 3.4)",
                           "apt-get install blender (scripts/install-deps.sh)"))
        return;

    const auto steps = test::parseTutorial(readTextFile(test::sourceDir() / "docs" / "TUTORIAL.md"), "tutorial-mixamo");
    std::vector<std::string> subcommands;
    for (const auto& step : steps) subcommands.push_back(step.fileName.empty() ? step.words[1] : "(file " + step.fileName + ")");
    // The checks below follow these steps.
    REQUIRE(subcommands == std::vector<std::string>{"info", "corpus", "analyse"});

    // The section's files: what the page's Blender command makes, in the folder it names.
    const fs::path dir = test::scratchDir("tutorial_mixamo");
    const fs::path mixamo = dir / "mixamo";
    fs::create_directories(mixamo);
    const fs::path log = dir / "blender.log";
    std::string command = "blender -b --factory-startup --python-exit-code 1 -P '" +
                          (test::sourceDir() / "tests" / "cli" / "blender_mixamo.py").string() + "' -- '" + mixamo.string() + "'";
    for (const auto& name : sources) command += " '" + (test::bandaiDir() / name).string() + "'";
    command += " >'" + log.string() + "' 2>&1 </dev/null";
    const int status = std::system(command.c_str());
    INFO("blender log:\n" << test::fileBytes(log));
    REQUIRE(status == 0);

    std::vector<test::CliRun> runs;
    for (const auto& step : steps) {
        const auto arguments = test::expandTutorialWords(step, test::bandaiDir(), dir);
        const auto run = test::runBunrakuWith("env -C '" + dir.string() + "'", arguments);
        INFO("docs/TUTORIAL.md:" << step.line << ": bunraku " << step.words[1] << "\n" << run.out << run.err);
        REQUIRE(run.exitCode == 0);
        runs.push_back(run);
    }

    {
        INFO("info names the file's Mixamo joints, its unit and axis, and the part map by name\n" << runs[0].out);
        for (const char* line : {"FBX: animation 0 'Armature|mixamo.com' of 1, sampled at 30 Hz (file rate) from 0 s; file unit cm, up axis +y",
                                 "BVH: 22 joints + 5 End Sites, 72 channels, 187 frames, frame time 0.0333333 s (30 Hz, 6.2 s)",
                                 "\n  Armature  [Xposition Yposition Zposition Zrotation Xrotation Yrotation]\n"
                                 "    mixamorig:Hips  [Xposition Yposition Zposition Zrotation Xrotation Yrotation]\n"
                                 "      mixamorig:Spine  [Zrotation Xrotation Yrotation]\n"})
            CHECK(runs[0].out.find(line) != std::string::npos);
        CHECK(runs[0].out.find("part map: head=mixamorig:Head (name), shoulder=mixamorig:Spine2 (topology), "
                               "arm=mixamorig:RightForeArm (name), hand=mixamorig:RightHand (name), right side")
              != std::string::npos);
    }
    {
        INFO("the corpus: 2 cells of 3 takes, neutral 'normal', each take on the file's skeleton and equal to its source BVH");
        auto corpus = analysis::io::readCorpus(dir / "mixamo-waves");
        REQUIRE(corpus);
        REQUIRE(corpus->takes.size() == 6);
        CHECK(corpus->neutralEmotion == "normal");
        CHECK(corpus->rateHz == Approx(30.0));
        for (const char* emotion : {"normal", "exhausted"}) CHECK(corpus->cell("wave-right-hand", emotion).size() == 3);
        for (const auto& take : corpus->cell("wave-right-hand", "normal")) {
            REQUIRE(take->skeleton);
            const auto& skeleton = *take->skeleton->skeleton;
            CHECK(skeleton.find("mixamorig:Hips") >= 0);
            CHECK(skeleton.find("mixamorig:RightHand") >= 0);
            CHECK(skeleton.find("Hips") < 0);
            // Every joint where the source BVH has it, within 0.1 cm at every frame.
            const std::string source = "wave-right-hand_normal_00" + std::to_string(take->labels.takeIndex) + ".bvh";
            INFO(source);
            auto bvh = analysis::io::readTakeFile(test::bandaiDir() / source);
            REQUIRE(bvh);
            REQUIRE(take->frameCount() == bvh->frameCount());
            double worst = 0.0;
            int compared = 0;
            for (Eigen::Index f = 0; f < take->frameCount(); ++f) {
                const auto ours = jointPositions(*take->skeleton, f);
                const auto theirs = jointPositions(*bvh->skeleton, f);
                for (const auto& [mixamoName, bandaiName] : bandaiNames()) {
                    REQUIRE(ours.count(mixamoName) == 1);
                    REQUIRE(theirs.count(bandaiName) == 1);
                    worst = std::max(worst, (ours.at(mixamoName) - theirs.at(bandaiName)).norm());
                    ++compared;
                }
            }
            CHECK(compared == 21 * int(take->frameCount()));
            CHECK(worst < 0.1);
        }
    }
    {
        INFO("the analysis of the FBX corpus\n" << runs[2].out);
        CHECK(runs[2].out.find("analysed 6 takes in 2 cells (KM2O M = 1, mean P = 0.02") != std::string::npos);
        const auto summary = nlohmann::json::parse(readTextFile(dir / "mixamo-analysis" / "summary.json"));
        CHECK(summary["takes"] == 6);
    }
}
