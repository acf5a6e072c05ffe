// The kimono as cloth (analysis/cloth/kimono_cloth.h): it hangs at rest and comes to rest, the
// same frame is the same cloth however it is reached, it keeps off the body, and a sleeve
// follows a swinging arm with a lag.
#include "analysis/cloth/kimono_cloth.h"

#include "analysis/body/body_description.h"
#include "tests/analysis/axis/puppet_fixture.h"
#include "tests/analysis/cloth/cloth_depth.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace bunraku::analysis;
using bunraku::test::puppetTake;
using bunraku::test::restPose;

namespace {

Take stillTake(Eigen::Index frames)
{
    Take take = puppetTake(frames, [](Eigen::Index) { return RigidTransform{}; });
    take.rateHz = 30.0;
    return take;
}

/// The right arm and hand, raised to point forward, swing left and right about the shoulder
/// joint (`amplitude` degrees at `hz`), the long sleeve hanging under the arm.
Take swingingTake(Eigen::Index frames, double amplitude, double hz)
{
    const Eigen::Vector3d shoulderJoint(0.0, -9.0, 99.0);
    Take take = puppetTake(
        frames, [](Eigen::Index) { return RigidTransform{}; },
        [&](Eigen::Index f, int p) {
            if (p < 2) return RigidTransform{};
            const double angle = amplitude * std::sin(2.0 * M_PI * hz * double(f) / 30.0) * M_PI / 180.0;
            const Eigen::Quaterniond turn = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-M_PI / 2.0, Eigen::Vector3d::UnitY());
            const RigidTransform aboutJoint{turn, shoulderJoint - turn * shoulderJoint};
            return restPose(p).inverse() * aboutJoint * restPose(p);
        });
    take.rateHz = 30.0;
    return take;
}

} // namespace

TEST_CASE("at rest the kimono hangs below the dō-wa and the arms and comes to rest")
{
    const Take take = stillTake(150);
    const auto simulation = simulateKimono(take);
    INFO((simulation.ok() ? std::string() : simulation.error().message));
    REQUIRE(simulation.ok());
    const KimonoCloth& cloth = *simulation->cloth;
    const auto x = kimonoFrame(*simulation, take, 149);
    REQUIRE(x.ok());
    const auto holders = kimonoHolderPoses(simulation->body, take, 149);
    REQUIRE(holders.ok());
    const double dowaZ = (*holders)[0].apply(Eigen::Vector3d(0.0, 0.0, -24.0)).z();
    // Every skirt particle but the sewn ring hangs below the dō-wa; the hem 25 cm or more below.
    for (std::uint32_t i = 0; i < cloth.skirtEnd; ++i)
        if (!cloth.pinned[i]) CHECK((*x)[i].z() < dowaZ);
    for (int point : {2, 3, 4, 5}) CHECK((*x)[cloth.measured[std::size_t(point)]].z() < dowaZ - 25.0);
    // Each sleeve hangs below its arm: every free particle lower than the sewn particle of its
    // column (the sleeves' grids are 7 columns along the arm, a sewn row then 8 free ones).
    for (const std::uint32_t first : {cloth.skirtEnd, cloth.rightSleeveEnd}) {
        int below = 0;
        for (std::uint32_t row = 1; row < 9; ++row)
            for (std::uint32_t column = 0; column < 7; ++column) {
                const std::uint32_t i = first + row * 7 + column, sewn = first + column;
                REQUIRE(cloth.pinned[sewn]);
                REQUIRE_FALSE(cloth.pinned[i]);
                if ((*x)[i].z() < (*x)[sewn].z()) ++below;
            }
        CHECK(below == 8 * 7);
    }
    // Energy does not grow: the cloth of a still puppet comes to rest (the points move less and
    // less: after 5 s a hundredth of what they moved at the start, under 0.05 mm a frame).
    const auto& points = simulation->points;
    const double early = (points.row(5) - points.row(4)).cwiseAbs().maxCoeff();
    const double late = (points.row(149) - points.row(148)).cwiseAbs().maxCoeff();
    INFO("largest move of a measured point: " << early << " cm at frame 5, " << late << " cm at frame 149");
    CHECK(late < 0.01 * early);
    CHECK(late < 0.005);
}

TEST_CASE("playing jumping and scrubbing to the same frame give identical cloth")
{
    Take take = bunraku::test::livelyTake(106);
    take.rateHz = 30.0;
    const auto simulation = simulateKimono(take);
    REQUIRE(simulation.ok());
    REQUIRE(simulation->checkpointInterval == 30);
    // In an order no player would use: forwards, back, across checkpoints.
    for (const Eigen::Index frame : {Eigen::Index(75), Eigen::Index(0), Eigen::Index(31), Eigen::Index(30), Eigen::Index(29),
                                     Eigen::Index(105), Eigen::Index(60), Eigen::Index(59)}) {
        const auto x = kimonoFrame(*simulation, take, frame);
        REQUIRE(x.ok());
        for (int p = 0; p < kKimonoPointCount; ++p) {
            const Eigen::Vector3d played = simulation->points.block<1, 3>(frame, 3 * p).transpose();
            INFO("frame " << frame << ", point " << kimonoPointName(KimonoPoint(p)));
            CHECK(((*x)[simulation->cloth->measured[std::size_t(p)]].array() == played.array()).all()); // bit for bit
        }
    }
    // The same take simulated again: the same bits.
    const auto again = simulateKimono(take);
    REQUIRE(again.ok());
    CHECK((again->points.array() == simulation->points.array()).all());
}

TEST_CASE("no cloth particle lies more than 0.5 cm inside the body on a lively take")
{
    Take take = bunraku::test::livelyTake(106);
    take.rateHz = 30.0;
    const auto simulation = simulateKimono(take);
    REQUIRE(simulation.ok());
    const auto colliders = kimonoColliders(simulation->body);
    REQUIRE(colliders.size() == 3);
    double deepest = 0.0;
    for (Eigen::Index frame = 0; frame < take.frameCount(); frame += 7) {
        const auto x = kimonoFrame(*simulation, take, frame);
        REQUIRE(x.ok());
        const auto holders = kimonoHolderPoses(simulation->body, take, frame);
        REQUIRE(holders.ok());
        deepest = std::max(deepest, bunraku::test::deepestInsideBody(*simulation->cloth, *x, colliders, *holders));
    }
    INFO("deepest: " << deepest << " cm");
    CHECK(deepest <= 0.5);
}

TEST_CASE("a sleeve follows a swinging arm with a lag")
{
    const Take take = swingingTake(150, 35.0, 0.8);
    const auto simulation = simulateKimono(take);
    REQUIRE(simulation.ok());
    // Sideways velocities (cm/frame, y) of the hand's sensor and of the right sleeve's tip.
    const Eigen::Index handY = 3 * 6 + 1;
    std::vector<double> handSpeed, tipSpeed;
    for (Eigen::Index f = 1; f < take.frameCount(); ++f) {
        handSpeed.push_back(take.values(f, handY) - take.values(f - 1, handY));
        tipSpeed.push_back(simulation->points(f, 1) - simulation->points(f - 1, 1));
    }
    // The lag (frames) of the best match of the two speeds over the last two periods.
    const int period = int(std::lround(30.0 / 0.8));
    const std::size_t from = handSpeed.size() - std::size_t(2 * period);
    const auto correlation = [&](int lag) {
        double sum = 0.0;
        for (std::size_t t = from; t < handSpeed.size(); ++t)
            if (int(t) + lag >= 0 && std::size_t(int(t) + lag) < tipSpeed.size()) sum += handSpeed[t] * tipSpeed[std::size_t(int(t) + lag)];
        return sum;
    };
    int bestLag = 0;
    for (int lag = -period / 2; lag <= period / 2; ++lag)
        if (correlation(lag) > correlation(bestLag)) bestLag = lag;
    // The peak between frames: a parabola through the best lag and its neighbours.
    const double before = correlation(bestLag - 1), at = correlation(bestLag), after = correlation(bestLag + 1);
    const double lag = double(bestLag) + 0.5 * (before - after) / (before - 2.0 * at + after);
    INFO("the sleeve tip's sideways velocity follows the hand's by " << lag << " frames");
    CHECK(lag > 0.1);
    CHECK(lag < 0.25 * period);
    // It swings, not a rigid copy of the arm's motion: it moves at least half as fast as the hand.
    CHECK(*std::max_element(tipSpeed.begin() + std::ptrdiff_t(from), tipSpeed.end()) > 0.5 * *std::max_element(handSpeed.begin() + std::ptrdiff_t(from), handSpeed.end()));
}

TEST_CASE("the kimono's channels and parameters")
{
    const auto channels = kimonoChannels();
    REQUIRE(channels.size() == 18);
    CHECK(channels.front().name() == "sleeve_right_tip.x");
    CHECK(channels[8].name() == "hem_front.z");
    CHECK(channels.back().name() == "hem_right.z");
    ClothParameters bad;
    bad.massPerArea = 0.0;
    const auto refused = validate(bad);
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().message.find("cloth.massPerArea") != std::string::npos);
    const Take take = stillTake(4);
    const auto simulation = simulateKimono(take);
    REQUIRE(simulation.ok());
    const Take with = withKimonoChannels(take, *simulation);
    CHECK(with.channelCount() == take.channelCount() + 18);
    CHECK(with.values.leftCols(take.channelCount()) == take.values);
}

TEST_CASE("in a deep bow the simulated hem stays below the dō-wa")
{
    // The body pitches forward 70 deg about a point at the dō-wa's height over 2 s and holds.
    const Eigen::Vector3d hips(0.0, 0.0, 76.0);
    Take take = puppetTake(120, [&](Eigen::Index f) {
        const double degrees = 70.0 * std::min(1.0, double(f) / 60.0);
        return bunraku::test::rotationAbout(Eigen::Vector3d::UnitY(), degrees, hips - Eigen::Quaterniond(Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::UnitY())) * hips);
    });
    take.rateHz = 30.0;
    const auto simulation = simulateKimono(take);
    REQUIRE(simulation.ok());
    for (const Eigen::Index frame : {Eigen::Index(30), Eigen::Index(60), Eigen::Index(119)}) {
        const auto holders = kimonoHolderPoses(simulation->body, take, frame);
        REQUIRE(holders.ok());
        const double dowaZ = (*holders)[0].apply(Eigen::Vector3d(0.0, 0.0, -24.0)).z();
        for (int point : {2, 3, 4, 5}) {
            INFO("frame " << frame << " " << kimonoPointName(KimonoPoint(point)));
            CHECK(simulation->points(frame, 3 * point + 2) < dowaZ - 10.0);
        }
    }
}

TEST_CASE("one player gives every frame the same cloth as a fresh simulation from the checkpoint whatever the order")
{
    Take take = bunraku::test::livelyTake(106);
    take.rateHz = 30.0;
    auto simulation = simulateKimono(take);
    REQUIRE(simulation.ok());
    const auto shared = std::make_shared<const KimonoSimulation>(std::move(*simulation));
    const auto sharedTake = std::make_shared<const Take>(take);
    KimonoPlayer player(shared, sharedTake);
    std::vector<Eigen::Index> order;
    for (Eigen::Index f = 0; f < 106; ++f) order.push_back(f); // playing
    for (Eigen::Index f = 105; f >= 0; f -= 7) order.push_back(f); // scrubbing back
    for (const Eigen::Index f : {40, 41, 43, 12, 95, 95, 59, 60, 61}) order.push_back(f); // jumps and steps
    // Every frame visited against the simulation's own (its stored particles, the doubles rounded
    // to floats), and every fourth visit and each jump's landing against a fresh rebuild from the
    // checkpoint, bit for bit (a rebuild costs up to 29 frames of simulation).
    int compared = 0, rebuilt = 0;
    for (std::size_t visit = 0; visit < order.size(); ++visit) {
        const Eigen::Index frame = order[visit];
        const auto played = player.frame(frame);
        REQUIRE(played.ok());
        const float* stored = shared->storedFrame(frame);
        REQUIRE(stored != nullptr);
        bool same = true;
        for (std::size_t i = 0; i < played.value()->size(); ++i)
            for (int k = 0; k < 3; ++k) same = same && float((*played.value())[i][k]) == stored[3 * i + std::size_t(k)];
        INFO("frame " << frame);
        CHECK(same);
        ++compared;
        if (visit % 4 == 0 || visit >= 106) {
            const auto fresh = kimonoFrame(*shared, take, frame);
            REQUIRE(fresh.ok());
            REQUIRE(played.value()->size() == fresh->size());
            bool exact = true;
            for (std::size_t i = 0; i < fresh->size(); ++i) exact = exact && ((*played.value())[i].array() == (*fresh)[i].array()).all();
            CHECK(exact);
            ++rebuilt;
        }
    }
    CHECK(compared == int(order.size()));
    CHECK(rebuilt > 30);
    CHECK_FALSE(player.frame(106).ok());
    CHECK_FALSE(player.frame(-1).ok());
}

TEST_CASE("a simulation keeps every frame's particles within its budget and only checkpoints beyond it")
{
    Take take = bunraku::test::livelyTake(90);
    take.rateHz = 30.0;
    const auto simulation = simulateKimono(take);
    REQUIRE(simulation.ok());
    const std::size_t particles = simulation->cloth->size();
    REQUIRE(simulation->particleFrames.size() == std::size_t(90) * particles * 3);
    for (const Eigen::Index frame : {Eigen::Index(0), Eigen::Index(44), Eigen::Index(89)}) {
        const auto x = kimonoFrame(*simulation, take, frame);
        REQUIRE(x.ok());
        const float* stored = simulation->storedFrame(frame);
        REQUIRE(stored != nullptr);
        bool same = true;
        for (std::size_t i = 0; i < particles; ++i)
            for (int k = 0; k < 3; ++k) same = same && stored[3 * i + std::size_t(k)] == float((*x)[i][k]);
        INFO("frame " << frame);
        CHECK(same);
    }
    CHECK(simulation->storedFrame(90) == nullptr);
    // A take whose frames exceed the budget keeps checkpoints only (about 2,700 frames fit).
    const std::size_t fit = kKimonoStoredFramesBytes / (particles * 3 * sizeof(float));
    CHECK(fit > 2000);
    CHECK(fit < 4000);
}

namespace {

/// Crossings of the ray from `origin` along `direction` with the skirt's triangles (Möller and
/// Trumbore): odd when the origin lies inside the skirt's tube; `nearest` the distance to the
/// nearest crossing.
int skirtCrossings(const KimonoCloth& cloth, const std::vector<Eigen::Vector3d>& x, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                   double& nearest)
{
    int crossings = 0;
    nearest = 1e9;
    for (std::size_t t = 0; t + 2 < cloth.triangles.size(); t += 3) {
        const std::uint32_t a = cloth.triangles[t], b = cloth.triangles[t + 1], c = cloth.triangles[t + 2];
        if (a >= cloth.skirtEnd || b >= cloth.skirtEnd || c >= cloth.skirtEnd) continue;
        const Eigen::Vector3d e1 = x[b] - x[a], e2 = x[c] - x[a];
        const Eigen::Vector3d p = direction.cross(e2);
        const double det = e1.dot(p);
        if (std::abs(det) < 1e-12) continue;
        const Eigen::Vector3d s = origin - x[a];
        const double u = s.dot(p) / det;
        if (u < 0.0 || u > 1.0) continue;
        const Eigen::Vector3d q = s.cross(e1);
        const double v = direction.dot(q) / det;
        if (v < 0.0 || u + v > 1.0) continue;
        const double distance = e2.dot(q) / det;
        if (distance > 0.0) {
            ++crossings;
            nearest = std::min(nearest, distance);
        }
    }
    return crossings;
}

} // namespace

TEST_CASE("a sleeve that meets the skirt stays outside it")
{
    for (const bool lively : {false, true}) {
        Take take = lively ? bunraku::test::livelyTake(106) : stillTake(90);
        take.rateHz = 30.0;
        const auto simulation = simulateKimono(take);
        REQUIRE(simulation.ok());
        const KimonoCloth& cloth = *simulation->cloth;
        int near = 0, inside = 0;
        double deepest = 0.0;
        for (Eigen::Index frame = 0; frame < take.frameCount(); frame += 9) {
            const auto x = kimonoFrame(*simulation, take, frame);
            REQUIRE(x.ok());
            // The skirt's axis: the centres of its top and bottom rings.
            Eigen::Vector3d top = Eigen::Vector3d::Zero(), hem = Eigen::Vector3d::Zero();
            for (int i = 0; i < 28; ++i) {
                top += (*x)[std::size_t(i)] / 28.0;
                hem += (*x)[std::size_t(12 * 28 + i)] / 28.0;
            }
            for (std::uint32_t i = cloth.skirtEnd; i < cloth.size(); ++i) {
                if (cloth.pinned[i]) continue;
                const Eigen::Vector3d& p = (*x)[i];
                if (p.z() > top.z() - 0.5 || p.z() < hem.z() + 0.5) continue;
                const double f = (top.z() - p.z()) / (top.z() - hem.z());
                const Eigen::Vector3d axis = (1.0 - f) * top + f * hem;
                Eigen::Vector3d out = p - axis;
                out.z() = 0.0;
                if (out.norm() < 1e-6 || out.norm() > 20.0) continue;
                ++near;
                double depth = 0.0;
                if (skirtCrossings(cloth, *x, p, out.normalized(), depth) % 2 == 1) {
                    deepest = std::max(deepest, depth);
                    if (depth > 0.5) ++inside; // the tolerance the body's collisions are held to
                }
            }
        }
        INFO((lively ? "lively take: " : "still take: ") << near << " sleeve particles beside the skirt, " << inside
                                                         << " more than 0.5 cm inside it, the deepest " << deepest << " cm");
        CHECK(near > 50);
        CHECK(inside == 0);
    }
}
