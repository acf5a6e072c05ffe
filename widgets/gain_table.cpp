#include "widgets/gain_table.h"

#include <QBrush>
#include <QColor>
#include <QFontMetrics>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSlider>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace bunraku::widgets {

GainTable::GainTable(QWidget* parent) : QWidget(parent), m_table(new QTableWidget(this))
{
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    // Each cell holds g0 over g1 on two lines: "g0 / g1" on one line is wider than a column and
    // was elided to "1.00 / ..." in the Design dock of a 1366-pixel window (a 252-pixel table,
    // 6 columns of 42). Columns share the width but never fall below their widest number (then
    // the table scrolls sideways rather than cut a number).
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->setTextElideMode(Qt::ElideNone);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->setDefaultSectionSize(2 * fontMetrics().lineSpacing() + 6);
    m_table->setToolTip(tr("Each cell: g0 (gain of the phrase's mean) over g1 (gain of its first harmonic), thesis eqs. 5.22, "
                           "5.23. Shaded cells: the extracted g1 is ill-conditioned (hover for why)."));
    auto makeSlider = [this](const char* name) {
        auto* slider = new QSlider(Qt::Horizontal, this);
        slider->setObjectName(name);
        slider->setRange(-200, 200);
        slider->setEnabled(false);
        connect(slider, &QSlider::sliderPressed, this, &GainTable::dragStarted);
        connect(slider, &QSlider::sliderReleased, this, &GainTable::dragFinished);
        connect(slider, &QSlider::valueChanged, this, &GainTable::sliderMoved);
        return slider;
    };
    m_g0 = makeSlider("gainG0");
    m_g1 = makeSlider("gainG1");
    m_label = new QLabel(tr("Select a phrase and DOF"), this);
    auto* form = new QFormLayout;
    form->addRow(m_label);
    form->addRow(tr("g0 (mean)"), m_g0);
    form->addRow(tr("g1 (amplitude)"), m_g1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table, 1);
    layout->addLayout(form);
    connect(m_table, &QTableWidget::currentCellChanged, this, [this] { bindSliders(); });
}

QString GainTable::cellText(const analysis::DofGain& gain)
{
    return QStringLiteral("%1\n%2").arg(gain.g0, 0, 'f', 2).arg(gain.g1, 0, 'f', 2);
}

void GainTable::fitColumns()
{
    // the widest line of any cell plus the item's margins
    const QFontMetrics metrics(m_table->font());
    int widest = metrics.horizontalAdvance(QStringLiteral("0.00"));
    for (int p = 0; p < m_table->rowCount(); ++p)
        for (int d = 0; d < m_table->columnCount(); ++d)
            if (const QTableWidgetItem* item = m_table->item(p, d))
                for (const QString& line : item->text().split('\n')) widest = std::max(widest, metrics.horizontalAdvance(line));
    m_table->horizontalHeader()->setMinimumSectionSize(widest + kCellMargin);
}

bool GainTable::cellTextFits(int phrase, int dof) const
{
    const QTableWidgetItem* item = m_table->item(phrase, dof);
    if (!item) return false;
    const QFontMetrics metrics(m_table->font());
    const QStringList lines = item->text().split('\n');
    int widest = 0;
    for (const QString& line : lines) widest = std::max(widest, metrics.horizontalAdvance(line));
    return widest + kCellMargin <= m_table->columnWidth(dof) + 1 &&
           int(lines.size()) * metrics.lineSpacing() <= m_table->rowHeight(phrase);
}

double GainTable::gainOfPosition(int position) { return std::pow(2.0, position / 100.0); }
int GainTable::positionOfGain(double gain) { return gain > 0.0 ? int(std::lround(100.0 * std::log2(gain))) : -200; }

void GainTable::setGains(const analysis::GainSet& gains)
{
    m_gains = gains;
    const int row = m_table->currentRow();
    const int column = m_table->currentColumn();
    m_binding = true;
    m_table->setRowCount(int(gains.phrases.size()));
    m_table->setColumnCount(int(gains.dofNames.size()));
    QStringList headers;
    for (const auto& name : gains.dofNames) headers << QString::fromStdString(name).remove(QStringLiteral("axis."));
    m_table->setHorizontalHeaderLabels(headers);
    for (int p = 0; p < int(gains.phrases.size()); ++p) {
        const auto& phrase = gains.phrases[std::size_t(p)];
        m_table->setVerticalHeaderItem(p, new QTableWidgetItem(tr("%1-%2").arg(phrase.begin).arg(phrase.end)));
        for (int d = 0; d < int(phrase.dofs.size()) && d < m_table->columnCount(); ++d) {
            const auto& gain = phrase.dofs[std::size_t(d)];
            auto* item = new QTableWidgetItem(cellText(gain));
            item->setTextAlignment(Qt::AlignCenter);
            m_table->setItem(p, d, item);
        }
    }
    fitColumns();
    updateTooltips();
    if (row >= 0 && row < m_table->rowCount() && column >= 0 && column < m_table->columnCount())
        m_table->setCurrentCell(row, column);
    m_binding = false;
    bindSliders();
}

void GainTable::setExtracted(const analysis::GainSet& extracted)
{
    m_extracted = extracted;
    updateTooltips();
    bindSliders();
}

namespace {

/// The extracted gain of `phrase` and `dof` when `extracted` has the same phrase there, else null.
const analysis::DofGain* extractedGain(const analysis::GainSet& extracted, const analysis::GainSet& shown, int phrase, int dof)
{
    const auto p = std::size_t(phrase);
    const auto d = std::size_t(dof);
    if (p >= extracted.phrases.size() || p >= shown.phrases.size() || d >= extracted.phrases[p].dofs.size()) return nullptr;
    if (extracted.phrases[p].begin != shown.phrases[p].begin || extracted.phrases[p].end != shown.phrases[p].end) return nullptr;
    return &extracted.phrases[p].dofs[d];
}

} // namespace

void GainTable::updateTooltips()
{
    for (int p = 0; p < m_table->rowCount(); ++p)
        for (int d = 0; d < m_table->columnCount(); ++d) {
            QTableWidgetItem* item = m_table->item(p, d);
            if (!item || p >= int(m_gains.phrases.size()) || d >= int(m_gains.phrases[std::size_t(p)].dofs.size())) continue;
            QStringList lines;
            if (const auto* extracted = extractedGain(m_extracted, m_gains, p, d)) {
                lines << tr("extracted: g0 = %1, g1 = %2").arg(extracted->g0, 0, 'f', 2).arg(extracted->g1, 0, 'f', 2);
                if (!extracted->reason.empty()) lines << QString::fromStdString(extracted->reason);
            }
            const auto& reason = m_gains.phrases[std::size_t(p)].dofs[std::size_t(d)].reason;
            if (!reason.empty()) lines << QString::fromStdString(reason);
            const bool ill = isIllConditioned(p, d);
            if (ill)
                lines.prepend(tr("Extracted g1 is ill-conditioned: %1")
                                  .arg(QString::fromStdString(extractedGain(m_extracted, m_gains, p, d)->illConditionedReason)));
            item->setBackground(ill ? QBrush(QColor(255, 214, 153)) : QBrush());
            item->setForeground(ill ? QBrush(Qt::black) : QBrush());
            item->setToolTip(lines.join('\n'));
        }
}

bool GainTable::isIllConditioned(int phrase, int dof) const
{
    const auto* extracted = extractedGain(m_extracted, m_gains, phrase, dof);
    return extracted && extracted->illConditioned;
}

QString GainTable::selectionText() const { return m_label->text(); }

void GainTable::selectCell(int phrase, int dof) { m_table->setCurrentCell(phrase, dof); }

void GainTable::bindSliders()
{
    const int p = m_table->currentRow();
    const int d = m_table->currentColumn();
    const bool valid = p >= 0 && d >= 0 && p < int(m_gains.phrases.size()) && d < int(m_gains.phrases[std::size_t(p)].dofs.size());
    m_g0->setEnabled(valid);
    m_g1->setEnabled(valid);
    if (!valid) return;
    const auto& gain = m_gains.phrases[std::size_t(p)].dofs[std::size_t(d)];
    const bool wasBinding = m_binding;
    m_binding = true;
    if (!m_g0->isSliderDown()) m_g0->setValue(positionOfGain(gain.g0));
    if (!m_g1->isSliderDown()) m_g1->setValue(positionOfGain(gain.g1));
    m_binding = wasBinding;
    QString text = tr("Phrase %1, %2: g0 = %3, g1 = %4")
                       .arg(p + 1)
                       .arg(QString::fromStdString(d < int(m_gains.dofNames.size()) ? m_gains.dofNames[std::size_t(d)] : std::string()))
                       .arg(gain.g0, 0, 'f', 2)
                       .arg(gain.g1, 0, 'f', 2);
    if (const auto* extracted = extractedGain(m_extracted, m_gains, p, d)) {
        text += tr(" (extracted %1 / %2)").arg(extracted->g0, 0, 'f', 2).arg(extracted->g1, 0, 'f', 2);
        if (extracted->illConditioned) text += tr("; extracted g1 ill-conditioned (regularised)");
    }
    m_label->setText(text);
}

void GainTable::sliderMoved()
{
    if (m_binding) return;
    const int p = m_table->currentRow();
    const int d = m_table->currentColumn();
    if (p < 0 || d < 0) return;
    emit gainEdited(p, d, gainOfPosition(m_g0->value()), gainOfPosition(m_g1->value()));
}

} // namespace bunraku::widgets
