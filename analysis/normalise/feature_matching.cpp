#include "analysis/normalise/feature_matching.h"

#include "analysis/normalise/correspondence_path.h"
#include "analysis/normalise/distance_kernel.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace bunraku::analysis {

namespace {

constexpr Eigen::Index kTile = 64; // reference frames per tile (a multiple of 4)

Eigen::Index roundUp(Eigen::Index value, Eigen::Index step) { return (value + step - 1) / step * step; }

// Feature-major copy of frames first + from .. first + to - 1 (one tile's worth, so it stays in
// cache): out[f * stride + (i - first)] = features(clamp(i), f). Window indices beyond either
// end replicate the edge frame.
void featureMajor(const FeatureMatrix& features, Eigen::Index first, Eigen::Index from, Eigen::Index to,
                  Eigen::Index stride, double* out)
{
    const Eigen::Index count = features.cols();
    for (Eigen::Index i = from; i < to; ++i) {
        const double* row = features.data() + std::clamp<Eigen::Index>(first + i, 0, features.rows() - 1) * count;
        for (Eigen::Index f = 0; f < count; ++f) out[f * stride + i] = row[f];
    }
}

// out[j] = sum over the window's rows of ring[k][j].
void sumRows(const double* __restrict ring, Eigen::Index rows, Eigen::Index width, double* __restrict out)
{
    for (Eigen::Index j = 0; j < width; ++j) out[j] = ring[j];
    for (Eigen::Index k = 1; k < rows; ++k) {
        const double* __restrict row = ring + k * width;
        for (Eigen::Index j = 0; j < width; ++j) out[j] += row[j];
    }
}

void addRow(double* __restrict out, const double* __restrict row, Eigen::Index width)
{
    for (Eigen::Index j = 0; j < width; ++j) out[j] += row[j];
}

void subtractRow(double* __restrict out, const double* __restrict row, Eigen::Index width)
{
    for (Eigen::Index j = 0; j < width; ++j) out[j] -= row[j];
}

// Greedy and independent paths: band rows streamed one at a time, so greedy can skip the
// distances left of its previous choice (about half the band).
Result<MatchResult> matchStreamed(const FeatureMatrix& reference, const FeatureMatrix& sample, const FeatureMatchOptions& options,
                                  const RunControl& control)
{
    const Eigen::Index referenceFrames = reference.rows();
    const Eigen::Index sampleFrames = sample.rows();
    const int band = options.searchBand;
    const int tau = options.tau;
    const Eigen::Index width = 2 * band + 1;
    const Eigen::Index windowRows = 2 * tau + 1;
    const std::size_t features = std::size_t(reference.cols());

    // Ring of e(i, j) = |f_ref(i) - f_smp(i - T_cmp + j)|^2 rows for i = t - tau .. t + tau.
    // Window indices beyond the ends replicate the edge frame (clamped row indices).
    std::vector<double> ring(std::size_t(windowRows * width));
    std::vector<const double*> rows(static_cast<std::size_t>(width));
    const Eigen::VectorXd referenceNorms = reference.rowwise().squaredNorm();
    const Eigen::VectorXd sampleNorms = sample.rowwise().squaredNorm();
    // Row i's entries for sample frames below `firstSample` are left at 0: the greedy scan
    // never reads a window that needs them (see the loop below).
    auto fillRow = [&](Eigen::Index i, Eigen::Index firstSample) {
        const Eigen::Index r = std::clamp<Eigen::Index>(i, 0, referenceFrames - 1);
        const Eigen::Index slot = ((i % windowRows) + windowRows) % windowRows;
        double* out = ring.data() + slot * width;
        const Eigen::Index skip = std::clamp<Eigen::Index>(firstSample - (i - band), 0, width);
        std::fill(out, out + skip, 0.0);
        const double* a = reference.data() + r * reference.cols();
        if (i - band + skip >= 0 && i + band <= sampleFrames - 1) {
            detail::squaredDistancesContiguous(a, referenceNorms[r], sample.data() + (i - band + skip) * sample.cols(),
                                               sampleNorms.data() + (i - band + skip), std::size_t(width - skip), features,
                                               out + skip);
            return;
        }
        for (Eigen::Index j = skip; j < width; ++j) {
            const Eigen::Index s = std::clamp<Eigen::Index>(i - band + j, 0, sampleFrames - 1);
            rows[std::size_t(j)] = sample.data() + s * sample.cols();
        }
        detail::squaredDistances(a, rows.data() + skip, std::size_t(width - skip), features, out + skip);
    };

    PathBuilder builder(band, referenceFrames, sampleFrames, options.path);
    std::vector<double> cost(static_cast<std::size_t>(width));
    for (Eigen::Index i = -tau; i < tau; ++i) fillRow(i, std::numeric_limits<Eigen::Index>::min() / 2);
    const Eigen::Index progressEvery = std::max<Eigen::Index>(1, referenceFrames / 50);
    for (Eigen::Index t = 0; t < referenceFrames; ++t) {
        if (t % progressEvery == 0) {
            if (control.cancelled()) return makeError(ErrorCode::Cancelled, "matching cancelled");
            control.report(double(t) / double(referenceFrames));
        }
        // Greedy reads only sample frames >= its previous choice p, so the window of a cell it reads
        // needs row t + tau only from sample frame p - tau on (earlier rows were filled under
        // smaller or equal bounds). Other paths need every entry.
        const Eigen::Index firstSample = options.path == PathMethod::Greedy && t > 0
                                             ? builder.firstUsefulSample() - tau
                                             : std::numeric_limits<Eigen::Index>::min() / 2;
        // Slide the window: add the new row, drop the one leaving; an exact re-sum every 256
        // rows keeps rounding from accumulating.
        if (t % 256 == 0) {
            fillRow(t + tau, firstSample);
            sumRows(ring.data(), windowRows, width, cost.data());
        } else {
            const Eigen::Index leaving = (((t - tau - 1) % windowRows) + windowRows) % windowRows;
            subtractRow(cost.data(), ring.data() + leaving * width, width);
            fillRow(t + tau, firstSample);
            addRow(cost.data(), ring.data() + ((((t + tau) % windowRows) + windowRows) % windowRows) * width, width);
        }
        builder.addRow(cost.data());
    }
        MatchResult result;
        result.correspondence = builder.finish(&result.cost);
        result.smoothWarp = smoothWarp(result.correspondence);
        control.report(1.0);
        return result;
}

// Optimal path: every band cell is needed, so each per-frame distance is computed once on the
// band's diagonals, tile by tile.
Result<MatchResult> matchTiled(const FeatureMatrix& reference, const FeatureMatrix& sample, const FeatureMatchOptions& options,
                                  const RunControl& control)
{
    const Eigen::Index referenceFrames = reference.rows();
    const Eigen::Index sampleFrames = sample.rows();
    const int band = options.searchBand;
    // Per-frame squared distances e(i, o) = |f_ref(i) - f_smp(i + o)|^2 on the diagonals
    // o = -T_cmp..T_cmp (column j = o + T_cmp), computed once each, then window sums along each
    // diagonal: cost(t, o) = sum_{i = t - tau .. t + tau} e(i, o) (eq. 3.21). Window indices
    // beyond the ends replicate the edge frame: the feature-major copies below are padded with
    // the edge frames (clamped rows). Tiles of kTile reference frames keep the work in cache; each tile reuses
    // the previous tile's last 2 tau distances of every diagonal.
    const Eigen::Index tau = options.tau;
    const Eigen::Index halfBand = band;
    const Eigen::Index width = 2 * halfBand + 1;
    const auto block = Eigen::Index(detail::kDiagonalBlock);
    const Eigen::Index paddedWidth = roundUp(width, block);
    const Eigen::Index features = reference.cols();
    // Tile buffers: rows of distances for frames t0 - tau .. (position p <-> frame t0 - tau + p),
    // rows of window costs for t0 .. t0 + kTile - 1, and feature-major copies of the frames
    // they need (short strides keep them in cache).
    const Eigen::Index distanceRows = roundUp(kTile + 2 * tau, 4);
    const Eigen::Index referenceLength = distanceRows;
    const Eigen::Index sampleLength = distanceRows + paddedWidth + block;
    std::vector<double> a(std::size_t(referenceLength * features));
    std::vector<double> b(std::size_t(sampleLength * features));
    std::vector<double> distances(std::size_t(distanceRows * paddedWidth));
    std::vector<double> rows(std::size_t(kTile * paddedWidth));

    PathBuilder builder(band, referenceFrames, sampleFrames, options.path);
    const Eigen::Index progressEvery = std::max<Eigen::Index>(kTile, roundUp(referenceFrames / 50, kTile));
    for (Eigen::Index t0 = 0; t0 < referenceFrames; t0 += kTile) {
        if (t0 % progressEvery == 0) {
            if (control.cancelled()) return makeError(ErrorCode::Cancelled, "matching cancelled");
            control.report(double(t0) / double(referenceFrames));
        }
        const Eigen::Index count = std::min(kTile, referenceFrames - t0);
        // The first tile computes all count + 2 tau rows, later ones keep the previous (full)
        // tile's last 2 tau.
        const Eigen::Index kept = t0 == 0 ? 0 : 2 * tau;
        if (kept > 0) std::copy_n(distances.data() + kTile * paddedWidth, kept * paddedWidth, distances.data());
        const Eigen::Index fresh = roundUp(count + 2 * tau - kept, 4);
        // a holds frames t0 - tau .. (the first `kept` are not needed), b frames t0 - tau - T_cmp ..
        featureMajor(reference, t0 - tau, kept, kept + fresh, referenceLength, a.data());
        // The sample copy slides by kTile frames a tile: keep what overlaps, copy the rest.
        const Eigen::Index reused = t0 == 0 ? 0 : sampleLength - kTile;
        if (reused > 0)
            for (Eigen::Index f = 0; f < features; ++f)
                std::copy_n(b.data() + f * sampleLength + kTile, reused, b.data() + f * sampleLength);
        featureMajor(sample, t0 - tau - halfBand, reused, sampleLength, sampleLength, b.data());
        for (Eigen::Index o0 = 0; o0 < paddedWidth; o0 += block)
            detail::diagonalDistances(a.data() + kept, std::size_t(referenceLength), b.data() + kept + o0, std::size_t(sampleLength),
                                      std::size_t(features), std::size_t(fresh),
                                      distances.data() + kept * paddedWidth + o0, std::size_t(paddedWidth));
        detail::windowRows(distances.data(), std::size_t(count), std::size_t(2 * tau + 1), std::size_t(width),
                           std::size_t(paddedWidth), rows.data());
        for (Eigen::Index p = 0; p < count; ++p) builder.addRow(rows.data() + p * paddedWidth);
    }
    MatchResult result;
    result.correspondence = builder.finish(&result.cost);
    result.smoothWarp = smoothWarp(result.correspondence);
    control.report(1.0);
    return result;
}

} // namespace

Result<MatchResult> matchFeatures(const FeatureMatrix& reference, const FeatureMatrix& sample,
                                  const FeatureMatchOptions& options, const RunControl& control)
{
    if (options.tau < 0) return makeError(ErrorCode::InvalidArgument, "matching: tau must be >= 0, got " + std::to_string(options.tau));
    if (options.searchBand < 0 || options.searchBand > 16000)
        return makeError(ErrorCode::InvalidArgument,
                         "matching: the search band T_cmp must be in 0..16000 frames, got " + std::to_string(options.searchBand));
    if (reference.rows() == 0 || sample.rows() == 0) return makeError(ErrorCode::InvalidArgument, "matching: a take has no frames");
    if (reference.cols() == 0 || reference.cols() != sample.cols())
        return makeError(ErrorCode::InvalidArgument, "matching: reference and sample must have the same (non-zero) number of features, got "
                                                         + std::to_string(reference.cols()) + " and " + std::to_string(sample.cols()));
    const Eigen::Index referenceFrames = reference.rows();
    const Eigen::Index sampleFrames = sample.rows();
    const int band = options.searchBand;
    if (referenceFrames - 1 - band > sampleFrames - 1)
        return makeError(ErrorCode::InvalidArgument,
                         "matching: the reference (" + std::to_string(referenceFrames) + " frames) is longer than the sample ("
                             + std::to_string(sampleFrames) + " frames) plus the search band T_cmp = " + std::to_string(band)
                             + ": its last frames have no sample frame to match");

    if (options.path == PathMethod::Optimal) return matchTiled(reference, sample, options, control);
    return matchStreamed(reference, sample, options, control);
}

} // namespace bunraku::analysis
