#include "widgets/take_series.h"

#include "tests/widgets/synthetic_take.h"

#include <catch2/catch.hpp>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

using namespace bunraku;

TEST_CASE("valueAt returns frame values at frame times and interpolates between them", "[widgets][take_series]")
{
    const auto take = test::syntheticPuppetTake(20);
    for (Eigen::Index k : {0, 7, 19}) {
        REQUIRE(widgets::valueAt(*take, 3, double(k) / 5.0).value() == Approx(test::syntheticValue(k, 3, 0.0)));
    }
    const double middle = 0.5 * (test::syntheticValue(4, 5, 0.0) + test::syntheticValue(5, 5, 0.0));
    REQUIRE(widgets::valueAt(*take, 5, 0.9).value() == Approx(middle));
}

TEST_CASE("valueAt has no value outside the take or for a missing channel", "[widgets][take_series]")
{
    const auto take = test::syntheticPuppetTake(20);
    REQUIRE_FALSE(widgets::valueAt(*take, 0, -0.5).has_value());
    REQUIRE_FALSE(widgets::valueAt(*take, 0, 19.0 / 5.0 + 0.01).has_value());
    REQUIRE_FALSE(widgets::valueAt(*take, 24, 1.0).has_value());
    REQUIRE(widgets::nearestFrame(*take, 100.0) == 19);
    REQUIRE(widgets::nearestFrame(*take, 0.29) == 1);
}

TEST_CASE("channelRange is the extreme values of a channel", "[widgets][take_series]")
{
    const auto take = test::syntheticPuppetTake(50);
    const auto range = widgets::channelRange(*take, 2).value();
    REQUIRE(range.lower == take->values.col(2).minCoeff());
    REQUIRE(range.upper == take->values.col(2).maxCoeff());
    REQUIRE(widgets::findChannel(*take, "arm", "pitch").value() == 16);
    REQUIRE_FALSE(widgets::findChannel(*take, "tail", "x").has_value());
}

namespace {

/// A long noisy channel: sin plus a deterministic hash, so buckets have distinct extremes.
std::shared_ptr<analysis::Take> longTake(Eigen::Index frames, double rateHz)
{
    auto take = std::make_shared<analysis::Take>();
    take->rateHz = rateHz;
    take->channels = {{"hand", "x", "cm"}, {"hand", "y", "cm"}};
    take->values.resize(frames, 2);
    std::uint64_t state = 12345;
    for (Eigen::Index k = 0; k < frames; ++k) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const double noise = double(state >> 40) / double(1ULL << 24) - 0.5;
        take->values(k, 0) = 10.0 * std::sin(1e-4 * double(k)) + noise;
        take->values(k, 1) = double(k % 977);
    }
    return take;
}

} // namespace

TEST_CASE("an envelope draws at most 4 points a pixel column and covers every frame's value", "[widgets][take_series][envelope]")
{
    const Eigen::Index frames = 432000;
    const auto take = longTake(frames, 120.0);
    const widgets::SeriesEnvelope envelope(take, 0);
    REQUIRE(envelope.frameCount() == frames);
    REQUIRE(envelope.range()->lower == take->values.col(0).minCoeff());
    REQUIRE(envelope.range()->upper == take->values.col(0).maxCoeff());

    const int columns = GENERATE(1, 37, 400, 1500);
    const double duration = take->duration();
    // The whole take, a 10 s window, 2 minutes, and a view wider than the take.
    const auto [lower, upper] = GENERATE_COPY(table<double, double>({{0.0, duration}, {1800.0, 1810.0}, {100.0, 220.0}, {-50.0, 2 * duration}}));
    CAPTURE(columns, lower, upper);
    const auto points = envelope.sample(lower, upper, columns);
    REQUIRE(!points.isEmpty());
    REQUIRE(points.size() <= 4 * columns + 6);
    for (int i = 1; i < points.size(); ++i) REQUIRE(points[i].key >= points[i - 1].key);
    // Every frame in view lies within the sampled extremes (min/max decimation loses no peak).
    const Eigen::Index bucket = widgets::SeriesEnvelope::bucketFrames((upper - lower) * 120.0, columns);
    const Eigen::Index first = std::clamp<Eigen::Index>(Eigen::Index(std::ceil(lower * 120.0)), 0, frames - 1);
    const Eigen::Index last = std::clamp<Eigen::Index>(Eigen::Index(std::floor(upper * 120.0)), 0, frames - 1);
    double viewLow = 1e300, viewHigh = -1e300;
    for (Eigen::Index f = first; f <= last; ++f) {
        viewLow = std::min(viewLow, take->values(f, 0));
        viewHigh = std::max(viewHigh, take->values(f, 0));
    }
    // Points are at most one bucket (or frame) outside the view on each side.
    const double margin = 1.5 * double(std::max<Eigen::Index>(bucket, 16)) / 120.0;
    double sampledLow = 1e300, sampledHigh = -1e300;
    for (const auto& point : points) {
        REQUIRE(point.key >= std::max(0.0, lower) - margin - 1.0 / 120.0);
        REQUIRE(point.key <= std::min(duration, upper) + margin + 1.0 / 120.0);
        sampledLow = std::min(sampledLow, point.value);
        sampledHigh = std::max(sampledHigh, point.value);
    }
    REQUIRE(sampledLow <= viewLow);
    REQUIRE(sampledHigh >= viewHigh);
}

TEST_CASE("an envelope's buckets hold the exact extremes of their frames", "[widgets][take_series][envelope]")
{
    const auto take = longTake(100003, 30.0); // not a multiple of any bucket
    const widgets::SeriesEnvelope envelope(take, 1);
    const int columns = GENERATE(10, 333, 1024, 5000);
    const double lower = 0.0, upper = take->duration();
    const Eigen::Index bucket = widgets::SeriesEnvelope::bucketFrames((upper - lower) * 30.0, columns);
    CAPTURE(columns, bucket);
    const auto points = envelope.sample(lower, upper, columns);
    if (bucket == 1) {
        REQUIRE(points.size() == take->frameCount());
        return;
    }
    const Eigen::Index buckets = (take->frameCount() + bucket - 1) / bucket;
    REQUIRE(points.size() == 2 * buckets);
    for (Eigen::Index b = 0; b < buckets; ++b) {
        const Eigen::Index start = b * bucket;
        const Eigen::Index count = std::min(bucket, take->frameCount() - start);
        const auto frames = take->values.col(1).segment(start, count);
        REQUIRE(points[int(2 * b)].value == frames.minCoeff());
        REQUIRE(points[int(2 * b + 1)].value == frames.maxCoeff());
        REQUIRE(points[int(2 * b)].key == Approx(0.5 * double(2 * start + count - 1) / 30.0));
    }
}

TEST_CASE("zoomed in to at most 2 frames a column an envelope gives the frames themselves", "[widgets][take_series][envelope]")
{
    const auto take = longTake(50000, 120.0);
    const widgets::SeriesEnvelope envelope(take, 0);
    // 10 s at 120 Hz across 1200 columns: 1 frame a column.
    const auto points = envelope.sample(100.0, 110.0, 1200);
    REQUIRE(widgets::SeriesEnvelope::bucketFrames(1200.0, 1200) == 1);
    REQUIRE(points.size() == 1200 + 1 + 2);
    for (const auto& point : points) {
        const auto frame = Eigen::Index(std::llround(point.key * 120.0));
        REQUIRE(point.key == double(frame) / 120.0);
        REQUIRE(point.value == take->values(frame, 0));
    }
    REQUIRE(points.front().key < 100.0);
    REQUIRE(points.back().key > 110.0);
    // No take, no channel: nothing to draw.
    REQUIRE(widgets::SeriesEnvelope(take, 5).sample(0.0, 10.0, 100).isEmpty());
    REQUIRE(widgets::SeriesEnvelope(nullptr, 0).sample(0.0, 10.0, 100).isEmpty());
    REQUIRE_FALSE(widgets::SeriesEnvelope(nullptr, 0).range().has_value());
}
