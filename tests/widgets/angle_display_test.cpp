// The graphs' "Angles" choice: Euler angles as stored, or rotation coordinates about take A's
// mean part orientations for A, B and the ghost alike.
#include "widgets/graph_panel.h"

#include "analysis/core/angle_channels.h"
#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"

#include <catch2/catch.hpp>

#include <QComboBox>

#include <cmath>

using namespace bunraku;

namespace {

/// A 4-part take whose hand pitches through 90 deg (gimbal) while it yaws.
std::shared_ptr<const analysis::Take> gimbalTake(double phase)
{
    analysis::Take take;
    take.channels = analysis::puppetChannels();
    take.rateHz = 30.0;
    take.values = Eigen::MatrixXd::Zero(90, analysis::kPuppetChannelCount);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        for (int part = 0; part < analysis::kPuppetPartCount; ++part) {
            const double t = double(f) / 30.0;
            analysis::RigidTransform pose;
            pose.translation = Eigen::Vector3d(10.0 * part, 2.0 * std::sin(t + phase), 100.0 + 5.0 * part);
            // The hand pitched near 90 deg and wobbling about the world's forward axis: its
            // Euler yaw and roll sweep far for small turns.
            pose.rotation = part == 3 ? Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * std::sin(3.0 * t + phase), Eigen::Vector3d::UnitX()) *
                                                           Eigen::AngleAxisd(1.5 + 0.1 * std::sin(t), Eigen::Vector3d::UnitY()))
                                      : Eigen::Quaterniond(Eigen::AngleAxisd(1.2 * std::sin(2.0 * t + phase), Eigen::Vector3d::UnitZ()) *
                                                           Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()));
            analysis::setPartPose(take, f, part * analysis::kDofCount, pose);
        }
    }
    return std::make_shared<const analysis::Take>(std::move(take));
}

} // namespace

TEST_CASE("the graphs show angles as Euler angles or as rotation coordinates about take A's mean orientations", "[widgets][angles]")
{
    widgets::GraphPanel panel;
    const auto a = gimbalTake(0.0);
    const auto b = gimbalTake(0.7);
    panel.setGhost(b);
    panel.setTakes(a, b, QStringLiteral("a|b"));
    CHECK(panel.angleDisplay() == widgets::AngleDisplay::Euler);
    CHECK(panel.shownTakeA() == a); // as given, not copied
    CHECK(panel.shownTakeB() == b);

    auto* box = panel.findChild<QComboBox*>(QStringLiteral("angleDisplay"));
    REQUIRE(box);
    box->setCurrentIndex(box->findData(int(widgets::AngleDisplay::RotationCoordinates)));
    REQUIRE(panel.angleDisplay() == widgets::AngleDisplay::RotationCoordinates);
    const analysis::RotationChart chart = analysis::meanPartChart({a.get()});
    CHECK(panel.shownTakeA()->values == analysis::rotationCoordinates(*a, chart));
    CHECK(panel.shownTakeB()->values == analysis::rotationCoordinates(*b, chart)); // A's base, not its own
    CHECK(panel.shownTakeA()->values.leftCols(3) == a->values.leftCols(3));
    // The hand's Euler yaw sweeps near pitch 90 deg (over 45 deg in a frame); its rotation coordinates do not.
    const Eigen::Index yaw = *a->channelIndex("hand", "yaw");
    const auto largestStep = [&](const Eigen::MatrixXd& values) {
        return (values.col(yaw).tail(values.rows() - 1) - values.col(yaw).head(values.rows() - 1)).cwiseAbs().maxCoeff();
    };
    CHECK(largestStep(a->values) > 45.0);
    CHECK(largestStep(panel.shownTakeA()->values) < 10.0);

    panel.setAngleDisplay(widgets::AngleDisplay::Euler);
    CHECK(panel.shownTakeA() == a);
    CHECK(panel.shownTakeB() == b);
}
