#include "app/normalise_panel.h"

#include "app/commands.h"
#include "app/analysis_controller.h"

#include "analysis/normalise/coupling.h"
#include "analysis/pipeline/parameters_json.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace bunraku::app {

namespace {

namespace pl = analysis::pipeline;

/// The corpus cell of take A ("function/emotion"), empty when A is not a corpus take.
std::pair<std::string, std::string> cellOfTakeA(const Document& document)
{
    const QString id = document.selectedId(TakeSlot::A);
    const TakePointer take = document.take(id);
    if (!take || !id.startsWith(QStringLiteral("corpus/"))) return {};
    return {take->labels.function, take->labels.emotion};
}

QVariant referenceData(const pl::ReferenceChoice& choice)
{
    return QString::fromStdString(pl::referenceName(choice));
}

} // namespace

NormalisePanel::NormalisePanel(Document& document, AnalysisController& analysis, QWidget* parent)
    : QWidget(parent), m_document(document), m_analysis(analysis)
{
    m_reference = new QComboBox(this);
    m_reference->setObjectName("normaliseReference");
    m_tau = new QSpinBox(this);
    m_tau->setObjectName("normaliseTau");
    m_tau->setRange(0, 20);
    m_tau->setSuffix(tr(" frames"));
    m_band = new QSpinBox(this);
    m_band->setRange(1, 60);
    m_band->setSuffix(tr(" frames"));
    m_scales = new QSpinBox(this);
    m_scales->setRange(1, 32);
    m_coupling = new QComboBox(this);
    m_coupling->setEditable(true);
    for (const auto& name : analysis::couplingPresetNames()) m_coupling->addItem(QString::fromStdString(name));
    m_path = new QComboBox(this);
    m_path->addItem(tr("greedy (thesis)"), QStringLiteral("greedy"));
    m_path->addItem(tr("optimal (DP)"), QStringLiteral("optimal"));
    m_reference->setToolTip(tr("The take every take of the cell is normalised to"));
    m_tau->setToolTip(tr("tau: half window of the wavelet shape comparison (thesis 3.5.2: 4)"));
    m_band->setToolTip(tr("T_cmp: search band around the reference frame (thesis: 20)"));
    m_scales->setToolTip(tr("Largest wavelet scale (scales 1..max; thesis: 16)"));
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_table = new QTableWidget(this);
    m_table->setColumnCount(3);
    m_table->setHorizontalHeaderLabels({tr("Take"), tr("Before"), tr("After")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->verticalHeader()->setVisible(false);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_curves = new QCustomPlot(this);
    m_curves->setMinimumHeight(150);
    m_curves->xAxis->setLabel(tr("reference frame"));
    m_curves->yAxis->setLabel(tr("sample frame"));

    auto* form = new QFormLayout;
    form->addRow(tr("Reference"), m_reference);
    form->addRow(tr("tau"), m_tau);
    form->addRow(tr("T_cmp"), m_band);
    form->addRow(tr("Largest scale"), m_scales);
    form->addRow(tr("Coupling"), m_coupling);
    form->addRow(tr("Path"), m_path);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(form);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_curves, 1);

    // Every control edits the typed parameters through ChangeStageParameters; consecutive steps
    // of a spin box (arrows, keys, wheel) are one undo step until it loses the focus.
    auto edit = [this](const QString& control, const std::function<void(pl::NormaliseParameters&)>& change) {
        if (m_updating) return;
        changeStageParameters(
            m_document, [&](AnalysisParameters& p) { change(p.normalise); }, tr("Change normalisation %1").arg(control),
            QStringLiteral("normalise.") + control);
    };
    connect(m_reference, &QComboBox::currentIndexChanged, this, [this, edit] {
        const auto [function, emotion] = cellOfTakeA(m_document);
        if (function.empty()) return;
        const QString data = m_reference->currentData().toString();
        pl::ReferenceChoice choice;
        if (data == QStringLiteral("average")) choice.kind = pl::ReferenceKind::Average;
        else if (data != QStringLiteral("suggested")) choice = {pl::ReferenceKind::Take, data.toInt()};
        edit(QStringLiteral("reference"), [&](pl::NormaliseParameters& p) {
            if (choice == p.reference) p.cellReferences.erase(pl::cellName(function, emotion));
            else p.cellReferences[pl::cellName(function, emotion)] = choice;
        });
    });
    connect(m_tau, &QSpinBox::valueChanged, this, [edit](int value) { edit(QStringLiteral("tau"), [value](auto& p) { p.tau = value; }); });
    connect(m_band, &QSpinBox::valueChanged, this,
            [edit](int value) { edit(QStringLiteral("searchBand"), [value](auto& p) { p.searchBand = value; }); });
    connect(m_scales, &QSpinBox::valueChanged, this,
            [edit](int value) { edit(QStringLiteral("maxScale"), [value](auto& p) { p.maxScale = value; }); });
    for (QSpinBox* box : {m_tau, m_band, m_scales})
        connect(box, &QSpinBox::editingFinished, &document, &Document::endStepSeries);
    connect(m_coupling, &QComboBox::currentTextChanged, this, [this, edit](const QString& text) {
        const std::string spec = text.trimmed().toStdString();
        if (spec.empty() || spec.size() > 4096) return;
        edit(QStringLiteral("coupling"), [&](pl::NormaliseParameters& p) { p.coupling = spec; });
    });
    connect(m_path, &QComboBox::currentIndexChanged, this, [this, edit] {
        const bool optimal = m_path->currentData().toString() == QStringLiteral("optimal");
        edit(QStringLiteral("path"), [optimal](pl::NormaliseParameters& p) {
            p.path = optimal ? analysis::PathMethod::Optimal : analysis::PathMethod::Greedy;
        });
    });

    connect(&document, &Document::parametersChanged, this, [this](int sections) {
        if (sections & kNormaliseSection) refreshControls();
    });
    connect(&document, &Document::selectionChanged, this, [this](TakeSlot slot) {
        if (slot != TakeSlot::A || cellOfTakeA(m_document).first.empty()) return; // keep the cell while viewing derived takes
        refreshControls();
        showResult();
    });
    connect(&document, &Document::corpusChanged, this, &NormalisePanel::refreshControls);
    connect(&analysis, &AnalysisController::resultChanged, this, [this](int slot) {
        if (slot == AnalysisController::kNormaliseSlot) showResult();
    });
    connect(&analysis.scheduler(), &StageScheduler::stateChanged, this, [this](int slot) {
        if (slot == AnalysisController::kNormaliseSlot) showResult();
    });
    refreshControls();
}

NormalisePanel::~NormalisePanel() = default;

TakePointer NormalisePanel::normalisedTake() const
{
    return m_analysis.normalised() ? m_document.take(QStringLiteral("live/normalised")) : nullptr;
}

QString NormalisePanel::summaryText() const { return m_summary->text(); }

void NormalisePanel::refreshControls()
{
    m_updating = true;
    const auto [function, emotion] = cellOfTakeA(m_document);
    const pl::NormaliseParameters& parameters = m_document.parameters().normalise;
    if (!function.empty()) {
        m_reference->clear();
        m_reference->addItem(tr("suggested (thesis 3.6.1)"), QStringLiteral("suggested"));
        m_reference->addItem(tr("average take (thesis 3.7)"), QStringLiteral("average"));
        for (const analysis::Take* take : m_document.corpus().cell(function, emotion))
            m_reference->addItem(tr("take %1").arg(take->labels.takeIndex), QString::number(take->labels.takeIndex));
        m_reference->setCurrentIndex(std::max(0, m_reference->findData(referenceData(parameters.referenceFor(function, emotion)))));
    }
    m_tau->setValue(parameters.tau);
    m_band->setValue(parameters.searchBand);
    m_scales->setValue(parameters.maxScale);
    m_coupling->setCurrentText(QString::fromStdString(parameters.coupling));
    m_path->setCurrentIndex(std::max(0, m_path->findData(QString::fromStdString(pl::pathName(parameters.path)))));
    m_updating = false;
}

void NormalisePanel::showResult()
{
    const auto& scheduler = m_analysis.scheduler();
    const int slot = AnalysisController::kNormaliseSlot;
    if (scheduler.state(slot) == SlotState::Failed) {
        m_summary->setText(tr("<span style=\"color:#b00020\">Normalisation failed: %1</span>").arg(scheduler.error(slot).toHtmlEscaped()));
        return;
    }
    const auto output = m_analysis.normalised();
    const auto [function, emotion] = cellOfTakeA(m_document);
    const pl::CellNormalisation* cell = output && !function.empty() ? output->cell(function, emotion) : nullptr;
    if (!cell) {
        m_summary->setText(scheduler.state(slot) == SlotState::Running ? tr("Normalising every cell...") : QString());
        return;
    }
    const auto& variance = cell->variance;
    m_summary->setText(tr("Cell %1/%2 normalised to <b>%3</b>%4. Squared difference to the reference, summed over channels:")
                           .arg(QString::fromStdString(function), QString::fromStdString(emotion),
                                QString::fromStdString(cell->referenceName),
                                scheduler.state(slot) == SlotState::Running ? tr(" (recomputing)") : QString()));
    m_table->setRowCount(int(variance.takeNames.size()));
    for (int k = 0; k < int(variance.takeNames.size()); ++k) {
        m_table->setItem(k, 0, new QTableWidgetItem(QString::fromStdString(variance.takeNames[std::size_t(k)])));
        m_table->setItem(k, 1, new QTableWidgetItem(QString::number(variance.totalBefore[k], 'g', 4)));
        m_table->setItem(k, 2, new QTableWidgetItem(QString::number(variance.totalAfter[k], 'g', 4)));
    }
    m_curves->clearGraphs();
    const std::size_t count = cell->normalisations.size();
    for (std::size_t k = 0; k < count; ++k) {
        const auto& matches = cell->normalisations[k].matches;
        const Eigen::VectorXd warp = matches.empty() ? Eigen::VectorXd() : matches.front().smoothWarp;
        QVector<double> x(warp.size()), y(warp.size());
        for (Eigen::Index i = 0; i < warp.size(); ++i) {
            x[i] = double(i);
            y[i] = warp[i];
        }
        auto* graph = m_curves->addGraph();
        graph->setData(x, y, true);
        graph->setPen(QPen(QColor::fromHsv(int(k * 360 / std::max<std::size_t>(1, count)), 200, 200), 1.5));
    }
    m_curves->rescaleAxes();
    m_curves->replot();
}

} // namespace bunraku::app
