#include "analysis/design/phrase_gains.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>
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
            } else {
                gain.g0 = no.a0 / em.a0;
            }
            const double flat = options.flatFraction * scale;
            if (no.a1 < flat) {
                gain.g1 = 1.0;
                gain.reason += std::string(gain.reason.empty() ? "" : "; ") + "first harmonic of " + where +
                               " is flat in the functional motion: g1 = 1";
            } else if (const double agreement = (no.cosine * em.cosine + no.sine * em.sine) / (no.a1 * std::max(em.a1, 1e-300));
                       em.a1 > options.additiveRatio * no.a1 || std::abs(agreement) < options.minimumPhaseAgreement) {
                gain.acMode = AcMode::Additive;
                gain.g1 = 1.0;
                gain.harmonicCos = em.cosine - no.cosine;
                gain.harmonicSin = em.sine - no.sine;
                gain.reason += std::string(gain.reason.empty() ? "" : "; ") + "first harmonic of " + where +
                               (em.a1 > options.additiveRatio * no.a1
                                    ? " is " + formatNumber(em.a1 / no.a1) + " times the functional one"
                                    : " is out of phase with the functional one (cos = " + formatNumber(agreement) + ")") +
                               ": added instead of scaled";
            } else if (agreement < 0.0 && em.a1 >= no.a1 / options.gainLimit) {
                gain.g1 = -std::clamp(no.a1 / em.a1, 1.0 / options.gainLimit, options.gainLimit);
                gain.reason += std::string(gain.reason.empty() ? "" : "; ") + "first harmonic of " + where +
                               " is opposite to the functional one: g1 negative";
            } else if (em.a1 < no.a1 / options.gainLimit) {
                gain.g1 = options.gainLimit;
                gain.reason += std::string(gain.reason.empty() ? "" : "; ") + "first harmonic of " + where +
                               " vanishes in the emotional motion: g1 clamped to " + formatNumber(options.gainLimit);
            } else {
                gain.g1 = std::clamp(no.a1 / em.a1, 1.0 / options.gainLimit, options.gainLimit);
                if (gain.g1 != no.a1 / em.a1)
                    gain.reason += std::string(gain.reason.empty() ? "" : "; ") + "g1 of " + where + " clamped";
            }
            phrase.dofs.push_back(gain);
        }
        set.phrases.push_back(std::move(phrase));
    }
    return set;
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

Status writeGainsJson(const GainSet& gains, const std::filesystem::path& file)
{
    nlohmann::json document;
    document["dofs"] = gains.dofNames;
    document["blend_frames"] = gains.blendFrames;
    document["convention"] = "thesis eqs. 5.22/5.23: g0 = a0_no/a0_em, g1 = A1_no/A1_em; design: mean_no/g0 (or mean_no + offset) + (x_no - mean_no)/g1";
    nlohmann::json phrases = nlohmann::json::array();
    for (const PhraseGains& phrase : gains.phrases) {
        nlohmann::json entries = nlohmann::json::array();
        for (std::size_t d = 0; d < phrase.dofs.size(); ++d) {
            const DofGain& g = phrase.dofs[d];
            entries.push_back({{"dof", d < gains.dofNames.size() ? gains.dofNames[d] : std::to_string(d)},
                               {"g0", g.g0},
                               {"g1", g.g1},
                               {"mode", g.dcMode == DcMode::Offset ? "offset" : "scale"},
                               {"offset", g.offset},
                               {"ac_mode", g.acMode == AcMode::Additive ? "additive" : "scale"},
                               {"harmonic_cos", g.harmonicCos},
                               {"harmonic_sin", g.harmonicSin},
                               {"reason", g.reason},
                               {"a0_functional", g.a0Functional},
                               {"a0_emotional", g.a0Emotional},
                               {"A1_functional", g.a1Functional},
                               {"A1_emotional", g.a1Emotional}});
        }
        phrases.push_back({{"begin", phrase.begin}, {"end", phrase.end}, {"gains", entries}});
    }
    document["phrases"] = phrases;
    std::ofstream stream(file);
    if (!stream) return makeError(ErrorCode::Io, file.string() + ": cannot write the gains");
    stream << document.dump(2) << '\n';
    stream.flush();
    if (!stream) return makeError(ErrorCode::Io, file.string() + ": writing the gains failed");
    return okStatus();
}

Result<GainSet> readGainsJson(const std::filesystem::path& file)
{
    std::ifstream stream(file);
    if (!stream) return makeError(ErrorCode::Io, file.string() + ": cannot open the gains");
    const std::string source = file.string();
    try {
        const nlohmann::json document = nlohmann::json::parse(stream);
        GainSet gains;
        gains.dofNames = document.at("dofs").get<std::vector<std::string>>();
        gains.blendFrames = document.value("blend_frames", 3);
        const auto& phrases = document.at("phrases");
        for (std::size_t p = 0; p < phrases.size(); ++p) {
            PhraseGains phrase;
            phrase.begin = phrases[p].at("begin").get<Eigen::Index>();
            phrase.end = phrases[p].at("end").get<Eigen::Index>();
            const auto& entries = phrases[p].at("gains");
            if (entries.size() != gains.dofNames.size())
                return parseError(source, 0, "phrases[" + std::to_string(p) + "].gains: expected one entry per DOF");
            for (const auto& entry : entries) {
                DofGain g;
                g.g0 = entry.value("g0", 1.0);
                g.g1 = entry.value("g1", 1.0);
                const std::string mode = entry.value("mode", std::string("scale"));
                if (mode != "scale" && mode != "offset")
                    return parseError(source, 0, "phrases[" + std::to_string(p) + "]: mode must be \"scale\" or \"offset\"");
                g.dcMode = mode == "offset" ? DcMode::Offset : DcMode::Scale;
                g.offset = entry.value("offset", 0.0);
                const std::string acMode = entry.value("ac_mode", std::string("scale"));
                if (acMode != "scale" && acMode != "additive")
                    return parseError(source, 0, "phrases[" + std::to_string(p) + "]: ac_mode must be \"scale\" or \"additive\"");
                g.acMode = acMode == "additive" ? AcMode::Additive : AcMode::Scale;
                g.harmonicCos = entry.value("harmonic_cos", 0.0);
                g.harmonicSin = entry.value("harmonic_sin", 0.0);
                g.reason = entry.value("reason", std::string());
                if (!std::isfinite(g.g0) || !std::isfinite(g.g1) || g.g0 == 0.0 || g.g1 == 0.0)
                    return parseError(source, 0, "phrases[" + std::to_string(p) + "]: g0 and g1 must be finite and non-zero");
                phrase.dofs.push_back(g);
            }
            gains.phrases.push_back(std::move(phrase));
        }
        return gains;
    } catch (const nlohmann::json::exception& error) {
        return parseError(source, 0, std::string("expected a gains document with dofs and phrases (") + error.what() + ")");
    }
}

} // namespace bunraku::analysis
