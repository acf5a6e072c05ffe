// The .glb export against a real client (issue 23): Blender 3.4 imports the export of a demo take
// (the modelled puppet) and of a Bandai take (the performer's body) as an armature with one
// skinned mesh (an armature modifier and vertex groups) and the take's frames, and renders
// Blender's evaluated, skinned mesh along x and y through orthographic cameras; its silhouettes
// must cover our own ID pass of the same frames through the same cameras (intersection over
// union >= 0.9), and each limb's vertices run along its bone. One Blender process per test case
// (tests/render/blender_silhouette.py). Without Blender the cases fail under CI=true and are
// reported as skipped otherwise.
#include "render_test_support.h"

#include "analysis/body/body_pose.h"
#include "analysis/body/puppet_model.h"
#include "analysis/core/skeleton.h"
#include "analysis/io/take_reader.h"
#include "analysis/synth/demo_corpus.h"
#include "render/skeleton_geometry.h"
#include "render/take_export.h"
#include "tests/support/blender_peer.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <nlohmann/json.hpp>

#include <Eigen/Eigenvalues>

#include <QImage>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>

using namespace bunraku;
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

/// Blender's world (z up, metres) of a workbench vector (cm): through glTF's axes (y up), which
/// Blender's glTF importer turns as (x, y, z) -> (x, -z, y).
Eigen::Vector3d blenderFromWorkbench(const glm::vec3& p) { return Eigen::Vector3d(p.y, -p.x, p.z) / 100.0; }
json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

/// Axis-aligned bounds of points (cm).
struct Box {
    Eigen::Vector3d lower = Eigen::Vector3d::Constant(1e30), upper = Eigen::Vector3d::Constant(-1e30);
    void add(const Eigen::Vector3d& p)
    {
        lower = lower.cwiseMin(p);
        upper = upper.cwiseMax(p);
    }
};

/// An orthographic camera looking horizontally at the box's centre from `angleDeg` (270: from +x,
/// the front of a figure facing +x; 0: from +y, its left side), the box's largest extent plus a
/// margin high.
render::Camera orthographicCamera(const Box& box, float angleDeg)
{
    render::Camera camera;
    camera.angleDeg = angleDeg;
    camera.elevationDeg = 0.0f;
    const Eigen::Vector3d centre = 0.5 * (box.lower + box.upper);
    camera.target = glm::vec3(float(centre.x()), float(centre.y()), float(centre.z()));
    camera.orthographicHeight = float(1.15 * (box.upper - box.lower).maxCoeff());
    camera.distance = 400.0f + camera.orthographicHeight;
    return camera;
}

struct Shot {
    Eigen::Index frame = 0;
    std::string view;
    render::Camera camera;
    fs::path blenderPng;
    QImage ours;
};

constexpr int kShotSize = 200;

json shotJob(const Shot& shot)
{
    const render::Camera& c = shot.camera;
    return json{{"frame", shot.frame},
                {"eye", vec(blenderFromWorkbench(c.eye()))},
                {"right", vec(blenderFromWorkbench(c.right()).normalized())},
                {"up", vec(blenderFromWorkbench(c.up()).normalized())},
                {"forward", vec(blenderFromWorkbench(c.forward()).normalized())},
                {"ortho_scale", double(c.orthographicHeight) / 100.0},
                {"size", kShotSize},
                {"png", shot.blenderPng.string()}};
}

/// One Blender process on `job` (blender_silhouette.py); its result.
json runBlender(const fs::path& dir, json job)
{
    job["output"] = (dir / "blender.json").string();
    {
        std::ofstream out(dir / "job.json");
        out << job.dump(1);
    }
    const fs::path script = test::sourceDir() / "tests" / "render" / "blender_silhouette.py";
    const fs::path log = dir / "blender.log";
    const std::string command = "blender -b --factory-startup --python-exit-code 1 -P '" + script.string() + "' -- '" + (dir / "job.json").string() +
                                "' >'" + log.string() + "' 2>&1 </dev/null";
    const int status = std::system(command.c_str());
    INFO("blender log:\n" << test::fileBytes(log));
    REQUIRE(status == 0);
    std::ifstream in(dir / "blender.json");
    REQUIRE(in.good());
    return json::parse(in);
}

/// Intersection over union of Blender's silhouette (alpha) and ours (any ID).
double silhouetteIou(const QImage& ours, const QImage& blender, int* oursCount = nullptr, int* theirsCount = nullptr)
{
    REQUIRE(ours.size() == blender.size());
    int both = 0, either = 0, a = 0, b = 0;
    for (int y = 0; y < ours.height(); ++y)
        for (int x = 0; x < ours.width(); ++x) {
            const bool inOurs = (ours.pixel(x, y) & 0x00FFFFFFu) != 0;
            const bool inTheirs = qAlpha(blender.pixel(x, y)) > 127;
            both += inOurs && inTheirs;
            either += inOurs || inTheirs;
            a += inOurs;
            b += inTheirs;
        }
    if (oursCount) *oursCount = a;
    if (theirsCount) *theirsCount = b;
    return either > 0 ? double(both) / double(either) : 0.0;
}

/// Renders every shot in our ID pass (the scene set, `frame` chosen per shot).
void renderOurs(render::OffscreenRenderer& offscreen, std::vector<Shot>& shots, const fs::path& dir)
{
    for (Shot& shot : shots) {
        offscreen.renderer().setFrame(shot.frame);
        shot.ours = offscreen.partIdImage(shot.camera, QSize(kShotSize, kShotSize));
        shot.ours.save(QString::fromStdString((dir / ("ours_" + std::to_string(shot.frame) + "_" + shot.view + ".png")).string()));
    }
}

/// Compares every shot with Blender's render; prints and checks the IoU.
void compareShots(const std::vector<Shot>& shots, const std::string& what)
{
    for (const Shot& shot : shots) {
        const QImage theirs(QString::fromStdString(shot.blenderPng.string()));
        INFO(shot.blenderPng.string());
        REQUIRE(!theirs.isNull());
        int ours = 0, blender = 0;
        const double iou = silhouetteIou(shot.ours, theirs.convertToFormat(QImage::Format_ARGB32), &ours, &blender);
        std::printf("blender silhouette: %s frame %lld %s view: IoU %.4f (ours %d px, Blender %d px)\n", what.c_str(),
                    static_cast<long long>(shot.frame), shot.view.c_str(), iou, ours, blender);
        INFO(what << " frame " << shot.frame << " " << shot.view << ": IoU " << iou << " (ours " << ours << " px, Blender " << blender << " px)");
        CHECK(ours > 2000);
        CHECK(iou >= 0.9);
    }
}

std::vector<Shot> frontAndSide(const std::vector<Eigen::Index>& frames, const std::function<Box(Eigen::Index)>& bounds, const fs::path& dir)
{
    std::vector<Shot> shots;
    for (const Eigen::Index frame : frames) {
        const Box box = bounds(frame);
        // Along the take's x (front to back: a demo take's puppet may be turned) and along its y.
        for (const auto& [view, angle] : {std::pair<std::string, float>{"x", 270.0f}, {"y", 0.0f}}) {
            Shot shot;
            shot.frame = frame;
            shot.view = view;
            shot.camera = orthographicCamera(box, angle);
            shot.blenderPng = dir / ("blender_" + std::to_string(frame) + "_" + view + ".png");
            shots.push_back(std::move(shot));
        }
    }
    return shots;
}

} // namespace

TEST_CASE("blender renders the glTF export of a demo take as the skinned puppet our view draws", "[render][export][blender]")
{
    if (!test::requireBlender()) return;
    const analysis::synth::DemoCorpus demo = analysis::synth::generateDemoCorpus();
    const analysis::Take& take = demo.corpus.takes.front();
    const analysis::BodyDescription body = analysis::defaultBodyDescription();
    REQUIRE(!take.skeleton);
    REQUIRE(take.rateHz == std::round(take.rateHz));
    const fs::path dir = test::scratchDir("blender_silhouette_puppet");
    REQUIRE(render::exportTake(take, body, dir / "puppet.glb").ok());

    // Framing from the puppet's skinned surface (the view's pose of it) at each frame.
    const analysis::PuppetMesh& mesh = analysis::shippedPuppetMesh();
    const auto binding = analysis::bindBody(body, take);
    REQUIRE(binding.ok());
    const auto bounds = [&](Eigen::Index frame) {
        const auto surface =
            analysis::skinPuppet(mesh, analysis::puppetJointPoses(mesh, body, analysis::worldPartPoses(body, *binding, take, frame)));
        Box box;
        for (const Eigen::Vector3f& p : surface.positions) box.add(p.cast<double>());
        return box;
    };
    const Eigen::Index frames = take.frameCount();
    std::vector<Shot> shots = frontAndSide({frames / 3, (2 * frames) / 3}, bounds, dir);

    json job{{"file", (dir / "puppet.glb").string()}, {"fps", take.rateHz}, {"renders", json::array()}};
    for (const Shot& shot : shots) job["renders"].push_back(shotJob(shot));
    const json blender = runBlender(dir, job);
    CHECK(blender["bones"].get<int>() == 1 + analysis::kPuppetJointCount);
    CHECK(blender["frames"].get<Eigen::Index>() == frames);
    CHECK(blender["armature_modifier"].get<bool>());
    CHECK(blender["vertex_groups"].get<int>() >= analysis::kPuppetJointCount);
    CHECK(blender["groups_named_as_bones"].get<bool>());
    CHECK(blender["max_influences"].get<int>() >= 2); // smoothly skinned, not rigid
    CHECK(blender["max_influences"].get<int>() <= 4);
    std::printf("blender silhouette: the puppet in Blender: %d vertices (ours %zu), %d vertex groups, up to %d influences\n",
                blender["vertices"].get<int>(), mesh.vertexCount(), blender["vertex_groups"].get<int>(), blender["max_influences"].get<int>());

    auto offscreen = test::makeOffscreenRenderer();
    render::SceneContent scene;
    scene.body = body;
    scene.takes.push_back(render::TakeSlot{take, {}});
    render::LayoutOptions layout;
    layout.centreTakes = false; // the take's own coordinates, as the file holds them
    REQUIRE(offscreen->setScene(scene, layout).ok());
    renderOurs(*offscreen, shots, dir);
    compareShots(shots, take.displayName());
}

TEST_CASE("blender renders the glTF export of a Bandai take as the performer's body our view draws", "[render][export][blender]")
{
    const fs::path source = test::bandaiDir() / "bye_angry_001.bvh";
    if (!test::requireBandaiData(fs::exists(source))) return;
    if (!test::requireBlender()) return;
    auto take = analysis::io::readTakeFile(source);
    REQUIRE(take.ok());
    REQUIRE(take->skeleton);
    REQUIRE(take->rateHz == std::round(take->rateHz));
    const analysis::SkeletalMotion& motion = *take->skeleton;
    const analysis::Skeleton& skeleton = *motion.skeleton;
    const fs::path dir = test::scratchDir("blender_silhouette_body");
    REQUIRE(render::exportTake(*take, analysis::defaultBodyDescription(), dir / "body.glb").ok());

    const float radius = render::skeletonJointRadius(motion);
    const auto bounds = [&](Eigen::Index frame) {
        Box box;
        for (const auto& pose : motion.worldPoses(frame)) {
            box.add(pose.translation - Eigen::Vector3d::Constant(radius));
            box.add(pose.translation + Eigen::Vector3d::Constant(radius));
        }
        return box;
    };
    const Eigen::Index frames = take->frameCount();
    std::vector<Shot> shots = frontAndSide({frames / 3, (2 * frames) / 3}, bounds, dir);
    const Eigen::Index axisFrame = frames / 2;
    json job{{"file", (dir / "body.glb").string()}, {"fps", take->rateHz}, {"renders", json::array()}, {"axis_frames", {axisFrame}}};
    for (const Shot& shot : shots) job["renders"].push_back(shotJob(shot));
    const json blender = runBlender(dir, job);
    int joints = 0;
    for (const auto& joint : skeleton.joints) joints += joint.endSite ? 0 : 1;
    CHECK(blender["bones"].get<int>() == joints);
    CHECK(blender["frames"].get<Eigen::Index>() == frames);
    CHECK(blender["armature_modifier"].get<bool>());
    CHECK(blender["groups_named_as_bones"].get<bool>());

    // Every limb's segment runs along its bone: the principal axis of the vertices that weigh
    // most on each limb joint with one drawn bone (20 or more of them), in Blender's evaluated
    // mesh.
    // Limbs: not the trunk (the chain from the root up to the head, whose segments are wider
    // than long).
    std::vector<bool> trunk(skeleton.joints.size(), false);
    const int head = skeleton.find("Head");
    REQUIRE(head >= 0);
    for (int j = head; j >= 0; j = skeleton.joints[std::size_t(j)].parent) trunk[std::size_t(j)] = true;
    const auto poses = motion.worldPoses(axisFrame);
    const json& axes = blender["axes"][std::to_string(axisFrame)];
    int limbs = 0;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
        if (trunk[j]) continue;
        std::vector<int> bones;
        for (std::size_t c = 0; c < skeleton.joints.size(); ++c)
            if (skeleton.joints[c].parent == int(j) && render::isRigidBone(motion, int(c))) bones.push_back(int(c));
        const std::string& name = skeleton.joints[j].name;
        if (bones.size() != 1 || !axes.contains(name) || axes[name]["vertices"].get<int>() < 20) continue;
        const Eigen::Vector3d bone = poses[std::size_t(bones.front())].translation - poses[j].translation;
        const Eigen::Vector3d along = blenderFromWorkbench(glm::vec3(float(bone.x()), float(bone.y()), float(bone.z()))).normalized();
        const auto& a = axes[name]["axis"];
        const Eigen::Vector3d axis(a[0].get<double>(), a[1].get<double>(), a[2].get<double>());
        const double cosine = std::abs(axis.normalized().dot(along));
        // And at rest against Blender's own bone (head to tail), the measure.
        REQUIRE(blender["rest_axes"].contains(name));
        const double rest = blender["rest_axes"][name]["cos"].get<double>();
        std::printf("blender silhouette: %s segment along its bone: |cos| %.3f at frame %lld, %.3f at rest (%d vertices)\n", name.c_str(),
                    cosine, static_cast<long long>(axisFrame), rest, axes[name]["vertices"].get<int>());
        INFO(name << ": |cos| " << cosine << " posed, " << rest << " at rest");
        CHECK(cosine >= 0.9);
        CHECK(rest >= 0.9);
        ++limbs;
    }
    CHECK(limbs >= 10);

    auto offscreen = test::makeOffscreenRenderer();
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{*take, {}});
    render::LayoutOptions layout;
    layout.centreTakes = false;
    REQUIRE(offscreen->setScene(scene, layout).ok());
    render::SceneVisibility visibility;
    visibility.figures[0] = render::FigureStyle::Body;
    offscreen->renderer().setVisibility(visibility);
    renderOurs(*offscreen, shots, dir);
    compareShots(shots, source.filename().string());
}
