#pragma once
/// Shared fixtures of the render tests: an offscreen renderer without multisampling (exact
/// pixels), puppet takes in known poses, and pixel probes.

#include "analysis/body/body_description.h"
#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"
#include "render/offscreen_renderer.h"

#include <catch2/catch.hpp>

#include <QImage>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace bunraku::test {

/// The renderer every test uses; a test fails (not skips) without OpenGL 3.3: run under xvfb-run.
inline std::unique_ptr<render::OffscreenRenderer> makeOffscreenRenderer()
{
    auto created = render::OffscreenRenderer::create(render::OffscreenOptions{0});
    INFO((created.ok() ? std::string() : created.error().message));
    REQUIRE(created.ok());
    return std::move(created).value();
}

/// The pose of one puppet part: position (cm) and yaw, pitch, roll (deg).
struct PartPose {
    double x = 0, y = 0, z = 0, yaw = 0, pitch = 0, roll = 0;
};

/// A 24-channel puppet take whose frame f has the sensor poses `pose(f)` (head, shoulder, arm, hand).
inline analysis::Take puppetTake(Eigen::Index frames, const std::function<std::array<PartPose, 4>(Eigen::Index)>& pose)
{
    analysis::Take take;
    take.channels = analysis::puppetChannels();
    take.values.resize(frames, analysis::kPuppetChannelCount);
    for (Eigen::Index f = 0; f < frames; ++f) {
        const auto parts = pose(f);
        for (int p = 0; p < 4; ++p) {
            const PartPose& q = parts[std::size_t(p)];
            const double values[6] = {q.x, q.y, q.z, q.yaw, q.pitch, q.roll};
            for (int d = 0; d < 6; ++d) take.values(f, p * 6 + d) = values[d];
        }
    }
    take.labels.source = "test";
    return take;
}

/// The puppet standing at `origin` facing +x with both arms spread sideways (no part hides
/// another when seen from the front), the same at every frame.
inline analysis::Take spreadArmsTake(Eigen::Index frames, const Eigen::Vector3d& origin = {0, 0, 100})
{
    return puppetTake(frames, [origin](Eigen::Index) {
        const double x = origin.x(), y = origin.y(), z = origin.z();
        // Parts spread apart so that no part hides another from the front: the head 22 cm above
        // the shoulder sensor, the right arm (bone along local x) straight out to the right
        // (yaw -90) clear of the shoulder board, the hand just beyond the arm's end.
        return std::array<PartPose, 4>{PartPose{x + 4.0, y, z + 22.0, 0, 0, 0}, PartPose{x, y, z, 0, 0, 0},
                                       PartPose{x, y - 27.0, z - 1.0, -90.0, 0, 0},
                                       PartPose{x, y - 43.0, z - 1.0, -90.0, 0, 0}};
    });
}

/// The spread-arms puppet walking `distance` cm along +x (towards the partner) at an even pace
/// over `frames` frames, starting `distance` / 2 behind the origin.
inline analysis::Take travellingTake(Eigen::Index frames, double distance)
{
    const analysis::Take still = spreadArmsTake(frames);
    analysis::Take take = still;
    for (Eigen::Index f = 0; f < frames; ++f)
        for (int p = 0; p < 4; ++p) take.values(f, p * 6) += distance * (double(f) / double(frames - 1) - 0.5);
    return take;
}

/// 8-connected components of the pixels of `ids` (an ID image) for which `inside` holds; the
/// number of those pixels in `pixels`.
inline int silhouetteComponents(const QImage& ids, const std::function<bool(QRgb)>& inside, int* pixels = nullptr)
{
    const int w = ids.width(), h = ids.height();
    std::vector<char> on(std::size_t(w) * std::size_t(h), 0);
    int count = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (inside(ids.pixel(x, y))) {
                on[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 1;
                ++count;
            }
    if (pixels) *pixels = count;
    int components = 0;
    std::vector<int> stack;
    for (int start = 0; start < w * h; ++start) {
        if (on[std::size_t(start)] != 1) continue;
        ++components;
        on[std::size_t(start)] = 2;
        stack.push_back(start);
        while (!stack.empty()) {
            const int i = stack.back();
            stack.pop_back();
            const int x = i % w, y = i / w;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const int j = ny * w + nx;
                    if (on[std::size_t(j)] == 1) {
                        on[std::size_t(j)] = 2;
                        stack.push_back(j);
                    }
                }
        }
    }
    return components;
}

inline bool isBackground(QRgb pixel)
{
    // The renderer's background is a light grey-blue (0.94, 0.95, 0.97).
    return std::abs(qRed(pixel) - 240) <= 2 && std::abs(qGreen(pixel) - 242) <= 2 && std::abs(qBlue(pixel) - 247) <= 2;
}

/// True when some pixel within `radius` of `centre` satisfies `predicate`.
inline bool anyPixelNear(const QImage& image, QPointF centre, int radius, const std::function<bool(QRgb)>& predicate)
{
    const int cx = int(std::floor(centre.x()));
    const int cy = int(std::floor(centre.y()));
    for (int y = cy - radius; y <= cy + radius; ++y)
        for (int x = cx - radius; x <= cx + radius; ++x)
            if (image.valid(x, y) && predicate(image.pixel(x, y))) return true;
    return false;
}

inline int countPixels(const QImage& image, const std::function<bool(QRgb)>& predicate)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (predicate(image.pixel(x, y))) ++count;
    return count;
}

} // namespace bunraku::test
