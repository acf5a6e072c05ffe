// The motion axis's masses from the modelled puppet (analysis/body/puppet_mass.h): every mass
// point lies inside the modelled solid, in the part its surface moves with; the left parts mirror
// the right; a fitted body carries its points and volumes with the fit; a body without the
// puppet's parts keeps its primitives.
#include "analysis/axis/inertia_axis.h"
#include "analysis/body/body_description.h"
#include "analysis/body/puppet_mass.h"
#include "analysis/body/puppet_model.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;

namespace {

/// The part joint a point of the solid belongs to (the kimono hangs from the shoulder, a sleeve
/// from its arm).
int partJointOf(PuppetJoint joint)
{
    if (joint == PuppetJoint::Kimono) return int(PuppetJoint::Shoulder);
    if (joint == PuppetJoint::RightSleeve) return int(PuppetJoint::RightArm);
    if (joint == PuppetJoint::LeftSleeve) return int(PuppetJoint::LeftArm);
    return int(joint);
}

} // namespace

TEST_CASE("the model's mass points lie inside the modelled solid in the part whose surface they move with")
{
    const PuppetSolidSample& sample = puppetSolidSample(1.0);
    const auto model_T_part = puppetPartBindPoses();
    Eigen::Index total = 0;
    for (int j = 0; j < 6; ++j) {
        const Eigen::Matrix3Xd& points = sample.partPoints[std::size_t(j)];
        INFO("part " << kPuppetJointNames[std::size_t(j)] << ": " << points.cols() << " points");
        CHECK(points.cols() > 30);
        total += points.cols();
        // Each part's volume converges with the lattice: within 10 % of the 0.5 cm lattice's
        // (the carved hands, 1-2 cm thick, are the coarsest).
        const double fineVolume = double(puppetSolidSample(0.5).partPoints[std::size_t(j)].cols()) * 0.125;
        INFO("volume " << double(points.cols()) << " cm^3 at 1 cm, " << fineVolume << " cm^3 at 0.5 cm");
        CHECK(std::abs(double(points.cols()) - fineVolume) < 0.1 * fineVolume);
        int outside = 0, elsewhere = 0;
        for (Eigen::Index k = 0; k < points.cols(); k += 7) {
            const Eigen::Vector3f p = model_T_part[std::size_t(j)].apply(points.col(k)).cast<float>();
            if (puppetSignedDistance(p) >= 0.0f) ++outside;
            if (partJointOf(puppetDominantJointAt(p)) != j) ++elsewhere;
        }
        CHECK(outside == 0);
        CHECK(elsewhere == 0);
    }
    // The solid's volume converges with the lattice: 1 cm and 0.5 cm agree within 2 %.
    const PuppetSolidSample& fine = puppetSolidSample(0.5);
    Eigen::Index fineTotal = 0;
    for (const auto& points : fine.partPoints) fineTotal += points.cols();
    const double volume = double(total) * sample.cellVolume();
    const double fineVolume = double(fineTotal) * fine.cellVolume();
    INFO("solid volume " << volume << " cm^3 at 1 cm, " << fineVolume << " cm^3 at 0.5 cm");
    CHECK(std::abs(volume - fineVolume) < 0.02 * fineVolume);
}

TEST_CASE("the model's left arm and hand weigh what the right ones do and sit at their mirror image")
{
    const BodyDescription& body = defaultBodyDescription();
    const AxisModel model = makeAxisModel(body);
    REQUIRE(model.massSource == MassSource::Model);
    for (const auto& [right, left] : {std::pair{"right_arm", "left_arm"}, std::pair{"right_hand", "left_hand"}}) {
        const PartMoments& r = model.parts[std::size_t(body.partIndex(right))];
        const PartMoments& l = model.parts[std::size_t(body.partIndex(left))];
        INFO(right << " " << r.mass << " g, " << left << " " << l.mass << " g");
        CHECK(r.mass > 10.0);
        CHECK(l.mass == Approx(r.mass).epsilon(1e-9));
        // Mirrored parts' frames hold the reflected geometry: the centre's y is negated.
        CHECK(l.centre.x() == Approx(r.centre.x()).margin(1e-6));
        CHECK(l.centre.y() == Approx(-r.centre.y()).margin(1e-6));
        CHECK(l.centre.z() == Approx(r.centre.z()).margin(1e-6));
    }
    // The masses are the description's densities times the model's volumes: the shoulder (board,
    // dō-wa and the kimono) is the heaviest part, then the head.
    const auto mass = [&](const char* part) { return model.parts[std::size_t(body.partIndex(part))].mass; };
    CHECK(mass("shoulder") > mass("head"));
    CHECK(mass("head") > mass("right_arm"));
    CHECK(mass("right_arm") > mass("right_hand"));
    double sum = 0.0;
    for (const PartMoments& part : model.parts) sum += part.mass;
    CHECK(model.totalMass == Approx(sum));
}

TEST_CASE("a fitted part carries its mass points and its volume with the fit")
{
    BodyDescription body = defaultBodyDescription();
    const int head = body.partIndex("head");
    REQUIRE(head >= 0);
    const auto shipped = modelMassPoints(body);
    REQUIRE(shipped.ok());
    Eigen::Affine3d fit = Eigen::Affine3d::Identity();
    fit.linear() = Eigen::Vector3d(1.2, 1.1, 0.9).asDiagonal();
    fit.translation() = Eigen::Vector3d(1.0, 0.0, -2.0);
    body.parts[std::size_t(head)].fit = fit;
    const auto fitted = modelMassPoints(body);
    REQUIRE(fitted.ok());
    const MassPoints& a = (*shipped)[std::size_t(head)];
    const MassPoints& b = (*fitted)[std::size_t(head)];
    REQUIRE(a.positions.cols() == b.positions.cols());
    for (Eigen::Index k = 0; k < a.positions.cols(); k += 11)
        CHECK((b.positions.col(k) - fit * Eigen::Vector3d(a.positions.col(k))).norm() < 1e-9);
    // The head's primitives were not fitted here, so the densities are looked up at the moved
    // points; the volume scales by det = 1.2 * 1.1 * 0.9.
    const double volumeA = double(a.positions.cols()), massA = a.masses.sum();
    INFO("head " << massA << " g shipped, " << b.masses.sum() << " g fitted, " << volumeA << " points");
    CHECK(b.masses.maxCoeff() / a.masses.maxCoeff() == Approx(1.2 * 1.1 * 0.9).epsilon(1e-9));
    // Other parts are untouched.
    const int shoulder = body.partIndex("shoulder");
    CHECK((*fitted)[std::size_t(shoulder)].masses.sum() == Approx((*shipped)[std::size_t(shoulder)].masses.sum()).epsilon(1e-12));
}

TEST_CASE("the primitives stay one option away and serve a body without the puppet's parts")
{
    const BodyDescription& puppet = defaultBodyDescription();
    AxisOptions options;
    options.massPoints.source = MassSource::Primitives;
    const AxisModel primitives = makeAxisModel(puppet, options);
    CHECK(primitives.massSource == MassSource::Primitives);
    double expected = 0.0;
    for (const MassPoints& points : sampleMassPoints(puppet)) expected += points.masses.sum();
    CHECK(primitives.totalMass == Approx(expected).epsilon(1e-12));

    // A one-part body (not the puppet): its primitives, whatever the option says.
    const auto rod = parseBodyDescription(R"({"format": "bunraku-body-description", "version": 1, "name": "rod",
        "mirror_frame_part": "torso",
        "parts": [{"name": "torso", "driven_by": "shoulder", "density": 1.0,
                   "primitives": [{"name": "rod", "shape": "cylinder", "radius": 2, "length": 40}]}]})",
                                          "rod.json");
    INFO((rod.ok() ? std::string() : rod.error().message));
    REQUIRE(rod.ok());
    const AxisModel model = makeAxisModel(*rod);
    CHECK(model.massSource == MassSource::Primitives);
    CHECK(model.totalMass == Approx(3.14159265358979 * 4.0 * 40.0).epsilon(0.05));
    CHECK_FALSE(modelMassPoints(*rod).ok());
}
