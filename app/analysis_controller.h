#pragma once
/// The workbench's side of the analysis pipeline (analysis/pipeline): the document's corpus and
/// typed parameters in, the stages' results out. Each stage runs as a job of the one
/// StageScheduler, keyed by its inputs and parameters, so a parameter change recomputes its
/// stage and those below it and nothing else (a changed tau: normalisation, decomposition and
/// motion axes; the emotion weight or a design edit: no stage at all). The cheap last steps -
/// the emotion weight (4.5) and the design (5.5, DesignController) - run on the GUI thread.
///
/// It is the only publisher of the analysis's live takes: "normalised" (take A on its cell's
/// reference time), "weighted" (y + a z of take A's cell), "axis" (take A's motion axis) and
/// "kimono" (the sleeve tips and hem of take A's kimono simulated as cloth, with the Cloth box on).
/// Views read them from the document and never write them. The motion axes of the shown takes
/// A and B (pipeline::runTakeAxis, keyed by each take's content and the axis parameters) are
/// scheduler jobs too: the 3D view draws them (takeAxis) and take A's is the "axis" take, one
/// computation per key for both.

#include "app/document.h"
#include "app/stage_scheduler.h"

#include "analysis/pipeline/chain.h"

#include <QObject>
#include <QStringList>

#include <filesystem>
#include <memory>
#include <string>

namespace bunraku::app {

class AnalysisController : public QObject {
    Q_OBJECT
public:
    /// Scheduler slots: the pipeline's stages, the motion axes of takes A and B, and the bodies of
    /// long live takes (backgroundBodyFrames). The .cpp gives each its result type (TypedSlot).
    enum Slot {
        kPreprocessSlot = 1,
        kNormaliseSlot = 2,
        kDecomposeSlot = 3,
        kAxesSlot = 5,
        kTakeAxisSlot = 10,
        kTakeAxisBSlot = 11,
        kNormalisedBodySlot = 12,
        kWeightedSlot = 13,
        kKimonoSlot = 14,
        kKimonoBSlot = 15
    };
    static int takeAxisSlot(TakeSlot slot) { return slot == TakeSlot::A ? kTakeAxisSlot : kTakeAxisBSlot; }
    static int kimonoSlot(TakeSlot slot) { return slot == TakeSlot::A ? kKimonoSlot : kKimonoBSlot; }
    static QString slotTitle(int slot);

    /// `executor` null: the thread pool (tests pass a manual one).
    explicit AnalysisController(Document& document, QObject* parent = nullptr, std::shared_ptr<Executor> executor = {});

    StageScheduler& scheduler() { return *m_scheduler; }
    const StageScheduler& scheduler() const { return *m_scheduler; }

    /// The latest results: the current inputs' once computed, until then the previous ones
    /// (null before the first). `isCurrent` says whether a slot's result matches the inputs.
    analysis::pipeline::Shared<analysis::pipeline::PreprocessOutput> preprocessed() const { return m_preprocessed; }
    analysis::pipeline::Shared<analysis::pipeline::NormaliseOutput> normalised() const { return m_normalised; }
    analysis::pipeline::Shared<analysis::pipeline::DecomposeOutput> decomposed() const { return m_decomposed; }
    analysis::pipeline::Shared<analysis::pipeline::AxisOutput> axes() const { return m_axes; }
    bool isCurrent(int slot) const;
    /// The motion axis of `take` shown in `slot`: null unless it is the take the slot's axis was
    /// asked for and that axis is computed for the current axis parameters (never another
    /// take's or older parameters').
    analysis::pipeline::Shared<analysis::pipeline::TakeAxis> takeAxis(TakeSlot slot, const TakePointer& take) const;
    /// The kimono as cloth (analysis/cloth) of the shown takes A and B: scheduler jobs keyed by
    /// each take's content, the body it is drawn with and the cloth parameters, run while
    /// `shown` (the 3D view's Cloth box), cleared when not.
    void setKimonoShown(bool shown);
    bool kimonoShown() const { return m_kimonoShown; }
    /// The cloth parameters (the 3D view's cloth settings); invalid ones are refused with the
    /// message of analysis::validate.
    analysis::Status setClothParameters(const analysis::ClothParameters& parameters);
    const analysis::ClothParameters& clothParameters() const { return m_clothParameters; }
    /// The kimono of `take` shown in `slot`: null unless it is the take the slot's kimono was
    /// asked for and it is simulated for the current cloth parameters.
    analysis::pipeline::Shared<analysis::KimonoSimulation> kimono(TakeSlot slot, const TakePointer& take) const;
    /// The body the 3D view draws a take with (and its kimono is simulated on): the puppet,
    /// fitted to the take's skeleton when it has one.
    static analysis::BodyDescription viewBody(const analysis::Take& take);

    /// The keys of every stage for the document's corpus and parameters.
    analysis::pipeline::ChainKeys keys() const { return m_keys; }

    /// Live takes longer than this many frames (default 20,000: 11 min at 30 Hz) are made off the
    /// GUI thread, with progress: the weighted take (y + a z and its body) and the normalised
    /// take's body (analysis::bodyMotion). Shorter ones are made at once, so that a weight drag
    /// shows its result in the same event. Tests set 0 to see the background path.
    void setBackgroundBodyFrames(qint64 frames) { m_backgroundBodyFrames = frames; }
    qint64 backgroundBodyFrames() const { return m_backgroundBodyFrames; }

    /// The normalise parameters the current normalise result was computed with.
    const analysis::pipeline::NormaliseParameters& normalisedParameters() const { return m_normalisedParameters; }
    /// "tau 4, T_cmp 20, scales 1-16, optimal path" (and the coupling when not the default): what
    /// a normalised take's label and the panel name.
    static QString normaliseParametersText(const analysis::pipeline::NormaliseParameters& parameters);
    /// "least squares" / "KM2O, M = 2 (chosen by P)": the method of a decomposition.
    static QString decompositionText(const analysis::pipeline::DecomposeOutput& decomposed);

    /// The cell the panels show: take A's when it is a corpus take, else the last one.
    const std::string& cellFunction() const { return m_function; }
    const std::string& cellEmotion() const { return m_emotion; }
    /// The cell weighted by the emotion weight: take A's, or when take A is neutral (z = 0
    /// there) its function's cell of the chosen emotion (setWeightEmotion), else of its first
    /// emotion.
    std::pair<std::string, std::string> weightedCell() const;
    /// The emotion a neutral take A is weighted against (empty: its function's first); view
    /// state, kept in projects. Re-synthesises the weighted take.
    void setWeightEmotion(const QString& emotion);
    QString weightEmotion() const { return QString::fromStdString(m_weightEmotion); }
    /// The emotions of take A's function that have an emotion component, in corpus order.
    QStringList weightableEmotions() const;
    /// y + a z of weightedCell(), null before a decomposition.
    TakePointer weightedTake() const { return m_weighted; }
    QString weightError() const { return m_weightError; }

    /// Every stage (spectra and ARMA too) for the document's corpus and parameters, through
    /// the caches the jobs filled, then the HTML report (analysis/report). On the GUI thread.
    analysis::Result<std::string> reportHtml() const;
    analysis::Status exportReport(const std::filesystem::path& file) const;

signals:
    /// A stage's result changed (Slot).
    void resultChanged(int slot);
    /// The weighted take was re-synthesised.
    void weightedChanged();
    /// The cloth parameters changed (the 3D view's Cloth Settings, a project): what a kimono
    /// export simulates with too.
    void clothParametersChanged(const analysis::ClothParameters& parameters);

private:
    void corpusChanged();
    void update();
    void stageFinished(int slot);
    void resolveCell();
    void publishNormalised();
    void synthesiseWeighted();
    void requestTakeAxis(TakeSlot slot);
    void requestKimono(TakeSlot slot);
    /// Publishes take A's computed motion axis as the "axis" live take.
    void publishAxis();
    /// Publishes take A's simulated kimono's measured points as the "kimono" live take (its 18
    /// channels, graphable beside take A); removes it when the Cloth box is off.
    void publishKimono();

    Document& m_document;
    /// The one cache: the scheduler's jobs' and the report's (runChain) stages, and the other
    /// slots' results.
    std::shared_ptr<analysis::pipeline::StageCache> m_stageCache;
    StageScheduler* m_scheduler = nullptr;
    analysis::pipeline::CorpusInput m_corpus;
    analysis::pipeline::ChainKeys m_keys;
    analysis::pipeline::Shared<analysis::pipeline::PreprocessOutput> m_preprocessed;
    analysis::pipeline::Shared<analysis::pipeline::NormaliseOutput> m_normalised;
    analysis::pipeline::Shared<analysis::pipeline::DecomposeOutput> m_decomposed;
    analysis::pipeline::Shared<analysis::pipeline::AxisOutput> m_axes;
    std::string m_function;
    std::string m_emotion;
    std::string m_weightEmotion;
    bool m_publishing = false; ///< inside publishNormalised
    analysis::pipeline::NormaliseParameters m_normalisedParameters;
    TakePointer m_weighted;
    QString m_weightError;
    qint64 m_backgroundBodyFrames = 20000;
    /// Labels (and the normalised take's ghost) of the live takes made in the background,
    /// published with them when their job finishes.
    QString m_pendingWeightedLabel;
    QString m_pendingNormalisedLabel;
    TakeId m_pendingNormalisedGhost;
    TakePointer m_kimonoTakes[2]; ///< the takes the kimono slots were last asked for
    bool m_kimonoShown = false;
    analysis::ClothParameters m_clothParameters;
    TakePointer m_axisTakes[2]; ///< the takes the axis slots were last asked for
    QString m_axisLabels[2];    ///< and their labels then (what the "axis" take's label names)
};

} // namespace bunraku::app
