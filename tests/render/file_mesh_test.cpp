// The file's own mesh (the "File's mesh" figure, FigureStyle::FileMesh; analysis/core/skeleton_mesh.h)
// against Blender 3.4: one Blender run (tests/render/blender_skinned_mesh.py) makes a character
// from a Bandai BVH - a tube along every bone, weighted by hand to one, two or three joints -
// exports it as binary glTF, FBX and Collada and writes Blender's own evaluated (depsgraph) vertex
// positions at rest and at three frames. Our reading of each file, skinned by the take on the
// CPU as the shader does, must put every vertex where Blender does within 0.1 cm; the figure is
// drawn as one piece over the skeleton's bones, picks by bone, and `bunraku info` / `bunraku
// render --figure mesh` say and draw it. Broken mesh data (a count past its buffer, weights on a
// node that is no joint) drops the mesh with a note, never the take. Without Blender or the
// Bandai files the cases fail under CI=true and are reported as skipped otherwise.
#include "analysis/core/skeleton.h"
#include "analysis/core/skeleton_mesh.h"
#include "analysis/io/scene_take.h"
#include "analysis/io/take_reader.h"
#include "render/take_scene.h"
#include "render_test_support.h"
#include "tests/support/blender_peer.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <QImage>

#include <array>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace bunraku;
using json = nlohmann::json;

namespace {

namespace fs = std::filesystem;

const char* const kSource = "bye_angry_001.bvh";
/// Blender's frames compared (the BVH's first frame is 1).
const std::array<int, 3> kFrames{1, 40, 90};

struct Character {
    bool made = false;
    fs::path dir;
    json evaluated;
};

/// The character, made by one Blender run for all of this file's cases: ctest runs each case in a
/// process of its own, so the files are kept in the build tree under a key of the script and its
/// arguments (a changed script makes them again), made in a folder of this process and renamed
/// into place (a case running beside it uses whichever finished first).
const Character& character()
{
    static const Character made = [] {
        Character c;
        const fs::path script = test::sourceDir() / "tests" / "render" / "blender_skinned_mesh.py";
        std::ostringstream arguments;
        arguments << "'" << (test::bandaiDir() / kSource).string() << "'";
        for (const int f : kFrames) arguments << ' ' << f;
        const std::size_t key = std::hash<std::string>{}(test::fileBytes(script) + arguments.str());
        const fs::path root = fs::path(BUNRAKU_BINARY_DIR) / "test-scratch";
        c.dir = root / ("file_mesh-" + std::to_string(key));
        const auto load = [](Character& into) {
            std::ifstream in(into.dir / "evaluated.json");
            into.evaluated = json::parse(in, nullptr, false);
            into.made = !into.evaluated.is_discarded() && fs::exists(into.dir / "character.glb") && fs::exists(into.dir / "character.fbx") &&
                        fs::exists(into.dir / "character.dae");
        };
        load(c);
        if (c.made) return c;
        const fs::path mine = root / ("file_mesh-" + std::to_string(key) + ".making-" + std::to_string(::getpid()));
        fs::remove_all(mine);
        fs::create_directories(mine);
        const std::string command = "blender -b --factory-startup --python-exit-code 1 -P '" + script.string() + "' -- '" + mine.string() +
                                    "' " + arguments.str() + " > '" + (mine / "blender.log").string() + "' 2>&1";
        const bool ran = std::system(command.c_str()) == 0;
        std::error_code error;
        if (ran) fs::rename(mine, c.dir, error); // fails when another process got there first: theirs is used
        if (!ran || error) {
            if (!ran) c.dir = mine; // its log says why
            else fs::remove_all(mine);
        }
        load(c);
        return c;
    }();
    return made;
}

/// True when Blender and the Bandai take are there (else failed under CI or skipped), and the
/// character was made.
bool requireCharacter()
{
    if (!test::requireBandaiData(fs::exists(test::bandaiDir() / kSource))) return false;
    if (!test::requireBlender()) return false;
    const Character& c = character();
    INFO("Blender's log: " << test::fileBytes(c.dir / "blender.log"));
    REQUIRE(c.made);
    return true;
}

Eigen::Vector3d vector(const json& value) { return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()}; }

/// Blender's world (m, z up) to the take's (cm): the signed axis permutation times 100, and a
/// translation, that put Blender's bone heads on our joints at the first compared frame (the
/// file formats turn the axes; the fit finds how). The largest residual comes back in `residual`.
Eigen::Affine3d blenderToTake(const analysis::SkeletalMotion& motion, const json& frame, Eigen::Index takeFrame, double& residual)
{
    const auto poses = motion.worldPoses(takeFrame);
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pairs; // ours, Blender's
    for (const auto& [name, head] : frame["heads"].items()) {
        const int j = motion.skeleton->find(name);
        if (j >= 0) pairs.emplace_back(poses[std::size_t(j)].translation, vector(head));
    }
    REQUIRE(pairs.size() >= 10);
    Eigen::Affine3d best = Eigen::Affine3d::Identity();
    residual = std::numeric_limits<double>::infinity();
    const std::array<std::array<int, 3>, 6> orders{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    for (const auto& order : orders)
        for (int signs = 0; signs < 8; ++signs) {
            Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
            for (int i = 0; i < 3; ++i) r(i, order[std::size_t(i)]) = (signs >> i) & 1 ? -100.0 : 100.0;
            if (r.determinant() < 0.0) continue;
            Eigen::Vector3d t = Eigen::Vector3d::Zero();
            for (const auto& [ours, theirs] : pairs) t += ours - r * theirs;
            t /= double(pairs.size());
            double worst = 0.0;
            for (const auto& [ours, theirs] : pairs) worst = std::max(worst, (ours - (r * theirs + t)).norm());
            if (worst < residual) {
                residual = worst;
                best.linear() = r;
                best.translation() = t;
            }
        }
    return best;
}

/// The largest distance (cm) between our skinned vertices and Blender's evaluated ones, at each
/// compared frame; vertices matched by their rest positions.
std::vector<double> compareWithBlender(const fs::path& file)
{
    const Character& c = character();
    auto take = analysis::io::readTakeFile(file);
    INFO(file.string() << ": " << (take.ok() ? std::string() : take.error().message));
    REQUIRE(take.ok());
    REQUIRE(render::takeHasFileMesh(*take));
    const analysis::SkeletalMotion& motion = *take->skeleton;
    const analysis::SkeletonMesh& mesh = *motion.skeleton->mesh;
    REQUIRE(mesh.vertexCount() >= c.evaluated["rest"]["vertices"].size());
    const double fps = c.evaluated["fps"].get<double>();
    const int first = c.evaluated["first"].get<int>();
    REQUIRE(take->rateHz == Approx(fps).epsilon(1e-3));

    double residual = 0.0;
    const Eigen::Affine3d toTake = blenderToTake(motion, c.evaluated["frames"][std::to_string(kFrames[0])], kFrames[0] - first, residual);
    INFO("bone heads to joints: " << residual << " cm");
    REQUIRE(residual < 0.1);

    // Our bind pose is Blender's rest: each of our vertices is one of Blender's.
    std::vector<Eigen::Vector3d> rest;
    for (const json& v : c.evaluated["rest"]["vertices"]) rest.push_back(toTake * vector(v));
    std::vector<std::size_t> match(mesh.vertexCount());
    double worstRest = 0.0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t b = 0; b < rest.size(); ++b) {
            const double d = (rest[b] - mesh.positions[v].cast<double>()).squaredNorm();
            if (d < nearest) {
                nearest = d;
                match[v] = b;
            }
        }
        worstRest = std::max(worstRest, std::sqrt(nearest));
    }
    INFO("bind pose against Blender's rest: " << worstRest << " cm");
    REQUIRE(worstRest < 0.02);

    std::vector<double> worst;
    for (const int f : kFrames) {
        const json& frame = c.evaluated["frames"][std::to_string(f)];
        const auto ours = analysis::skinSkeletonMesh(mesh, motion.worldPoses(f - first));
        double error = 0.0;
        for (std::size_t v = 0; v < ours.size(); ++v)
            error = std::max(error, (ours[v] - toTake * vector(frame["vertices"][match[v]])).norm());
        worst.push_back(error);
    }
    return worst;
}

fs::path cliPath() { return fs::path(BUNRAKU_BINARY_DIR) / "bin" / "bunraku"; }

/// Runs the command line in `dir`: exit code, standard output, standard error.
std::tuple<int, std::string, std::string> runCli(const std::string& arguments, const fs::path& dir)
{
    const std::string command = "'" + cliPath().string() + "' " + arguments + " > '" + (dir / "out.txt").string() + "' 2> '" +
                                (dir / "err.txt").string() + "'";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::fileBytes(dir / "out.txt"), test::fileBytes(dir / "err.txt")};
}

/// A binary glTF's JSON and BIN chunks, and back.
std::pair<json, std::string> splitGlb(const std::string& bytes)
{
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return {json::parse(bytes.substr(20, length)), bytes.substr(20 + length)};
}

std::string joinGlb(const json& document, const std::string& rest)
{
    std::string text = document.dump();
    while (text.size() % 4 != 0) text += ' ';
    std::string out = "glTF";
    const auto put = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    put(2);
    put(std::uint32_t(12 + 8 + text.size() + rest.size()));
    put(std::uint32_t(text.size()));
    put(0x4E4F534Au);
    return out + text + rest;
}

} // namespace

TEST_CASE("the file's mesh skinned by the take is where Blender puts it in glTF and FBX and Collada", "[render][mesh][blender]")
{
    if (!requireCharacter()) return;
    for (const char* name : {"character.glb", "character.fbx", "character.dae"}) {
        const fs::path file = character().dir / name;
        const auto worst = compareWithBlender(file);
        std::cout << "file mesh vs Blender, " << name << ": largest vertex distance";
        for (std::size_t k = 0; k < worst.size(); ++k) std::cout << " frame " << kFrames[k] << " " << worst[k] << " cm;";
        std::cout << "\n";
        for (std::size_t k = 0; k < worst.size(); ++k) {
            INFO(name << ", Blender frame " << kFrames[k]);
            CHECK(worst[k] < 0.1);
        }
        // What info says: the mesh and the bones it moves with.
        auto scene = analysis::io::readSceneTake(file);
        REQUIRE(scene.ok());
        const auto& take = analysis::io::readTakeFile(file);
        REQUIRE(take.ok());
        CHECK(scene->info.meshVertices == take->skeleton->skeleton->mesh->vertexCount());
        CHECK(scene->info.meshTriangles == take->skeleton->skeleton->mesh->triangleCount());
        CHECK(scene->info.meshBones.size() >= 15);
        CHECK(std::find(scene->info.meshBones.begin(), scene->info.meshBones.end(), "LowerArm_R") != scene->info.meshBones.end());
    }
}

TEST_CASE("the file's mesh figure is one piece over the skeleton's bones and picks by bone", "[render][mesh][blender]")
{
    if (!requireCharacter()) return;
    auto take = analysis::io::readTakeFile(character().dir / "character.glb");
    REQUIRE(take.ok());
    auto offscreen = test::makeOffscreenRenderer();
    render::TakeSceneOptions options;
    options.computeAxes = false;
    auto scene = render::makeTakeScene(analysis::defaultBodyDescription(), {*take}, options);
    REQUIRE(scene.ok());
    REQUIRE(offscreen->setScene(*scene).ok());
    render::Renderer& renderer = offscreen->renderer();
    render::SceneVisibility visibility;
    visibility.figures = {render::FigureStyle::FileMesh, render::FigureStyle::FileMesh};
    visibility.partner = false;
    renderer.setVisibility(visibility);
    REQUIRE(renderer.skeletonDrawn(0));
    REQUIRE_FALSE(renderer.puppetDrawn(0));
    const analysis::Skeleton& skeleton = *take->skeleton->skeleton;
    const QSize size(400, 400);
    for (const Eigen::Index frame : {Eigen::Index(0), Eigen::Index(39), Eigen::Index(89)}) {
        renderer.setFrame(frame);
        render::Camera camera = renderer.framingCamera();
        camera.angleDeg = 270.0f; // from the front
        const QImage ids = offscreen->partIdImage(camera, size);
        int pixels = 0;
        const int components = test::silhouetteComponents(ids, [&renderer](QRgb pixel) {
            const auto hit = renderer.decodePartId(pixel);
            return hit && hit->takeSlot == 0 && hit->joint >= 0;
        }, &pixels);
        INFO("frame " << frame << ": " << pixels << " pixels");
        CHECK(pixels > 1500);
        CHECK(components == 1);
        // Over the bones: the middle of each limb bone is on the mesh, and picks that bone.
        const auto joints = renderer.displayedJointTransforms(0, camera);
        int checked = 0, onBone = 0;
        for (const char* name : {"UpperArm_L", "LowerArm_L", "UpperArm_R", "LowerArm_R", "UpperLeg_L", "LowerLeg_L", "UpperLeg_R", "LowerLeg_R"}) {
            const int j = skeleton.find(name);
            REQUIRE(j >= 0);
            const auto children = skeleton.children(j);
            REQUIRE(children.size() == 1);
            const glm::vec3 middle = 0.5f * (glm::vec3(joints[std::size_t(j)][3]) + glm::vec3(joints[std::size_t(children.front())][3]));
            const QPoint pixel = camera.project(middle, size).pixel.toPoint();
            const auto hit = renderer.pick(camera, size, pixel);
            ++checked;
            onBone += hit && hit->takeSlot == 0 && hit->jointName == name ? 1 : 0;
        }
        INFO(onBone << " of " << checked << " limb bones picked by their middle");
        CHECK(onBone >= checked - 2); // a bone seen end-on from the front may hide behind another
    }
}

TEST_CASE("bunraku info and bunraku render --figure mesh show the file's mesh", "[render][mesh][blender][cli]")
{
    if (!requireCharacter()) return;
    if (!test::requirePeer(fs::exists(cliPath()), "the bunraku executable (" + cliPath().string() + ")", "build the target bunraku")) return;
    const fs::path dir = test::scratchDir("file_mesh_cli");
    const fs::path glb = character().dir / "character.glb";
    {
        const auto [code, out, err] = runCli("info --json '" + glb.string() + "'", dir);
        INFO(err);
        REQUIRE(code == 0);
        const json info = json::parse(out);
        const json& mesh = info["scene"]["skinned_mesh"];
        REQUIRE(mesh.is_object());
        CHECK(mesh["vertices"].get<int>() > 800);
        CHECK(mesh["triangles"].get<int>() > 1000);
        CHECK(mesh["bones"].size() >= 15);
    }
    {
        const auto [code, out, err] = runCli("info '" + glb.string() + "'", dir);
        REQUIRE(code == 0);
        CHECK(out.find("skinned mesh: ") != std::string::npos);
        CHECK(out.find(" vertices, ") != std::string::npos);
    }
    {
        const auto [code, out, err] = runCli("render '" + glb.string() + "' --figure mesh --frame 40 --size 200x200 --samples 0 --json -o '" +
                                                 (dir / "mesh.png").string() + "'",
                                             dir);
        INFO(err);
        REQUIRE(code == 0);
        CHECK(QImage(QString::fromStdString((dir / "mesh.png").string())).size() == QSize(200, 200));
        const json summary = json::parse(out, nullptr, false);
        REQUIRE(!summary.is_discarded());
        CHECK(summary["figures"][0]["mesh"] == true);
    }
    {
        // A take without a mesh asked for one: an error naming the take.
        const fs::path bvh = test::bandaiDir() / kSource;
        const auto [code, out, err] = runCli("render '" + bvh.string() + "' --figure mesh --size 64x64 -o '" + (dir / "none.png").string() + "'", dir);
        CHECK(code != 0);
        CHECK(err.find(kSource) != std::string::npos);
        CHECK(err.find("mesh") != std::string::npos);
        CHECK(std::count(err.begin(), err.end(), '\n') <= 1);
    }
}

TEST_CASE("a glTF mesh with broken data is dropped with a note and the take still reads", "[render][mesh][blender]")
{
    if (!requireCharacter()) return;
    const auto [document, rest] = splitGlb(test::fileBytes(character().dir / "character.glb"));
    const fs::path dir = test::scratchDir("file_mesh_broken");
    struct Case {
        const char* name;
        std::function<void(json&)> breakIt;
        const char* note;
    };
    const std::vector<Case> cases{
        {"count past the buffer", [](json& d) { d["accessors"][d["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<int>()]["count"] = 1000000000; },
         "more than"},
        {"weights on a node that is no joint",
         [](json& d) {
             int body = -1;
             for (std::size_t n = 0; n < d["nodes"].size(); ++n)
                 if (d["nodes"][n].contains("mesh")) body = int(n);
             for (auto& joint : d["skins"][0]["joints"]) joint = body;
         },
         "not a joint of the take"},
        {"a joint index outside the skin", [](json& d) {
             d["skins"][0]["joints"] = json::array({d["skins"][0]["joints"][0]});
             d["skins"][0].erase("inverseBindMatrices");
         }, "names joint"},
    };
    for (const Case& c : cases) {
        json broken = document;
        c.breakIt(broken);
        const fs::path file = dir / (std::string(c.name) + ".glb");
        std::ofstream(file, std::ios::binary) << joinGlb(broken, rest);
        auto scene = analysis::io::readSceneTake(file);
        INFO(c.name << ": " << (scene.ok() ? std::string() : scene.error().message));
        REQUIRE(scene.ok());
        CHECK(scene->bvh.mesh == nullptr);
        CHECK(scene->info.meshVertices == 0);
        REQUIRE(scene->info.meshNotes.size() >= 1);
        INFO(scene->info.meshNotes.front());
        CHECK(scene->info.meshNotes.front().find(c.note) != std::string::npos);
        auto take = analysis::io::readTakeFile(file);
        REQUIRE(take.ok());
        CHECK_FALSE(render::takeHasFileMesh(*take));
    }
}
