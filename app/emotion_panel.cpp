#include "app/emotion_panel.h"

#include "analysis/pipeline/stage_parameters.h"

#include "app/analysis_scope_notice.h"
#include "app/focus_return.h"

#include "app/analysis_controller.h"
#include "app/commands.h"

#include "widgets/bounded_spin_box.h"

#include "analysis/decompose/emotion_weight.h"
#include "analysis/pipeline/parameters_json.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace bunraku::app {
namespace {
namespace pl = analysis::pipeline;
constexpr double kSliderScale = 100.0; // slider position = a * 100
} // namespace

EmotionPanel::EmotionPanel(Document& document, AnalysisController& analysis, QWidget* parent)
    : QWidget(parent), m_document(document), m_analysis(analysis)
{
    m_input = new QComboBox(this);
    m_input->setObjectName("emotionInput");
    m_input->addItem(tr("normalised takes (thesis 4.1)"), QStringLiteral("normalised"));
    m_input->addItem(tr("preprocessed takes"), QStringLiteral("preprocessed"));
    m_method = new QComboBox(this);
    m_method->addItem(tr("KM2O-Langevin (thesis 4.4.4)"), QStringLiteral("km2o"));
    m_method->addItem(tr("least squares (thesis 4.3.1)"), QStringLiteral("least-squares"));
    m_method->setObjectName("emotionMethod");
    m_method->setToolTip(tr("Decomposition of the corpus into function and emotion components"));
    m_order = new widgets::BoundedSpinBox(this);
    m_order->setObjectName("emotionOrder");
    // At most M_max of the corpus's shortest take, the largest M KM2O accepts (showParameters).
    m_order->setRange(0, pl::usableCorrelationLength(m_document.corpus()));
    m_order->setSpecialValueText(tr("chosen by P (4.4.4)"));
    m_order->setDescription(tr("KM2O correlation length M; 0 chooses it by the relative error P over 1..M_max as thesis "
                               "4.4.4 (which found M = 2); must not exceed M_max = floor(3 sqrt(T + 1)) - 1 for T frames."));
    m_emotion = new QComboBox(this);
    m_emotion->setObjectName("emotionChoice");
    m_emotion->setToolTip(tr("The emotion z a neutral take is weighted against (x = y + a z); an emotional take A is "
                             "weighted with its own emotion"));
    m_weight = new QSlider(Qt::Horizontal, this);
    m_weight->setObjectName("emotionWeight");
    m_weight->setRange(int(analysis::kMinEmotionWeight * kSliderScale), int(analysis::kMaxEmotionWeight * kSliderScale));
    m_weight->setValue(int(kSliderScale));
    m_weight->setToolTip(tr("a = 0: the function alone; 1: the measured emotion; > 1: emphasised (thesis eq. 4.45). "
                            "From %1 to %2.")
                             .arg(analysis::kMinEmotionWeight, 0, 'f', 2)
                             .arg(analysis::kMaxEmotionWeight, 0, 'f', 2));
    m_weightBox = new QDoubleSpinBox(this);
    m_weightBox->setObjectName("emotionWeightValue");
    m_weightBox->setRange(analysis::kMinEmotionWeight, analysis::kMaxEmotionWeight);
    m_weightBox->setDecimals(2);
    m_weightBox->setSingleStep(0.05);
    m_weightBox->setValue(1.0);
    m_weightBox->setKeyboardTracking(false); // a typed value applies on Enter: "2.5" never applies 2 on the way
    m_weightBox->setToolTip(m_weight->toolTip());
    m_label = new QLabel(tr("Decomposing the corpus..."), this);
    m_label->setObjectName("emotionSummary");
    m_label->setWordWrap(true);
    auto* show = new QPushButton(tr("Show weighted as A"), this);
    auto* form = new QFormLayout;
    form->addRow(tr("Input"), m_input);
    form->addRow(tr("Method"), m_method);
    form->addRow(tr("Correlation length M"), m_order);
    form->addRow(tr("Emotion z of"), m_emotion);
    auto* weightRow = new QHBoxLayout;
    weightRow->addWidget(m_weight, 1);
    weightRow->addWidget(m_weightBox);
    form->addRow(tr("Emotion weight a"), weightRow);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(new AnalysisScopeNotice(m_document, this));
    layout->addLayout(form);
    layout->addWidget(m_label);
    layout->addWidget(show);
    layout->addStretch(1);

    connect(m_weight, &QSlider::sliderPressed, &document, &Document::beginInteraction);
    connect(m_weight, &QSlider::sliderReleased, &document, &Document::endInteraction);
    // A drag is one interaction; keyboard and wheel steps of the slider merge as steps.
    connect(m_weight, &QSlider::valueChanged, this, [this](int position) { setEmotionWeight(m_document, position / kSliderScale); });
    // The spin box's steps merge as the slider's and M's do, until it loses the focus.
    connect(m_weightBox, &QDoubleSpinBox::valueChanged, this, [this](double weight) { setEmotionWeight(m_document, weight); });
    endSeriesWhenEdited(m_weightBox, [this] { m_document.endStepSeries(); });
    connect(m_input, &QComboBox::currentIndexChanged, this, [this](int index) {
        const bool normalised = m_input->itemData(index).toString() == QStringLiteral("normalised");
        changeStageParameters(
            m_document,
            [normalised](AnalysisParameters& p) {
                p.decompose.input = normalised ? pl::DecomposeInput::Normalised : pl::DecomposeInput::Preprocessed;
            },
            tr("Set the decomposition input to %1").arg(m_input->itemText(index)));
    });
    connect(m_method, &QComboBox::currentIndexChanged, this, [this](int index) {
        const bool km2o = m_method->itemData(index).toString() == QStringLiteral("km2o");
        changeStageParameters(
            m_document,
            [km2o](AnalysisParameters& p) { p.decompose.method = km2o ? pl::DecomposeMethod::Km2o : pl::DecomposeMethod::LeastSquares; },
            tr("Set the decomposition method to %1").arg(m_method->itemText(index)));
    });
    // Consecutive steps of M (arrows, keys, wheel) are one undo step until the box loses the focus.
    connect(m_order, &QSpinBox::valueChanged, this, [this](int order) {
        changeStageParameters(
            m_document, [order](AnalysisParameters& p) { p.decompose.correlationLength = order; },
            order == 0 ? tr("Set the correlation length M to chosen by P") : tr("Set the correlation length M to %1").arg(order),
            QStringLiteral("decompose.M"));
    });
    endSeriesWhenEdited(m_order, [this] { m_document.endStepSeries(); });
    connect(m_order, &widgets::BoundedSpinBox::clamped, this, [this](int requested, int applied) {
        emit statusMessage(tr("M %1 is %2 the limit: set to %3 (%4)")
                               .arg(requested)
                               .arg(requested > applied ? tr("above") : tr("below"))
                               .arg(applied)
                               .arg(m_order->limitsText()));
    });
    connect(m_emotion, &QComboBox::activated, this, [this](int index) {
        m_analysis.setWeightEmotion(m_emotion->itemData(index).toString());
    });
    connect(show, &QPushButton::clicked, this, [this] { m_document.selectTake(TakeSlot::A, TakeId::live(QStringLiteral("weighted"))); });

    connect(&document, &Document::parametersChanged, this, [this](ParameterSections sections) {
        if (sections & (kDecomposeSection | kWeightSection)) showParameters();
    });
    // Another corpus: its parameters (the defaults) and no result until it is decomposed.
    connect(&document, &Document::corpusChanged, this, [this] {
        showParameters();
        showResult();
    });
    connect(&analysis, &AnalysisController::weightedChanged, this, &EmotionPanel::showResult);
    connect(&analysis.scheduler(), &StageScheduler::stateChanged, this, [this](int slot) {
        if (slot == AnalysisController::kDecomposeSlot) showResult();
    });
    showParameters();
}

bool EmotionPanel::ready() const { return m_analysis.decomposed() != nullptr; }

TakePointer EmotionPanel::weightedTake() const { return m_analysis.weightedTake(); }

QString EmotionPanel::statusText() const { return m_label->text(); }

QString EmotionPanel::decomposedMethod() const
{
    const auto decomposed = m_analysis.decomposed();
    return decomposed ? QString::fromStdString(pl::methodName(decomposed->parameters.method)) : QString();
}

int EmotionPanel::decomposedOrder() const
{
    const auto decomposed = m_analysis.decomposed();
    return decomposed && decomposed->km2o ? decomposed->km2o->correlationLength : 0;
}

void EmotionPanel::showParameters()
{
    const QSignalBlocker blockInput(m_input);
    const QSignalBlocker blockMethod(m_method);
    const QSignalBlocker blockOrder(m_order);
    const pl::DecomposeParameters& p = m_document.parameters().decompose;
    m_input->setCurrentIndex(std::max(0, m_input->findData(QString::fromStdString(pl::inputName(p.input)))));
    m_method->setCurrentIndex(std::max(0, m_method->findData(QString::fromStdString(pl::methodName(p.method)))));
    m_order->setLimits(0, pl::usableCorrelationLength(m_document.corpus()));
    m_order->setValue(p.correlationLength);
    m_order->setEnabled(p.method == pl::DecomposeMethod::Km2o);
    const QSignalBlocker blockWeight(m_weight);
    const QSignalBlocker blockWeightBox(m_weightBox);
    const double weight = m_document.parameters().design.emotionWeight;
    if (!m_weight->isSliderDown()) m_weight->setValue(int(std::lround(weight * kSliderScale)));
    m_weightBox->setValue(weight);
}

void EmotionPanel::showResult()
{
    const auto& scheduler = m_analysis.scheduler();
    const int slot = AnalysisController::kDecomposeSlot;
    if (scheduler.state(slot) == SlotState::Failed) {
        m_label->setText(tr("<span style=\"color:#b00020\">The corpus cannot be decomposed: %1</span>").arg(scheduler.error(slot).toHtmlEscaped()));
        return;
    }
    if (!m_analysis.weightError().isEmpty()) {
        m_label->setText(m_analysis.weightError().toHtmlEscaped());
        return;
    }
    const auto decomposed = m_analysis.decomposed();
    const TakePointer weighted = m_analysis.weightedTake();
    showEmotions();
    if (!decomposed || !weighted) {
        m_label->setText(tr("Decomposing the corpus..."));
        return;
    }
    const auto [function, emotion] = m_analysis.weightedCell();
    const double weight = m_document.parameters().design.emotionWeight;
    QString method = AnalysisController::decompositionText(*decomposed);
    if (decomposed->km2o && decomposed->km2o->estimable())
        method += tr(", mean P = %1 %").arg(decomposed->km2o->meanCellErrorPercent, 0, 'f', 2);
    m_label->setText(tr("Weighted take <b>%1/%2</b>: x = y + a z, a = %3, components by %4 of the %5 takes%6 (the live take "
                        "\"weighted\").")
                         .arg(QString::fromStdString(function), QString::fromStdString(emotion))
                         .arg(weight, 0, 'f', 2)
                         .arg(method.toHtmlEscaped(), QString::fromStdString(pl::inputName(decomposed->parameters.input)),
                              scheduler.state(slot) == SlotState::Running ? tr("; recomputing") : QString()) +
                     oneTakeNotes(*decomposed));
}

QString EmotionPanel::oneTakeNotes(const pl::DecomposeOutput& decomposed)
{
    // What KM2O did with cells of one take (docs/KM2O.md), the first few; the report lists all.
    if (!decomposed.km2o || decomposed.km2o->notes.empty()) return {};
    constexpr std::size_t kShown = 6;
    const auto& notes = decomposed.km2o->notes;
    QString text = QStringLiteral("<ul style=\"margin:0\">");
    for (std::size_t i = 0; i < std::min(notes.size(), kShown); ++i)
        text += QStringLiteral("<li>") + QString::fromStdString(notes[i]).toHtmlEscaped() + QStringLiteral("</li>");
    if (notes.size() > kShown) text += QStringLiteral("<li>") + tr("and %1 more (the report lists every cell)").arg(notes.size() - kShown) + QStringLiteral("</li>");
    return text + QStringLiteral("</ul>");
}

void EmotionPanel::showEmotions()
{
    const QSignalBlocker block(m_emotion);
    m_emotion->clear();
    for (const QString& emotion : m_analysis.weightableEmotions()) m_emotion->addItem(emotion, emotion);
    const QString weighted = QString::fromStdString(m_analysis.weightedCell().second);
    m_emotion->setCurrentIndex(std::max(0, m_emotion->findData(weighted)));
    // Only a neutral take A has an emotion to choose: an emotional one is weighted with its own.
    m_emotion->setEnabled(m_analysis.cellEmotion() == m_document.corpus().neutralEmotion && m_emotion->count() > 0);
}

} // namespace bunraku::app
