#include "app/design_panel.h"

#include "app/analysis_scope_notice.h"

#include "app/design_controller.h"
#include "app/document.h"

#include "analysis/axis/axis_channels.h"

#include "widgets/flow_layout.h"
#include "widgets/gain_table.h"
#include "widgets/scale_error_plot.h"
#include "widgets/warp_curve_editor.h"

#include <QLabel>
#include <QStringList>
#include <QPushButton>
#include <QSplitter>
#include <QVBoxLayout>

namespace bunraku::app {

DesignPanel::DesignPanel(Document& document, DesignController& controller, QWidget* parent)
    : QWidget(parent), m_document(document), m_controller(controller)
{
    m_editor = new widgets::WarpCurveEditor(this);
    m_gains = new widgets::GainTable(this);
    m_scaleError = new widgets::ScaleErrorPlot(this);
    m_inputs = new QLabel(tr("Preparing the design..."), this);
    m_inputs->setWordWrap(true);
    m_timing = new QLabel(this);
    m_timing->setEnabled(false);
    m_conditioning = new QLabel(this);
    m_conditioning->setObjectName("illConditionedNotice");
    m_conditioning->setWordWrap(true);
    m_conditioning->setTextFormat(Qt::PlainText);
    m_conditioning->hide();
    auto* showDesigned = new QPushButton(tr("Show designed as A"), this);
    showDesigned->setObjectName("showDesigned");
    auto* extractedGains = new QPushButton(tr("Use extracted gains"), this);
    auto* resetGains = new QPushButton(tr("Reset gains"), this);
    auto* resetBoundaries = new QPushButton(tr("Reset phrases"), this);
    resetBoundaries->setObjectName("resetBoundaries");
    resetBoundaries->setToolTip(tr("Back to the suggested phrase boundaries (drag the orange ticks on the timeline to move them)"));
    auto* addBoundary = new QPushButton(tr("Add phrase boundary at cursor"), this);
    addBoundary->setObjectName("addBoundary");
    addBoundary->setToolTip(tr("Split the phrase under the time cursor there; both halves keep its gains"));
    auto* removeBoundary = new QPushButton(tr("Remove nearest boundary"), this);
    removeBoundary->setObjectName("removeBoundary");
    removeBoundary->setToolTip(tr("Remove the phrase boundary nearest to the time cursor; the merged phrase keeps the "
                                  "gains of the longer of the two"));

    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_editor);
    splitter->addWidget(m_gains);
    splitter->addWidget(m_scaleError);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setStretchFactor(2, 2);
    // The buttons at their full width, wrapped onto as many rows as the dock's width needs
    // (a 1280-pixel screen's narrow column: one or two per row, never clipped).
    auto* buttons = new widgets::FlowLayout;
    for (QPushButton* button : {showDesigned, extractedGains, resetGains, addBoundary, removeBoundary, resetBoundaries})
        buttons->addWidget(button);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(new AnalysisScopeNotice(m_document, this));
    layout->addWidget(m_inputs);
    layout->addWidget(m_conditioning);
    layout->addWidget(splitter, 1);
    layout->addLayout(buttons);
    layout->addWidget(m_timing);

    connect(m_editor, &widgets::WarpCurveEditor::dragStarted, &document, &Document::beginInteraction);
    connect(m_editor, &widgets::WarpCurveEditor::dragFinished, &document, &Document::endInteraction);
    connect(m_editor, &widgets::WarpCurveEditor::curveEdited, &controller, &DesignController::editWarp);
    connect(m_editor, &widgets::WarpCurveEditor::resetToIdentityRequested, &controller, &DesignController::resetWarpToIdentity);
    connect(m_editor, &widgets::WarpCurveEditor::resetToExtractedRequested, &controller, &DesignController::resetWarpToExtracted);
    connect(m_gains, &widgets::GainTable::dragStarted, &document, &Document::beginInteraction);
    connect(m_gains, &widgets::GainTable::dragFinished, &document, &Document::endInteraction);
    connect(m_gains, &widgets::GainTable::gainEdited, &controller, &DesignController::editGain);
    connect(extractedGains, &QPushButton::clicked, &controller, &DesignController::useExtractedGains);
    connect(resetGains, &QPushButton::clicked, &controller, &DesignController::resetGains);
    connect(resetBoundaries, &QPushButton::clicked, &controller, &DesignController::resetBoundaries);
    connect(addBoundary, &QPushButton::clicked, this, [this] { m_controller.addBoundary(cursorFrame()); });
    connect(removeBoundary, &QPushButton::clicked, this,
            [this] { m_controller.removeBoundary(m_controller.nearestBoundary(cursorFrame())); });
    connect(showDesigned, &QPushButton::clicked, this, [this] {
        m_document.selectTake(TakeSlot::A, TakeId::live(QStringLiteral("designed")));
    });
    connect(&controller, &DesignController::prepared, this, &DesignPanel::refresh);
    connect(&controller, &DesignController::designed, this, [this] {
        // On every drag step: only what an edit changes (the curve, the gains, the timing).
        m_editor->setCurve(m_controller.warpCurve());
        const auto gains = m_controller.gains();
        bool same = gains.phrases.size() == m_gains->gains().phrases.size();
        for (std::size_t p = 0; same && p < gains.phrases.size(); ++p)
            for (std::size_t d = 0; same && d < gains.phrases[p].dofs.size(); ++d)
                same = gains.phrases[p].begin == m_gains->gains().phrases[p].begin &&
                       gains.phrases[p].end == m_gains->gains().phrases[p].end &&
                       gains.phrases[p].dofs[d].g0 == m_gains->gains().phrases[p].dofs[d].g0 &&
                       gains.phrases[p].dofs[d].g1 == m_gains->gains().phrases[p].dofs[d].g1;
        if (!same) {
            m_gains->setGains(gains);
            m_gains->setExtracted(m_controller.extractedGains()); // they follow the boundaries
            showConditioning();
        }
        showStatus();
    });
    connect(&document, &Document::currentTimeChanged, this,
            [this](double seconds) { m_editor->setCurrentFrame(seconds * m_document.rateHz()); });
}

void DesignPanel::refresh()
{
    if (!m_controller.ready()) {
        m_inputs->setText(tr("Preparing the design..."));
        return;
    }
    m_inputs->setText(tr("Functional take: <b>%1</b>; correspondence extracted from the average take of <b>%2</b>. "
                         "The designed take is <i>designed</i> under Derived takes.")
                          .arg(m_document.takeLabel(m_controller.sourceId()),
                               m_controller.targetCell().isEmpty() ? tr("(none)") : m_controller.targetCell()));
    m_editor->setExtracted(m_controller.extractedWarp());
    m_editor->setCurve(m_controller.warpCurve());
    m_gains->setGains(m_controller.gains());
    m_gains->setExtracted(m_controller.extractedGains());
    showConditioning();
    std::vector<std::string> dofs;
    for (const auto& channel : analysis::axisCoordinateChannels()) dofs.push_back(channel.name());
    m_scaleError->setError(m_controller.approximationError(), dofs, m_controller.targetCell());
    showStatus();
}

void DesignPanel::showStatus()
{
    QString text = tr("synthesis %1 ms").arg(m_controller.lastSynthesisMilliseconds(), 0, 'f', 2);
    if (const QString error = m_controller.extractionError(); !error.isEmpty())
        text += QStringLiteral("<br><span style=\"color:#b00020\">%1</span>")
                    .arg(tr("No extracted gains for these phrases: %1").arg(error.toHtmlEscaped()));
    m_timing->setText(text);
}

void DesignPanel::showConditioning()
{
    // One line naming the phrases and DOF; the reasons (amplitudes, ratio) in the tooltip and
    // in the shaded cells' tooltips.
    const auto ill = analysis::illConditionedGains(m_controller.extractedGains());
    if (ill.empty()) {
        m_conditioning->clear();
        m_conditioning->setToolTip({});
        m_conditioning->hide();
        return;
    }
    QStringList phrases, reasons;
    for (std::size_t i = 0; i < ill.size();) {
        QStringList dofs;
        std::size_t j = i;
        for (; j < ill.size() && ill[j].phrase == ill[i].phrase; ++j) {
            dofs << QString::fromStdString(ill[j].dofName).remove(QStringLiteral("axis."));
            reasons << tr("Phrase %1 (frames %2-%3), %4: %5")
                           .arg(ill[j].phrase + 1)
                           .arg(ill[j].begin)
                           .arg(ill[j].end)
                           .arg(QString::fromStdString(ill[j].dofName), QString::fromStdString(ill[j].reason));
        }
        phrases << tr("phrase %1 (%2)").arg(ill[i].phrase + 1).arg(dofs.join(QStringLiteral(", ")));
        i = j;
    }
    m_conditioning->setText(
        tr("Ill-conditioned g1, regularised to %1 (emotional amplitude below %2 % of the functional one): %3")
            .arg(1.0 / analysis::kIllConditionedAmplitudeFraction, 0, 'g', 3)
            .arg(100.0 * analysis::kIllConditionedAmplitudeFraction, 0, 'g', 3)
            .arg(phrases.join(QStringLiteral("; "))));
    m_conditioning->setToolTip(reasons.join('\n'));
    m_conditioning->setStyleSheet(QStringLiteral("color: #8a4b00"));
    m_conditioning->show();
}

QString DesignPanel::illConditionedNotice() const { return m_conditioning->text(); }

bool DesignPanel::illConditionedNoticeShown() const { return !m_conditioning->isHidden(); }

QString DesignPanel::statusText() const { return m_timing->text(); }

double DesignPanel::cursorFrame() const
{
    return m_controller.functionalFrameAt(m_document.selectedId(TakeSlot::A), m_document.currentTime());
}

} // namespace bunraku::app
