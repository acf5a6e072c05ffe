#pragma once
/// Synthetic puppet takes for the body, axis and design tests: the 4 sensor parts at a rest
/// pose (shoulder 100 cm up, head above it, arm hanging at the right shoulder, hand below it;
/// sensor placements as resources/puppet/bunraku_puppet.json describes them), moved by a
/// whole-body rigid motion and small per-part wiggles.

#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/core/take.h"

#include <cmath>
#include <functional>

namespace bunraku::test {

/// world_T_part of part p (0 head, 1 shoulder, 2 arm, 3 hand) at rest.
inline analysis::RigidTransform restPose(int part)
{
    // head sensor 7 cm above and 3 cm in front of the neck joint (8 cm above the shoulder
    // sensor); the arm and hand frames run along the bone (x), here hanging down: pitch 90.
    static const Eigen::Vector3d positions[4] = {{4, 0, 115}, {0, 0, 100}, {0, -9, 89}, {0, -9, 75}};
    const bool limb = part >= 2;
    return analysis::RigidTransform{limb ? Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitY()))
                                         : Eigen::Quaterniond::Identity(),
                                    positions[part]};
}

/// A 24-channel puppet take of `frames` frames: frame f shows body(f) * part(f, p) * rest(p).
inline analysis::Take puppetTake(Eigen::Index frames,
                                 const std::function<analysis::RigidTransform(Eigen::Index)>& body,
                                 const std::function<analysis::RigidTransform(Eigen::Index, int)>& part = {})
{
    analysis::Take take;
    take.channels = analysis::puppetChannels();
    take.values = Eigen::MatrixXd::Zero(frames, analysis::kPuppetChannelCount);
    take.labels.source = "fixture";
    for (Eigen::Index f = 0; f < frames; ++f)
        for (int p = 0; p < analysis::kPuppetPartCount; ++p) {
            analysis::RigidTransform local = restPose(p);
            if (part) local = local * part(f, p);
            analysis::setPartPose(take, f, p * analysis::kDofCount, body(f) * local);
        }
    return take;
}

inline analysis::RigidTransform rotationAbout(const Eigen::Vector3d& axis, double degrees,
                                              const Eigen::Vector3d& translation = Eigen::Vector3d::Zero())
{
    return analysis::RigidTransform{Eigen::Quaterniond(Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized())),
                                    translation};
}

/// A lively take: the body sways and bows, each part wiggles about its own sensor.
inline analysis::Take livelyTake(Eigen::Index frames = 106)
{
    return puppetTake(
        frames,
        [](Eigen::Index f) {
            const double t = double(f);
            return analysis::RigidTransform{
                Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * std::sin(t / 9.0), Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(0.25 * std::sin(t / 13.0) + 0.1, Eigen::Vector3d::UnitY())),
                Eigen::Vector3d(5.0 * std::sin(t / 11.0), 3.0 * std::cos(t / 7.0), 2.0 * std::sin(t / 5.0))};
        },
        [](Eigen::Index f, int p) {
            const double t = double(f) + 7.0 * p;
            return rotationAbout(Eigen::Vector3d(std::sin(t / 3.0), 1.0, 0.3), 15.0 * std::sin(t / 6.0));
        });
}

} // namespace bunraku::test
