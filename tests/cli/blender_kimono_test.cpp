// Blender 3.4 (Debian's) as the peer of the kimono in the .glb: `bunraku convert TAKE --kimono -o
// F.glb` of a demo take and of a Bandai take, both imported by one headless Blender
// (tests/cli/blender_kimono.py); at several times of each file the kimono object's evaluated mesh
// (shape keys applied by the depsgraph) lies where our simulation puts the cloth, and it moves.
// Without Blender (or the Bandai data) the case fails under CI=true and is reported as skipped
// otherwise.
#include "tests/cli/cli_runner.h"
#include "tests/support/blender_peer.h"
#include "tests/support/peer.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/io/gltf_export.h"
#include "analysis/io/take_reader.h"
#include "render/take_export.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>

using namespace bunraku;
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

/// Blender's world (z up, forward -y, metres) of a point in the workbench's axes (cm): through
/// glTF's axes, which Blender's importer turns as (x, y, z) -> (x, -z, y).
Eigen::Vector3d blenderFromWorkbench(const Eigen::Vector3d& p)
{
    const Eigen::Vector3d y_up = analysis::io::gltfAxisChange() * (0.01 * p);
    return {y_up.x(), -y_up.z(), y_up.y()};
}

struct Job {
    std::string label;
    fs::path take;               ///< what `convert` read
    fs::path glb;                ///< what it wrote
    std::vector<Eigen::Index> frames; ///< compared at frame / rate seconds
    analysis::Take read;
};

} // namespace

TEST_CASE("blender plays the kimono of a glb export where our simulation puts it", "[cli][export][kimono][blender]")
{
    const fs::path bandai = test::bandaiDir() / "bye_angry_001.bvh";
    if (!test::requireBandaiData(fs::exists(bandai))) return;
    if (!test::requireBlender()) return;
    const fs::path dir = test::scratchDir("blender_kimono");
    auto demo = test::runBunraku({"demo", "-o", (dir / "demo").string()});
    REQUIRE(demo.exitCode == 0);

    std::vector<Job> jobs{{"demo greeting_friendly_2", dir / "demo" / "greeting_friendly_2.csv", dir / "demo.glb", {}, {}},
                          {"Bandai bye_angry_001", bandai, dir / "bye.glb", {}, {}}};
    for (Job& job : jobs) {
        const auto run = test::runBunraku({"convert", job.take.string(), "--kimono", "-o", job.glb.string()});
        INFO(run.out << run.err);
        REQUIRE(run.exitCode == 0);
        CHECK(run.out.find("the simulated kimono as morph targets") != std::string::npos);
        auto read = analysis::io::readTakeFile(job.take);
        REQUIRE(read.ok());
        job.read = std::move(read).value();
        const Eigen::Index frames = job.read.frameCount();
        REQUIRE(frames <= render::kKimonoExportMaxKeys); // every frame a key
        // Times that fall on whole frames of Blender's default 24 fps and between them.
        job.frames = {0, frames / 5, frames / 3, frames / 2, (2 * frames) / 3, frames - 1};
    }

    const fs::path script = test::sourceDir() / "tests" / "cli" / "blender_kimono.py";
    const fs::path out = dir / "blender.json", log = dir / "blender.log";
    std::string command = "blender -b --factory-startup --python-exit-code 1 -P '" + script.string() + "' -- '" + out.string() + "'";
    for (const Job& job : jobs) {
        std::string times;
        for (Eigen::Index f : job.frames) {
            char t[32];
            std::snprintf(t, sizeof t, "%.9g", double(f) / job.read.rateHz);
            times += (times.empty() ? "" : ",") + std::string(t);
        }
        command += " '" + job.glb.string() + "' " + times;
    }
    command += " >'" + log.string() + "' 2>&1 </dev/null";
    const int status = std::system(command.c_str());
    std::ifstream logIn(log);
    const std::string logText((std::istreambuf_iterator<char>(logIn)), std::istreambuf_iterator<char>());
    INFO("blender log:\n" << logText.substr(logText.size() > 6000 ? logText.size() - 6000 : 0));
    REQUIRE(status == 0);
    std::ifstream in(out);
    REQUIRE(in.good());
    const json blender = json::parse(in);
    REQUIRE(blender["files"].size() == jobs.size());

    for (std::size_t j = 0; j < jobs.size(); ++j) {
        const Job& job = jobs[j];
        const json& file = blender["files"][j];
        INFO(job.label << ": blender's kimono object " << file["object"] << ", meshes " << file["meshes"].dump());
        // The simulation exportTake makes of the take `convert` read.
        const analysis::Take clothTake = render::kimonoExportTake(job.read);
        auto simulated = analysis::simulateKimono(clothTake);
        REQUIRE(simulated.ok());
        const auto simulation = std::make_shared<const analysis::KimonoSimulation>(std::move(simulated).value());
        analysis::KimonoPlayer player(simulation, std::make_shared<const analysis::Take>(clothTake));
        const std::size_t particles = simulation->cloth->size();
        CHECK(file["vertices"].get<std::size_t>() == particles);
        CHECK(file["shape_keys"].get<Eigen::Index>() == job.read.frameCount()); // the basis and a key per later frame
        CHECK(file["keyframes"].get<Eigen::Index>() == job.read.frameCount());
        REQUIRE(file["positions"].size() == job.frames.size());
        double worst = 0.0;
        std::vector<std::vector<Eigen::Vector3d>> theirs;
        for (std::size_t k = 0; k < job.frames.size(); ++k) {
            const json& positions = file["positions"][k];
            REQUIRE(positions.size() == particles);
            const auto ours = player.frame(job.frames[k]);
            REQUIRE(ours.ok());
            theirs.emplace_back();
            for (std::size_t i = 0; i < particles; ++i) {
                const Eigen::Vector3d p(positions[i][0].get<double>(), positions[i][1].get<double>(), positions[i][2].get<double>());
                theirs.back().push_back(p);
                worst = std::max(worst, (p - blenderFromWorkbench((**ours)[i])).norm());
            }
        }
        // It moves: the largest displacement of a vertex between two of the times.
        double moved = 0.0;
        for (std::size_t a = 0; a < theirs.size(); ++a)
            for (std::size_t b = a + 1; b < theirs.size(); ++b)
                for (std::size_t i = 0; i < particles; ++i) moved = std::max(moved, (theirs[a][i] - theirs[b][i]).norm());
        std::printf("blender kimono: %s (%lld frames at %g Hz, %zu particles, %s at %g fps): worst %.3g mm from our simulation at %zu times, "
                    "moved up to %.1f mm\n",
                    job.label.c_str(), static_cast<long long>(job.read.frameCount()), job.read.rateHz, particles,
                    file["object"].get<std::string>().c_str(), file["scene_fps"].get<double>(), 1000.0 * worst, job.frames.size(),
                    1000.0 * moved);
        CHECK(worst < 1e-3);  // within 1 mm
        CHECK(moved > 5e-3);  // more than 5 mm
    }
}
