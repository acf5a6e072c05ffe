// The simulated kimono in a take's .glb (render/take_export.h, exportTake with KimonoExport): a
// mesh node "kimono_cloth" moving by morph targets animated by weights, its shapes at the key frames
// the simulation's particles in the file's coordinates, the puppet without the skinned pieces the
// cloth replaces; at most kKimonoExportMaxKeys shapes however long the take; the Khronos glTF
// validator finds no error in the file.
#include "analysis/body/body_description.h"
#include "analysis/body/puppet_model.h"
#include "analysis/cloth/kimono_mesh.h"
#include "analysis/io/gltf_export.h"
#include "analysis/io/take_reader.h"
#include "analysis/synth/demo_corpus.h"
#include "render/take_export.h"
#include "tests/support/gltf_readback.h"
#include "tests/support/gltf_validator.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <tiny_gltf.h>

#include <cstdio>
#include <filesystem>
#include <memory>

using namespace bunraku;

namespace {

namespace fs = std::filesystem;

/// Index of the node named `name`, or -1.
int nodeNamed(const tinygltf::Model& model, const std::string& name)
{
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        if (model.nodes[n].name == name) return int(n);
    return -1;
}

struct CheckedKimono {
    std::size_t keys = 0;
    double worstMetres = 0.0;
};

/// Checks the file's kimono against the simulation of `take` (as exportTake makes it) at
/// `keyFrames`: the morph targets, the weights animation and every key's positions.
CheckedKimono checkKimono(const tinygltf::Model& model, const analysis::Take& take, const std::vector<Eigen::Index>& keyFrames)
{
    const int node = nodeNamed(model, "kimono_cloth");
    REQUIRE(node >= 0);
    const tinygltf::Node& kimonoNode = model.nodes[std::size_t(node)];
    CHECK(kimonoNode.skin < 0);
    CHECK(kimonoNode.rotation.empty());
    CHECK(kimonoNode.translation.empty());
    REQUIRE(kimonoNode.mesh >= 0);
    const tinygltf::Mesh& mesh = model.meshes[std::size_t(kimonoNode.mesh)];
    REQUIRE(mesh.primitives.size() == 1);
    const tinygltf::Primitive& primitive = mesh.primitives[0];
    const std::size_t keys = keyFrames.size();
    REQUIRE(primitive.targets.size() == keys - 1);
    CHECK(mesh.weights.size() == keys - 1);

    // The weights: sampled at the keys' times, target k - 1 at 1 at key k, the rest 0.
    const tinygltf::Animation& animation = model.animations.at(0);
    const tinygltf::AnimationChannel* weightsChannel = nullptr;
    for (const auto& channel : animation.channels)
        if (channel.target_node == node) {
            CHECK(channel.target_path == "weights");
            weightsChannel = &channel;
        }
    REQUIRE(weightsChannel != nullptr);
    const tinygltf::AnimationSampler& sampler = animation.samplers[std::size_t(weightsChannel->sampler)];
    CHECK(sampler.interpolation == "LINEAR");
    const auto times = test::gltfFloats(model, sampler.input);
    const auto weights = test::gltfFloats(model, sampler.output);
    REQUIRE(times.size() == keys);
    REQUIRE(weights.size() == keys * (keys - 1));
    for (std::size_t k = 0; k < keys; ++k) {
        CHECK(times[k] == Approx(double(keyFrames[k]) / take.rateHz).margin(1e-6));
        for (std::size_t t = 0; t + 1 < keys; ++t) CHECK(weights[k * (keys - 1) + t] == (k >= 1 && t == k - 1 ? 1.0 : 0.0));
    }

    // Every key's shape (the mesh plus its target) is the simulation's particles at the key's
    // frame, in the file's axes and metres.
    const analysis::Take clothTake = render::kimonoExportTake(take);
    auto simulated = analysis::simulateKimono(clothTake);
    REQUIRE(simulated.ok());
    const auto simulation = std::make_shared<const analysis::KimonoSimulation>(std::move(simulated).value());
    analysis::KimonoPlayer player(simulation, std::make_shared<const analysis::Take>(clothTake));
    const auto base = test::gltfFloats(model, primitive.attributes.at("POSITION"));
    REQUIRE(base.size() == 3 * simulation->cloth->size());
    CHECK(model.accessors[std::size_t(primitive.indices)].count == simulation->cloth->triangles.size());
    const Eigen::Quaterniond g = analysis::io::gltfAxisChange();
    CheckedKimono checked;
    checked.keys = keys;
    for (std::size_t k = 0; k < keys; ++k) {
        const auto particles = player.frame(keyFrames[k]);
        REQUIRE(particles.ok());
        std::vector<double> displacement(base.size(), 0.0);
        if (k > 0) displacement = test::gltfFloats(model, primitive.targets[k - 1].at("POSITION"));
        REQUIRE(displacement.size() == base.size());
        for (std::size_t i = 0; i < simulation->cloth->size(); ++i) {
            const Eigen::Vector3d expected = g * (0.01 * (**particles)[i]);
            const Eigen::Vector3d file(base[3 * i] + displacement[3 * i], base[3 * i + 1] + displacement[3 * i + 1],
                                       base[3 * i + 2] + displacement[3 * i + 2]);
            checked.worstMetres = std::max(checked.worstMetres, (file - expected).norm());
        }
    }
    INFO("the file's kimono against the simulation: worst " << checked.worstMetres << " m over " << keys << " keys");
    CHECK(checked.worstMetres < 1e-4);
    return checked;
}

} // namespace

TEST_CASE("a demo take's glb carries the simulated kimono as morph targets animated by weights", "[render][export][kimono]")
{
    const analysis::synth::DemoCorpus demo = analysis::synth::generateDemoCorpus();
    const analysis::Take& take = demo.corpus.takes.front();
    REQUIRE(!take.skeleton);
    REQUIRE(take.frameCount() <= render::kKimonoExportMaxKeys);
    const auto body = analysis::defaultBodyDescription();
    const fs::path dir = test::scratchDir("kimono_export_demo");
    render::KimonoExport kimono;
    REQUIRE(render::exportTake(take, body, dir / "kimono.glb", {}, {}, &kimono).ok());
    REQUIRE(render::exportTake(take, body, dir / "plain.glb").ok());
    const tinygltf::Model model = test::loadGlbBytes(test::readBinaryFile((dir / "kimono.glb").string()));

    // Every frame of a short take is a key.
    std::vector<Eigen::Index> every;
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) every.push_back(f);
    CHECK(render::kimonoKeyFrames(take.frameCount()) == every);
    const CheckedKimono checked = checkKimono(model, take, every);

    // The puppet's own mesh without the skinned skirt and sleeves the cloth replaces.
    const analysis::PuppetMesh puppet = analysis::fittedPuppetMesh(analysis::shippedPuppetMesh(), body);
    const std::vector<std::uint32_t> under = analysis::puppetIndicesUnderCloth(puppet);
    REQUIRE(model.meshes.size() == 2); // the figure's, then the kimono's
    const tinygltf::Primitive& figurePrimitive = model.meshes[0].primitives.at(0);
    CHECK(model.accessors[std::size_t(figurePrimitive.indices)].count / 3 == under.size() / 3);
    CHECK(under.size() < puppet.indices.size());
    const tinygltf::Model plain = test::loadGlbBytes(test::readBinaryFile((dir / "plain.glb").string()));
    CHECK(plain.meshes.size() == 1);
    CHECK(plain.accessors[std::size_t(plain.meshes[0].primitives.at(0).indices)].count == puppet.indices.size());

    std::printf("kimono export: demo take %s, %lld frames at %g Hz: %zu keys, worst %.2g m from the simulation; %ju bytes "
                "(without the kimono %ju)\n",
                take.displayName().c_str(), static_cast<long long>(take.frameCount()), take.rateHz, checked.keys, checked.worstMetres,
                std::uintmax_t(fs::file_size(dir / "kimono.glb")), std::uintmax_t(fs::file_size(dir / "plain.glb")));

    // A .csv gets the kimono's 18 channels; a .bvh cannot hold the kimono.
    REQUIRE(render::exportTake(take, body, dir / "kimono.csv", {}, {}, &kimono).ok());
    auto csv = analysis::io::readTakeFile(dir / "kimono.csv");
    REQUIRE(csv.ok());
    CHECK(csv->channelCount() == take.channelCount() + 18);
    const auto refused = render::exportTake(take, body, dir / "kimono.bvh", {}, {}, &kimono);
    REQUIRE_FALSE(refused.ok());
    CHECK_THAT(refused.error().message, Catch::Contains("kimono.bvh") && Catch::Contains("cannot hold the kimono"));
    CHECK_FALSE(fs::exists(dir / "kimono.bvh"));
}

TEST_CASE("a long take keeps at most the budgeted key shapes of the kimono evenly spaced", "[render][export][kimono]")
{
    // An hour at 30 Hz: 512 keys from the first frame to the last, evenly spaced.
    const auto hour = render::kimonoKeyFrames(108000);
    REQUIRE(hour.size() == std::size_t(render::kKimonoExportMaxKeys));
    CHECK(hour.front() == 0);
    CHECK(hour.back() == 107999);
    for (std::size_t k = 1; k < hour.size(); ++k) {
        CHECK(hour[k] > hour[k - 1]);
        CHECK(std::abs(double(hour[k] - hour[k - 1]) - 107999.0 / 511.0) <= 1.0);
    }
    // A take longer than the keys: the file holds them, and the shapes there are the simulation's.
    const analysis::synth::DemoCorpus demo = analysis::synth::generateDemoCorpus();
    const analysis::Take& take = demo.corpus.takes.front();
    const fs::path dir = test::scratchDir("kimono_export_keys");
    render::KimonoExport kimono;
    kimono.maxKeys = 9;
    std::vector<double> progress;
    kimono.control.progress = [&](double fraction) { progress.push_back(fraction); };
    REQUIRE(render::exportTake(take, analysis::defaultBodyDescription(), dir / "keys.glb", {}, {}, &kimono).ok());
    REQUIRE(!progress.empty());
    CHECK(progress.back() == 1.0);
    CHECK(std::is_sorted(progress.begin(), progress.end()));
    const auto keys = render::kimonoKeyFrames(take.frameCount(), 9);
    REQUIRE(keys.size() == 9);
    CHECK(keys.back() == take.frameCount() - 1);
    const tinygltf::Model model = test::loadGlbBytes(test::readBinaryFile((dir / "keys.glb").string()));
    checkKimono(model, take, keys);
    std::printf("kimono export: the same take with 9 keys: %ju bytes\n", std::uintmax_t(fs::file_size(dir / "keys.glb")));
}

TEST_CASE("a Bandai take's glb carries the kimono on the performer where the simulation puts it", "[render][export][kimono][bandai]")
{
    const fs::path source = test::bandaiDir() / "bye_angry_001.bvh";
    if (!test::requireBandaiData(fs::exists(source))) return;
    auto take = analysis::io::readTakeFile(source);
    REQUIRE(take.ok());
    const fs::path dir = test::scratchDir("kimono_export_bandai");
    render::KimonoExport kimono;
    REQUIRE(render::exportTake(*take, analysis::defaultBodyDescription(), dir / "bye.glb", {}, {}, &kimono).ok());
    const tinygltf::Model model = test::loadGlbBytes(test::readBinaryFile((dir / "bye.glb").string()));
    const CheckedKimono checked = checkKimono(model, *take, render::kimonoKeyFrames(take->frameCount()));
    std::printf("kimono export: Bandai bye_angry_001 (%lld frames): %zu keys, worst %.2g m; %ju bytes\n",
                static_cast<long long>(take->frameCount()), checked.keys, checked.worstMetres,
                std::uintmax_t(fs::file_size(dir / "bye.glb")));
}

TEST_CASE("the Khronos glTF validator finds no error in a glb with the kimono", "[render][export][kimono][validator]")
{
    if (!test::requireGltfValidator()) return;
    const analysis::synth::DemoCorpus demo = analysis::synth::generateDemoCorpus();
    const fs::path dir = test::scratchDir("kimono_export_validator");
    render::KimonoExport kimono;
    std::vector<fs::path> files{dir / "demo.glb"};
    REQUIRE(render::exportTake(demo.corpus.takes.front(), analysis::defaultBodyDescription(), files[0], {}, {}, &kimono).ok());
    const fs::path bandai = test::bandaiDir() / "bye_angry_001.bvh";
    if (fs::exists(bandai)) {
        auto take = analysis::io::readTakeFile(bandai);
        REQUIRE(take.ok());
        files.push_back(dir / "bye.glb");
        REQUIRE(render::exportTake(*take, analysis::defaultBodyDescription(), files.back(), {}, {}, &kimono).ok());
    }
    for (const fs::path& file : files) {
        const nlohmann::json report = test::validateGltf(file);
        INFO(file.filename().string() << ": errors\n"
                                      << test::gltfIssues(report, 0) << "warnings\n"
                                      << test::gltfIssues(report, 1) << "infos\n"
                                      << test::gltfIssues(report, 2));
        CHECK(report["issues"]["numErrors"].get<int>() == 0);
        CHECK(report["issues"]["numWarnings"].get<int>() == 0);
        std::printf("gltf-validator on %s: %d errors, %d warnings, %d infos, %d hints\n", file.filename().string().c_str(),
                    report["issues"]["numErrors"].get<int>(), report["issues"]["numWarnings"].get<int>(),
                    report["issues"]["numInfos"].get<int>(), report["issues"]["numHints"].get<int>());
    }
}
