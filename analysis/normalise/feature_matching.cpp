#include "analysis/normalise/feature_matching.h"

#include "analysis/normalise/correspondence_path.h"
#include "analysis/normalise/distance_kernel.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace bunraku::analysis {

namespace {

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

} // namespace bunraku::analysis
