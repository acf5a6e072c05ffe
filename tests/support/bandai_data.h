#pragma once
/// The real Bandai Namco takes (../shared/data/bandai, read in place) for tests, and checks
/// every derived take must pass: continuous Euler angles and constant bone lengths.
/// A missing file fails the test under CI=true and is reported as skipped otherwise.

#include "analysis/core/angle_channels.h"
#include "analysis/core/corpus.h"
#include "analysis/core/rotation.h"
#include "analysis/core/skeleton.h"
#include "analysis/io/take_reader.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

namespace bunraku::test {

/// True when every named Bandai file exists; otherwise fails under CI=true and is reported as
/// skipped outside (requireBandaiData, tests/support/peer.h).
inline bool bandaiAvailable(const std::vector<std::string>& names)
{
    const bool all = std::all_of(names.begin(), names.end(), [](const std::string& name) { return std::filesystem::exists(bandaiDir() / name); });
    return requireBandaiData(all);
}

inline std::vector<std::string> bandaiWaveStyles() { return {"normal", "active", "exhausted"}; }

inline std::string bandaiWaveFile(const std::string& style, int take)
{
    return "wave-right-hand_" + style + "_00" + std::to_string(take) + ".bvh";
}

inline std::vector<std::string> bandaiWaveFiles()
{
    std::vector<std::string> names;
    for (const auto& style : bandaiWaveStyles())
        for (int k = 1; k <= 5; ++k) names.push_back(bandaiWaveFile(style, k));
    return names;
}

/// One Bandai take read as the importer reads it (io::readTakeFile: puppet parts and skeleton).
inline analysis::Take readBandai(const std::string& name, analysis::TakeLabels labels = {})
{
    auto take = analysis::io::readTakeFile(bandaiDir() / name);
    if (!take) FAIL(take.error().message);
    analysis::Take result = std::move(take).value();
    if (!labels.function.empty()) {
        labels.source = name;
        result.labels = labels;
    }
    return result;
}

/// The Bandai waves as a corpus: function "wave" x styles normal (neutral), active, exhausted
/// x takes 1..5, each file read and labelled here (no corpus command involved).
inline analysis::Corpus bandaiWaveCorpus()
{
    analysis::Corpus corpus;
    corpus.name = "bandai waves";
    corpus.neutralEmotion = "normal";
    for (const auto& style : bandaiWaveStyles())
        for (int k = 1; k <= 5; ++k) corpus.takes.push_back(readBandai(bandaiWaveFile(style, k), {"wave", style, k, ""}));
    corpus.rateHz = corpus.takes.front().rateHz;
    return corpus;
}

/// The Bandai bye takes as a corpus of one take per cell: function "bye" x styles normal
/// (neutral), happy, angry.
inline analysis::Corpus bandaiByeCorpus()
{
    analysis::Corpus corpus;
    corpus.name = "bandai bye";
    corpus.neutralEmotion = "normal";
    for (const std::string style : {"normal", "happy", "angry"})
        corpus.takes.push_back(readBandai("bye_" + style + "_001.bvh", {"bye", style, 1, ""}));
    corpus.rateHz = corpus.takes.front().rateHz;
    return corpus;
}

/// Steps of the Euler angles "that the rotation itself does not make": a 6-DOF part's step
/// above `limitDeg` (largest of |d yaw|, |d pitch|, |d roll|) between consecutive frames when
/// an equivalent triple of the later frame (whole turns, the mirrored triple) lies nearer the
/// earlier one and the rotation itself turns by less than `limitDeg`. A gimbal region (|pitch|
/// near 90) legitimately moves yaw and roll far for a small turn; a branch jump or a mix of
/// angles from different rotations does not pass.
inline int unexplainedEulerSteps(const analysis::Take& take, double limitDeg = 45.0)
{
    using namespace bunraku::analysis;
    int count = 0;
    for (const auto& part : sixDofParts(take)) {
        const Eigen::Index c = part.firstChannel;
        for (Eigen::Index f = 1; f < take.frameCount(); ++f) {
            const YawPitchRoll a{take.values(f - 1, c + 3), take.values(f - 1, c + 4), take.values(f - 1, c + 5)};
            const YawPitchRoll b{take.values(f, c + 3), take.values(f, c + 4), take.values(f, c + 5)};
            auto stepTo = [&](const YawPitchRoll& x) {
                return std::max({std::abs(x.yaw - a.yaw), std::abs(x.pitch - a.pitch), std::abs(x.roll - a.roll)});
            };
            const double step = stepTo(b);
            if (step <= limitDeg) continue;
            const double turn = rotationDistance(rotationFromYawPitchRoll(a), rotationFromYawPitchRoll(b)) * 180.0 / std::numbers::pi;
            if (turn >= limitDeg) continue;
            if (step > stepTo(nearestEquivalent(b, a)) + 1e-6) ++count;
        }
    }
    return count;
}

/// Largest change over the frames of any bone's length (distance of a joint from its parent in
/// world space), cm.
inline double maxBoneLengthChange(const analysis::SkeletalMotion& motion)
{
    const auto& joints = motion.skeleton->joints;
    const auto first = motion.worldPoses(0);
    double worst = 0.0;
    for (Eigen::Index f = 0; f < motion.frameCount(); ++f) {
        const auto poses = motion.worldPoses(f);
        for (std::size_t j = 0; j < joints.size(); ++j) {
            const int parent = joints[j].parent;
            if (parent < 0) continue;
            // a moving joint's translation is a position, not a bone
            if (std::find(motion.movingJoints.begin(), motion.movingJoints.end(), int(j)) != motion.movingJoints.end()) continue;
            const double length = (poses[j].translation - poses[std::size_t(parent)].translation).norm();
            const double reference = (first[j].translation - first[std::size_t(parent)].translation).norm();
            worst = std::max(worst, std::abs(length - reference));
        }
    }
    return worst;
}

/// The same take with every 6-DOF part's angles written on other branches: frame by frame the
/// mirrored triple on every other frame and whole turns on the rest (the orientations are
/// unchanged; the numbers jump everywhere).
inline analysis::Take onOtherBranches(const analysis::Take& take)
{
    analysis::Take out = take;
    for (const auto& part : analysis::sixDofParts(out)) {
        const Eigen::Index c = part.firstChannel;
        for (Eigen::Index f = 0; f < out.frameCount(); ++f) {
            double& yaw = out.values(f, c + 3);
            double& pitch = out.values(f, c + 4);
            double& roll = out.values(f, c + 5);
            if (f % 2 == 0) {
                yaw += 180.0 + 360.0 * double(f % 3);
                pitch = 180.0 - pitch;
                roll += 180.0 - 720.0;
            } else {
                yaw -= 360.0;
                roll += 360.0 * double(f % 5);
            }
        }
    }
    return out;
}

/// The same take as another calibration of the same skeleton would give it: every 6-DOF part's
/// frame turned by a constant rotation of its own (world_R_part C_p), angles written
/// continuously; positions unchanged.
inline analysis::Take recalibrated(const analysis::Take& take)
{
    using namespace bunraku::analysis;
    Take out = take;
    int p = 0;
    for (const auto& part : sixDofParts(out)) {
        const Eigen::Quaterniond c(Eigen::AngleAxisd(0.4 + 0.9 * p, Eigen::Vector3d(1.0, 0.5 * p - 1.0, 0.3 * p).normalized()));
        for (Eigen::Index f = 0; f < out.frameCount(); ++f) {
            RigidTransform pose = partPose(take, f, part.firstChannel);
            pose.rotation = pose.rotation * c;
            setPartPose(out, f, part.firstChannel, pose);
        }
        ++p;
    }
    return out;
}

} // namespace bunraku::test
