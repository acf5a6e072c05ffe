// Acceptance against a real client: Blender 3.4 (Debian's) imports the workbench's BVH and glTF
// exports with the source's bone and frame counts, and its joint positions on sampled frames
// agree with ours within 0.1 cm. Blender runs headless on tests/cli/blender_import.py. Without
// Blender the cases fail under CI=true and are reported as skipped otherwise.
#include "tests/cli/cli_runner.h"
#include "tests/support/blender_peer.h"
#include "tests/support/peer.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include "analysis/body/body_description.h"
#include "analysis/body/body_pose.h"
#include "analysis/body/puppet_model.h"
#include "analysis/core/skeleton.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/gltf_export.h"
#include "analysis/io/take_csv.h"
#include "render/take_export.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>

using namespace bunraku::analysis;
using bunraku::test::runBunraku;
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

/// What Blender made of a file (blender_import.py's JSON).
json blenderImport(const std::string& kind, const fs::path& file, const std::vector<Eigen::Index>& frames)
{
    const fs::path out = fs::path(file).replace_extension(kind + ".blender.json");
    const fs::path log = fs::path(file).replace_extension(kind + ".blender.log");
    std::string list;
    for (Eigen::Index f : frames) {
        if (!list.empty()) list += ',';
        list += std::to_string(f);
    }
    const fs::path script = bunraku::test::sourceDir() / "tests" / "cli" / "blender_import.py";
    const std::string command = "blender -b --factory-startup --python-exit-code 1 -P '" + script.string() + "' -- " + kind + " '" +
                                file.string() + "' '" + out.string() + "' " + list + " >'" + log.string() + "' 2>&1 </dev/null";
    const int status = std::system(command.c_str());
    std::ifstream logIn(log);
    const std::string logText((std::istreambuf_iterator<char>(logIn)), std::istreambuf_iterator<char>());
    INFO("blender log:\n" << logText);
    REQUIRE(status == 0);
    std::ifstream in(out);
    REQUIRE(in.good());
    return json::parse(in);
}

/// Blender's world (z up, forward -y) of a point in the workbench's axes (cm): through glTF's
/// axes (y up, +Z forward), which Blender's glTF importer turns as (x, y, z) -> (x, -z, y); and
/// its BVH importer (forward -Z, up Y) does the same with a file's y-up axes.
Eigen::Vector3d blenderFromWorkbench(const Eigen::Vector3d& p)
{
    const Eigen::Vector3d y_up = bunraku::analysis::io::gltfAxisChange() * p;
    return {y_up.x(), -y_up.z(), y_up.y()};
}

/// Largest distance (cm) between Blender's bone heads and the expected joint positions
/// (workbench axes, cm), by joint name; `unitsPerCm` is Blender's scale (1 for a BVH in cm,
/// 0.01 for glTF in metres).
double worstDistance(const json& blender, Eigen::Index frame, const std::map<std::string, Eigen::Vector3d>& expected, double unitsPerCm)
{
    const json& positions = blender["positions"][std::to_string(frame)];
    double worst = 0.0;
    for (const auto& [name, p] : expected) {
        INFO("joint " << name << " at frame " << frame);
        REQUIRE(positions.contains(name));
        const Eigen::Vector3d theirs(positions[name][0].get<double>(), positions[name][1].get<double>(), positions[name][2].get<double>());
        worst = std::max(worst, (theirs / unitsPerCm - blenderFromWorkbench(p)).norm());
    }
    return worst;
}

std::map<std::string, Eigen::Vector3d> jointPositions(const SkeletalMotion& motion, Eigen::Index frame)
{
    std::map<std::string, Eigen::Vector3d> positions;
    const auto poses = motion.worldPoses(frame);
    for (std::size_t j = 0; j < poses.size(); ++j)
        if (!motion.skeleton->joints[j].endSite) positions[motion.skeleton->joints[j].name] = poses[j].translation;
    return positions;
}

std::vector<Eigen::Index> sampledFrames(Eigen::Index frames) { return {0, frames / 4, frames / 2, frames - 1}; }

void checkSkeletonInBlender(const fs::path& file, const std::string& kind, const SkeletalMotion& motion)
{
    const auto frames = sampledFrames(motion.frameCount());
    const json blender = blenderImport(kind, file, frames);
    CHECK(blender["bones"].get<int>() == motion.skeleton->jointCount());
    CHECK(blender["frames"].get<Eigen::Index>() == motion.frameCount());
    for (Eigen::Index f : frames) CHECK(worstDistance(blender, f, jointPositions(motion, f), kind == "bvh" ? 1.0 : 0.01) < 0.1);
}

std::shared_ptr<const SkeletalMotion> bandaiMotion(const fs::path& path)
{
    auto file = io::readBvh(path);
    REQUIRE(file.ok());
    auto motion = io::bvhToSkeletalMotion(*file);
    REQUIRE(motion.ok());
    return *motion;
}

} // namespace

TEST_CASE("blender imports a bandai take exported by the command line as BVH and glTF on its 22-joint skeleton", "[cli][blender]")
{
    const fs::path source = bunraku::test::bandaiDir() / "bye_angry_001.bvh";
    if (!bunraku::test::requireBandaiData(fs::exists(source))) return;
    if (!bunraku::test::requireBlender()) return;
    const auto motion = bandaiMotion(source);
    REQUIRE(motion->skeleton->jointCount() == 22);
    const fs::path dir = bunraku::test::scratchDir("blender_bandai");
    for (const std::string kind : {"bvh", "glb"}) {
        INFO(kind);
        const fs::path out = dir / ("bye_angry." + kind);
        const auto run = runBunraku({"convert", source.string(), "-o", out.string()});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
        checkSkeletonInBlender(out, kind, *motion);
    }
}

TEST_CASE("blender imports a derived take on the source skeleton", "[cli][blender]")
{
    const fs::path source = bunraku::test::bandaiDir() / "bye_normal_001.bvh";
    if (!bunraku::test::requireBandaiData(fs::exists(source))) return;
    if (!bunraku::test::requireBlender()) return;
    auto file = io::readBvh(source);
    REQUIRE(file.ok());
    auto take = io::bvhToPuppetTake(*file);
    REQUIRE(take.ok());
    // Slowed to two thirds of its speed: frame f shows the source at 2f/3, every joint's rotation
    // interpolated on the sphere and the root translation linearly (built through the skeleton API).
    const SkeletalMotion& original = *take->skeleton;
    const Eigen::Index frames = (original.frameCount() - 1) * 3 / 2 + 1;
    auto slowed = std::make_shared<SkeletalMotion>(makeRestMotion(original.skeleton, frames));
    slowed->staticTranslations = original.staticTranslations;
    slowed->movingJoints = original.movingJoints;
    slowed->movingTranslations.resize(frames, original.movingTranslations.cols());
    Take derived;
    derived.channels = take->channels;
    derived.rateHz = take->rateHz;
    derived.values.resize(frames, take->channelCount());
    for (Eigen::Index f = 0; f < frames; ++f) {
        const double at = double(f) * 2.0 / 3.0;
        const auto low = std::min<Eigen::Index>(Eigen::Index(at), original.frameCount() - 2);
        const double w = at - double(low);
        for (int j = 0; j < original.jointSlots(); ++j) slowed->rotation(f, j) = original.rotation(low, j).slerp(w, original.rotation(low + 1, j));
        slowed->movingTranslations.row(f) = (1.0 - w) * original.movingTranslations.row(low) + w * original.movingTranslations.row(low + 1);
        derived.values.row(f) = (1.0 - w) * take->values.row(low) + w * take->values.row(low + 1);
    }
    derived.skeleton = slowed;
    derived.labels = {"bye", "normal", 1, "bye_normal_001 slowed to 2/3"};
    const fs::path dir = bunraku::test::scratchDir("blender_derived");
    for (const std::string kind : {"bvh", "glb"}) {
        INFO(kind);
        const fs::path out = dir / ("slowed." + kind);
        REQUIRE(bunraku::render::exportTake(derived, defaultBodyDescription(), out).ok());
        checkSkeletonInBlender(out, kind, *slowed);
    }
}

TEST_CASE("blender imports a designed demo take as glTF: the puppet's parts as bones with its mesh", "[cli][blender]")
{
    if (!bunraku::test::requireBlender()) return;
    const fs::path dir = bunraku::test::scratchDir("blender_puppet");
    REQUIRE(runBunraku({"demo", "-o", (dir / "demo").string(), "--seed", "3"}).exitCode == 0);
    fs::path takeFile;
    for (const auto& entry : fs::directory_iterator(dir / "demo"))
        if (entry.path().extension() == ".csv" && (takeFile.empty() || entry.path() < takeFile)) takeFile = entry.path();
    REQUIRE(!takeFile.empty());
    for (const std::string out : {"designed.glb", "designed.csv"}) {
        const auto run = runBunraku({"design", takeFile.string(), "-o", (dir / out).string()});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
    }
    auto designed = io::readTakeCsv(dir / "designed.csv");
    REQUIRE(designed.ok());
    const BodyDescription body = defaultBodyDescription();
    const auto frames = sampledFrames(designed->frameCount());
    const json blender = blenderImport("glb", dir / "designed.glb", frames);
    // The modelled puppet's joints (its six parts, the kimono, the sleeves) under the root.
    CHECK(blender["bones"].get<int>() == 1 + kPuppetJointCount);
    CHECK(blender["frames"].get<Eigen::Index>() == designed->frameCount());
    const PuppetMesh& puppet = shippedPuppetMesh();
    for (Eigen::Index f : frames) {
        const auto poses = puppetJointPoses(puppet, body, worldPartPoses(body, *designed, f));
        std::map<std::string, Eigen::Vector3d> expected{{"puppet", Eigen::Vector3d::Zero()}};
        for (int j = 0; j < kPuppetJointCount; ++j) expected[kPuppetJointNames[std::size_t(j)]] = poses[std::size_t(j)].translation;
        CHECK(worstDistance(blender, f, expected, 0.01) < 0.1);
    }
}

TEST_CASE("blender imports a designed Bandai take on the performer's 22-joint skeleton", "[cli][blender][design]")
{
    // The whole edit of the thesis's chapter 5 from the command line: the angry take's timing
    // (phase) and per-phrase gains applied to the normal take, exported as BVH and glTF.
    const fs::path normal = bunraku::test::bandaiDir() / "bye_normal_001.bvh";
    const fs::path angry = bunraku::test::bandaiDir() / "bye_angry_001.bvh";
    if (!bunraku::test::requireBandaiData(fs::exists(normal) && fs::exists(angry)))
        return;
    if (!bunraku::test::requireBlender()) return;
    const fs::path dir = bunraku::test::scratchDir("blender_designed");
    const std::string warp = (dir / "warp.csv").string();
    const std::string gains = (dir / "gains.json").string();
    REQUIRE(runBunraku({"phase", "--reference", normal.string(), "--sample", angry.string(), "-o", warp}).exitCode == 0);
    REQUIRE(runBunraku({"gains", "--reference", normal.string(), "--sample", angry.string(), "--warp", warp, "-o", gains}).exitCode == 0);
    for (const std::string kind : {"bvh", "glb"}) {
        const auto run = runBunraku({"design", normal.string(), "--warp", warp, "--gains", gains, "-o", (dir / ("designed." + kind)).string()});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
    }
    const auto source = bandaiMotion(normal);
    const auto designed = bandaiMotion(dir / "designed.bvh");
    REQUIRE(designed->skeleton->jointCount() == 22);
    CHECK(designed->frameCount() == bandaiMotion(angry)->frameCount()); // the emotional take's timing
    // Not the source replayed: the designed timing moves the joints.
    double moved = 0.0;
    for (Eigen::Index f : sampledFrames(designed->frameCount())) {
        const auto ours = jointPositions(*designed, f);
        const auto theirs = jointPositions(*source, std::min(f, source->frameCount() - 1));
        for (const auto& [name, p] : ours) moved = std::max(moved, (p - theirs.at(name)).norm());
    }
    CHECK(moved > 1.0);
    // Blender reads both files as the designed motion (the glTF against the BVH's joints).
    checkSkeletonInBlender(dir / "designed.bvh", "bvh", *designed);
    checkSkeletonInBlender(dir / "designed.glb", "glb", *designed);
}

TEST_CASE("blender imports a whole-body design of a Bandai wave on the performer's 22-joint skeleton", "[cli][blender][design][wholebody]")
{
    // Issue 25: phase, gains and design on the performer's whole-body axis (--all-joints: every
    // joint a part, the segments of de Leva 1996), the active wave's timing and gains on the
    // normal one, exported as BVH on the source skeleton.
    const fs::path normal = bunraku::test::bandaiDir() / "wave-right-hand_normal_001.bvh";
    const fs::path active = bunraku::test::bandaiDir() / "wave-right-hand_active_001.bvh";
    if (!bunraku::test::requireBandaiData(fs::exists(normal) && fs::exists(active))) return;
    if (!bunraku::test::requireBlender()) return;
    const fs::path dir = bunraku::test::scratchDir("blender_wholebody_designed");
    const std::string warp = (dir / "warp.csv").string();
    const std::string gains = (dir / "gains.json").string();
    const auto phase = runBunraku({"phase", "--reference", normal.string(), "--sample", active.string(), "--all-joints", "-o", warp});
    INFO(phase.err);
    REQUIRE(phase.exitCode == 0);
    const auto gained =
        runBunraku({"gains", "--reference", normal.string(), "--sample", active.string(), "--all-joints", "--warp", warp, "-o", gains});
    INFO(gained.err);
    REQUIRE(gained.exitCode == 0);
    const auto run = runBunraku({"design", normal.string(), "--all-joints", "--warp", warp, "--gains", gains, "-o",
                                 (dir / "designed.bvh").string(), "--json"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    const auto source = bandaiMotion(normal);
    const auto designed = bandaiMotion(dir / "designed.bvh");
    REQUIRE(designed->skeleton->jointCount() == 22);
    CHECK(designed->frameCount() == bandaiMotion(active)->frameCount()); // the emotional take's timing
    // Every joint moves with the design, the legs as the waving arm: not the source replayed.
    double legMoved = 0.0;
    for (Eigen::Index f : sampledFrames(designed->frameCount())) {
        const auto ours = jointPositions(*designed, f);
        const auto theirs = jointPositions(*source, std::min(f, source->frameCount() - 1));
        legMoved = std::max(legMoved, (ours.at("Foot_L") - theirs.at("Foot_L")).norm());
    }
    CHECK(legMoved > 0.1);
    checkSkeletonInBlender(dir / "designed.bvh", "bvh", *designed);
}
