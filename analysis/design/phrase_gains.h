#pragma once
/// Amplitude components (thesis 5.4): the axis split into phrases; per phrase and axis DOF the
/// 0th and 1st Fourier coefficients of the functional (no emotion) and the phase-adjusted
/// emotional axis, and the gains g0 = a0_no / a0_em (eq. 5.22), g1 = A1_no / A1_em (eq. 5.23).
/// Designing applies them the other way round (no emotion -> emotion):
///   X_em(t) = (a0_no / g0) / 2 + (x_no(t) - a0_no / 2) / g1,
/// the inverse of eq. 5.28, with phrases blended at their boundaries by cubic (smoothstep)
/// spline weights. Decision (beyond the thesis): where the emotional phrase has a first harmonic
/// many times the functional one (motion the function lacks), the harmonic difference is added
/// instead of scaling. A DC term near zero (|a0/2| below the DOF's motion range) would make g0
/// meaningless or infinite: that DOF's phrase switches to an additive offset (a0_em - a0_no)/2,
/// with the reason recorded. A1 is a magnitude (eq. 5.19), so g1 = A1_no / A1_em >= 0 always;
/// where A1_em is below kIllConditionedAmplitudeFraction of A1_no the ratio divides by (nearly)
/// nothing: A1_em is floored at that fraction (g1 = 1 / fraction = 10) and the phrase and DOF are
/// marked ill-conditioned, with the reason.

#include "analysis/core/result.h"

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace bunraku::analysis {

enum class DcMode {
    Scale,  ///< mean_em = mean_no / g0
    Offset, ///< mean_em = mean_no + offset
};

enum class AcMode {
    Scale,    ///< (x_no - mean_no) / g1
    Additive, ///< (x_no - mean_no) + the first-harmonic difference (harmonicCos, harmonicSin)
};

/// A1_em below this fraction of A1_no makes g1 = A1_no / A1_em ill-conditioned (thesis eq. 5.23
/// divides by a first harmonic that the emotional phrase hardly has: g1 would exceed 10 and be
/// set by noise and by how the phase adjustment cut the phrase). Such a gain is regularised -
/// A1_em floored at this fraction of A1_no, g1 = 1 / fraction = 10 - and flagged
/// (DofGain::illConditioned). Not left at 1: the measurement does say the emotion stills the
/// phrase's swing, and on the demo corpus g1 = 1 there raises serving-tea/hostile's design error
/// from under 0.10 to 0.27 (docs/MOTION-AXIS.md).
inline constexpr double kIllConditionedAmplitudeFraction = 0.1;

struct DofGain {
    double g0 = 1.0;     ///< a0_no / a0_em (thesis eq. 5.22)
    double g1 = 1.0;     ///< A1_no / A1_em (thesis eq. 5.23): a ratio of magnitudes, never negative when extracted
    DcMode dcMode = DcMode::Scale;
    double offset = 0.0; ///< (a0_em - a0_no) / 2 when dcMode is Offset (units of the DOF)
    AcMode acMode = AcMode::Scale;
    /// Additive first harmonic (units of the DOF): harmonicCos cos(2 pi n / N) + harmonicSin sin(2 pi n / N),
    /// n = frame - phrase begin, N = phrase frames; the emotional minus the functional one.
    double harmonicCos = 0.0, harmonicSin = 0.0;
    std::string reason;  ///< why a default or offset replaced a ratio; empty when the ratios hold
    /// True when A1_em < fraction x A1_no (GainOptions::illConditionedFraction): the ratio was
    /// not taken, g1 is regularised to 1 / fraction, and illConditionedReason says why.
    bool illConditioned = false;
    std::string illConditionedReason; ///< "A1_em = 0.02 is below 0.1 x A1_no = 3.1 (...)"; empty when well conditioned
    // the coefficients they came from (0 when set by hand)
    double a0Functional = 0.0, a0Emotional = 0.0, a1Functional = 0.0, a1Emotional = 0.0;
};

struct PhraseGains {
    Eigen::Index begin = 0; ///< first frame (functional time)
    Eigen::Index end = 0;   ///< last frame, inclusive; the next phrase begins here
    std::vector<DofGain> dofs;
};

struct GainSet {
    std::vector<std::string> dofNames; ///< e.g. axis.x ... axis.rot_z
    std::vector<PhraseGains> phrases;
    int blendFrames = 3; ///< half width of the spline blend at each inner boundary, frames
};

struct GainOptions {
    /// |a0/2| below this fraction of the DOF's motion range (max - min of the functional DOF
    /// over the whole take) counts as "near zero": offset mode.
    double nearZeroDcFraction = 1.0;
    /// A1 below this fraction of the motion range: g1 is set to 1 (nothing to scale).
    double flatFraction = 1e-3;
    /// A1_em below this fraction of A1_no: g1 is ill-conditioned, regularised to 1 / fraction and flagged.
    double illConditionedFraction = kIllConditionedAmplitudeFraction;
    double gainLimit = 100.0; ///< g1 and 1/g1 are clamped to this, with a reason
    /// A1_em above this multiple of A1_no: the emotion adds motion the function hardly has in
    /// this phrase (a hostile turn away); scaling the functional wiggle that much would amplify
    /// its noise, so the first harmonic is added instead (AcMode::Additive, with a reason).
    double additiveRatio = 4.0;
    /// cos(theta1_no - theta1_em) below this: the first harmonics are out of phase (the thesis
    /// assumes them equal, eq. 5.24), so the harmonic is added instead of scaled. Opposite
    /// harmonics (cos near -1) are out of phase too: g1 is a ratio of magnitudes (eq. 5.23) and
    /// cannot carry a sign.
    double minimumPhaseAgreement = 0.5;
    int blendFrames = 3;
};

/// 0th and 1st Fourier coefficients of samples x_0..x_{N-1} over a period of N samples
/// (thesis eq. 5.19): a0 = 2/N sum x, A1 = |2/N sum x e^{-2 pi i n / N}|.
struct FourierLow {
    double a0 = 0.0;
    double a1 = 0.0;
    double cosine = 0.0; ///< 2/N sum x cos(2 pi n / N)
    double sine = 0.0;   ///< 2/N sum x sin(2 pi n / N); a1 = hypot(cosine, sine)
};
FourierLow lowFourier(const Eigen::Ref<const Eigen::VectorXd>& samples);

/// Gains of every phrase and DOF. functional and emotional: frames x DOF on the functional time
/// axis (the emotional one already phase adjusted); boundaries: increasing frames starting at 0
/// and ending at frames - 1. InvalidArgument for mismatched shapes or bad boundaries.
Result<GainSet> extractGains(const Eigen::MatrixXd& functional, const Eigen::MatrixXd& emotional,
                             const std::vector<Eigen::Index>& boundaries, const std::vector<std::string>& dofNames,
                             const GainOptions& options = {});

/// One ill-conditioned gain of a GainSet: phrase index (0-based), DOF index, and the reason.
struct IllConditionedGain {
    std::size_t phrase = 0;
    std::size_t dof = 0;
    Eigen::Index begin = 0, end = 0; ///< the phrase's frames
    std::string dofName;
    double a1Functional = 0.0, a1Emotional = 0.0;
    double g1 = 1.0; ///< the regularised gain in use
    std::string reason;
};
/// Every gain flagged illConditioned, phrase by phrase, DOF by DOF.
std::vector<IllConditionedGain> illConditionedGains(const GainSet& gains);
/// Them as JSON, one object each: phrase (from 1), begin, end, dof, A1_functional, A1_emotional,
/// g1 and reason (`bunraku gains`' summary; gains_json.cpp).
nlohmann::json illConditionedGainsJson(const std::vector<IllConditionedGain>& gains);
/// Them for a person: nothing when there are none, else a line saying what ill-conditioned
/// means and to what g1 is regularised, then a line per gain.
std::string illConditionedGainsText(const std::vector<IllConditionedGain>& gains);

/// Gains that change nothing (g0 = g1 = 1) over the given phrases.
GainSet unitGains(const std::vector<Eigen::Index>& boundaries, const std::vector<std::string>& dofNames);

/// Applies the gains to a functional signal (frames x DOF, functional time), phrases blended by
/// spline weights over +-blendFrames at inner boundaries. Means of the functional phrases are
/// taken from `functional` itself.
Eigen::MatrixXd applyGains(const Eigen::MatrixXd& functional, const GainSet& gains);

struct PhraseOptions {
    int minimumPhraseFrames = 8; ///< no two boundaries closer than this
    int maximumPhrases = 8;
    double rotationRadiusCm = 30.0; ///< deg/frame -> cm/frame at this radius when adding rotation to speed
    int smoothingFrames = 5;        ///< moving-average width of the speed
};

/// Suggested phrase boundaries: frame 0, then the deepest local minima of the axis speed
/// (|d centre/dt| + radius * |d rotation/dt|, moving-averaged), below the median speed and at
/// least minimumPhraseFrames apart, then the last frame. axisCoordinates: frames x 6
/// (axis_channels.h).
std::vector<Eigen::Index> suggestPhraseBoundaries(const Eigen::MatrixXd& axisCoordinates, const PhraseOptions& options = {});

/// "0,40,105" -> {0, 40, 105}; Parse errors name the text.
Result<std::vector<Eigen::Index>> parsePhraseBoundaries(const std::string& text, Eigen::Index frames);

/// Bounds of a gains document: the last frame a phrase may reach, the widest blend, the largest
/// |g0|, |g1|, |offset| and harmonic amplitude.
inline constexpr Eigen::Index kMaxGainsFrame = 100'000'000;
inline constexpr int kMaxBlendFrames = 1000;
inline constexpr double kMaxGainMagnitude = 1e6;
inline constexpr double kMaxGainOffset = 1e9;

/// gains.json: {"dofs": [...], "blend_frames": 3, "phrases": [{"begin", "end", "gains": [{"dof", "g0", "g1",
/// "mode", "offset", "reason", "ill_conditioned", "ill_conditioned_reason", ...}]}]}. Written atomically.
Status writeGainsJson(const GainSet& gains, const std::filesystem::path& file);
/// Parses gains JSON text, checking every field: dofs a non-empty list of distinct names;
/// blend_frames a whole number in [0, kMaxBlendFrames]; phrases in order, each begin < end,
/// whole frames in [0, kMaxGainsFrame], the first beginning at 0 and each next one where the
/// previous ends; one gain per DOF, g0 and g1 finite, non-zero and within kMaxGainMagnitude,
/// offsets and harmonics within kMaxGainOffset. Errors name `sourceName` and the field.
Result<GainSet> parseGainsJson(const std::string& text, const std::string& sourceName);
/// parseGainsJson of a file (a regular file of at most io::kDocumentLimitBytes).
Result<GainSet> readGainsJson(const std::filesystem::path& file);

} // namespace bunraku::analysis
