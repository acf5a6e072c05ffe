#include "analysis/design/phrase_gains.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <utility>
#include <sstream>

namespace bunraku::analysis {

namespace {

double smoothstep(double u)
{
    u = std::clamp(u, 0.0, 1.0);
    return u * u * (3.0 - 2.0 * u);
}

std::string formatNumber(double value)
{
    std::ostringstream text;
    text.precision(3);
    text << value;
    return text.str();
}

/// The frames [first, last] of rows begin..end of `emotional` over which it is held at one row
/// (identical rows: the phase adjustment resamples the emotional take's first or last frame
/// where the warp does not reach), the longer of the run at the start and at the end; nullopt
/// when neither run is longer than one frame.
std::optional<std::pair<Eigen::Index, Eigen::Index>> heldFrames(const Eigen::MatrixXd& emotional, Eigen::Index begin, Eigen::Index end)
{
    Eigen::Index tail = end;
    while (tail > begin && emotional.row(tail - 1) == emotional.row(end)) --tail;
    Eigen::Index head = begin;
    while (head < end && emotional.row(head + 1) == emotional.row(begin)) ++head;
    if (end - tail >= head - begin && end - tail >= 1) return std::pair{tail, end};
    if (head - begin >= 1) return std::pair{begin, head};
    return std::nullopt;
}

} // namespace

FourierLow lowFourier(const Eigen::Ref<const Eigen::VectorXd>& samples)
{
    FourierLow low;
    const Eigen::Index n = samples.size();
    if (n == 0) return low;
    std::complex<double> first = 0.0;
    for (Eigen::Index k = 0; k < n; ++k)
        first += samples[k] * std::polar(1.0, -2.0 * std::numbers::pi * double(k) / double(n));
    low.a0 = 2.0 * samples.mean();
    low.a1 = 2.0 * std::abs(first) / double(n);
    low.cosine = 2.0 * first.real() / double(n);
    low.sine = -2.0 * first.imag() / double(n);
    return low;
}

Result<GainSet> extractGains(const Eigen::MatrixXd& functional, const Eigen::MatrixXd& emotional,
                             const std::vector<Eigen::Index>& boundaries, const std::vector<std::string>& dofNames,
                             const GainOptions& options)
{
    if (functional.rows() != emotional.rows() || functional.cols() != emotional.cols())
        return makeError(ErrorCode::InvalidArgument, "functional and emotional axes differ in shape (phase-adjust first)");
    if (Eigen::Index(dofNames.size()) != functional.cols())
        return makeError(ErrorCode::InvalidArgument, "one DOF name per column expected");
    const Eigen::Index frames = functional.rows();
    if (boundaries.size() < 2 || boundaries.front() != 0 || boundaries.back() != frames - 1)
        return makeError(ErrorCode::InvalidArgument,
                         "phrase boundaries must start at 0 and end at the last frame " + std::to_string(frames - 1));
    for (std::size_t i = 1; i < boundaries.size(); ++i)
        if (boundaries[i] - boundaries[i - 1] < 2)
            return makeError(ErrorCode::InvalidArgument, "phrase " + std::to_string(i) + " is shorter than 2 frames");
    if (!functional.allFinite() || !emotional.allFinite()) return makeError(ErrorCode::Numerical, "axis values are not finite");

    GainSet set;
    set.dofNames = dofNames;
    set.blendFrames = options.blendFrames;
    const Eigen::RowVectorXd range = functional.colwise().maxCoeff() - functional.colwise().minCoeff();
    for (std::size_t p = 0; p + 1 < boundaries.size(); ++p) {
        PhraseGains phrase;
        phrase.begin = boundaries[p];
        phrase.end = boundaries[p + 1];
        const Eigen::Index length = phrase.end - phrase.begin + 1;
        for (Eigen::Index d = 0; d < functional.cols(); ++d) {
            const FourierLow no = lowFourier(functional.col(d).segment(phrase.begin, length));
            const FourierLow em = lowFourier(emotional.col(d).segment(phrase.begin, length));
            const double scale = std::max(range[d], 1e-9);
            DofGain gain;
            gain.a0Functional = no.a0;
            gain.a0Emotional = em.a0;
            gain.a1Functional = no.a1;
            gain.a1Emotional = em.a1;
            const std::string where = dofNames[std::size_t(d)] + " in phrase " + std::to_string(p + 1);
            const double nearZero = options.nearZeroDcFraction * scale;
            if (std::abs(no.a0 / 2) < nearZero || std::abs(em.a0 / 2) < nearZero) {
                gain.dcMode = DcMode::Offset;
                gain.offset = (em.a0 - no.a0) / 2.0;
                gain.g0 = 1.0;
                gain.reason = "DC term of " + where + " is near zero (|a0/2| = " +
                              formatNumber(std::min(std::abs(no.a0), std::abs(em.a0)) / 2) + " < motion range " +
                              formatNumber(nearZero) + "): additive offset instead of g0";
            } else if (no.a0 * em.a0 < 0.0) {
                // means on opposite sides of 0: a negative g0 would mirror the phrase's mean
                gain.dcMode = DcMode::Offset;
                gain.offset = (em.a0 - no.a0) / 2.0;
                gain.g0 = 1.0;
                gain.reason = "DC terms of " + where + " have opposite signs: additive offset instead of g0";
            } else {
                gain.g0 = no.a0 / em.a0;
            }
            // thesis eq. 5.23: g1 = A1_no / A1_em, A1 = |2/N sum x e^{-2 pi i n / N}| (eq. 5.19): a
            // ratio of magnitudes, never negative. The phase difference of the harmonics belongs to
            // the phase component (5.3), which the thesis assumes has made them equal (eq. 5.24).
            const double flat = options.flatFraction * scale;
            auto note = [&gain](const std::string& text) { gain.reason += (gain.reason.empty() ? "" : "; ") + text; };
            if (no.a1 < flat) {
                gain.g1 = 1.0;
                note("first harmonic of " + where + " is flat in the functional motion: g1 = 1");
            } else if (em.a1 < options.illConditionedFraction * no.a1) {
                // Dividing by a harmonic the emotional phrase hardly has: the ratio is set by noise
                // and by where the phase adjustment cut the phrase. Regularised: A1_em is floored at
                // the fraction of A1_no, so g1 = 1 / fraction, the largest well-conditioned gain -
                // the emotion does still this phrase's swing, by an amount the data cannot tell.
                gain.g1 = std::min(1.0 / options.illConditionedFraction, options.gainLimit);
                gain.illConditioned = true;
                gain.illConditionedReason = "A1_em = " + formatNumber(em.a1) + " is below " +
                                            formatNumber(options.illConditionedFraction) + " x A1_no = " +
                                            formatNumber(no.a1) + " (g1 = A1_no/A1_em would be " +
                                            (em.a1 > 0.0 ? formatNumber(no.a1 / em.a1) : std::string("infinite")) +
                                            "): g1 regularised to " + formatNumber(gain.g1);
                if (const auto held = heldFrames(emotional, phrase.begin, phrase.end); held && 2 * (held->second - held->first + 1) >= length)
                    gain.illConditionedReason += "; the phase-adjusted emotional axis is held still over frames " +
                                                 std::to_string(held->first) + "-" + std::to_string(held->second) +
                                                 " (the emotional take stands still there, or the warp does not reach them)";
                note("g1 of " + where + " is ill-conditioned: " + gain.illConditionedReason);
            } else if (const double agreement = (no.cosine * em.cosine + no.sine * em.sine) / (no.a1 * em.a1);
                       em.a1 > options.additiveRatio * no.a1 || agreement < options.minimumPhaseAgreement) {
                gain.acMode = AcMode::Additive;
                gain.g1 = 1.0;
                gain.harmonicCos = em.cosine - no.cosine;
                gain.harmonicSin = em.sine - no.sine;
                note("first harmonic of " + where +
                     (em.a1 > options.additiveRatio * no.a1
                          ? " is " + formatNumber(em.a1 / no.a1) + " times the functional one"
                          : " is out of phase with the functional one (cos = " + formatNumber(agreement) + ")") +
                     ": added instead of scaled");
            } else {
                gain.g1 = std::clamp(no.a1 / em.a1, 1.0 / options.gainLimit, options.gainLimit);
                if (gain.g1 != no.a1 / em.a1) note("g1 of " + where + " clamped");
            }
            phrase.dofs.push_back(gain);
        }
        set.phrases.push_back(std::move(phrase));
    }
    return set;
}

std::vector<IllConditionedGain> illConditionedGains(const GainSet& gains)
{
    std::vector<IllConditionedGain> found;
    for (std::size_t p = 0; p < gains.phrases.size(); ++p)
        for (std::size_t d = 0; d < gains.phrases[p].dofs.size(); ++d) {
            const DofGain& gain = gains.phrases[p].dofs[d];
            if (!gain.illConditioned) continue;
            found.push_back({p, d, gains.phrases[p].begin, gains.phrases[p].end,
                             d < gains.dofNames.size() ? gains.dofNames[d] : std::to_string(d), gain.a1Functional,
                             gain.a1Emotional, gain.g1, gain.illConditionedReason});
        }
    return found;
}

GainSet unitGains(const std::vector<Eigen::Index>& boundaries, const std::vector<std::string>& dofNames)
{
    GainSet set;
    set.dofNames = dofNames;
    for (std::size_t p = 0; p + 1 < boundaries.size(); ++p)
        set.phrases.push_back({boundaries[p], boundaries[p + 1], std::vector<DofGain>(dofNames.size())});
    return set;
}

Eigen::MatrixXd applyGains(const Eigen::MatrixXd& functional, const GainSet& gains)
{
    if (gains.phrases.empty()) return functional;
    const Eigen::Index frames = functional.rows();
    Eigen::MatrixXd result = Eigen::MatrixXd::Zero(frames, functional.cols());
    const double half = std::max(0, gains.blendFrames);
    for (std::size_t p = 0; p < gains.phrases.size(); ++p) {
        const PhraseGains& phrase = gains.phrases[p];
        const Eigen::Index begin = std::clamp<Eigen::Index>(phrase.begin, 0, frames - 1);
        const Eigen::Index end = std::clamp<Eigen::Index>(phrase.end, begin, frames - 1);
        // partition of unity: ramps up across the phrase's start, down across its end
        auto ramp = [&](double boundary, double t) {
            return half > 0 ? smoothstep((t - (boundary - half)) / (2.0 * half)) : (t >= boundary ? 1.0 : 0.0);
        };
        const bool first = p == 0, last = p + 1 == gains.phrases.size();
        Eigen::RowVectorXd means = functional.middleRows(begin, end - begin + 1).colwise().mean();
        for (Eigen::Index t = 0; t < frames; ++t) {
            const double up = first ? 1.0 : ramp(double(begin), double(t));
            const double down = last ? 0.0 : ramp(double(end), double(t));
            const double weight = up - down;
            if (weight <= 0.0) continue;
            for (Eigen::Index d = 0; d < functional.cols() && std::size_t(d) < phrase.dofs.size(); ++d) {
                const DofGain& g = phrase.dofs[std::size_t(d)];
                const double meanNo = means[d];
                const double meanEm = g.dcMode == DcMode::Offset ? meanNo + g.offset : meanNo / (g.g0 != 0.0 ? g.g0 : 1.0);
                const double g1 = g.g1 != 0.0 ? g.g1 : 1.0;
                double value = meanEm + (functional(t, d) - meanNo) / g1;
                if (g.acMode == AcMode::Additive) {
                    const double angle = 2.0 * std::numbers::pi * double(t - begin) / double(end - begin + 1);
                    value += g.harmonicCos * std::cos(angle) + g.harmonicSin * std::sin(angle);
                }
                result(t, d) += weight * value;
            }
        }
    }
    return result;
}

std::vector<Eigen::Index> suggestPhraseBoundaries(const Eigen::MatrixXd& axis, const PhraseOptions& options)
{
    const Eigen::Index frames = axis.rows();
    std::vector<Eigen::Index> boundaries{0};
    if (frames < 3) {
        if (frames > 1) boundaries.push_back(frames - 1);
        return boundaries;
    }
    Eigen::VectorXd speed = Eigen::VectorXd::Zero(frames);
    const double radius = options.rotationRadiusCm * std::numbers::pi / 180.0;
    for (Eigen::Index t = 1; t + 1 < frames; ++t) {
        const Eigen::RowVectorXd delta = 0.5 * (axis.row(t + 1) - axis.row(t - 1));
        speed[t] = delta.head(3).norm() + (axis.cols() >= 6 ? radius * delta.segment(3, 3).norm() : 0.0);
    }
    speed[0] = speed[1];
    speed[frames - 1] = speed[frames - 2];
    const int half = std::max(0, options.smoothingFrames / 2);
    Eigen::VectorXd smooth(frames);
    for (Eigen::Index t = 0; t < frames; ++t) {
        const Eigen::Index a = std::max<Eigen::Index>(0, t - half), b = std::min<Eigen::Index>(frames - 1, t + half);
        smooth[t] = speed.segment(a, b - a + 1).mean();
    }
    std::vector<double> sorted(smooth.data(), smooth.data() + frames);
    std::nth_element(sorted.begin(), sorted.begin() + frames / 2, sorted.end());
    const double median = sorted[std::size_t(frames / 2)];
    std::vector<Eigen::Index> minima;
    for (Eigen::Index t = 1; t + 1 < frames; ++t)
        if (smooth[t] <= smooth[t - 1] && smooth[t] < smooth[t + 1] && smooth[t] < median) minima.push_back(t);
    std::sort(minima.begin(), minima.end(), [&](Eigen::Index a, Eigen::Index b) { return smooth[a] < smooth[b]; });
    std::vector<Eigen::Index> chosen;
    const Eigen::Index gap = std::max(2, options.minimumPhraseFrames);
    for (Eigen::Index t : minima) {
        if (int(chosen.size()) + 1 >= options.maximumPhrases) break;
        if (t < gap || frames - 1 - t < gap) continue;
        if (std::any_of(chosen.begin(), chosen.end(), [&](Eigen::Index c) { return std::abs(c - t) < gap; })) continue;
        chosen.push_back(t);
    }
    std::sort(chosen.begin(), chosen.end());
    boundaries.insert(boundaries.end(), chosen.begin(), chosen.end());
    boundaries.push_back(frames - 1);
    return boundaries;
}

Result<std::vector<Eigen::Index>> parsePhraseBoundaries(const std::string& text, Eigen::Index frames)
{
    std::vector<Eigen::Index> boundaries;
    std::istringstream stream(text);
    std::string field;
    while (std::getline(stream, field, ',')) {
        std::size_t used = 0;
        long value = 0;
        try {
            value = std::stol(field, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != field.size())
            return makeError(ErrorCode::Parse, "phrase boundaries \"" + text + "\": expected frames like 0,40,105");
        boundaries.push_back(value);
    }
    if (boundaries.size() < 2 || boundaries.front() != 0 || boundaries.back() != frames - 1 ||
        !std::is_sorted(boundaries.begin(), boundaries.end()) ||
        std::adjacent_find(boundaries.begin(), boundaries.end()) != boundaries.end())
        return makeError(ErrorCode::InvalidArgument, "phrase boundaries \"" + text + "\": expected increasing frames from 0 to " +
                                                         std::to_string(frames - 1));
    return boundaries;
}

} // namespace bunraku::analysis
