// Averages and skeleton coordinates of full-skeleton motions, on rotations.
#include "analysis/skeleton/skeleton_blend.h"
#include "tests/support/bandai_data.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bunraku::analysis;

namespace {

/// root (moving) -> spine -> arm -> hand -> hand_End, offsets 10 cm each.
std::shared_ptr<const Skeleton> chain()
{
    auto skeleton = std::make_shared<Skeleton>();
    skeleton->name = "chain";
    const char* names[] = {"root", "spine", "arm", "hand"};
    for (int j = 0; j < 4; ++j) {
        SkeletonJoint joint;
        joint.name = names[j];
        joint.parent = j - 1;
        joint.offset = j == 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0, 0, 10);
        skeleton->joints.push_back(joint);
    }
    SkeletonJoint end;
    end.name = "hand_End";
    end.parent = 3;
    end.endSite = true;
    end.offset = Eigen::Vector3d(5, 0, 0);
    skeleton->joints.push_back(end);
    skeleton->parts = {{"hand", 3, {}}};
    return skeleton;
}

/// Joint j turns by phase + 0.02 j f about an axis of its own; the root walks along x.
std::shared_ptr<const SkeletalMotion> motion(double phase, Eigen::Index frames = 30, const std::shared_ptr<const Skeleton>& skeleton = chain())
{
    auto m = std::make_shared<SkeletalMotion>(makeRestMotion(skeleton, frames));
    m->movingJoints = {0};
    m->movingTranslations.resize(frames, 3);
    for (Eigen::Index f = 0; f < frames; ++f) {
        for (int j = 0; j < 4; ++j)
            m->rotation(f, j) = Eigen::Quaterniond(Eigen::AngleAxisd(phase + 0.02 * double(j + 1) * double(f),
                                                                     Eigen::Vector3d(1.0, double(j), 0.5).normalized()));
        m->movingTranslations.row(f) << 2.0 * double(f) + phase, 0.0, 90.0;
    }
    return m;
}

} // namespace

TEST_CASE("the average of identical motions is that motion")
{
    const auto a = motion(0.3);
    const Eigen::VectorXd frames = Eigen::VectorXd::LinSpaced(30, 0.0, 29.0);
    auto mean = meanSkeletalMotion({{a.get(), frames, 1.0}, {a.get(), frames, 1.0}, {a.get(), frames, 2.0}});
    REQUIRE(mean.ok());
    for (Eigen::Index f = 0; f < 30; ++f)
        for (int j = 0; j < a->jointSlots(); ++j) {
            CHECK(rotationDistance((*mean)->rotation(f, j), a->rotation(f, j)) < 1e-12);
            CHECK(((*mean)->translation(f, j) - a->translation(f, j)).norm() < 1e-12);
        }
}

TEST_CASE("the average of two motions takes each joint's geodesic midpoint and the mean root position")
{
    const auto a = motion(0.0);
    const auto b = motion(0.6);
    const Eigen::VectorXd frames = Eigen::VectorXd::LinSpaced(30, 0.0, 29.0);
    auto mean = meanSkeletalMotion({{a.get(), frames, 1.0}, {b.get(), frames, 1.0}});
    REQUIRE(mean.ok());
    for (Eigen::Index f = 0; f < 30; ++f) {
        for (int j = 0; j < 4; ++j) {
            const double half = 0.5 * rotationDistance(a->rotation(f, j), b->rotation(f, j));
            CHECK(rotationDistance((*mean)->rotation(f, j), a->rotation(f, j)) == Approx(half).margin(1e-9));
            CHECK(rotationDistance((*mean)->rotation(f, j), b->rotation(f, j)) == Approx(half).margin(1e-9));
        }
        CHECK((*mean)->translation(f, 0).x() == Approx(2.0 * double(f) + 0.3));
    }
    CHECK(bunraku::test::maxBoneLengthChange(**mean) < 1e-9);
    // members read at other frames: b one frame later
    Eigen::VectorXd later = frames.array() + 1.0;
    auto shifted = meanSkeletalMotion({{a.get(), frames, 1.0}, {b.get(), later, 1.0}});
    REQUIRE(shifted.ok());
    CHECK((*shifted)->translation(0, 0).x() == Approx(0.5 * (0.0 + 2.0 + 0.6)));
}

TEST_CASE("skeleton coordinates round-trip and weighted sums stay rotations with constant bones")
{
    const auto a = motion(0.1);
    const auto b = motion(0.9);
    auto chart = meanSkeletonChart({a, b});
    REQUIRE(chart.ok());
    CHECK(chart->coordinateCount() == 3 * 5 + 3);
    const Eigen::MatrixXd ca = skeletonCoordinates(*a, *chart);
    const Eigen::MatrixXd cb = skeletonCoordinates(*b, *chart);
    const SkeletalMotionPtr back = motionFromSkeletonCoordinates(ca, *chart);
    for (Eigen::Index f = 0; f < 30; ++f)
        for (int j = 0; j < 5; ++j) {
            CHECK(rotationDistance(back->rotation(f, j), a->rotation(f, j)) < 1e-9);
            CHECK((back->translation(f, j) - a->translation(f, j)).norm() < 1e-9);
        }
    // y + a z with y the mean and z the half difference: a = 0, 1, 2 give the mean, b and beyond
    const Eigen::MatrixXd y = 0.5 * (ca + cb);
    const Eigen::MatrixXd z = cb - y;
    for (double weight : {0.0, 1.0, 2.0}) {
        const SkeletalMotionPtr weighted = motionFromSkeletonCoordinates(y + weight * z, *chart);
        CHECK(validateSkeletalMotion(*weighted).ok());
        CHECK(bunraku::test::maxBoneLengthChange(*weighted) < 1e-9);
        if (weight == 1.0)
            for (int j = 0; j < 4; ++j) CHECK(rotationDistance(weighted->rotation(12, j), b->rotation(12, j)) < 1e-9);
    }
}

TEST_CASE("motions of other bones are averaged on the first one's bones, motions of other joints not at all")
{
    const auto a = motion(0.0);
    auto other = std::make_shared<Skeleton>(*chain());
    other->joints[2].offset = Eigen::Vector3d(0, 0, 12); // a longer bone
    const auto b = motion(0.0, 30, other);
    CHECK(compatibleMotions(*a, *b));
    const Eigen::VectorXd frames = Eigen::VectorXd::LinSpaced(30, 0.0, 29.0);
    auto mean = meanSkeletalMotion({{a.get(), frames, 1.0}, {b.get(), frames, 1.0}});
    REQUIRE(mean.ok());
    // One body: the first member's bone, constant over the frames.
    CHECK(((*mean)->staticTranslations[2] - a->staticTranslations[2]).norm() < 1e-12);
    CHECK(bunraku::test::maxBoneLengthChange(**mean) < 1e-9);
    CHECK(meanSkeletonChart({a, b}).ok());
    // Another joint layout cannot be averaged joint by joint.
    auto renamed = std::make_shared<Skeleton>(*chain());
    renamed->joints[2].name = "elsewhere";
    const auto c = motion(0.0, 30, renamed);
    CHECK_FALSE(compatibleMotions(*a, *c));
    auto refused = meanSkeletalMotion({{a.get(), frames, 1.0}, {c.get(), frames, 1.0}});
    REQUIRE_FALSE(refused.ok());
    CHECK_FALSE(meanSkeletonChart({a, c}).ok());
    // a root that stands elsewhere is a position, not a bone
    auto moved = std::make_shared<SkeletalMotion>(*a);
    moved->movingJoints.clear();
    moved->movingTranslations.resize(30, 0);
    moved->staticTranslations[0] = Eigen::Vector3d(100, 0, 0);
    CHECK(compatibleMotions(*a, *moved));
}
