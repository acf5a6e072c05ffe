#include "analysis/core/angle_channels.h"

#include "analysis/core/rotation.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace bunraku::analysis {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

YawPitchRoll anglesAt(const Eigen::MatrixXd& values, Eigen::Index frame, Eigen::Index first)
{
    return YawPitchRoll{values(frame, first + 3), values(frame, first + 4), values(frame, first + 5)};
}

void setAngles(Eigen::MatrixXd& values, Eigen::Index frame, Eigen::Index first, const YawPitchRoll& a)
{
    values(frame, first + 3) = a.yaw;
    values(frame, first + 4) = a.pitch;
    values(frame, first + 5) = a.roll;
}

/// rotationFromYawPitchRoll in closed form (Rz(yaw) Ry(pitch) Rx(roll) from the half-angle
/// sines and cosines): the same rotation to rounding, at a third of the cost, for the many
/// conversions of whole takes.
Eigen::Quaterniond quaternionFromAngles(const YawPitchRoll& a)
{
    const double hy = 0.5 * a.yaw * kDegree, hp = 0.5 * a.pitch * kDegree, hr = 0.5 * a.roll * kDegree;
    const double cy = std::cos(hy), sy = std::sin(hy), cp = std::cos(hp), sp = std::sin(hp), cr = std::cos(hr), sr = std::sin(hr);
    return Eigen::Quaterniond(cy * cp * cr + sy * sp * sr, cy * cp * sr - sy * sp * cr, cy * sp * cr + sy * cp * sr,
                              sy * cp * cr - cy * sp * sr);
}

double l1(const YawPitchRoll& a, const YawPitchRoll& b)
{
    return std::abs(a.yaw - b.yaw) + std::abs(a.pitch - b.pitch) + std::abs(a.roll - b.roll);
}

} // namespace

std::vector<Eigen::Quaterniond> partRotations(const Take& take, const SixDofPart& part)
{
    std::vector<Eigen::Quaterniond> rotations(std::size_t(take.frameCount()));
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
        rotations[std::size_t(f)] = quaternionFromAngles(anglesAt(take.values, f, part.firstChannel));
    return rotations;
}

Take rotationCoordinateTake(const Take& take, const Take* reference)
{
    const auto parts = sixDofParts(take);
    if (reference) {
        const auto referenceParts = sixDofParts(*reference);
        const bool same = referenceParts.size() == parts.size() &&
                          std::equal(parts.begin(), parts.end(), referenceParts.begin(),
                                     [](const SixDofPart& a, const SixDofPart& b) { return a.part == b.part; });
        if (!same || reference->frameCount() == 0) reference = nullptr;
    }
    Take out = take;
    if (parts.empty() || take.frameCount() == 0) return out;
    const RotationChart chart = meanPartChart({reference ? reference : &take});
    out.values = rotationCoordinates(take, chart);
    return out;
}

RotationChart meanPartChart(const std::vector<const Take*>& takes, ChartTime time)
{
    RotationChart chart;
    if (takes.empty()) return chart;
    const auto parts = sixDofParts(*takes.front());
    chart.tracks = int(parts.size());
    if (parts.empty()) return chart;
    // Each take's parts are found by name, so takes with the same parts in another order agree.
    std::vector<std::vector<std::vector<Eigen::Quaterniond>>> rotations; // [take][part][frame]
    Eigen::Index shortest = takes.front()->frameCount();
    for (const Take* take : takes) {
        shortest = std::min(shortest, take->frameCount());
        const auto own = sixDofParts(*take);
        std::vector<std::vector<Eigen::Quaterniond>> perPart;
        for (const auto& part : parts) {
            const auto match = std::find_if(own.begin(), own.end(), [&](const SixDofPart& p) { return p.part == part.part; });
            perPart.push_back(match == own.end() ? std::vector<Eigen::Quaterniond>{} : partRotations(*take, *match));
        }
        rotations.push_back(std::move(perPart));
    }
    std::vector<Eigen::Quaterniond> samples;
    if (time == ChartTime::Constant) {
        chart.frames = 1;
        for (std::size_t p = 0; p < parts.size(); ++p) {
            samples.clear();
            for (const auto& take : rotations) samples.insert(samples.end(), take[p].begin(), take[p].end());
            chart.base.push_back(chordalMeanRotation(samples));
        }
        return chart;
    }
    chart.frames = std::max<Eigen::Index>(shortest, 1);
    chart.base.resize(std::size_t(chart.frames) * parts.size());
    for (Eigen::Index f = 0; f < chart.frames; ++f)
        for (std::size_t p = 0; p < parts.size(); ++p) {
            samples.clear();
            for (const auto& take : rotations)
                if (f < Eigen::Index(take[p].size())) samples.push_back(take[p][std::size_t(f)]);
            chart.base[std::size_t(f) * parts.size() + p] = chordalMeanRotation(samples);
        }
    return chart;
}

Eigen::MatrixXd rotationCoordinates(const Take& take, const RotationChart& chart)
{
    Eigen::MatrixXd out = take.values;
    const auto parts = sixDofParts(take);
    assert(int(parts.size()) == chart.tracks);
    for (std::size_t p = 0; p < parts.size() && int(p) < chart.tracks; ++p) {
        const Eigen::Index c = parts[p].firstChannel;
        Eigen::Vector3d previous = Eigen::Vector3d::Zero();
        for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
            const Eigen::Quaterniond world_R_part = quaternionFromAngles(anglesAt(take.values, f, c));
            // The turn away from the base in world axes: independent of the part's own frame.
            const Eigen::Quaterniond turn = world_R_part * chart.at(f, int(p)).conjugate();
            const Eigen::Vector3d r = f == 0 ? logMap(turn) : nearestRotationVector(turn, previous);
            previous = r;
            out(f, c + 3) = r.z() / kDegree;
            out(f, c + 4) = r.y() / kDegree;
            out(f, c + 5) = r.x() / kDegree;
        }
    }
    return out;
}

Eigen::MatrixXd eulerFromRotationCoordinates(const Take& layout, const Eigen::MatrixXd& coordinates, const RotationChart& chart,
                                             const std::optional<Eigen::RowVectorXd>& firstAngles)
{
    Eigen::MatrixXd out = coordinates;
    const auto parts = sixDofParts(layout);
    assert(int(parts.size()) == chart.tracks);
    for (std::size_t p = 0; p < parts.size() && int(p) < chart.tracks; ++p) {
        const Eigen::Index c = parts[p].firstChannel;
        for (Eigen::Index f = 0; f < coordinates.rows(); ++f) {
            const Eigen::Vector3d r(coordinates(f, c + 5), coordinates(f, c + 4), coordinates(f, c + 3));
            const Eigen::Quaterniond world_R_part = expMap(r * kDegree) * chart.at(f, int(p));
            YawPitchRoll angles = yawPitchRollFromRotation(world_R_part);
            if (f > 0)
                angles = nearestEquivalent(angles, anglesAt(out, f - 1, c));
            else if (firstAngles && firstAngles->size() == coordinates.cols())
                angles = nearestEquivalent(angles, YawPitchRoll{(*firstAngles)[c + 3], (*firstAngles)[c + 4], (*firstAngles)[c + 5]});
            setAngles(out, f, c, angles);
        }
    }
    return out;
}

int filterEulerAngles(Take& take)
{
    // The correction of a frame: whether its triple was mirrored and the whole turns added to
    // each angle; a discontinuity is removed wherever the correction changes.
    struct Correction {
        bool mirrored = false;
        double yaw = 0.0, pitch = 0.0, roll = 0.0;
        bool operator==(const Correction&) const = default;
    };
    auto correctionOf = [](const YawPitchRoll& raw, const YawPitchRoll& chosen) {
        const bool mirrored = std::abs(std::remainder(chosen.pitch - raw.pitch, 360.0)) > 1e-6;
        const YawPitchRoll base = mirrored ? YawPitchRoll{raw.yaw + 180.0, 180.0 - raw.pitch, raw.roll + 180.0} : raw;
        return Correction{mirrored, std::round((chosen.yaw - base.yaw) / 360.0), std::round((chosen.pitch - base.pitch) / 360.0),
                          std::round((chosen.roll - base.roll) / 360.0)};
    };
    int removed = 0;
    for (const auto& part : sixDofParts(take)) {
        const Eigen::Index c = part.firstChannel;
        Correction previous;
        for (Eigen::Index f = 1; f < take.frameCount(); ++f) {
            const YawPitchRoll own = anglesAt(take.values, f, c);
            const YawPitchRoll nearest = nearestEquivalent(own, anglesAt(take.values, f - 1, c));
            const bool changed = l1(own, nearest) > 1e-9; // else keep the numbers bit for bit
            const Correction correction = changed ? correctionOf(own, nearest) : Correction{};
            if (!(correction == previous)) ++removed;
            previous = correction;
            if (changed) setAngles(take.values, f, c, nearest);
        }
    }
    return removed;
}

int matchPartBranches(Take& take, const Take& reference)
{
    int changed = 0;
    if (take.frameCount() == 0 || reference.frameCount() == 0) return 0;
    const auto referenceParts = sixDofParts(reference);
    for (const auto& part : sixDofParts(take)) {
        const auto match = std::find_if(referenceParts.begin(), referenceParts.end(),
                                        [&](const SixDofPart& p) { return p.part == part.part; });
        if (match == referenceParts.end()) continue;
        const Eigen::Index c = part.firstChannel;
        const YawPitchRoll own = anglesAt(take.values, 0, c);
        const YawPitchRoll target = anglesAt(reference.values, 0, match->firstChannel);
        // The two families of equivalent triples: whole turns of each angle, and the mirrored
        // triple (yaw + 180, 180 - pitch, roll + 180) with whole turns.
        auto turns = [](double value, double goal) { return 360.0 * std::round((goal - value) / 360.0); };
        const YawPitchRoll straight{own.yaw + turns(own.yaw, target.yaw), own.pitch + turns(own.pitch, target.pitch),
                                    own.roll + turns(own.roll, target.roll)};
        const YawPitchRoll mirroredFirst{own.yaw + 180.0, 180.0 - own.pitch, own.roll + 180.0};
        const YawPitchRoll mirrored{mirroredFirst.yaw + turns(mirroredFirst.yaw, target.yaw),
                                    mirroredFirst.pitch + turns(mirroredFirst.pitch, target.pitch),
                                    mirroredFirst.roll + turns(mirroredFirst.roll, target.roll)};
        const bool mirror = l1(mirrored, target) < l1(straight, target);
        const YawPitchRoll shift = mirror ? YawPitchRoll{mirrored.yaw - own.yaw - 180.0, mirrored.pitch - (180.0 - own.pitch),
                                                         mirrored.roll - own.roll - 180.0}
                                          : YawPitchRoll{straight.yaw - own.yaw, straight.pitch - own.pitch, straight.roll - own.roll};
        if (!mirror && shift.yaw == 0.0 && shift.pitch == 0.0 && shift.roll == 0.0) continue;
        for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
            YawPitchRoll a = anglesAt(take.values, f, c);
            if (mirror) a = YawPitchRoll{a.yaw + 180.0, 180.0 - a.pitch, a.roll + 180.0};
            setAngles(take.values, f, c, YawPitchRoll{a.yaw + shift.yaw, a.pitch + shift.pitch, a.roll + shift.roll});
        }
        changed += int(std::lround((std::abs(shift.yaw) + std::abs(shift.pitch) + std::abs(shift.roll)) / 360.0)) + (mirror ? 1 : 0);
    }
    return changed;
}

} // namespace bunraku::analysis
