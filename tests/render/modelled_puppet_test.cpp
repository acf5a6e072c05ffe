// The modelled, skinned puppet in the view (issue 23): one connected silhouette in the ID pass
// at sampled frames of the demo corpus and of every Bandai take (the puppet fitted to the
// performer), and a fitted puppet bowing deeply keeps its kimono hanging below the dō-wa.
#include "analysis/body/body_fit.h"
#include "analysis/body/body_pose.h"
#include "analysis/body/puppet_model.h"
#include "analysis/io/take_reader.h"
#include "analysis/synth/demo_corpus.h"
#include "render/take_scene.h"
#include "tests/support/bandai_files.h"
#include "render_test_support.h"

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

using namespace bunraku;

namespace {

/// 8-connected components of the puppet's pixels (any part of take slot 0) in an ID image.
int silhouetteComponents(const render::Renderer& renderer, const QImage& ids, int* pixels = nullptr)
{
    return test::silhouetteComponents(ids, [&renderer](QRgb pixel) {
        const auto hit = renderer.decodePartId(pixel);
        return hit && hit->takeSlot == 0 && hit->partIndex >= 0;
    }, pixels);
}

/// Renders `frames` of a one-take scene from the front and the side and requires one silhouette.
void requireOneSilhouette(render::OffscreenRenderer& offscreen, const render::SceneContent& scene, const std::vector<Eigen::Index>& frames,
                          const std::string& name)
{
    REQUIRE(offscreen.setScene(scene).ok());
    render::Renderer& renderer = offscreen.renderer();
    for (const Eigen::Index frame : frames) {
        renderer.setFrame(frame);
        for (const float angle : {270.0f, 0.0f, 315.0f}) {
            render::Camera camera = renderer.framingCamera();
            camera.angleDeg = angle;
            const QImage ids = offscreen.partIdImage(camera, QSize(480, 480));
            int pixels = 0;
            const int components = silhouetteComponents(renderer, ids, &pixels);
            INFO(name << ", frame " << frame << ", camera angle " << angle << ": " << pixels << " pixels");
            REQUIRE(pixels > 2000);
            REQUIRE(components == 1);
        }
    }
}

std::vector<Eigen::Index> sampledFrames(const analysis::Take& take, int count)
{
    std::vector<Eigen::Index> frames;
    for (int k = 0; k < count; ++k) frames.push_back(Eigen::Index(double(k) / (count - 1) * double(take.frameCount() - 1)));
    return frames;
}

} // namespace

TEST_CASE("the modelled puppet is one connected silhouette at sampled frames of the demo corpus", "[render][puppet][modelled]")
{
    const analysis::synth::DemoCorpus demo = analysis::synth::generateDemoCorpus();
    auto offscreen = test::makeOffscreenRenderer();
    int takes = 0;
    for (std::size_t t = 0; t < demo.corpus.takes.size(); t += 3) {
        render::SceneContent scene;
        scene.body = analysis::defaultBodyDescription();
        scene.takes.push_back(render::TakeSlot{demo.corpus.takes[t], {}});
        requireOneSilhouette(*offscreen, scene, sampledFrames(demo.corpus.takes[t], 5), demo.corpus.takes[t].displayName());
        ++takes;
    }
    CHECK(takes >= 8);
}

TEST_CASE("the puppet fitted to a performer is one connected silhouette at sampled frames of every Bandai take", "[render][puppet][modelled]")
{
    auto offscreen = test::makeOffscreenRenderer();
    for (const auto& path : test::bandaiFilesOrSkip()) {
        auto take = analysis::io::readTakeFile(path);
        INFO(path.string() << ": " << (take.ok() ? std::string() : take.error().message));
        REQUIRE(take.ok());
        render::TakeSceneOptions options;
        options.computeAxes = false;
        auto scene = render::makeTakeScene(analysis::defaultBodyDescription(), {*take}, options);
        REQUIRE(scene.ok());
        REQUIRE(scene->takes.front().body); // the puppet fitted to the performer
        requireOneSilhouette(*offscreen, *scene, sampledFrames(*take, 4), path.filename().string());
    }
}

TEST_CASE("a puppet fitted to a Bandai performer bowing 70 degrees keeps its kimono hem below the do-wa", "[render][puppet][modelled]")
{
    const auto path = test::bandaiDir() / "bye_normal_001.bvh";
    if (!test::requireBandaiData(std::filesystem::exists(path))) return;
    auto read = analysis::io::readTakeFile(path);
    REQUIRE(read.ok());
    analysis::Take take = std::move(read).value();
    render::TakeSceneOptions options;
    options.computeAxes = false;
    auto fittedScene = render::makeTakeScene(analysis::defaultBodyDescription(), {take}, options);
    REQUIRE(fittedScene.ok());
    const analysis::BodyDescription body = *fittedScene->takes.front().body;
    const analysis::PuppetMesh mesh = analysis::fittedPuppetMesh(analysis::shippedPuppetMesh(), body);

    // Every frame bowed: the four sensors turned 70 deg forward and down about the shoulder's
    // left-right axis through the dō-wa (the performer's hips).
    const int shoulder = body.partIndex("shoulder");
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        const auto parts = analysis::worldPartPoses(body, take, f);
        const analysis::RigidTransform& world_T_shoulder = parts[std::size_t(shoulder)];
        const Eigen::Vector3d pivot = world_T_shoulder.apply(mesh.dowaInShoulder);
        const Eigen::Vector3d axis = world_T_shoulder.rotation * Eigen::Vector3d::UnitY();
        const Eigen::Quaterniond bow(Eigen::AngleAxisd(70.0 * M_PI / 180.0, axis));
        const analysis::RigidTransform turn{bow, pivot - bow * pivot};
        for (int p = 0; p < analysis::kPuppetPartCount; ++p) {
            const Eigen::Index first = p * analysis::kDofCount;
            analysis::setPartPose(take, f, first, turn * analysis::partPose(take, f, first));
        }
    }
    for (const Eigen::Index f : sampledFrames(take, 5)) {
        const auto parts = analysis::worldPartPoses(body, take, f);
        const Eigen::Vector3d up = parts[std::size_t(shoulder)].rotation * Eigen::Vector3d::UnitZ();
        const double pitch = std::acos(std::clamp(up.z(), -1.0, 1.0)) * 180.0 / M_PI;
        const double dowaZ = parts[std::size_t(shoulder)].apply(mesh.dowaInShoulder).z();
        const analysis::SkinnedSurface skinned = analysis::skinPuppet(mesh, analysis::puppetJointPoses(mesh, body, parts));
        double hemHighest = -1e9, hemSum = 0.0;
        int hem = 0;
        const double hemBelow = analysis::shippedPuppetMesh().dowaInShoulder.z() - 25.0;
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            if (mesh.paintPositions[v].z() > hemBelow) continue;
            hemHighest = std::max(hemHighest, double(skinned.positions[v].z()));
            hemSum += skinned.positions[v].z();
            ++hem;
        }
        INFO("frame " << f << ": torso pitched " << pitch << " deg, do-wa at z " << dowaZ << ", hem highest " << hemHighest
                      << ", mean " << hemSum / hem);
        REQUIRE(pitch >= 60.0);
        REQUIRE(hem > 200);
        CHECK(hemHighest < dowaZ - 10.0);
        CHECK(hemSum / hem < dowaZ - 20.0);
    }
    // And the bowing puppet is drawn in one piece.
    render::SceneContent scene = *fittedScene;
    scene.takes.front().take = take;
    auto offscreen = test::makeOffscreenRenderer();
    requireOneSilhouette(*offscreen, scene, sampledFrames(take, 3), "bowing " + path.filename().string());
}
