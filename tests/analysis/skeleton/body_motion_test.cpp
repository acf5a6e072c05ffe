// One body per take: the puppet's rig fitted to takes without a skeleton, and every derived take
// (preprocessed, normalised by method1 and method2, averaged, weighted, designed) shown as the
// motion of one articulated body (analysis/skeleton/puppet_rig_fit.h, analysis/core/skeleton_take.h).
#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton_take.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/gltf_export.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/take_reader.h"
#include "analysis/pipeline/stages.h"
#include "analysis/skeleton/puppet_rig_fit.h"
#include "analysis/synth/demo_corpus.h"
#include "tests/support/bandai_data.h"
#include "tests/support/gltf_readback.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>

using namespace bunraku;
using namespace bunraku::analysis;

namespace {

/// A derived take and what it is, for messages.
struct Derived {
    std::string what;
    Take take;
};

/// Every kind of derived take of `corpus`: preprocessed, normalised (method1 and method2),
/// the 3.7 averages, weighted at a = 0, 0.5, 1, 2, 3 (every emotional cell) and designed
/// (the extracted phase and gains of every emotional cell, and a moved warp).
std::vector<Derived> derivedTakes(const Corpus& corpus)
{
    std::vector<Derived> out;
    auto pre = pipeline::runPreprocess(corpus, {});
    REQUIRE(pre);
    for (const auto& take : pre->corpus.takes) out.push_back({"preprocessed " + take.displayName(), take});
    std::optional<pipeline::NormaliseOutput> method2;
    for (const std::string coupling : {"method1", "method2"}) {
        pipeline::NormaliseParameters parameters;
        parameters.coupling = coupling;
        auto normalised = pipeline::runNormalise(pre->corpus, parameters);
        REQUIRE(normalised);
        for (const auto& take : normalised->normalised.takes) out.push_back({coupling + " normalised " + take.displayName(), take});
        for (const auto& cell : normalised->cells) out.push_back({coupling + " average " + cell.function + "/" + cell.emotion, cell.average});
        if (coupling == "method2") method2 = std::move(normalised).value();
    }
    auto decomposed = pipeline::runDecompose(method2->normalised, {});
    REQUIRE(decomposed);
    for (const auto& cell : decomposed->components.emotions) {
        for (const double a : {0.0, 0.5, 1.0, 2.0, 3.0}) {
            auto weighted = pipeline::weightedTake(*decomposed, cell.function, cell.emotion, a);
            REQUIRE(weighted);
            out.push_back({"weighted " + cell.function + "/" + cell.emotion + " a = " + std::to_string(a), *weighted});
        }
    }
    auto axes = pipeline::runAxes(*method2, corpus.neutralEmotion, {});
    REQUIRE(axes);
    for (const auto& cell : axes->cells) {
        const auto* function = axes->function(cell.function);
        REQUIRE(function);
        pipeline::DesignEdits edits;
        edits.warp = cell.extracted.phase.curve;
        out.push_back({"designed with the phase of " + cell.function + "/" + cell.emotion, pipeline::designFunction(*function, edits).take});
        edits.setGain({0, 1, 1.0, 1.5});
        out.push_back({"designed with the phase of " + cell.function + "/" + cell.emotion + " and a gain",
                       pipeline::designFunction(*function, edits).take});
    }
    return out;
}

/// The largest distance (cm) and angle (deg) between the parts the channels of `body` give and
/// the parts `jointPoses(f)` (the file's joints at frame f, by name) give through `body`'s own
/// part bindings: the file's forward kinematics against the graphed channels.
template <typename JointPoses>
std::pair<double, double> fileAgainstChannels(const Take& body, JointPoses jointPoses)
{
    const Skeleton& skeleton = *body.skeleton->skeleton;
    double cm = 0.0, deg = 0.0;
    for (Eigen::Index f = 0; f < body.frameCount(); ++f) {
        const std::map<std::string, RigidTransform> joints = jointPoses(f);
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const PartBinding* binding = skeleton.binding(kPuppetParts[std::size_t(p)]);
            REQUIRE(binding);
            const auto joint = joints.find(skeleton.joints[std::size_t(binding->joint)].name);
            REQUIRE(joint != joints.end());
            const RigidTransform fromFile = joint->second * binding->joint_T_part;
            const RigidTransform graphed = partPose(body, f, Eigen::Index(p) * kDofCount);
            cm = std::max(cm, (fromFile.translation - graphed.translation).norm());
            deg = std::max(deg, rotationDistance(fromFile.rotation, graphed.rotation) * 180.0 / std::numbers::pi);
        }
    }
    return {cm, deg};
}

/// A BVH and a glTF export of `body`: forward kinematics of each file (its joints by name,
/// through the take's part frames) gives the graphed channels: to 1e-6 cm and deg for BVH (its
/// numbers are written to round trip), to 32-bit float precision for glTF.
void checkFilesHoldBody(const Take& body, const std::filesystem::path& scratch)
{
    const auto bvhFile = scratch / "take.bvh";
    REQUIRE(io::writeTakeFile(body, bvhFile));
    auto parsed = io::readBvh(bvhFile);
    REQUIRE(parsed);
    io::BvhImportOptions options;
    options.upAxis = body.skeleton->skeleton->source.upAxis == "z" ? io::BvhUpAxis::Z : io::BvhUpAxis::Y;
    options.unitScale = body.skeleton->skeleton->source.cmPerUnit;
    auto motion = io::bvhToSkeletalMotion(*parsed, options);
    REQUIRE(motion);
    REQUIRE((*motion)->frameCount() == body.frameCount());
    const auto [bvhCm, bvhDeg] = fileAgainstChannels(body, [&](Eigen::Index f) {
        const auto poses = (*motion)->worldPoses(f);
        std::map<std::string, RigidTransform> byName;
        for (std::size_t j = 0; j < poses.size(); ++j) byName[(*motion)->skeleton->joints[j].name] = poses[j];
        return byName;
    });
    INFO("BVH: " << bvhCm << " cm, " << bvhDeg << " deg");
    CHECK(bvhCm < 1e-6);
    CHECK(bvhDeg < 1e-6);

    const auto glb = scratch / "take.glb";
    std::vector<io::JointMesh> meshes;
    const auto& joints = body.skeleton->skeleton->joints;
    for (std::size_t j = 0; j < joints.size(); ++j)
        if (!joints[j].endSite)
            meshes.push_back(io::JointMesh{int(j), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {3, Eigen::Vector3f(0, 0, 1)}, {3, Eigen::Vector3f(1, 1, 1)}, {0, 1, 2}});
    REQUIRE(io::writeSkeletalGlb(*body.skeleton, body.rateHz, meshes, glb));
    const tinygltf::Model model = test::loadGlbBytes(test::readBinaryFile(glb.string()));
    const Eigen::Quaterniond g = io::gltfAxisChange();
    const auto [gltfCm, gltfDeg] = fileAgainstChannels(body, [&](Eigen::Index f) {
        std::map<std::string, RigidTransform> byName;
        for (const auto& [name, pose] : test::gltfNodePoses(model, std::size_t(f))) {
            const Eigen::Quaterniond q(pose.rotation());
            byName[name] = RigidTransform{(g.conjugate() * q * g).normalized(), g.conjugate() * (100.0 * pose.translation())};
        }
        return byName;
    });
    INFO("glTF: " << gltfCm << " cm, " << gltfDeg << " deg");
    CHECK(gltfCm < 1e-3);
    CHECK(gltfDeg < 1e-3);
}

/// The checks of one body per take on a derived take: it has a skeleton, its body motion's
/// channels are the parts its skeleton poses, its bones keep their lengths, and its CSV holds
/// those channels.
void checkOneBody(const Derived& derived, const std::filesystem::path& scratch)
{
    INFO(derived.what);
    REQUIRE(derived.take.skeleton);
    const Take body = bodyTake(derived.take);
    REQUIRE(body.skeleton == derived.take.skeleton);
    const auto gap = skeletonChannelGap(body);
    REQUIRE(gap);
    CHECK(gap->maxPositionCm < 1e-6);
    CHECK(gap->maxAngleDeg < 1e-6);
    CHECK(test::maxBoneLengthChange(*body.skeleton) < 1e-6);
    // Idempotent: the body of a body is itself, bit for bit.
    CHECK(bodyTake(body).values == body.values);
    // What a CSV export holds is the graphed body motion.
    const auto file = scratch / "take.csv";
    REQUIRE(io::writeTakeCsv(body, file));
    auto back = io::readTakeCsv(file);
    REQUIRE(back);
    CHECK((back->values - body.values).cwiseAbs().maxCoeff() < 1e-6);
    checkFilesHoldBody(body, scratch);
}

std::filesystem::path scratchFolder(const std::string& name)
{
    const auto folder = std::filesystem::temp_directory_path() / ("bunraku-body-" + name);
    std::filesystem::create_directories(folder);
    return folder;
}

/// The lowest point of the body (every joint and End Site but the roots) per frame, cm (computed
/// here, apart from analysis::lowestPoints).
Eigen::VectorXd lowestJointHeights(const SkeletalMotion& motion)
{
    Eigen::VectorXd low(motion.frameCount());
    for (Eigen::Index f = 0; f < motion.frameCount(); ++f) {
        const auto poses = motion.worldPoses(f);
        double z = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < poses.size(); ++j)
            if (motion.skeleton->joints[j].parent >= 0) z = std::min(z, poses[j].translation.z());
        low(f) = z;
    }
    return low;
}


} // namespace

TEST_CASE("the puppet rig fitted to the demo corpus finds the demo rig's neck and head", "[body][rig]")
{
    const Corpus corpus = synth::generateDemoCorpus().corpus;
    std::vector<const Take*> takes;
    for (const auto& take : corpus.takes) takes.push_back(&take);
    const auto fit = fitPuppetRig(takes);
    REQUIRE(fit);
    const Skeleton& rig = *fit->skeleton;
    REQUIRE(isPuppetRig(rig));
    // The demo rig (analysis/synth/puppet_rig.cpp): the neck 1 cm forward and 8 cm above the
    // shoulder sensor, the head sensor 3 cm forward and 7 cm above the neck in the head's frame.
    CHECK((rig.joints[std::size_t(rig.find(kRigNeckJoint))].offset - Eigen::Vector3d(1, 0, 8)).norm() < 0.5);
    CHECK((rig.binding("head")->joint_T_part.translation - Eigen::Vector3d(3, 0, 7)).norm() < 0.5);
    // Head and shoulder are rigid in the demo rig; the arm sensor slides with the reach.
    CHECK(fit->residual.maxCm[0] < 1.0);
    CHECK(fit->residual.maxCm[1] < 1e-9);
    CHECK(fit->residual.maxDeg[0] < 1e-6);
    CHECK(fit->residual.maxDeg[3] < 1e-6);
    Eigen::Index frames = 0;
    for (const auto& take : corpus.takes) frames += take.frameCount();
    CHECK(fit->residual.frames == frames);
    // A take of another layout is refused by name.
    Take other = corpus.takes.front();
    other.values = Eigen::MatrixXd(other.values.leftCols(6)); // a copy: the block views the matrix it replaces
    other.channels.resize(6);
    const auto refused = fitPuppetRig({&other});
    REQUIRE_FALSE(refused);
    CHECK(refused.error().message.find("24 puppet channels") != std::string::npos);
}

TEST_CASE("a demo take on the puppet rig written as BVH reads back as the rig with the same channels", "[body][rig][export]")
{
    auto pre = pipeline::runPreprocess(synth::generateDemoCorpus().corpus, {});
    REQUIRE(pre);
    auto normalised = pipeline::runNormalise(pre->corpus, {});
    REQUIRE(normalised);
    auto decomposed = pipeline::runDecompose(normalised->normalised, {});
    REQUIRE(decomposed);
    auto weighted = pipeline::weightedTake(*decomposed, "greeting", "hostile", 2.0);
    REQUIRE(weighted);
    const Take body = bodyTake(*weighted);
    REQUIRE(isPuppetRig(*body.skeleton->skeleton));
    const auto scratch = scratchFolder("rig-back");
    const auto file = scratch / "weighted.bvh";
    REQUIRE(io::writeTakeFile(body, file));
    auto back = io::readTakeFile(file);
    INFO((back ? std::string() : back.error().message));
    REQUIRE(back);
    REQUIRE(back->skeleton);
    CHECK(isPuppetRig(*back->skeleton->skeleton));
    REQUIRE(back->frameCount() == body.frameCount());
    double cm = 0.0, deg = 0.0;
    for (Eigen::Index f = 0; f < body.frameCount(); ++f)
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const RigidTransform x = partPose(body, f, Eigen::Index(p) * kDofCount);
            const RigidTransform y = partPose(*back, f, Eigen::Index(p) * kDofCount);
            cm = std::max(cm, (x.translation - y.translation).norm());
            deg = std::max(deg, rotationDistance(x.rotation, y.rotation) * 180.0 / std::numbers::pi);
        }
    INFO(cm << " cm, " << deg << " deg");
    CHECK(cm < 1e-6);
    CHECK(deg < 1e-6);
    std::filesystem::remove_all(scratch);
}

TEST_CASE("preprocessing gives every demo take the corpus's rig and leaves its channels as they were", "[body][rig]")
{
    const Corpus corpus = synth::generateDemoCorpus().corpus;
    auto pre = pipeline::runPreprocess(corpus, {});
    REQUIRE(pre);
    const Skeleton* first = nullptr;
    for (const auto& take : pre->corpus.takes) {
        INFO(take.displayName());
        REQUIRE(take.skeleton);
        REQUIRE(isPuppetRig(*take.skeleton->skeleton));
        if (!first) first = take.skeleton->skeleton.get();
        CHECK(take.skeleton->skeleton.get() == first); // one puppet: one rig for the corpus
        CHECK(take.skeleton->frameCount() == take.frameCount());
    }
}

TEST_CASE("every derived take of the demo corpus is one articulated body", "[body]")
{
    const auto scratch = scratchFolder("demo");
    const auto derived = derivedTakes(synth::generateDemoCorpus().corpus);
    CHECK(derived.size() > 100);
    for (const auto& d : derived) checkOneBody(d, scratch);
    std::filesystem::remove_all(scratch);
}

TEST_CASE("every derived take of the Bandai waves is one articulated body", "[body][bandai]")
{
    if (!test::bandaiAvailable(test::bandaiWaveFiles())) return;
    const auto scratch = scratchFolder("waves");
    for (const auto& d : derivedTakes(test::bandaiWaveCorpus())) {
        checkOneBody(d, scratch);
        CHECK(d.take.skeleton->skeleton->jointCount() == 22);
    }
    std::filesystem::remove_all(scratch);
}

TEST_CASE("the weighted bye take of one take per cell keeps the performer's 22 joints at a = 2", "[body][bandai]")
{
    if (!test::bandaiAvailable({"bye_normal_001.bvh", "bye_happy_001.bvh", "bye_angry_001.bvh"})) return;
    const Corpus corpus = test::bandaiByeCorpus();
    const auto scratch = scratchFolder("bye");
    for (const auto& d : derivedTakes(corpus)) {
        checkOneBody(d, scratch);
        CHECK(d.take.skeleton->skeleton->jointCount() == 22);
    }
    std::filesystem::remove_all(scratch);
    // On the floor: at every frame of the weighted takes the lowest point of the body (a foot) is
    // where the inputs' lowest points are, never below the lowest of them nor above the highest.
    auto pre = pipeline::runPreprocess(corpus, {});
    REQUIRE(pre);
    auto normalised = pipeline::runNormalise(pre->corpus, {});
    REQUIRE(normalised);
    auto decomposed = pipeline::runDecompose(normalised->normalised, {});
    REQUIRE(decomposed);
    // The hips (the pelvis) within the range of the inputs' hips: a weight past 1 bends the legs
    // less rather than crouching deeper than any input does. The weighted take's inputs are y
    // and y + z (a = 0 and a = 1: the function component and the cell's emotional motion); at
    // a = 2 the hips are also within the range of the three takes read from the files.
    const int hips = corpus.takes.front().skeleton->skeleton->find("Hips");
    REQUIRE(hips >= 0);
    const auto hipsRange = [&](const SkeletalMotion& motion) {
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (Eigen::Index f = 0; f < motion.frameCount(); ++f) {
            const double z = motion.worldPoses(f)[std::size_t(hips)].translation.z();
            low = std::min(low, z);
            high = std::max(high, z);
        }
        return std::pair<double, double>{low, high};
    };
    double floor = std::numeric_limits<double>::infinity(), ceiling = -floor;
    double takesLow = floor, takesHigh = -floor;
    for (const auto& take : corpus.takes) {
        const auto low = lowestJointHeights(*take.skeleton);
        floor = std::min(floor, low.minCoeff());
        ceiling = std::max(ceiling, low.maxCoeff());
        const auto [a, b] = hipsRange(*take.skeleton);
        takesLow = std::min(takesLow, a);
        takesHigh = std::max(takesHigh, b);
    }
    double inputsLow = std::numeric_limits<double>::infinity(), inputsHigh = -inputsLow;
    for (const double a : {0.0, 1.0}) {
        auto input = pipeline::weightedTake(*decomposed, "bye", "angry", a);
        REQUIRE(input);
        const auto [low, high] = hipsRange(*input->skeleton);
        inputsLow = std::min(inputsLow, low);
        inputsHigh = std::max(inputsHigh, high);
    }
    for (const double a : {0.5, 2.0, 3.0}) {
        INFO("a = " << a);
        auto weighted = pipeline::weightedTake(*decomposed, "bye", "angry", a);
        REQUIRE(weighted);
        const auto low = lowestJointHeights(*weighted->skeleton);
        CHECK(low.minCoeff() > floor - 0.1); // the inputs' bones differ by rounding at the End Sites
        CHECK(low.maxCoeff() < ceiling + 0.1);
        const auto [weightedLow, weightedHigh] = hipsRange(*weighted->skeleton);
        INFO("hips " << weightedLow << " .. " << weightedHigh << " cm, y and y + z " << inputsLow << " .. " << inputsHigh
                     << " cm, the takes' " << takesLow << " .. " << takesHigh << " cm");
        CHECK(weightedLow > inputsLow - 1e-6);
        CHECK(weightedHigh < inputsHigh + 1e-6);
        if (a == 2.0) {
            CHECK(weightedLow > takesLow - 1e-6);
            CHECK(weightedHigh < takesHigh + 1e-6);
        }
    }
}

namespace {

/// Root mean square distance of the parts' positions (cm) and mean angle (deg) between a take's
/// channels and `truth` (frames x 24), over the frames both have.
std::pair<double, double> truthError(const Eigen::MatrixXd& values, const Eigen::MatrixXd& truth)
{
    Take a, b;
    a.channels = b.channels = puppetChannels();
    const Eigen::Index frames = std::min(values.rows(), truth.rows());
    a.values = values.topRows(frames);
    b.values = truth.topRows(frames);
    double squares = 0.0, angles = 0.0;
    for (Eigen::Index f = 0; f < frames; ++f)
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const RigidTransform x = partPose(a, f, Eigen::Index(p) * kDofCount);
            const RigidTransform y = partPose(b, f, Eigen::Index(p) * kDofCount);
            squares += (x.translation - y.translation).squaredNorm();
            angles += rotationDistance(x.rotation, y.rotation) * 180.0 / std::numbers::pi;
        }
    const double n = double(frames * kPuppetPartCount);
    return {std::sqrt(squares / n), angles / n};
}

} // namespace

TEST_CASE("on the demo corpus the body's weighted and designed takes are as near the truth as the per-channel ones", "[body][truth]")
{
    const auto demo = synth::generateDemoCorpus();
    auto pre = pipeline::runPreprocess(demo.corpus, {});
    REQUIRE(pre);
    auto normalised = pipeline::runNormalise(pre->corpus, {});
    REQUIRE(normalised);
    auto decomposed = pipeline::runDecompose(normalised->normalised, {});
    REQUIRE(decomposed);
    double perChannelCm = 0.0, bodyCm = 0.0, perChannelDeg = 0.0, bodyDeg = 0.0;
    int cells = 0;
    for (const auto& cell : decomposed->components.emotions) {
        const auto* truth = demo.truth.cell(cell.function, cell.emotion);
        REQUIRE(truth);
        auto weighted = pipeline::weightedTake(*decomposed, cell.function, cell.emotion, 1.0);
        REQUIRE(weighted);
        const auto [pc, pd] = truthError(weighted->values, truth->motion);
        const auto [bc, bd] = truthError(bodyTake(*weighted).values, truth->motion);
        std::printf("truth %-24s a = 1: per-channel %.3f cm %.3f deg, body %.3f cm %.3f deg\n",
                    (cell.function + "/" + cell.emotion).c_str(), pc, pd, bc, bd);
        perChannelCm += pc;
        perChannelDeg += pd;
        bodyCm += bc;
        bodyDeg += bd;
        ++cells;
    }
    std::printf("truth mean over %d cells: per-channel %.3f cm %.3f deg, body %.3f cm %.3f deg\n", cells, perChannelCm / cells,
                perChannelDeg / cells, bodyCm / cells, bodyDeg / cells);
    CHECK(cells == 6);
}

TEST_CASE("a weighted Bandai take written as BVH reads back with its parts where the graphs put them", "[body][bandai][export]")
{
    if (!test::bandaiAvailable(test::bandaiWaveFiles())) return;
    auto pre = pipeline::runPreprocess(test::bandaiWaveCorpus(), {});
    REQUIRE(pre);
    auto normalised = pipeline::runNormalise(pre->corpus, {});
    REQUIRE(normalised);
    auto decomposed = pipeline::runDecompose(normalised->normalised, {});
    REQUIRE(decomposed);
    const auto scratch = scratchFolder("bvh-back");
    for (const double a : {0.5, 2.0}) {
        INFO("a = " << a);
        auto weighted = pipeline::weightedTake(*decomposed, "wave", "active", a);
        REQUIRE(weighted);
        const Take body = bodyTake(*weighted);
        const auto file = scratch / "weighted.bvh";
        REQUIRE(io::writeTakeFile(body, file));
        auto back = io::readTakeFile(file);
        REQUIRE(back);
        REQUIRE(back->frameCount() == body.frameCount());
        // The importer's own channels: positions the same (its part frames are calibrated anew
        // from the file's bones, so they may turn by the calibration; docs/FORMATS.md).
        double worst = 0.0;
        for (Eigen::Index f = 0; f < body.frameCount(); ++f)
            for (int p = 0; p < kPuppetPartCount; ++p) {
                const RigidTransform x = partPose(body, f, Eigen::Index(p) * kDofCount);
                const RigidTransform y = partPose(*back, f, Eigen::Index(p) * kDofCount);
                worst = std::max(worst, (x.translation - y.translation).norm());
            }
        CHECK(worst < 1e-6);
    }
    std::filesystem::remove_all(scratch);
}

TEST_CASE("every derived take of the Bandai waves with all joints is one articulated body", "[body][bandai][wholebody]")
{
    // Issue 25: takes of every joint (6 channels each, the joint's world pose). The graphs show,
    // and every export writes, the motion the skeleton makes: each joint's channels are its pose
    // by forward kinematics, the thesis's per-channel result kept as the ghost.
    if (!test::bandaiAvailable(test::bandaiWaveFiles())) return;
    Corpus corpus;
    corpus.neutralEmotion = "normal";
    io::ImportOptions allJoints;
    allJoints.bvhLayout = io::BvhTakeLayout::AllJoints;
    for (const auto& style : test::bandaiWaveStyles())
        for (int k = 1; k <= 5; ++k) {
            auto take = io::readTakeFile(test::bandaiDir() / test::bandaiWaveFile(style, k), allJoints);
            REQUIRE(take);
            take->labels = {"wave", style, k, test::bandaiWaveFile(style, k)};
            corpus.takes.push_back(std::move(take).value());
        }
    corpus.rateHz = corpus.takes.front().rateHz;
    std::vector<Derived> derived;
    auto pre = pipeline::runPreprocess(corpus, {});
    REQUIRE(pre);
    auto normalised = pipeline::runNormalise(pre->corpus, {}); // auto: the chains coupling
    REQUIRE(normalised);
    for (const auto& take : normalised->normalised.takes) derived.push_back({"normalised " + take.displayName(), take});
    for (const auto& cell : normalised->cells) derived.push_back({"average " + cell.function + "/" + cell.emotion, cell.average});
    auto decomposed = pipeline::runDecompose(normalised->normalised, {});
    REQUIRE(decomposed);
    for (const auto& cell : decomposed->components.emotions)
        for (const double a : {0.0, 2.0}) {
            auto weighted = pipeline::weightedTake(*decomposed, cell.function, cell.emotion, a);
            REQUIRE(weighted);
            derived.push_back({"weighted " + cell.emotion + " a = " + std::to_string(a), *weighted});
        }
    auto axes = pipeline::runAxes(*normalised, corpus.neutralEmotion, {});
    REQUIRE(axes);
    REQUIRE(axes->cells.size() == 2);
    for (const auto& cell : axes->cells) {
        pipeline::DesignEdits edits;
        edits.warp = cell.extracted.phase.curve;
        edits.setGain({0, 2, 1.0, 1.5});
        derived.push_back({"designed " + cell.emotion, pipeline::designFunction(*axes->function(cell.function), edits).take});
    }
    const auto scratch = scratchFolder("wholebody");
    int projected = 0;
    for (const auto& d : derived) {
        INFO(d.what);
        REQUIRE(d.take.skeleton);
        const BodyMotion motion = bodyMotion(d.take);
        const Take& body = motion.take;
        REQUIRE(body.channels.size() == 132);
        projected += motion.perChannel ? 1 : 0;
        // Every joint's channels are its world pose.
        double cm = 0.0, deg = 0.0;
        for (Eigen::Index f = 0; f < body.frameCount(); ++f) {
            const auto poses = body.skeleton->worldPoses(f);
            for (const SixDofPart& part : sixDofParts(body)) {
                const RigidTransform joint = poses[std::size_t(body.skeleton->skeleton->find(part.part))];
                const RigidTransform graphed = partPose(body, f, part.firstChannel);
                cm = std::max(cm, (joint.translation - graphed.translation).norm());
                deg = std::max(deg, rotationDistance(joint.rotation, graphed.rotation) * 180.0 / std::numbers::pi);
            }
        }
        CHECK(cm < 1e-6);
        CHECK(deg < 1e-6);
        CHECK(test::maxBoneLengthChange(*body.skeleton) < 1e-6);
        CHECK(bodyTake(body).values == body.values);
        // The per-channel result, when the body differs from it, is measured against it.
        if (motion.perChannel) {
            const auto distance = perChannelDistance(body, *motion.perChannel);
            REQUIRE(distance);
            CHECK(distance->maxPositionCm == Approx(motion.distance.maxPositionCm).margin(1e-9));
        }
        // A BVH export's joints, read back, are the graphed channels.
        const auto file = scratch / "take.bvh";
        REQUIRE(io::writeTakeFile(body, file));
        auto parsed = io::readBvh(file);
        REQUIRE(parsed);
        io::BvhImportOptions options;
        options.upAxis = body.skeleton->skeleton->source.upAxis == "z" ? io::BvhUpAxis::Z : io::BvhUpAxis::Y;
        options.unitScale = body.skeleton->skeleton->source.cmPerUnit;
        auto back = io::bvhToJointTake(*parsed, options);
        REQUIRE(back);
        REQUIRE(back->values.rows() == body.values.rows());
        double fileCm = 0.0;
        for (Eigen::Index f = 0; f < body.frameCount(); ++f)
            for (const SixDofPart& part : sixDofParts(body)) {
                const auto first = back->channelIndex(part.part, "x");
                REQUIRE(first);
                fileCm = std::max(fileCm, (partPose(*back, f, *first).translation - partPose(body, f, part.firstChannel).translation).norm());
            }
        CHECK(fileCm < 1e-6);
    }
    // The normalised, averaged, weighted and designed takes' channels were the thesis's
    // per-channel arithmetic: most are projected onto the body.
    CHECK(projected > int(derived.size()) / 2);
    std::filesystem::remove_all(scratch);
}
