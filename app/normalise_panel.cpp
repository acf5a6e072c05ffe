#include "app/normalise_panel.h"

#include "app/analysis_scope_notice.h"

#include "app/commands.h"
#include "app/focus_return.h"
#include "app/analysis_controller.h"
#include "app/variance_tree.h"

#include "widgets/bounded_spin_box.h"

#include "analysis/normalise/coupling.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/pipeline/stage_parameters.h"

#include <qcustomplot.h>

#include <algorithm>

#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStringList>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace bunraku::app {

namespace {

namespace pl = analysis::pipeline;

/// The corpus cell of take A ("function/emotion"), empty when A is not a corpus take.
std::pair<std::string, std::string> cellOfTakeA(const Document& document)
{
    const TakeId id = document.selectedId(TakeSlot::A);
    const TakePointer take = document.take(id);
    if (!take || !id.isCorpus()) return {};
    return {take->labels.function, take->labels.emotion};
}

/// "1 frame", "30 frames".
QString framesText(int frames)
{
    return frames == 1 ? NormalisePanel::tr("1 frame") : NormalisePanel::tr("%1 frames").arg(frames);
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
    m_tau = new widgets::BoundedSpinBox(this);
    m_tau->setObjectName("normaliseTau");
    // The limits the analysis accepts (stage_parameters.h, the one table the command line and
    // project files use too): a control at its maximum gives a value the stages run with. The
    // largest scale is also bounded by the corpus's shortest take (refreshControls).
    m_tau->setRange(0, analysis::pipeline::kMaxTau);
    m_tau->setSuffix(tr(" frames"));
    m_band = new widgets::BoundedSpinBox(this);
    m_band->setObjectName("normaliseSearchBand");
    m_band->setRange(0, analysis::pipeline::kMaxSearchBand);
    m_band->setSuffix(tr(" frames"));
    m_scales = new widgets::BoundedSpinBox(this);
    m_scales->setObjectName("normaliseMaxScale");
    m_scales->setRange(1, analysis::pipeline::kMaxScale);
    m_coupling = new QComboBox(this);
    m_coupling->setObjectName("normaliseCoupling");
    m_coupling->setEditable(true);
    for (const auto& name : analysis::couplingPresetNames()) m_coupling->addItem(QString::fromStdString(name));
    m_path = new QComboBox(this);
    m_path->setObjectName("normalisePath");
    m_path->addItem(tr("optimal (DP)"), QStringLiteral("optimal")); // the default (pl::NormaliseParameters::path)
    m_path->addItem(tr("greedy (thesis)"), QStringLiteral("greedy"));
    m_reference->setToolTip(tr("The take every take of the cell is normalised to"));
    m_tau->setDescription(tr("tau: half window of the wavelet shape comparison (thesis 3.5.2: 4)."));
    m_band->setDescription(tr("T_cmp: search band around the reference frame (thesis: 20)."));
    m_scales->setDescription(tr("Largest wavelet scale: scales 1..max (thesis: 16)."));
    m_coupling->setToolTip(tr("Which channels share one time correspondence (thesis eq. 3.29): a preset or a spec"));
    m_path->setToolTip(tr("The correspondence path: the optimal monotone path (the default: on real takes the greedy scan "
                          "can lock onto the next cycle of a repeated gesture) or the thesis's greedy scan (3.5.3)"));
    m_summary = new QLabel(this);
    m_summary->setObjectName("normaliseSummary");
    m_summary->setWordWrap(true);
    m_table = new QTreeWidget(this);
    m_table->setObjectName("varianceTree");
    m_table->setColumnCount(4);
    m_table->setHeaderLabels({tr("Take"), tr("Before"), tr("After"), tr("Change")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setRootIsDecorated(true);
    m_table->setMinimumHeight(90);
    m_curves = new QCustomPlot(this);
    m_curves->setObjectName("correspondencePlot");
    m_curves->setMinimumHeight(120);
    m_curves->xAxis->setLabel(tr("reference frame"));
    m_curves->yAxis->setLabel(tr("sample frame"));
    m_curves->legend->setVisible(true);
    QFont legendFont = font();
    legendFont.setPointSizeF(std::max(6.0, legendFont.pointSizeF() - 2.0));
    m_curves->legend->setFont(legendFont);
    m_curves->legend->setBrush(QColor(255, 255, 255, 210));
    m_curves->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);

    auto* form = new QFormLayout;
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    form->addRow(tr("Reference"), m_reference);
    form->addRow(tr("tau"), m_tau);
    form->addRow(tr("T_cmp"), m_band);
    form->addRow(tr("Largest scale"), m_scales);
    form->addRow(tr("Coupling"), m_coupling);
    form->addRow(tr("Path"), m_path);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(new AnalysisScopeNotice(m_document, this));
    layout->addLayout(form);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_curves, 1);

    // Every control edits the typed parameters through ChangeStageParameters, named after the
    // value it sets; consecutive steps of a spin box (arrows, keys, wheel) are one undo step
    // until it loses the focus.
    auto edit = [this](const QString& control, const QString& text, const std::function<void(pl::NormaliseParameters&)>& change) {
        if (m_updating) return;
        changeStageParameters(
            m_document, [&](AnalysisParameters& p) { change(p.normalise); }, text, QStringLiteral("normalise.") + control);
    };
    connect(m_reference, &QComboBox::currentIndexChanged, this, [this, edit] {
        const auto [function, emotion] = shownCell();
        if (function.empty()) return;
        const QString data = m_reference->currentData().toString();
        pl::ReferenceChoice choice;
        if (data == QStringLiteral("average")) choice.kind = pl::ReferenceKind::Average;
        else if (data != QStringLiteral("suggested")) choice = {pl::ReferenceKind::Take, data.toInt()};
        // A name, not the bindings, in the lambda: clang 14 (the sanitizer builds) cannot capture
        // structured bindings.
        const std::string name = pl::cellName(function, emotion);
        const QString cell = QString::fromStdString(name);
        edit(QStringLiteral("reference"), tr("Set the reference of %1 to %2").arg(cell, m_reference->currentText()),
             [&](pl::NormaliseParameters& p) {
                 if (choice == p.reference) p.cellReferences.erase(name);
                 else p.cellReferences[name] = choice;
             });
    });
    connect(m_tau, &QSpinBox::valueChanged, this, [edit](int value) {
        edit(QStringLiteral("tau"), tr("Set tau to %1").arg(framesText(value)), [value](auto& p) { p.tau = value; });
    });
    connect(m_band, &QSpinBox::valueChanged, this, [edit](int value) {
        edit(QStringLiteral("searchBand"), tr("Set T_cmp to %1").arg(framesText(value)), [value](auto& p) { p.searchBand = value; });
    });
    connect(m_scales, &QSpinBox::valueChanged, this, [edit](int value) {
        edit(QStringLiteral("maxScale"), tr("Set the largest scale to %1").arg(value), [value](auto& p) { p.maxScale = value; });
    });
    for (widgets::BoundedSpinBox* box : {m_tau, m_band, m_scales}) {
        endSeriesWhenEdited(box, [this] { m_document.endStepSeries(); });
        connect(box, &widgets::BoundedSpinBox::clamped, this, [this, box](int requested, int applied) {
            const QString name = box == m_tau ? tr("tau") : box == m_band ? tr("T_cmp") : tr("The largest scale");
            emit statusMessage(tr("%1 %2%3 is %4 the limit: set to %5%3 (%6)")
                                   .arg(name)
                                   .arg(requested)
                                   .arg(box->suffix())
                                   .arg(requested > applied ? tr("above") : tr("below"))
                                   .arg(applied)
                                   .arg(box->limitsText()));
        });
    }
    connect(m_coupling, &QComboBox::currentTextChanged, this, [this, edit](const QString& text) {
        const std::string spec = text.trimmed().toStdString();
        if (spec.empty() || spec.size() > 4096) return;
        edit(QStringLiteral("coupling"), tr("Set the coupling to %1").arg(text.trimmed()),
             [&](pl::NormaliseParameters& p) { p.coupling = spec; });
    });
    connect(m_path, &QComboBox::currentIndexChanged, this, [this, edit] {
        const bool optimal = m_path->currentData().toString() == QStringLiteral("optimal");
        edit(QStringLiteral("path"), tr("Set the path to %1").arg(m_path->currentText()), [optimal](pl::NormaliseParameters& p) {
            p.path = optimal ? analysis::PathMethod::Optimal : analysis::PathMethod::Greedy;
        });
    });

    connect(&document, &Document::parametersChanged, this, [this](ParameterSections sections) {
        if (sections & kNormaliseSection) refreshControls();
    });
    connect(&document, &Document::selectionChanged, this, [this](TakeSlot slot) {
        if (slot != TakeSlot::A || cellOfTakeA(m_document).first.empty()) return; // keep the cell while viewing derived takes
        refreshControls();
        showResult();
    });
    connect(&document, &Document::corpusChanged, this, [this] {
        refreshControls();
        showResult();
    });
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
    return m_analysis.normalised() ? m_document.take(TakeId::live(QStringLiteral("normalised"))) : nullptr;
}

QString NormalisePanel::summaryText() const { return m_summary->text(); }

std::pair<std::string, std::string> NormalisePanel::shownCell() const
{
    // Take A's cell; while A shows a derived take (the normalised take itself), the cell last shown.
    auto cell = cellOfTakeA(m_document);
    if (cell.first.empty()) cell = {m_analysis.cellFunction(), m_analysis.cellEmotion()};
    return cell;
}

void NormalisePanel::refreshControls()
{
    m_updating = true;
    const auto [function, emotion] = shownCell();
    const pl::NormaliseParameters& parameters = m_document.parameters().normalise;
    if (!function.empty()) {
        m_reference->clear();
        m_reference->addItem(tr("suggested (thesis 3.6.1)"), QStringLiteral("suggested"));
        m_reference->addItem(tr("average take (thesis 3.7)"), QStringLiteral("average"));
        for (const analysis::Take* take : m_document.corpus().cell(function, emotion))
            m_reference->addItem(tr("take %1").arg(take->labels.takeIndex), QString::number(take->labels.takeIndex));
        m_reference->setCurrentIndex(std::max(0, m_reference->findData(referenceData(parameters.referenceFor(function, emotion)))));
    }
    // Scales past the shortest take's largest scale do not fit it: the analysis refuses them.
    m_scales->setLimits(1, pl::usableMaxScale(m_document.corpus()));
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
    const auto [function, emotion] = shownCell();
    const pl::CellNormalisation* cell = output && !function.empty() ? output->cell(function, emotion) : nullptr;
    if (!cell) {
        m_summary->setText(scheduler.state(slot) == SlotState::Running ? tr("Normalising every cell...") : QString());
        m_table->clear();
        m_curves->clearGraphs();
        m_curves->replot();
        return;
    }
    const auto& variance = cell->variance;
    // Takes that came out further from the reference in a whole DOF family, as `bunraku
    // normalise` lists them (analysis/normalise/variance_families.h).
    QStringList worse;
    for (const auto& row : analysis::varianceRows(variance, cell->referenceTake.channels)) {
        if (!row.part.empty() || !row.worse()) continue;
        const auto k = std::size_t(std::find(variance.takeNames.begin(), variance.takeNames.end(), row.take) - variance.takeNames.begin());
        const QString take = k < cell->takeIndices.size() ? QString::number(cell->takeIndices[k]) : QString::fromStdString(row.take);
        if (!worse.contains(take)) worse << take;
    }
    QString advice;
    if (!worse.isEmpty())
        advice = tr(" <span style=\"color:#b00020\">Take(s) %1 came out further from the reference in a DOF family%2.</span>")
                     .arg(worse.join(QStringLiteral(", ")),
                          m_analysis.normalisedParameters().path == analysis::PathMethod::Greedy
                              ? tr(": Path <i>optimal (DP)</i> finds the least-cost correspondence")
                              : QString());
    // The coupling `auto` chose (method2 on the puppet's parts, chains on a skeleton's joints).
    QString parametersText = AnalysisController::normaliseParametersText(m_analysis.normalisedParameters());
    if (const auto& used = cell->normalisations.empty() ? std::string() : cell->normalisations.front().coupling.preset;
        m_analysis.normalisedParameters().coupling == "auto" && !used.empty() && used != "auto")
        parametersText += tr(", coupling auto (%1)").arg(QString::fromStdString(used));
    m_summary->setText(tr("Cell <b>%1/%2</b> normalised to <b>%3</b> with %4%5.%6 Squared difference to the reference, "
                          "summed over frames, per DOF family and part:")
                           .arg(QString::fromStdString(function), QString::fromStdString(emotion),
                                QString::fromStdString(cell->referenceName).toHtmlEscaped(),
                                parametersText.toHtmlEscaped(),
                                scheduler.state(slot) == SlotState::Running ? tr(" (recomputing with the new parameters)") : QString(),
                                advice));
    std::vector<QString> labels;
    const std::size_t reference = std::size_t(cell->suggestion.takeIndex);
    for (std::size_t k = 0; k < cell->takeIndices.size(); ++k) {
        const bool isReference = cell->reference.kind == pl::ReferenceKind::Take ? cell->takeIndices[k] == cell->reference.takeIndex
                                 : cell->reference.kind == pl::ReferenceKind::Suggested ? k == reference
                                                                                        : false;
        labels.push_back(isReference ? tr("take %1 (ref.)").arg(cell->takeIndices[k]) : tr("take %1").arg(cell->takeIndices[k]));
    }
    fillVarianceTree(m_table, variance, cell->referenceTake.channels, labels);
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
        graph->setName(k < variance.takeNames.size() ? QString::fromStdString(variance.takeNames[k])
                                                     : tr("take %1").arg(cell->takeIndices[k]));
    }
    m_curves->rescaleAxes();
    m_curves->replot();
}

} // namespace bunraku::app
