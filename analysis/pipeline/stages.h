#pragma once
/// The stages of the thesis's chain as plain functions over typed inputs, parameters and
/// results: each is what both the workbench and the command line call (never a copy of it).
/// Keys (stage_key.h) follow the chain: a stage's key mixes its input stage's key and its own
/// parameters, so a changed parameter changes the keys of its stage and those below only.
///
///   import (corpus) -> preprocess (2.2) -> normalise (3) -> decompose (4) -> fluctuations (4.3.2)
///                                                      \-> motion axes, phase, gains (5)
///   decompose -> emotion weight (4.5); motion axes -> design (5.5): cheap, run on demand.

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/decompose/arma.h"
#include "analysis/decompose/km2o_decomposition.h"
#include "analysis/decompose/least_squares.h"
#include "analysis/decompose/spectrum.h"
#include "analysis/design/approximation_error.h"
#include "analysis/design/motion_design.h"
#include "analysis/normalise/take_normalisation.h"
#include "analysis/normalise/variance_evaluation.h"
#include "analysis/pipeline/stage_key.h"
#include "analysis/pipeline/stage_parameters.h"
#include "analysis/preprocess/preprocess.h"

#include <Eigen/Core>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace bunraku::analysis::pipeline {

enum class Stage { Import, Preprocess, Normalise, Decompose, Fluctuations, Axes };
inline constexpr std::size_t kStageCount = 6;
/// "import", "preprocess", "normalise", "decompose", "fluctuations", "axes".
const char* stageName(Stage stage);
/// What the user reads in progress and errors: "Preprocessing (2.2)", ...
const char* stageTitle(Stage stage);
inline constexpr std::array<Stage, kStageCount> kStages{Stage::Import, Stage::Preprocess, Stage::Normalise,
                                                        Stage::Decompose, Stage::Fluctuations, Stage::Axes};

template <class T> using Shared = std::shared_ptr<const T>;

// ---- import -------------------------------------------------------------------------------

/// A corpus with its content key (the import stage's result).
struct CorpusInput {
    Shared<Corpus> corpus;
    StageKey key;
};
/// Validates the corpus and computes its key.
Result<CorpusInput> makeCorpusInput(Corpus corpus);
/// A corpus folder (corpus.json), or "demo" for the embedded synthetic corpus.
Result<CorpusInput> importCorpus(const std::string& source);

// ---- preprocess (thesis 2.2) -----------------------------------------------------------------

using PreprocessOutput = preprocess::PreprocessResult;

StageKey preprocessKey(StageKey corpus, const PreprocessParameters& parameters);
Result<PreprocessOutput> runPreprocess(const Corpus& corpus, const PreprocessParameters& parameters,
                                       const RunControl& control = {});

// ---- normalise (thesis 3) ------------------------------------------------------------------

/// One function x emotion cell normalised to its reference (3.6), evaluated (3.8), averaged (3.7).
struct CellNormalisation {
    std::string function;
    std::string emotion;
    std::vector<int> takeIndices;      ///< TakeLabels::takeIndex of the cell's takes, in order
    ReferenceSuggestion suggestion;    ///< thesis 3.6.1 (takeIndex is an index into the cell)
    ReferenceChoice reference;         ///< as asked for
    std::string referenceName;         ///< "take 4 (suggested)", "take 2", "4ave"
    Take referenceTake;
    std::vector<TakeNormalisation> normalisations; ///< per take, cell order
    VarianceTable variance;            ///< thesis 3.8, raw and normalised takes vs the reference
    Take average;                      ///< thesis 3.7: base the suggested take
    std::vector<int> averageMembers;   ///< take indices averaged
    std::string averageName;           ///< "5ave", "4ave"
};

struct NormaliseOutput {
    std::vector<CellNormalisation> cells; ///< functions() x emotions() order, cells with takes
    /// The corpus with every take replaced by its normalised take (reference frames), labels kept.
    Corpus normalised;
    const CellNormalisation* cell(const std::string& function, const std::string& emotion) const;
};

StageKey normaliseKey(StageKey preprocessed, const NormaliseParameters& parameters);
/// Every cell of the (preprocessed) corpus; progress per cell; Cancelled between cells.
Result<NormaliseOutput> runNormalise(const Corpus& preprocessed, const NormaliseParameters& parameters,
                                     const RunControl& control = {});

// ---- decompose (thesis 4) ------------------------------------------------------------------

struct DecomposeOutput {
    DecomposeParameters parameters;
    Decomposition components;            ///< y, z, eta, cell means
    /// With KM2O: M, P by M (4.4.4), P^{ij} per channel (Table 4.5); components duplicated above.
    std::optional<Km2oDecomposition> km2o;
};

/// Keyed on the normalise stage's key, or the preprocess stage's for DecomposeInput::Preprocessed.
StageKey decomposeKey(StageKey input, const DecomposeParameters& parameters);
Result<DecomposeOutput> runDecompose(const Corpus& input, const DecomposeParameters& parameters, const RunControl& control = {});

// ---- fluctuations (thesis 4.3.2) ---------------------------------------------------------------

/// Power spectra of eta averaged over a cell's takes, per channel.
struct CellSpectra {
    std::string function;
    std::string emotion;
    Eigen::VectorXd frequencyHz;
    Eigen::MatrixXd power; ///< bins x channels, Welch PSD averaged over the cell's takes
};

struct FluctuationOutput {
    std::vector<std::string> channelNames;
    std::vector<CellSpectra> spectra;                    ///< Decomposition::emotions order
    int armaP = 2;
    int armaQ = 2;
    std::vector<std::vector<ArmaCellRow>> armaTables;    ///< per channel: Table 4.1 (rows per cell)
    std::vector<std::string> armaErrors;                 ///< per channel: why its table is empty
};

StageKey fluctuationKey(StageKey decomposed, const FluctuationParameters& parameters);
Result<FluctuationOutput> runFluctuations(const Decomposition& decomposition, const FluctuationParameters& parameters,
                                          const RunControl& control = {});

// ---- motion axes, phase, gains (thesis 5) ------------------------------------------------------

/// A function's functional motion: the neutral cell's average take (3.7), its axis (5.2.1),
/// relative motion and suggested phrase boundaries (5.2.2).
struct FunctionAxis {
    std::string function;
    Shared<DesignBasis> basis;
    std::vector<Eigen::Index> boundaries;
};

/// An emotional cell against its function: the cell's average take's axis, the phase (5.3)
/// and gains (5.4), and the eq. 5.18 error of the motion designed with them (5.5).
struct CellAxis {
    std::string function;
    std::string emotion;
    Eigen::MatrixXd coordinates;     ///< frames x 6 axis coordinates of the emotional average take
    std::vector<RigidTransform> world_T_axis;
    DesignParameters extracted;      ///< phase, phase-adjusted axis, gains
    double designRelativeError = 0;  ///< designed (extracted parameters) vs emotional axis, eq. 5.18
    double undesignedRelativeError = 0; ///< functional vs emotional axis
    /// 5.4.1: eq. 5.18 per largest scale c = 1..maxScale and axis DOF, functional axis vs the
    /// phase-adjusted emotional axis (Fig. 5.16).
    ApproximationError approximation;
};

struct AxisOutput {
    std::vector<FunctionAxis> functions;
    std::vector<CellAxis> cells;       ///< every non-neutral cell with takes
    /// Why nothing was computed, one line (empty when computed): the motion axis integrates
    /// the puppet's parts (head, shoulder, arm, hand), which a take of a skeleton's joints
    /// lacks; the chain goes on without the axes.
    std::string unavailable;
    const FunctionAxis* function(const std::string& name) const;
    const CellAxis* cell(const std::string& function, const std::string& emotion) const;
};

StageKey axisKey(StageKey normalised, const AxisParameters& parameters);
/// On the default body (the shipped puppet description). Takes without the puppet's four parts
/// give an empty output that says so (AxisOutput::unavailable), not an error.
Result<AxisOutput> runAxes(const NormaliseOutput& normalised, const std::string& neutralEmotion,
                           const AxisParameters& parameters, const RunControl& control = {});

// ---- the motion axis of one take (thesis 5.2.1), on demand: what the 3D view draws -------------

/// The body a take's motion axis integrates: the performer's segments (segment_inertia.h) for a
/// take of a skeleton's joints, else the default puppet, fitted to the take's skeleton when
/// `fitToSkeleton` (the one take's axis) or as it is (the motion-axes stage of averages).
Result<std::shared_ptr<const AxisModel>> axisModelFor(const Take& take, const AxisOptions& options, bool fitToSkeleton = false);

/// A take's motion axis: per frame, and as the 6 axis-coordinate channels (axis_channels.h)
/// labelled "axis of <the take's name>".
struct TakeAxis {
    std::vector<RigidTransform> world_T_axis;
    Take coordinates;
};

/// The axis parameters (their names in toJson) one take's axis depends on: the body's masses and
/// the front-back axis; the matching and design parameters are the corpus axes' (axisKey).
inline constexpr std::array<const char*, 4> kTakeAxisParameters{"frontBack", "massSpacing", "masses", "segments"};
/// Keyed on the take's content (takeKey) and kTakeAxisParameters of the axis parameters, so each
/// take's axis is computed once.
StageKey takeAxisKey(StageKey take, const AxisParameters& parameters);
/// On the default body (fitted to the take's skeleton when it has one), or on the performer's
/// segments for a take of a skeleton's joints, with the parameters' axis options.
Result<TakeAxis> runTakeAxis(const Take& take, const AxisParameters& parameters, const RunControl& control = {});

// ---- the kimono as cloth of one take (thesis 6, future work), on demand: what the 3D view draws --

/// Keyed on the take's content (takeKey), the body it is drawn with (each part's fit) and every
/// cloth parameter, so each take's cloth is simulated once per body and parameters.
StageKey kimonoKey(StageKey take, const BodyDescription& body, const ClothParameters& parameters);
/// The take's kimono simulated on `body` (simulateKimono), the error naming the take.
Result<KimonoSimulation> runKimono(const Take& take, const BodyDescription& body, const ClothParameters& parameters,
                                   const RunControl& control = {});

// ---- emotion weight and design (thesis 4.5, 5.5): cheap, computed on demand -------------------

/// x = y + a z of one cell (eq. 4.45), labelled as weightEmotion labels it.
Result<Take> weightedTake(const DecomposeOutput& decomposed, const std::string& function, const std::string& emotion,
                          double weight);

/// The phrase boundaries in use (0, inner..., last): the edited ones when they fit the
/// functional take (inside it, at least 2 frames apart), else the suggested ones.
std::vector<Eigen::Index> boundariesInUse(const FunctionAxis& function, const PhraseBoundaries& edits);
/// The warp in use: the edited curve when valid, else the identity over the functional frames.
WarpCurve warpInUse(const FunctionAxis& function, const DesignEdits& edits);
/// Unit gains over the boundaries in use with the edits applied (edits outside them ignored).
GainSet gainsInUse(const FunctionAxis& function, const DesignEdits& edits, const std::vector<std::string>& dofNames);
/// Thesis 5.5: the function's functional motion designed with the edits.
DesignedMotion designFunction(const FunctionAxis& function, const DesignEdits& edits);

} // namespace bunraku::analysis::pipeline
