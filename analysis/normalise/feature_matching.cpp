#include "analysis/normalise/feature_matching.h"

#include "analysis/normalise/correspondence_path.h"
#include "analysis/normalise/band_distances.h"
#include "analysis/normalise/distance_kernel.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace bunraku::analysis {

namespace {

// Window sums restart (an exact sum of their rows) every kRestart reference frames, so
// rounding accumulates over that many slides at most.
constexpr Eigen::Index kRestart = 96;
// Band distances are computed kBlock rows at a time (the distance kernel's register blocks),
// from feature-major copies of kTileRows rows' features (a multiple of kBlock).
constexpr Eigen::Index kBlock = 6;
constexpr Eigen::Index kTileRows = 480;

Eigen::Index roundUp(Eigen::Index value, Eigen::Index step) { return (value + step - 1) / step * step; }

// norms[i] = sum_k series[k * stride + i]^2 for from <= i < to, summed over k in order.
void squaredNorms(const double* series, Eigen::Index stride, Eigen::Index count, Eigen::Index from, Eigen::Index to, double* norms)
{
    std::fill(norms + from, norms + to, 0.0);
    for (Eigen::Index k = 0; k < count; ++k) {
        const double* values = series + k * stride;
        for (Eigen::Index i = from; i < to; ++i) norms[i] += values[i] * values[i];
    }
}

// Feature-major copy of the listed feature columns of frames first + from .. first + to - 1
// (one tile's worth, so it stays in cache): out[k * stride + (i - first)] = features(clamp(i),
// columns[k]), and norms[i - first] the squared norm of those values. Window indices beyond
// either end replicate the edge frame. Column-major features are copied a series at a time.
template <class Features>
void featureMajor(const Features& features, const std::vector<Eigen::Index>& columns, Eigen::Index first, Eigen::Index from,
                  Eigen::Index to, Eigen::Index stride, double* out, double* norms)
{
    const Eigen::Index last = features.rows() - 1;
    if constexpr (Features::IsRowMajor) {
        const Eigen::Index count = features.cols();
        for (Eigen::Index i = from; i < to; ++i) {
            const double* row = features.data() + std::clamp<Eigen::Index>(first + i, 0, last) * count;
            for (std::size_t k = 0; k < columns.size(); ++k) out[Eigen::Index(k) * stride + i] = row[columns[k]];
        }
    } else {
        // Frames inside the take are one contiguous run per feature; the edges replicate.
        const Eigen::Index inFrom = std::clamp<Eigen::Index>(-first, from, to);
        const Eigen::Index inTo = std::clamp<Eigen::Index>(last + 1 - first, inFrom, to);
        for (std::size_t k = 0; k < columns.size(); ++k) {
            const double* series = features.data() + columns[k] * features.rows();
            double* target = out + Eigen::Index(k) * stride;
            std::fill(target + from, target + inFrom, series[0]);
            std::copy_n(series + first + inFrom, inTo - inFrom, target + inFrom);
            std::fill(target + inTo, target + to, series[last]);
        }
    }
    squaredNorms(out, stride, Eigen::Index(columns.size()), from, to, norms);
}

// The columns listed are consecutive series of column-major features (a coupling set's own
// features): tiles away from the takes' ends are then read in place, not copied.
template <class Features>
bool consecutiveSeries(const std::vector<Eigen::Index>& columns)
{
    if constexpr (Features::IsRowMajor) return false;
    for (std::size_t k = 0; k < columns.size(); ++k)
        if (columns[k] != columns[0] + Eigen::Index(k)) return false;
    return true;
}

// The path once every row is in, its cost and its smooth (sub-frame) warp.
MatchResult finishedMatch(PathBuilder& builder, const RunControl& control)
{
    MatchResult result;
    result.correspondence = builder.finish(&result.cost);
    result.smoothWarp = smoothWarp(result.correspondence);
    control.report(1.0);
    return result;
}

// Every path: the per-frame squared distances e(i, o) = |f_ref(i) - f_smp(i - T_cmp + o)|^2 on
// the band's diagonals o = 0 .. 2 T_cmp, computed once each, kBlock reference frames at a time
// into a ring of rows; window sums along each diagonal, cost(t, o) = sum_{i = t - tau .. t + tau}
// e(i, o) (eq. 3.21), slid one row at a time; each row handed to the path as soon as its
// window is complete. The greedy scan reads only sample frames at or after its previous
// choice, so its distances left of that (less the window) are skipped.
template <class Features>
Result<MatchResult> matchBand(const Features& reference, const Features& sample, const std::vector<Eigen::Index>& columns,
                              const FeatureMatchOptions& options, const RunControl& control)
{
    const Eigen::Index referenceFrames = reference.rows();
    const Eigen::Index sampleFrames = sample.rows();
    // A band wider than the takes adds only frames outside them: every reference frame and
    // sample frame lie within max(N_ref, N_smp) - 1 of each other, so that band holds the same
    // candidates, window sums and path (T_cmp 16000 on 106-frame takes did 150 times the work).
    const Eigen::Index band = std::min<Eigen::Index>(options.searchBand, std::max(referenceFrames, sampleFrames) - 1);
    const Eigen::Index tau = options.tau;
    const Eigen::Index width = 2 * band + 1;
    // Rows of distances and window sums padded as the path's sliding rows need (0 and infinity).
    const Eigen::Index paddedWidth = std::max(roundUp(width, 4), PathBuilder::slidingRowLength(int(band)));
    const auto features = Eigen::Index(columns.size());
    const bool greedy = options.path == PathMethod::Greedy;
    // Tile copies, padded with the edge frames: position p of `a` is reference frame
    // tileStart + p, of `b` sample frame tileStart - T_cmp + p (or the same positions of the
    // features themselves, read in place).
    const Eigen::Index tileRows = std::min(kTileRows, roundUp(referenceFrames + 2 * tau, kBlock));
    const Eigen::Index referenceLength = tileRows;
    const Eigen::Index sampleLength = roundUp(tileRows + width + Eigen::Index(detail::kBandReadAhead), 4);
    // (Left uninitialised: every entry the kernels read is copied in first, and tiles read in
    // place never touch the copies.)
    const std::unique_ptr<double[]> a(new double[std::size_t(referenceLength * features)]);
    const std::unique_ptr<double[]> aNorms(new double[std::size_t(referenceLength)]);
    const std::unique_ptr<double[]> b(new double[std::size_t(sampleLength * features)]);
    const std::unique_ptr<double[]> bNorms(new double[std::size_t(sampleLength)]);
    // Distance rows -tau .. referenceFrames - 1 + tau; row i in slot (i + tau) mod ringRows. Row
    // t's window slides in row t + tau and out row t - tau - 1, while the block just computed
    // holds up to kBlock rows past t + tau.
    const Eigen::Index ringRows = roundUp(2 * tau + 1 + kBlock, kBlock);
    std::vector<double> ring(std::size_t(ringRows * paddedWidth));
    auto distanceRow = [&](Eigen::Index i) { return ring.data() + ((i + tau) % ringRows) * paddedWidth; };
    std::vector<const double*> window(static_cast<std::size_t>(2 * tau + 1));
    std::vector<double> running(static_cast<std::size_t>(paddedWidth), std::numeric_limits<double>::infinity());

    PathBuilder builder(int(band), referenceFrames, sampleFrames, options.path);
    const Eigen::Index lastRow = referenceFrames - 1 + tau;
    const Eigen::Index progressEvery = std::max<Eigen::Index>(kRestart, roundUp(referenceFrames / 50, kBlock));
    Eigen::Index tileStart = 0;
    Eigen::Index tileEnd = -tau; // rows tileStart .. tileEnd - 1 are in the copies
    const bool inPlace = consecutiveSeries<Features>(columns);
    const double* aBase = a.get();
    const double* bBase = b.get();
    Eigen::Index aStride = referenceLength;
    Eigen::Index bStride = sampleLength;
    Eigen::Index t = 0;          // the next reference frame to add to the path
    for (Eigen::Index i0 = -tau; t < referenceFrames; i0 += kBlock) {
        const Eigen::Index count = std::min(kBlock, lastRow + 1 - i0);
        if (i0 + count > tileEnd) {
            if (control.cancelled()) return makeError(ErrorCode::Cancelled, "matching cancelled");
            tileStart = i0;
            tileEnd = std::min(i0 + tileRows, lastRow + 1);
            const Eigen::Index sampleFrom = tileStart - band;
            const Eigen::Index sampleCount = tileEnd - tileStart + width + Eigen::Index(detail::kBandReadAhead);
            if (inPlace && tileStart >= 0 && tileEnd <= referenceFrames && sampleFrom >= 0 && sampleFrom + sampleCount <= sampleFrames) {
                // The norms pass also brings the tile's features into cache for the kernel.
                aBase = reference.data() + columns[0] * referenceFrames + tileStart;
                aStride = referenceFrames;
                bBase = sample.data() + columns[0] * sampleFrames + sampleFrom;
                bStride = sampleFrames;
                squaredNorms(aBase, aStride, features, 0, tileEnd - tileStart, aNorms.get());
                squaredNorms(bBase, bStride, features, 0, sampleCount, bNorms.get());
            } else {
                featureMajor(reference, columns, tileStart, 0, tileEnd - tileStart, referenceLength, a.get(), aNorms.get());
                featureMajor(sample, columns, sampleFrom, 0, sampleCount, sampleLength, b.get(), bNorms.get());
                aBase = a.get();
                aStride = referenceLength;
                bBase = b.get();
                bStride = sampleLength;
            }
        }
        const Eigen::Index offset = i0 - tileStart;
        detail::BandTile tile;
        tile.a = aBase + offset;
        tile.aStride = std::size_t(aStride);
        tile.aNorms = aNorms.get() + offset;
        tile.b = bBase + offset;
        tile.bStride = std::size_t(bStride);
        tile.bNorms = bNorms.get() + offset;
        tile.features = std::size_t(features);
        tile.count = std::size_t(count);
        tile.width = std::size_t(width);
        tile.e = distanceRow(i0);
        tile.eStride = std::size_t(paddedWidth);
        // Greedy reads only sample frames >= its previous choice p in rows t.., so the windows
        // it reads need these rows only from sample frame p - tau on (later choices only grow).
        if (greedy && t > 0) tile.from = std::size_t(std::max<Eigen::Index>(0, builder.firstUsefulSample() - tau - (i0 - band)));
        detail::bandDistances(tile);
        for (; t < referenceFrames && t + tau < i0 + count; ++t) {
            if (t % progressEvery == 0) {
                if (control.cancelled()) return makeError(ErrorCode::Cancelled, "matching cancelled");
                control.report(double(t) / double(referenceFrames));
            }
            if (t % kRestart == 0) {
                for (Eigen::Index s = 0; s <= 2 * tau; ++s) window[std::size_t(s)] = distanceRow(t - tau + s);
                detail::windowStart(window.data(), window.size(), std::size_t(width), running.data());
                builder.addRow(running.data());
            } else {
                builder.addRow(running.data(), distanceRow(t + tau), distanceRow(t - tau - 1));
            }
        }
    }
    return finishedMatch(builder, control);
}

template <class Features>
Result<MatchResult> matchSelected(const Features& reference, const Features& sample, const std::vector<Eigen::Index>& columns,
                                  const FeatureMatchOptions& options, const RunControl& control)
{
    if (options.tau < 0) return makeError(ErrorCode::InvalidArgument, "matching: tau must be >= 0, got " + std::to_string(options.tau));
    if (options.searchBand < 0 || options.searchBand > kMaxSearchBand)
        return makeError(ErrorCode::InvalidArgument, "matching: the search band T_cmp must be in 0.." + std::to_string(kMaxSearchBand)
                                                         + " frames, got " + std::to_string(options.searchBand));
    if (reference.rows() == 0 || sample.rows() == 0) return makeError(ErrorCode::InvalidArgument, "matching: a take has no frames");
    if (reference.cols() == 0 || reference.cols() != sample.cols())
        return makeError(ErrorCode::InvalidArgument, "matching: reference and sample must have the same (non-zero) number of features, got "
                                                         + std::to_string(reference.cols()) + " and " + std::to_string(sample.cols()));
    if (columns.empty()) return makeError(ErrorCode::InvalidArgument, "matching: no feature columns selected");
    for (Eigen::Index column : columns)
        if (column < 0 || column >= reference.cols())
            return makeError(ErrorCode::InvalidArgument, "matching: feature column " + std::to_string(column) + " is not in 0.."
                                                             + std::to_string(reference.cols() - 1));
    const Eigen::Index referenceFrames = reference.rows();
    const Eigen::Index sampleFrames = sample.rows();
    const int band = options.searchBand;
    if (referenceFrames - 1 - band > sampleFrames - 1)
        return makeError(ErrorCode::InvalidArgument,
                         "matching: the reference (" + std::to_string(referenceFrames) + " frames) is longer than the sample ("
                             + std::to_string(sampleFrames) + " frames) plus the search band T_cmp = " + std::to_string(band)
                             + ": its last frames have no sample frame to match");

    return matchBand(reference, sample, columns, options, control);
}

} // namespace

Result<MatchResult> matchFeatures(const FeatureMatrix& reference, const FeatureMatrix& sample,
                                  const std::vector<Eigen::Index>& columns, const FeatureMatchOptions& options,
                                  const RunControl& control)
{
    return matchSelected(reference, sample, columns, options, control);
}

Result<MatchResult> matchFeatures(const FeatureSeries& reference, const FeatureSeries& sample,
                                  const std::vector<Eigen::Index>& columns, const FeatureMatchOptions& options,
                                  const RunControl& control)
{
    return matchSelected(reference, sample, columns, options, control);
}

std::vector<Eigen::Index> allColumns(Eigen::Index count)
{
    std::vector<Eigen::Index> columns(std::size_t(std::max<Eigen::Index>(count, 0)));
    std::iota(columns.begin(), columns.end(), Eigen::Index(0));
    return columns;
}

Result<MatchResult> matchFeatures(const FeatureMatrix& reference, const FeatureMatrix& sample,
                                  const FeatureMatchOptions& options, const RunControl& control)
{
    return matchFeatures(reference, sample, allColumns(reference.cols()), options, control);
}

Result<MatchResult> matchFeatures(const FeatureSeries& reference, const FeatureSeries& sample,
                                  const FeatureMatchOptions& options, const RunControl& control)
{
    return matchFeatures(reference, sample, allColumns(reference.cols()), options, control);
}

} // namespace bunraku::analysis
