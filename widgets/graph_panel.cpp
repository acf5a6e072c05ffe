#include "widgets/graph_panel.h"

#include "widgets/flow_layout.h"

#include "analysis/core/angle_channels.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCompleter>
#include <QLineEdit>
#include <QHBoxLayout>
#include <QLabel>
#include <QSet>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace bunraku::widgets {
namespace {

/// The item a combo box has chosen (an editable box's typed text is not a choice until it matches).
QString currentItem(const QComboBox* box) { return box->currentIndex() >= 0 ? box->itemText(box->currentIndex()) : QString(); }

void refill(QComboBox* box, const QStringList& items)
{
    const QString current = currentItem(box);
    const QSignalBlocker block(box);
    box->clear();
    box->addItems(items);
    const int index = box->findText(current);
    box->setCurrentIndex(index >= 0 ? index : 0);
}

} // namespace

GraphPanel::GraphPanel(QWidget* parent) : QWidget(parent), m_grid(new GraphGrid(this))
{
    m_layout = new QComboBox(this);
    m_layout->setObjectName("graphLayout");
    m_layout->addItem(tr("All channels"), int(GraphLayout::AllChannels));
    m_layout->addItem(tr("One part"), int(GraphLayout::OnePart));
    m_layout->addItem(tr("One DOF"), int(GraphLayout::OneDof));
    m_layout->addItem(tr("Single"), int(GraphLayout::Single));
    m_part = new QComboBox(this);
    m_part->setObjectName("graphPart");
    // A skeleton's takes have a part per joint (22 to 100 and more): the list is searchable -
    // typing any part of a name ("hand", "_L") offers the joints that contain it.
    m_part->setEditable(true);
    m_part->setInsertPolicy(QComboBox::NoInsert);
    // As wide as its longest name (the kimono's "sleeve_right_tip", a skeleton's long joint
    // names), up to 32 characters; a longer name shows its beginning, not its end.
    m_part->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_part->setMaximumWidth(m_part->fontMetrics().averageCharWidth() * 32 + 48);
    connect(m_part, &QComboBox::currentIndexChanged, this, [this] { m_part->lineEdit()->setCursorPosition(0); });
    m_part->lineEdit()->setPlaceholderText(tr("Find a part or joint"));
    auto* finder = new QCompleter(m_part->model(), m_part);
    finder->setFilterMode(Qt::MatchContains);
    finder->setCaseSensitivity(Qt::CaseInsensitive);
    finder->setCompletionMode(QCompleter::PopupCompletion);
    m_part->setCompleter(finder);
    // Text that names no part goes back to the part shown.
    connect(m_part->lineEdit(), &QLineEdit::editingFinished, this, [this] {
        const int index = m_part->findText(m_part->currentText(), Qt::MatchFixedString);
        if (index >= 0 && index != m_part->currentIndex()) m_part->setCurrentIndex(index);
        else m_part->setEditText(currentItem(m_part));
    });
    m_dof = new QComboBox(this);
    m_dof->setObjectName("graphDof");
    m_mode = new QComboBox(this);
    m_mode->setObjectName("twoTakeMode");
    m_mode->addItem(tr("A and B overlaid"), int(TwoTakeMode::Overlay));
    m_mode->addItem(tr("A and B side by side"), int(TwoTakeMode::SideBySide));
    m_scale = new QComboBox(this);
    m_scale->setObjectName("valueScale");
    m_scale->addItem(tr("Scale per graph"), int(ValueScale::PerGraph));
    m_scale->addItem(tr("Scale per DOF"), int(ValueScale::PerDof));
    m_angles = new QComboBox(this);
    m_angles->setObjectName("angleDisplay");
    m_angles->addItem(tr("Euler angles"), int(AngleDisplay::Euler));
    m_angles->addItem(tr("Rotation coordinates"), int(AngleDisplay::RotationCoordinates));
    m_angles->setToolTip(tr("How the yaw, pitch and roll graphs show orientations: as the take's Z-Y'-X'' Euler angles, or as "
                            "rotation coordinates - the turn from the part's mean orientation in take A, as a rotation vector in "
                            "degrees about the vertical (yaw), lateral (pitch) and forward (roll) axes - which never wind or jump "
                            "near pitch +-90 deg, where Euler yaw and roll sweep far for a small turn. The analyses always "
                            "compute on rotation coordinates."));
    m_thesisTicks = new QCheckBox(tr("Thesis ticks"), this);
    m_thesisTicks->setObjectName("thesisTicks");
    m_thesisTicks->setToolTip(tr("Value ticks every 10 units and time ticks every 2 s, as the thesis's graphs"));
    m_layout->setToolTip(tr("Which graphs to show"));
    m_part->setToolTip(tr("The part (a skeleton's joint) shown by the 'one part' and 'single' layouts: choose it, type to find "
                          "it, or click it in the 3D view"));
    m_dof->setToolTip(tr("The DOF shown by the 'one DOF' and 'single' layouts"));

    m_mode->setToolTip(tr("How take B is shown beside take A"));
    m_scale->setToolTip(tr("Each graph fits its own values, or graphs of one DOF share their range"));
    // The controls flow onto more rows in a narrow dock: every one stays reachable, and the
    // dock does not widen (a tool bar's extension menu cannot show combo and check boxes).
    auto* controls = new QWidget(this);
    controls->setObjectName("graphToolBar");
    auto* flow = new FlowLayout(controls);
    flow->setContentsMargins(4, 2, 4, 2);
    for (QWidget* widget : std::initializer_list<QWidget*>{m_layout, m_part, m_dof, m_mode, m_scale, m_angles, m_thesisTicks}) flow->addWidget(widget);
    const QString help = tr("drag: scrub   wheel: zoom   Shift+drag: pan   double click: whole take");
    auto* hint = new QLabel(help, this);
    hint->setEnabled(false);
    hint->setContentsMargins(8, 0, 0, 0);
    flow->addWidget(hint);
    m_grid->setToolTip(help);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(controls);
    m_ghostCaption = new QLabel(this);
    m_ghostCaption->setObjectName("ghostCaption");
    m_ghostCaption->setWordWrap(true);
    m_ghostCaption->setContentsMargins(8, 0, 8, 0);
    m_ghostCaption->setVisible(false);
    layout->addWidget(m_ghostCaption);
    m_limitCaption = new QLabel(this);
    m_limitCaption->setObjectName("graphLimitCaption");
    m_limitCaption->setWordWrap(true);
    m_limitCaption->setContentsMargins(8, 0, 8, 0);
    m_limitCaption->setVisible(false);
    layout->addWidget(m_limitCaption);
    connect(m_grid, &GraphGrid::interactionEnded, this, [this] { showPerChannel(false); });
    connect(m_grid, &GraphGrid::graphsLimited, this, [this](int hidden, int total) {
        m_limitCaption->setText(tr("Showing the first %1 of %2 graphs: the 'one part' and 'single' layouts show any channel.")
                                    .arg(total - hidden)
                                    .arg(total));
        m_limitCaption->setVisible(hidden > 0);
    });
    layout->addWidget(m_grid, 1);

    connect(m_layout, &QComboBox::currentIndexChanged, this,
            [this] { m_grid->setGraphLayout(GraphLayout(m_layout->currentData().toInt())); });
    connect(m_mode, &QComboBox::currentIndexChanged, this,
            [this] { m_grid->setTwoTakeMode(TwoTakeMode(m_mode->currentData().toInt())); });
    connect(m_scale, &QComboBox::currentIndexChanged, this,
            [this] { m_grid->setValueScale(ValueScale(m_scale->currentData().toInt())); });
    connect(m_thesisTicks, &QCheckBox::toggled, m_grid, &GraphGrid::setThesisTicks);
    connect(m_angles, &QComboBox::currentIndexChanged, this, [this] { showTakes({}); });
    connect(m_part, &QComboBox::currentIndexChanged, this, &GraphPanel::applySelection);
    connect(m_dof, &QComboBox::currentIndexChanged, this, &GraphPanel::applySelection);
}

void GraphPanel::setTakes(std::shared_ptr<const analysis::Take> takeA, std::shared_ptr<const analysis::Take> takeB,
                          const QString& identity)
{
    QStringList parts;
    QStringList dofs;
    if (takeA) {
        // In order of first appearance; the sets keep it linear in the channels (10,000 parts).
        QSet<QString> seenParts, seenDofs;
        for (const auto& channel : takeA->channels) {
            const QString part = QString::fromStdString(channel.part);
            const QString dof = QString::fromStdString(channel.dof);
            if (!seenParts.contains(part)) {
                seenParts.insert(part);
                parts << part;
            }
            if (!seenDofs.contains(dof)) {
                seenDofs.insert(dof);
                dofs << dof;
            }
        }
    }
    refill(m_part, parts);
    m_part->lineEdit()->setCursorPosition(0);
    refill(m_dof, dofs);
    m_grid->setSelectedChannel(selectedPart().toStdString(), selectedDof().toStdString());
    m_takeA = std::move(takeA);
    m_takeB = std::move(takeB);
    showTakes(identity);
}

void GraphPanel::setGhost(std::shared_ptr<const analysis::Take> ghost)
{
    // The same ghost again (every step of a drag of the take in front of it): setTakes shows it
    // on the new take A's base; converting it here as well would be done twice.
    if (ghost == m_ghost) return;
    m_ghost = std::move(ghost);
    m_grid->setGhost(shown(m_ghost));
}

void GraphPanel::setPerChannelGhost(std::shared_ptr<const analysis::Take> take, const QString& caption)
{
    m_caption = caption;
    const bool changed = take != m_perChannel;
    m_perChannel = std::move(take);
    showPerChannel(changed);
}

void GraphPanel::showPerChannel(bool changed)
{
    m_perChannelOwed = m_perChannelOwed || changed;
    // During a drag the grid holds the line (GraphGrid::setPerChannelGhost): it is converted, and
    // its caption changed, when the drag ends.
    if (m_grid->interactionActive()) return;
    m_ghostCaption->setText(m_caption);
    m_ghostCaption->setVisible(!m_caption.isEmpty());
    if (!std::exchange(m_perChannelOwed, false)) return;
    m_grid->setPerChannelGhost(shown(m_perChannel));
}

QString GraphPanel::ghostCaption() const { return m_ghostCaption->isHidden() ? QString() : m_ghostCaption->text(); }

void GraphPanel::setAngleDisplay(AngleDisplay display) { m_angles->setCurrentIndex(m_angles->findData(int(display))); }

AngleDisplay GraphPanel::angleDisplay() const { return AngleDisplay(m_angles->currentData().toInt()); }

std::shared_ptr<const analysis::Take> GraphPanel::shown(const std::shared_ptr<const analysis::Take>& take) const
{
    if (!take || angleDisplay() == AngleDisplay::Euler) return take;
    // Every take about take A's mean part orientations, so A, B and the ghost share one base.
    return std::make_shared<const analysis::Take>(analysis::rotationCoordinateTake(*take, m_takeA.get()));
}

void GraphPanel::showTakes(const QString& identity)
{
    m_shownA = shown(m_takeA);
    m_shownB = shown(m_takeB);
    m_grid->setGhost(shown(m_ghost));
    showPerChannel(true); // on take A's new base
    m_grid->setTakes(m_shownA, m_shownB, identity);
}

void GraphPanel::setGraphLayout(GraphLayout layout) { m_layout->setCurrentIndex(m_layout->findData(int(layout))); }
void GraphPanel::setTwoTakeMode(TwoTakeMode mode) { m_mode->setCurrentIndex(m_mode->findData(int(mode))); }
void GraphPanel::setValueScale(ValueScale scale) { m_scale->setCurrentIndex(m_scale->findData(int(scale))); }
void GraphPanel::setThesisTicks(bool on) { m_thesisTicks->setChecked(on); }

void GraphPanel::selectPart(const QString& part)
{
    const int index = m_part->findText(part);
    if (index < 0) return;
    m_part->setCurrentIndex(index);
    if (m_grid->graphLayout() == GraphLayout::AllChannels || m_grid->graphLayout() == GraphLayout::OneDof)
        setGraphLayout(GraphLayout::OnePart);
}

void GraphPanel::selectDof(const QString& dof)
{
    const int index = m_dof->findText(dof);
    if (index >= 0) m_dof->setCurrentIndex(index);
}

QString GraphPanel::selectedPart() const { return currentItem(m_part); }
QString GraphPanel::selectedDof() const { return currentItem(m_dof); }

void GraphPanel::applySelection() { m_grid->setSelectedChannel(selectedPart().toStdString(), selectedDof().toStdString()); }

} // namespace bunraku::widgets
