#include "analysis/normalise/feature_matching.h"

#include "analysis/normalise/correspondence_path.h"
#include "analysis/normalise/band_distances.h"
#include "analysis/normalise/distance_kernel.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace bunraku::analysis {

namespace {

constexpr Eigen::Index kTile = 96; // reference frames per tile (a multiple of the distance kernel's 6-frame blocks)

Eigen::Index roundUp(Eigen::Index value, Eigen::Index step) { return (value + step - 1) / step * step; }

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
    std::fill(norms + from, norms + to, 0.0);
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const double* values = out + Eigen::Index(k) * stride;
        for (Eigen::Index i = from; i < to; ++i) norms[i] += values[i] * values[i];
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

// The path once every row is in, its cost and its smooth (sub-frame) warp.
MatchResult finishedMatch(PathBuilder& builder, const RunControl& control)
{
    MatchResult result;
    result.correspondence = builder.finish(&result.cost);
    result.smoothWarp = smoothWarp(result.correspondence);
    control.report(1.0);
    return result;
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
    return finishedMatch(builder, control);
}

// Optimal path: every band cell is needed, so each per-frame distance is computed once on the
// band's diagonals, tile by tile.
template <class Features>
Result<MatchResult> matchTiled(const Features& reference, const Features& sample, const std::vector<Eigen::Index>& columns,
                               const FeatureMatchOptions& options, const RunControl& control)
{
    const Eigen::Index referenceFrames = reference.rows();
    const Eigen::Index sampleFrames = sample.rows();
    const int band = options.searchBand;
    // Per-frame squared distances e(i, o) = |f_ref(i) - f_smp(i + o)|^2 on the diagonals
    // o = -T_cmp..T_cmp (column j = o + T_cmp), computed once each, then window sums along each
    // diagonal: cost(t, o) = sum_{i = t - tau .. t + tau} e(i, o) (eq. 3.21). Tiles of kTile
    // reference frames keep the work in cache; each tile reuses the previous tile's last
    // 2 tau distances of every diagonal.
    const Eigen::Index tau = options.tau;
    const Eigen::Index width = 2 * Eigen::Index(band) + 1;
    const Eigen::Index paddedWidth = roundUp(width, 4);
    const auto features = Eigen::Index(columns.size());
    const auto readAhead = Eigen::Index(detail::kBandReadAhead);
    // Tile buffers: rows of distances for frames t0 - tau .. (position p <-> frame t0 - tau + p),
    // the window costs of the current row, and feature-major copies of the frames
    // they need, padded with the edge frames (window indices beyond the ends replicate the edge
    // frame); short strides keep them in cache.
    const Eigen::Index distanceRows = roundUp(kTile + 2 * tau, 4);
    const Eigen::Index referenceLength = distanceRows;
    const Eigen::Index sampleLength = distanceRows + width + readAhead;
    std::vector<double> a(std::size_t(referenceLength * features));
    std::vector<double> aNorms(static_cast<std::size_t>(referenceLength));
    std::vector<double> b(std::size_t(sampleLength * features));
    std::vector<double> bNorms(static_cast<std::size_t>(sampleLength));
    std::vector<const double*> aSeries(static_cast<std::size_t>(features));
    std::vector<const double*> bSeries(static_cast<std::size_t>(features));
    std::vector<double> distances(std::size_t(distanceRows * paddedWidth));
    std::vector<double> running(static_cast<std::size_t>(paddedWidth));

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
        const Eigen::Index fresh = count + 2 * tau - kept;
        // Position p of a is reference frame t0 - tau + p; of b, sample frame t0 - tau - T_cmp + p.
        featureMajor(reference, columns, t0 - tau, kept, kept + fresh, referenceLength, a.data(), aNorms.data());
        // The sample copy slides by kTile frames a tile: keep what overlaps, copy the rest.
        const Eigen::Index reused = t0 == 0 ? 0 : sampleLength - kTile;
        if (reused > 0) {
            for (Eigen::Index f = 0; f < features; ++f)
                std::copy_n(b.data() + f * sampleLength + kTile, reused, b.data() + f * sampleLength);
            std::copy_n(bNorms.data() + kTile, reused, bNorms.data());
        }
        featureMajor(sample, columns, t0 - tau - band, reused, sampleLength, sampleLength, b.data(), bNorms.data());
        detail::BandTile tile;
        for (Eigen::Index k = 0; k < features; ++k) {
            aSeries[std::size_t(k)] = a.data() + k * referenceLength + kept;
            bSeries[std::size_t(k)] = b.data() + k * sampleLength + kept;
        }
        tile.a = aSeries.data();
        tile.aNorms = aNorms.data() + kept;
        tile.bNorms = bNorms.data() + kept;
        tile.b = bSeries.data();
        tile.features = std::size_t(features);
        tile.count = std::size_t(fresh);
        tile.width = std::size_t(width);
        tile.e = distances.data() + kept * paddedWidth;
        tile.eStride = std::size_t(paddedWidth);
        detail::bandDistances(tile);
        // Each tile starts its window sums afresh (rounding accumulates over kTile rows at most).
        detail::windowStart(distances.data(), std::size_t(2 * tau + 1), std::size_t(width), std::size_t(paddedWidth),
                            running.data());
        builder.addRow(running.data());
        for (Eigen::Index p = 1; p < count; ++p) {
            detail::windowSlide(running.data(), distances.data() + (p + 2 * tau) * paddedWidth,
                                distances.data() + (p - 1) * paddedWidth, std::size_t(width));
            builder.addRow(running.data());
        }
    }
    return finishedMatch(builder, control);
}

template <class Features>
FeatureMatrix selectedColumns(const Features& features, const std::vector<Eigen::Index>& columns)
{
    FeatureMatrix out(features.rows(), Eigen::Index(columns.size()));
    for (std::size_t k = 0; k < columns.size(); ++k) out.col(Eigen::Index(k)) = features.col(columns[k]);
    return out;
}

template <class Features>
Result<MatchResult> matchSelected(const Features& reference, const Features& sample, const std::vector<Eigen::Index>& columns,
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

    if (options.path == PathMethod::Optimal) return matchTiled(reference, sample, columns, options, control);
    // The streamed paths read whole rows: copy the selected columns when they are not all of them.
    if constexpr (Features::IsRowMajor) {
        const bool all = Eigen::Index(columns.size()) == reference.cols() && std::is_sorted(columns.begin(), columns.end())
                         && std::adjacent_find(columns.begin(), columns.end()) == columns.end();
        if (all) return matchStreamed(reference, sample, options, control);
    }
    return matchStreamed(selectedColumns(reference, columns), selectedColumns(sample, columns), options, control);
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
