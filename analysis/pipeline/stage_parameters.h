#pragma once
/// The typed parameters of every stage of the analysis pipeline, with the thesis's defaults (one
/// exception: normalisation's optimal path, NormaliseParameters::path), and their validation. The workbench's document and project file, and the command line's options
/// and `--parameters` file, are these structs; nothing passes them as strings or variants.
///
/// Chain (docs/ARCHITECTURE.md): import -> preprocess (2.2) -> normalise every cell (3) ->
/// decompose (4) -> fluctuations (4.3.2), and normalise -> motion axes, phase and gains (5) ->
/// design / emotion weight (4.5, 5.5).

#include "analysis/axis/inertia_axis.h"
#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/design/motion_design.h"
#include "analysis/design/warp_curve.h"
#include "analysis/normalise/take_normalisation.h"
#include "analysis/preprocess/preprocess.h"

#include <Eigen/Core>

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis::pipeline {

/// Thesis 2.2: which preprocessing steps run (all of them by default).
struct PreprocessParameters {
    bool pad = true;
    bool unwrap = true;
    bool alignStart = true;
    bool alignHeading = true;
    bool alignPosition = true;
    /// 2.2-4: one rigid translation per take (thesis), or one offset per part.
    preprocess::PositionAlignment positionAlignment = preprocess::PositionAlignment::Rigid;
    /// Take index of every cell's time reference; 0 = automatic (thesis 3.6.1 reading).
    int referenceTakeIndex = 0;

    preprocess::PreprocessOptions options() const;
    bool operator==(const PreprocessParameters&) const = default;
};

/// The reference a cell is normalised to.
enum class ReferenceKind {
    Suggested, ///< thesis 3.6.1: a long take with an early start, not an outlier
    Take,      ///< the cell's take with this take index
    Average,   ///< thesis 3.7: the cell's average take (base: the suggested take; outliers left out)
};

struct ReferenceChoice {
    ReferenceKind kind = ReferenceKind::Suggested;
    int takeIndex = 0; ///< for ReferenceKind::Take: TakeLabels::takeIndex (1-based)
    bool operator==(const ReferenceChoice&) const = default;
};

/// Thesis 3.5-3.8: wavelet matching of every cell's takes to its reference.
struct NormaliseParameters {
    int tau = 4;           ///< half window, frames (3.5.2)
    int searchBand = 20;   ///< T_cmp, frames (3.5.1)
    int maxScale = 16;     ///< scales 1..maxScale (3.5)
    /// couplingFor: `auto` = eq. 3.29 (method2) on the puppet's parts, `chains` on a skeleton's joints.
    std::string coupling = kDefaultCoupling;
    /// The optimal monotone path (default), or 3.5.3's greedy scan (the thesis's choice; set it to
    /// reproduce the thesis). Decision (docs/NORMALISATION.md, "Real takes"): on the real Bandai
    /// waves at 30 Hz the greedy scan raises the 3.8 variance of some takes, the optimal path of none.
    PathMethod path = PathMethod::Optimal;
    /// Explicit scales (each in (0, 256]); empty = 1..maxScale.
    std::vector<double> scales;
    ChannelWeighting weighting = ChannelWeighting::None;
    LevelAlignment level = LevelAlignment::FirstFrame;
    double approximationWeight = 0.0; ///< M of eq. 5.17; 0 = eq. 3.28 (chapter 3)
    ReferenceChoice reference;  ///< for every cell without its own choice
    /// Per cell ("function/emotion"): a reference other than `reference`.
    std::map<std::string, ReferenceChoice> cellReferences;
    /// Thesis 3.7 "4ave": the average take leaves out the takes 3.6.1 marks as outliers.
    bool averageExcludesOutliers = true;
    /// Base of the average take (a take index); 0 = the suggested reference.
    int averageBase = 0;
    /// Take indices left out of the average; when given, instead of the outliers.
    std::vector<int> averageExcluded;

    NormaliseOptions options() const;
    ReferenceChoice referenceFor(const std::string& function, const std::string& emotion) const;
    bool operator==(const NormaliseParameters&) const = default;
};

/// "function/emotion", the key of NormaliseParameters::cellReferences.
std::string cellName(const std::string& function, const std::string& emotion);

enum class DecomposeInput {
    Normalised,   ///< thesis 4.1: the chapter-3-normalised takes (default)
    Preprocessed, ///< the takes after 2.2 only
};

enum class DecomposeMethod {
    LeastSquares, ///< 4.3.1
    Km2o,         ///< 4.4.4: the KM2O-Langevin equation with exogenous inputs (default)
};

/// Thesis chapter 4.
struct DecomposeParameters {
    DecomposeInput input = DecomposeInput::Normalised;
    DecomposeMethod method = DecomposeMethod::Km2o;
    /// KM2O's correlation length M; 0 = chosen by the relative error P over 1..M_max (4.4.4).
    int correlationLength = 0;
    bool operator==(const DecomposeParameters&) const = default;
};

/// Thesis 4.3.2: spectra and ARMA identification of the fluctuation eta.
struct FluctuationParameters {
    int armaP = 2;        ///< Table 4.1's order
    int armaQ = 2;
    int welchSegment = 32; ///< samples per Welch segment (clamped to the take)
    bool operator==(const FluctuationParameters&) const = default;
};

/// Thesis chapter 5: motion axes of the average takes, phase and gains of every emotional cell.
struct AxisParameters {
    FrontBackAxis frontBack = FrontBackAxis::ShoulderForward;
    double massSpacing = 1.0;     ///< cm between mass points
    /// The masses from the modelled puppet's solid (default) or the description's primitives
    /// (analysis/body/puppet_mass.h, docs/MOTION-AXIS.md "Masses").
    MassSource masses = MassSource::Model;
    /// de Leva's male or female segment table for a take of a skeleton's joints (the whole-body
    /// axis: analysis/axis/segment_inertia.h, docs/MOTION-AXIS.md "The whole body").
    SegmentTable segments = SegmentTable::DeLevaMale;
    int tau = 4;                  ///< 5.3.4
    int searchBand = 30;          ///< T_cmp (docs/MOTION-AXIS.md)
    int maxScale = 16;            ///< scales 1..16
    double approximationWeight = 8.0; ///< M of eq. 5.17
    /// Each axis coordinate minus its first frame before the transform (docs/MOTION-AXIS.md,
    /// "Level"), or the signals as they are (None, eq. 5.16 literally).
    LevelAlignment level = LevelAlignment::FirstFrame;
    PathMethod path = PathMethod::Greedy;
    int controlSpacing = 8;       ///< frames between warp control points
    int refinementPasses = 2;     ///< extractDesign's refinement rounds

    AxisOptions axisOptions() const;
    ExtractionOptions extractionOptions() const;
    bool operator==(const AxisParameters&) const = default;
};

/// One edited gain: phrase and axis DOF (indices into the gain set in use), g0 and g1 (5.4).
struct GainEdit {
    int phrase = 0;
    int dof = 0;
    double g0 = 1.0;
    double g1 = 1.0;
    bool operator==(const GainEdit&) const = default;
};

/// The phrase boundaries of a design: the suggested ones, or the inner boundaries the user set
/// (functional frames, increasing; empty = one phrase over the whole take).
struct PhraseBoundaries {
    bool suggested = true;
    std::vector<Eigen::Index> inner;
    bool operator==(const PhraseBoundaries&) const = default;
};

/// Thesis 4.5 and 5.5: what the user edits on top of the analysis.
struct DesignEdits {
    double emotionWeight = 1.0;      ///< a of eq. 4.45
    std::optional<WarpCurve> warp;   ///< the edited warp; none = the identity
    std::vector<GainEdit> gains;     ///< sorted by (phrase, dof), one per cell at most
    PhraseBoundaries boundaries;

    /// The edited gain of (phrase, dof), null when unedited.
    const GainEdit* gain(int phrase, int dof) const;
    /// Sets (or adds) one gain, keeping the order.
    void setGain(const GainEdit& edit);
    bool operator==(const DesignEdits& other) const;
};

/// Every parameter of the chain: a project's analysis, or `bunraku analyse --parameters`.
struct ChainParameters {
    PreprocessParameters preprocess;
    NormaliseParameters normalise;
    DecomposeParameters decompose;
    FluctuationParameters fluctuations;
    AxisParameters axis;
    DesignEdits design;
    bool operator==(const ChainParameters&) const = default;
};

// Limits checked by validation (and by the project file and command line before anything is
// allocated from a value): the one table of them. Each is one the analysis accepts all the way
// down (a control or option at its maximum gives a value the stages run with); the workbench's
// spin boxes and the command line's options take their ranges from here.
inline constexpr int kMaxTau = 200;
/// T_cmp: the matcher's own limit (analysis/normalise/wavelet_matching.h).
inline constexpr int kMaxSearchBand = analysis::kMaxSearchBand;
inline constexpr int kMaxScale = 256;
inline constexpr int kMaxTakeIndex = 1000000;
inline constexpr int kMaxCorrelationLength = 1000;
inline constexpr int kMaxArmaOrder = 4;
inline constexpr int kMaxWelchSegment = 1 << 20;
inline constexpr int kMaxControlSpacing = 100000;
inline constexpr int kMaxRefinementPasses = 10;
inline constexpr double kMinMassSpacing = 0.5; ///< finer lattices hold millions of points
inline constexpr double kMaxMassSpacing = 100.0;
inline constexpr double kMaxApproximationWeight = 1e6;
/// Warp control points and phrase boundaries a design may hold.
inline constexpr std::size_t kMaxWarpPoints = 20000;
inline constexpr std::size_t kMaxPhraseBoundaries = 10000;
inline constexpr std::size_t kMaxGainEdits = 100000;
/// Frames a warp may reach (output and source): 10^8 frames, over 5 hours at 5 kHz.
inline constexpr double kMaxWarpFrame = 1e8;
inline constexpr double kMaxGain = 1e6;

/// A numeric parameter's range: the one table that validation, the parameter files and the
/// command line's options check (docs/FORMATS.md). `path` is the parameter's in the files
/// ("normalise.tau"); for an array ("normalise.averageExcluded") the range of each element.
struct ParameterRange {
    std::string_view path;
    double low = 0.0;
    double high = 0.0;
    bool integer = true;
    bool contains(double value) const;
    /// "0..200" for an integer, "[0, 1e+06]" for a number.
    std::string interval() const;
    /// What a value must be: "an integer in 0..200", "a number in [0, 1e+06]".
    std::string expected() const;
};
/// Every numeric parameter of ChainParameters but the design's warp and gains, one entry each.
std::span<const ParameterRange> parameterRanges();
/// The entry of `path`; throws std::logic_error for a path the table does not hold (a
/// parameter added without its range).
const ParameterRange& parameterRange(std::string_view path);

/// The largest NormaliseParameters::maxScale the normalisation accepts on `corpus`: the largest
/// scale whose wavelet (sym3) fits its shortest take (thesis 5.3.2: 21 for 106 frames), at most
/// kMaxScale; kMaxScale for a corpus without takes. Takes are matched at their length or
/// longer (padding, a global time scale to the reference's length), so every scale up to it fits.
int usableMaxScale(const Corpus& corpus);
/// The largest DecomposeParameters::correlationLength KM2O accepts on `corpus`: M_max of its
/// shortest take (thesis eq. 4.30: floor(3 sqrt(T + 1)) - 1), at most kMaxCorrelationLength;
/// kMaxCorrelationLength for a corpus without takes.
int usableCorrelationLength(const Corpus& corpus);

/// InvalidArgument naming the parameter ("normalise.maxScale"), its range and the value.
Status validate(const PreprocessParameters& parameters);
Status validate(const NormaliseParameters& parameters);
Status validate(const DecomposeParameters& parameters);
Status validate(const FluctuationParameters& parameters);
Status validate(const AxisParameters& parameters);
Status validate(const DesignEdits& edits);
Status validate(const ChainParameters& parameters);

} // namespace bunraku::analysis::pipeline
