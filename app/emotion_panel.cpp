#include "app/emotion_panel.h"

#include "app/commands.h"
#include "app/parameters.h"
#include "app/recomputer.h"

#include "analysis/decompose/emotion_weight.h"
#include "analysis/decompose/km2o_decomposition.h"
#include "analysis/decompose/least_squares.h"
#include "analysis/preprocess/preprocess.h"

#include <QComboBox>
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

struct EmotionModel {
    analysis::Decomposition decomposition;
    QString method; ///< "least-squares" | "km2o"
    int order = 0;  ///< M (KM2O), 0 for least squares
};

namespace {
constexpr double kSliderScale = 100.0; // slider position = a * 100
const QString kKm2o = QStringLiteral("km2o");
} // namespace

EmotionPanel::EmotionPanel(Document& document, QWidget* parent) : QWidget(parent), m_document(document)
{
    m_method = new QComboBox(this);
    m_method->addItem(tr("least squares (thesis 4.3.1)"), QStringLiteral("least-squares"));
    m_method->addItem(tr("KM2O-Langevin (thesis 4.4.4)"), kKm2o);
    m_method->setObjectName("emotionMethod");
    m_method->setToolTip(tr("Decomposition of the preprocessed corpus into function and emotion components"));
    m_order = new QSpinBox(this);
    m_order->setObjectName("emotionOrder");
    m_order->setRange(1, 64);
    m_order->setToolTip(tr("KM2O correlation length M (thesis 4.4.4 found M = 2); must not exceed "
                           "M_max = floor(3 sqrt(T + 1)) - 1 for T frames"));
    m_weight = new QSlider(Qt::Horizontal, this);
    m_weight->setObjectName("emotionWeight");
    m_weight->setRange(int(analysis::kMinEmotionWeight * kSliderScale), int(analysis::kMaxEmotionWeight * kSliderScale));
    m_weight->setValue(int(kSliderScale));
    m_weight->setToolTip(tr("a = 0: the function alone; 1: the measured emotion; > 1: emphasised (thesis eq. 4.45)"));
    m_label = new QLabel(tr("Decomposing the corpus..."), this);
    m_label->setWordWrap(true);
    auto* show = new QPushButton(tr("Show weighted as A"), this);
    auto* form = new QFormLayout;
    form->addRow(tr("Method"), m_method);
    form->addRow(tr("Correlation length M"), m_order);
    form->addRow(tr("Emotion weight a"), m_weight);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(form);
    layout->addWidget(m_label);
    layout->addWidget(show);
    layout->addStretch(1);

    connect(m_weight, &QSlider::sliderPressed, &document, &Document::beginInteraction);
    connect(m_weight, &QSlider::sliderReleased, &document, &Document::endInteraction);
    // A drag is one interaction; keyboard and wheel steps of the slider merge as steps.
    connect(m_weight, &QSlider::valueChanged, this, [this](int position) {
        stepParameter(m_document, parameters::kEmotionWeight, position / kSliderScale, tr("Set emotion weight"));
    });
    connect(m_method, &QComboBox::currentIndexChanged, this, [this](int index) {
        changeParameter(m_document, parameters::kEmotionMethod, m_method->itemData(index), tr("Set decomposition method"));
    });
    // Consecutive steps of M (arrows, keys, wheel) are one undo step until the box loses the focus.
    connect(m_order, &QSpinBox::valueChanged, this, [this](int order) {
        stepParameter(m_document, parameters::kEmotionOrder, order, tr("Set correlation length M"));
    });
    connect(m_order, &QSpinBox::editingFinished, &document, &Document::endStepSeries);
    connect(show, &QPushButton::clicked, this, [this] { m_document.selectTake(TakeSlot::A, QStringLiteral("live/weighted")); });

    m_recomputer = new Recomputer(
        document,
        [this]() -> Job {
            if (m_document.corpus().takes.empty()) return {};
            auto corpus = std::make_shared<const analysis::Corpus>(m_document.corpus());
            const bool km2o = m_document.parameter(parameters::kEmotionMethod).toString() == kKm2o;
            const int order = m_document.parameter(parameters::kEmotionOrder).toInt();
            return [corpus, km2o, order](const analysis::RunControl& control) -> JobOutput {
                auto prepared = analysis::preprocess::preprocessCorpus(*corpus, {}, control);
                if (!prepared) return {{}, QString::fromStdString(prepared.error().message)};
                if (control.cancelled()) return {{}, QStringLiteral("cancelled")};
                if (km2o) {
                    analysis::Km2oDecompositionOptions options;
                    options.correlationLength = order; // the given M: no search over candidates
                    auto decomposition = analysis::decomposeKm2o(prepared->corpus, options, control);
                    if (!decomposition) return {{}, QString::fromStdString(decomposition.error().message)};
                    return {std::make_shared<const EmotionModel>(EmotionModel{
                                std::move(decomposition->components), kKm2o, decomposition->correlationLength}),
                            {}};
                }
                auto decomposition = analysis::decomposeLeastSquares(prepared->corpus);
                if (!decomposition) return {{}, QString::fromStdString(decomposition.error().message)};
                return {std::make_shared<const EmotionModel>(
                            EmotionModel{std::move(decomposition).value(), QStringLiteral("least-squares"), 0}),
                        {}};
            };
        },
        [this](const JobOutput& output) {
            if (!output.value.has_value()) {
                m_label->setText(tr("The corpus cannot be decomposed: %1").arg(output.error));
                return;
            }
            m_model = std::any_cast<std::shared_ptr<const EmotionModel>>(output.value);
            resolveCell();
            synthesise();
        },
        this, 50, [this] { return m_inputSerial; });
    m_recomputer->setObjectName(tr("Decomposition"));
    showParameters();

    connect(&document, &Document::corpusChanged, this, [this] {
        m_model.reset();
        ++m_inputSerial;
        m_recomputer->schedule();
    });
    connect(&document, &Document::selectionChanged, this, [this](TakeSlot slot) {
        if (slot == TakeSlot::A && m_document.selectedId(TakeSlot::A).startsWith(QStringLiteral("corpus/"))) {
            resolveCell();
            synthesise();
        }
    });
    connect(&document, &Document::parameterChanged, this, [this](const QString& key) {
        if (key == parameters::kEmotionMethod || key == parameters::kEmotionOrder) {
            showParameters();
            const bool km2o = m_document.parameter(parameters::kEmotionMethod).toString() == kKm2o;
            if (key == parameters::kEmotionOrder && !km2o) return; // M only matters for KM2O
            ++m_inputSerial;
            m_label->setText(tr("Decomposing the corpus..."));
            m_recomputer->schedule();
            return;
        }
        if (key != parameters::kEmotionWeight) return;
        const QSignalBlocker block(m_weight);
        if (!m_weight->isSliderDown())
            m_weight->setValue(int(std::lround(m_document.parameter(key).toDouble() * kSliderScale)));
        synthesise();
    });
}

EmotionPanel::~EmotionPanel() = default;

QString EmotionPanel::decomposedMethod() const { return m_model ? m_model->method : QString(); }

int EmotionPanel::decomposedOrder() const { return m_model ? m_model->order : 0; }

void EmotionPanel::showParameters()
{
    const QSignalBlocker blockMethod(m_method);
    const QSignalBlocker blockOrder(m_order);
    const QString method = m_document.parameter(parameters::kEmotionMethod).toString();
    m_method->setCurrentIndex(std::max(0, m_method->findData(method)));
    m_order->setValue(m_document.parameter(parameters::kEmotionOrder).toInt());
    m_order->setEnabled(method == kKm2o);
}

void EmotionPanel::resolveCell()
{
    if (!m_model) return;
    const auto& decomposition = m_model->decomposition;
    const auto known = [&](const std::string& function) {
        return std::any_of(decomposition.emotions.begin(), decomposition.emotions.end(),
                           [&](const auto& component) { return component.function == function; });
    };
    const TakePointer takeA = m_document.selectedTake(TakeSlot::A);
    if (takeA && m_document.selectedId(TakeSlot::A).startsWith(QStringLiteral("corpus/"))) {
        m_function = takeA->labels.function;
        m_emotion = takeA->labels.emotion;
    } else if (m_function.empty() || !known(m_function)) {
        // A shows a derived take (a project may reopen on one before the decomposition is
        // done): keep weighting the current cell, or start from the corpus's first function.
        if (decomposition.emotions.empty()) return;
        m_function = decomposition.emotions.front().function;
        m_emotion = decomposition.neutralEmotion;
    } else {
        return;
    }
    if (m_emotion == decomposition.neutralEmotion) {
        // The neutral emotion has z = 0: weight the first other emotion of the function instead.
        for (const auto& component : decomposition.emotions)
            if (component.function == m_function && component.emotion != decomposition.neutralEmotion) {
                m_emotion = component.emotion;
                break;
            }
    }
}

void EmotionPanel::synthesise()
{
    if (!m_model || m_function.empty()) return;
    const double weight = m_document.parameter(parameters::kEmotionWeight).toDouble();
    auto take = analysis::weightEmotion(m_model->decomposition, m_function, m_emotion, weight);
    if (!take) {
        m_label->setText(QString::fromStdString(take.error().message));
        return;
    }
    m_weighted = std::make_shared<const analysis::Take>(std::move(take).value());
    const QString label = tr("%1/%2 a=%3").arg(QString::fromStdString(m_function), QString::fromStdString(m_emotion)).arg(weight, 0, 'f', 2);
    const QString method = m_model->method == kKm2o ? tr("KM2O, M = %1").arg(m_model->order) : tr("least squares");
    m_label->setText(tr("Weighted take <b>%1</b>: x = y + a z, a = %2, components by %3 (the live take \"weighted\").")
                         .arg(label)
                         .arg(weight, 0, 'f', 2)
                         .arg(method));
    m_document.setLiveTake(QStringLiteral("weighted"), label, m_weighted);
}

} // namespace bunraku::app
