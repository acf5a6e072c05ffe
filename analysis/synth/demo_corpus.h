#pragma once
/// The synthetic Bunraku corpus: the embedded demo and the ground truth of every later test.
/// Shaped like the thesis's corpus (chapter 2): functions greeting and serving-tea x emotions
/// none, friendly, hostile x 5 takes, 24 puppet channels, 5 Hz, the longest take 106 frames.
/// Model, phrases, emotions, randomisation and the ground-truth files: docs/DEMO-CORPUS.md.
/// Writing the corpus folder with its truth/ subfolder: demo_corpus_io.h.
///
/// Time axes (all in frames at 5 Hz, fractional where noted):
///  - functional time s: the axis of the function's motion y^i, 0..105;
///  - cell time u: the axis of one function x emotion cell's noiseless motion, 0..105; the
///    cell's phase warp maps u to s (for the neutral cell it is the identity);
///  - take frame t: 0..frames-1 of one take; the take's warp maps t to u.
///
/// Model (thesis ch. 4): cell motion x^{ij}(u) = y^i(u) + z^{ij}(u), with y^i the neutral cell's
/// noiseless motion and z^{i,none} = 0, both sampled on the nominal axis u = 0..105. A take is
///   take_k(t) = wrap(x^{ij}(0) + g_k (x^{ij}(w_k(t)) - x^{ij}(0)) + offsets_k) + noise,
/// with x^{ij}(w) the cubic interpolation of the sampled cell motion (interpolateMotion), g_k
/// the amplitude jitter, offsets_k a whole-body translation on the 4 position triples and a yaw
/// offset on the 4 yaw channels, wrap() putting angles into (-180, 180] as a sensor reports them.
/// Least squares on unnormalised takes (mean of takes) only approximates y and z: the per-take
/// warps, offsets and wraps must be removed first.

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace bunraku::analysis::synth {

/// Frames of the nominal time axis (t = 0..105, 21.2 s at 5 Hz).
inline constexpr int kDemoNominalFrames = 106;
inline constexpr double kDemoRateHz = 5.0;

struct DemoOptions {
    /// Seeds std::mt19937_64; every random draw derives from it (same seed, same corpus).
    std::uint64_t seed = 1;
    /// Takes per function x emotion cell (thesis: K = 5).
    int takesPerCell = 5;
    /// Standard deviation of the Gaussian sensor noise on positions, cm.
    double positionNoiseCm = 0.1;
    /// Standard deviation of the Gaussian sensor noise on angles, degrees.
    double angleNoiseDeg = 0.2;
    /// Largest relative deviation of a take's local speed from its mean speed (0.15 = +-15 %).
    double warpStrength = 0.15;
    /// Largest relative amplitude jitter of a take (0.06: gain in [0.94, 1.06]).
    double amplitudeJitter = 0.06;
};

/// One function's noiseless motion and its phrase script (functional time).
struct FunctionTruth {
    std::string function;
    /// Phrase names in order, e.g. rest, travel, offer, release, bow, return, rest.
    std::vector<std::string> phraseNames;
    /// Phrase boundaries in functional frames: phrase p spans [b[p], b[p+1]]; size phrases + 1.
    std::vector<double> phraseBoundaries;
    /// Phrases x motion parameters: the change of each generator parameter over the phrase
    /// (parameter names: DemoGroundTruth::parameterNames; units cm and degrees).
    Eigen::MatrixXd phraseDisplacements;
    /// y^i: 106 x 24 channels, the noiseless neutral motion (equal to the neutral cell's motion).
    Eigen::MatrixXd motion;
};

/// One function x emotion cell: the emotion's phase and amplitude design and the result.
struct CellTruth {
    std::string function;
    std::string emotion;
    /// Phase warp: for each cell frame u = 0..105 the functional time s (frames) it shows.
    /// Strictly increasing, 0 -> 0 and 105 -> 105; identity for the neutral cell.
    Eigen::VectorXd phaseWarp;
    /// Its inverse: for each functional frame s = 0..105 the cell time u (frames) showing it.
    Eigen::VectorXd functionalToEmotional;
    /// Phrase boundaries in cell frames (the phase warp maps them onto the function's).
    std::vector<double> phraseBoundaries;
    /// Phrases x motion parameters: gain on the function's phrase displacement (1 = unchanged).
    Eigen::MatrixXd phraseGains;
    /// Phrases x motion parameters: displacement added to the phrase (part-relative changes,
    /// e.g. the hostile head turning away), cm and degrees.
    Eigen::MatrixXd phraseOffsets;
    /// x^{ij}: 106 x 24, the noiseless cell motion on the cell axis u.
    Eigen::MatrixXd motion;
    /// z^{ij} = motion - y^i: 106 x 24; exactly zero for the neutral emotion.
    Eigen::MatrixXd emotionComponent;
};

/// One take's randomisation.
struct TakeTruth {
    TakeLabels labels; ///< function, emotion, takeIndex (1-based), source "demo"
    /// For each take frame t the cell time u (frames) it shows: non-decreasing, 0 for
    /// t <= lateStartFrames (the late start holds the cell's first pose), strictly increasing
    /// after, ending exactly at 105 on the take's last frame.
    Eigen::VectorXd takeToCell;
    /// Frames held still before moving (0 unless this is the cell's late-start take).
    int lateStartFrames = 0;
    /// Amplitude jitter g_k: the take shows x(0) + g_k (x(u) - x(0)) on every channel.
    double amplitudeGain = 1.0;
    /// Whole-body translation added to the 4 part positions (x, y, z), cm.
    Eigen::Vector3d positionOffset = Eigen::Vector3d::Zero();
    /// Whole-body heading: the puppet turned rigidly by this angle about the vertical through
    /// the shoulder's start position (headingPivot): positions rotated, the 4 yaw channels offset
    /// before wrapping; degrees in (-180, 180]. Applied before positionOffset.
    double yawOffsetDeg = 0.0;
    /// True when yawOffsetDeg was chosen near 180 so that the yaw channels cross +-180.
    bool yawWraps = false;
};

struct DemoGroundTruth {
    std::uint64_t seed = 1;
    double rateHz = kDemoRateHz;
    int nominalFrames = kDemoNominalFrames;
    double positionNoiseCm = 0.1;
    double angleNoiseDeg = 0.2;
    std::string neutralEmotion = "none";
    /// Names of the generator's motion parameters (columns of the phrase matrices).
    std::vector<std::string> parameterNames;
    std::vector<FunctionTruth> functions;
    std::vector<CellTruth> cells;
    std::vector<TakeTruth> takes;

    const FunctionTruth* function(const std::string& name) const;
    const CellTruth* cell(const std::string& function, const std::string& emotion) const;
    /// Matches function, emotion and takeIndex (the source is ignored).
    const TakeTruth* take(const TakeLabels& labels) const;
};

struct DemoCorpus {
    Corpus corpus;
    DemoGroundTruth truth;
};

/// The pivot of a take's heading turn: the cell motion's first shoulder position, cm.
Eigen::Vector3d headingPivot(const CellTruth& cell);
/// The rotation about world z by the take's yawOffsetDeg.
Eigen::Matrix3d headingTurn(const TakeTruth& take);

/// The demo corpus and its ground truth; deterministic per options.seed.
DemoCorpus generateDemoCorpus(const DemoOptions& options = {});

/// Whether `name` names a take of the demo corpus, "demo:FUNCTION/EMOTION/K" (the command line's
/// way of naming one instead of a file).
bool isDemoTakeName(const std::string& name);
/// The demo take `name` names, from the default demo corpus (generated once). InvalidArgument
/// for a malformed name; NotFound naming the corpus's functions, emotions and takes otherwise.
Result<Take> demoTake(const std::string& name);

/// The row of `motion` (frames x channels) at fractional frame `frame`, by cubic Hermite
/// interpolation with Catmull-Rom tangents (one-sided at the ends); clamped to the first and
/// last rows outside [0, frames-1]. This is the interpolation the generator uses.
Eigen::RowVectorXd interpolateMotion(const Eigen::MatrixXd& motion, double frame);
/// Rows of `motion` at each fractional frame of `frames` (interpolateMotion per entry).
Eigen::MatrixXd resampleMotion(const Eigen::MatrixXd& motion, const Eigen::VectorXd& frames);

/// The take's expected value (frames x 24, angles wrapped to (-180, 180]): the take without
/// its sensor noise, rebuilt from the stored truth. NotFound for unknown labels.
Result<Eigen::MatrixXd> noiselessTake(const DemoGroundTruth& truth, const TakeLabels& labels);

/// For each frame of the reference take, the fractional frame of the sample take showing the
/// same moment of the motion. Same cell: u = takeToCell_ref(t), then the sample frame with
/// takeToCell_smp = u. Different emotions of one function: through the functional axis,
/// s = phaseWarp_ref(u), then the sample cell time with phaseWarp_smp = s. Every stored series
/// is read as linear between whole frames, so the composition is exact for the stored data. Flat starts: the reference's held interval [0, late_ref] maps linearly
/// onto the sample's [0, late_smp]; when late_ref = 0 frame 0 maps to late_smp (onset to
/// onset). Results are clamped to [0, frames_smp - 1]; the map is non-decreasing and a take
/// maps to itself as the identity. InvalidArgument for takes of different functions.
Result<Eigen::VectorXd> trueCorrespondence(const DemoGroundTruth& truth, const TakeLabels& reference,
                                           const TakeLabels& sample);

/// Writes the ground truth into `folder` (created when needed): truth.json plus CSVs, format in
/// docs/DEMO-CORPUS.md. Files are written atomically one by one.
Status writeGroundTruth(const DemoGroundTruth& truth, const std::filesystem::path& folder);
/// Reads what writeGroundTruth wrote; Parse errors name the file, line and expectation.
Result<DemoGroundTruth> readGroundTruth(const std::filesystem::path& folder);

} // namespace bunraku::analysis::synth
