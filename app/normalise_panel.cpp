#include "app/normalise_panel.h"

#include "app/commands.h"
#include "app/parameters.h"
#include "app/recomputer.h"

#include "analysis/normalise/coupling.h"
#include "analysis/normalise/take_normalisation.h"
#include "analysis/normalise/variance_evaluation.h"

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

/// One normalisation result: the cell normalised to its reference.
struct NormaliseOutput {
    QStringList takeIds;            ///< the cell's takes
    QString referenceId;
    QString sampleId;               ///< take A
    TakePointer normalisedSample;   ///< take A normalised
    analysis::VarianceTable variance;
    std::vector<Eigen::VectorXd> warps; ///< per take: reference frame -> sample frame (first coupling set)
};

namespace {

struct CellTakes {
    QStringList ids;
    std::vector<TakePointer> takes;
};

CellTakes cellOf(const Document& document, const analysis::Take& take)
{
    CellTakes cell;
    const auto& corpus = document.corpus();
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        const auto& labels = corpus.takes[i].labels;
        if (labels.function == take.labels.function && labels.emotion == take.labels.emotion) {
            cell.ids << Document::corpusTakeId(i);
            cell.takes.push_back(document.take(Document::corpusTakeId(i)));
        }
    }
    return cell;
}

} // namespace

NormalisePanel::NormalisePanel(Document& document, QWidget* parent) : QWidget(parent), m_document(document)
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

    auto push = [this](const QString& key, const QVariant& value) {
        if (!m_updating) changeParameter(m_document, key, value);
    };
    connect(m_reference, &QComboBox::currentIndexChanged, this,
            [this, push] { push(parameters::kNormaliseReference, m_reference->currentData().toString()); });
    // Consecutive steps of a spin box (arrows, keys, wheel) are one undo step until it loses the focus.
    auto step = [this](const QString& key, const QVariant& value) {
        if (!m_updating) stepParameter(m_document, key, value);
    };
    connect(m_tau, &QSpinBox::valueChanged, this, [step](int value) { step(parameters::kNormaliseTau, value); });
    connect(m_band, &QSpinBox::valueChanged, this, [step](int value) { step(parameters::kNormaliseSearchBand, value); });
    connect(m_scales, &QSpinBox::valueChanged, this, [step](int value) { step(parameters::kNormaliseMaxScale, value); });
    for (QSpinBox* box : {m_tau, m_band, m_scales})
        connect(box, &QSpinBox::editingFinished, &document, &Document::endStepSeries);
    connect(m_coupling, &QComboBox::currentTextChanged, this,
            [push](const QString& text) { push(parameters::kNormaliseCoupling, text); });
    connect(m_path, &QComboBox::currentIndexChanged, this,
            [this, push] { push(parameters::kNormalisePath, m_path->currentData().toString()); });

    m_recomputer = new Recomputer(
        document,
        [this]() -> Job {
            const QString sampleId = m_document.selectedId(TakeSlot::A);
            const TakePointer sample = m_document.take(sampleId);
            if (!sample || !sampleId.startsWith(QStringLiteral("corpus/"))) return {};
            const CellTakes cell = cellOf(m_document, *sample);
            QString referenceId = m_document.parameter(parameters::kNormaliseReference).toString();
            if (!cell.ids.contains(referenceId)) referenceId.clear(); // suggested
            analysis::NormaliseOptions options;
            options.match.tau = m_document.parameter(parameters::kNormaliseTau).toInt();
            options.match.searchBand = m_document.parameter(parameters::kNormaliseSearchBand).toInt();
            options.match.scales = analysis::integerScales(m_document.parameter(parameters::kNormaliseMaxScale).toInt());
            options.match.path = m_document.parameter(parameters::kNormalisePath).toString() == QStringLiteral("optimal")
                                     ? analysis::PathMethod::Optimal
                                     : analysis::PathMethod::Greedy;
            options.coupling = m_document.parameter(parameters::kNormaliseCoupling).toString().toStdString();
            return [cell, sampleId, referenceId, options](const analysis::RunControl& control) -> JobOutput {
                std::vector<const analysis::Take*> takes;
                for (const auto& take : cell.takes) takes.push_back(take.get());
                int referenceIndex = int(cell.ids.indexOf(referenceId));
                if (referenceIndex < 0) {
                    auto suggestion = analysis::suggestReference(takes, control);
                    if (!suggestion) return {{}, QString::fromStdString(suggestion.error().message)};
                    referenceIndex = suggestion->takeIndex;
                }
                const analysis::Take& reference = *takes[std::size_t(referenceIndex)];
                auto normalised = analysis::normaliseTakes(reference, takes, options, control);
                if (!normalised) return {{}, QString::fromStdString(normalised.error().message)};
                std::vector<const analysis::Take*> results;
                for (const auto& n : *normalised) results.push_back(&n.normalised);
                auto variance = analysis::varianceTable(reference, takes, results);
                if (!variance) return {{}, QString::fromStdString(variance.error().message)};
                auto output = std::make_shared<NormaliseOutput>();
                output->takeIds = cell.ids;
                output->referenceId = cell.ids[referenceIndex];
                output->sampleId = sampleId;
                output->variance = std::move(variance).value();
                for (std::size_t k = 0; k < normalised->size(); ++k) {
                    const auto& matches = (*normalised)[k].matches;
                    output->warps.push_back(matches.empty() ? Eigen::VectorXd() : matches.front().smoothWarp);
                    if (cell.ids[int(k)] == sampleId) {
                        auto take = (*normalised)[k].normalised;
                        take.labels.source = "normalised to " + reference.displayName();
                        output->normalisedSample = std::make_shared<const analysis::Take>(std::move(take));
                    }
                }
                return {std::shared_ptr<const NormaliseOutput>(std::move(output)), {}};
            };
        },
        [this](const JobOutput& output) {
            if (output.value.has_value()) accept(std::any_cast<std::shared_ptr<const NormaliseOutput>>(output.value));
            else m_summary->setText(tr("Normalisation failed: %1").arg(output.error));
        },
        this, 80);
    m_recomputer->setObjectName(tr("Normalisation"));

    connect(&document, &Document::parameterChanged, this, [this](const QString& key) {
        if (!key.startsWith(QStringLiteral("normalise."))) return;
        refreshControls();
        m_recomputer->schedule();
    });
    connect(&document, &Document::selectionChanged, this, [this](TakeSlot slot) {
        if (slot != TakeSlot::A) return;
        const QString id = m_document.selectedId(TakeSlot::A);
        if (!id.startsWith(QStringLiteral("corpus/"))) return; // keep the result while viewing derived takes
        refreshControls();
        m_recomputer->schedule();
    });
    connect(&document, &Document::corpusChanged, this, [this] {
        m_output.reset();
        refreshControls();
    });
    refreshControls();
}

NormalisePanel::~NormalisePanel() = default;

TakePointer NormalisePanel::normalisedTake() const { return m_output ? m_output->normalisedSample : nullptr; }

void NormalisePanel::refreshControls()
{
    m_updating = true;
    const TakePointer takeA = m_document.selectedTake(TakeSlot::A);
    if (takeA && m_document.selectedId(TakeSlot::A).startsWith(QStringLiteral("corpus/"))) {
        const CellTakes cell = cellOf(m_document, *takeA);
        m_reference->clear();
        m_reference->addItem(tr("suggested (thesis 3.6.1)"), QString());
        for (int i = 0; i < cell.ids.size(); ++i) m_reference->addItem(m_document.takeLabel(cell.ids[i]), cell.ids[i]);
        const int index = m_reference->findData(m_document.parameter(parameters::kNormaliseReference).toString());
        m_reference->setCurrentIndex(std::max(0, index));
    }
    m_tau->setValue(m_document.parameter(parameters::kNormaliseTau).toInt());
    m_band->setValue(m_document.parameter(parameters::kNormaliseSearchBand).toInt());
    m_scales->setValue(m_document.parameter(parameters::kNormaliseMaxScale).toInt());
    m_coupling->setCurrentText(m_document.parameter(parameters::kNormaliseCoupling).toString());
    m_path->setCurrentIndex(std::max(0, m_path->findData(m_document.parameter(parameters::kNormalisePath))));
    m_updating = false;
}

void NormalisePanel::accept(std::shared_ptr<const NormaliseOutput> output)
{
    m_output = std::move(output);
    const auto& variance = m_output->variance;
    m_summary->setText(tr("Cell of %1 normalised to <b>%2</b>. Squared difference to the reference, summed over channels:")
                           .arg(m_document.takeLabel(m_output->sampleId), m_document.takeLabel(m_output->referenceId)));
    m_table->setRowCount(int(variance.takeNames.size()));
    for (int k = 0; k < int(variance.takeNames.size()); ++k) {
        m_table->setItem(k, 0, new QTableWidgetItem(QString::fromStdString(variance.takeNames[std::size_t(k)])));
        m_table->setItem(k, 1, new QTableWidgetItem(QString::number(variance.totalBefore[k], 'g', 4)));
        m_table->setItem(k, 2, new QTableWidgetItem(QString::number(variance.totalAfter[k], 'g', 4)));
    }
    m_curves->clearGraphs();
    for (std::size_t k = 0; k < m_output->warps.size(); ++k) {
        const Eigen::VectorXd& warp = m_output->warps[k];
        QVector<double> x(warp.size()), y(warp.size());
        for (Eigen::Index i = 0; i < warp.size(); ++i) {
            x[i] = double(i);
            y[i] = warp[i];
        }
        auto* graph = m_curves->addGraph();
        graph->setData(x, y, true);
        graph->setPen(QPen(QColor::fromHsv(int(k * 360 / std::max<std::size_t>(1, m_output->warps.size())), 200, 200), 1.5));
    }
    m_curves->rescaleAxes();
    m_curves->replot();
    m_document.setLiveTake(QStringLiteral("normalised"), tr("%1 normalised").arg(m_document.takeLabel(m_output->sampleId)),
                           m_output->normalisedSample, m_output->sampleId);
}

} // namespace bunraku::app
