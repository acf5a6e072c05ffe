#include "app/viewport_panel.h"

#include "app/recomputer.h"

#include "widgets/viewport_widget.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/axis/inertia_axis.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/body/body_description.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QToolBar>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>

namespace bunraku::app {
namespace {

using AxisPoses = std::vector<std::vector<analysis::RigidTransform>>;

/// A finished axis job: the takes it computed for and their axes (empty where it failed).
struct AxisResult {
    std::vector<TakePointer> takes;
    AxisPoses axes;
};

render::SceneContent sceneOf(const std::vector<TakePointer>& takes, const AxisPoses& axes)
{
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    for (std::size_t i = 0; i < takes.size(); ++i) {
        render::TakeSlot slot;
        slot.take = *takes[i];
        if (i < axes.size()) slot.world_T_axis = axes[i];
        scene.takes.push_back(std::move(slot));
    }
    return scene;
}

/// The slots (A, B) whose takes are shown: those that can pose the puppet (an axis take, for
/// one, cannot). The scene's take slots are these, in this order.
std::vector<TakeSlot> shownSlots(const Document& document)
{
    std::vector<TakeSlot> shown;
    for (TakeSlot slot : {TakeSlot::A, TakeSlot::B})
        if (TakePointer take = document.selectedTake(slot); take && analysis::hasPuppetLayout(*take)) shown.push_back(slot);
    return shown;
}

std::vector<TakePointer> shownTakes(const Document& document)
{
    std::vector<TakePointer> takes;
    for (TakeSlot slot : shownSlots(document)) takes.push_back(document.selectedTake(slot));
    return takes;
}

} // namespace

ViewportPanel::ViewportPanel(Document& document, QWidget* parent) : QWidget(parent), m_document(document)
{
    m_viewport = new widgets::ViewportWidget(this);
    m_viewport->setObjectName("viewport");
    m_viewport->setMinimumSize(240, 200);
    m_puppet = new QCheckBox(tr("Puppet"), this);
    m_axis = new QCheckBox(tr("Axis"), this);
    m_orbits = new QCheckBox(tr("Orbits"), this);
    m_grid = new QCheckBox(tr("Grid"), this);
    m_partner = new QCheckBox(tr("Partner"), this);
    const auto visibility = m_viewport->visibility();
    m_puppet->setChecked(visibility.puppet);
    m_axis->setChecked(visibility.axis);
    m_orbits->setChecked(false);
    m_grid->setChecked(visibility.grid);
    m_partner->setChecked(visibility.partner);
    m_puppet->setObjectName("showPuppet");
    m_axis->setObjectName("showAxis");
    m_orbits->setObjectName("showOrbits");
    m_grid->setObjectName("showGrid");
    m_partner->setObjectName("showPartner");
    m_puppet->setToolTip(tr("The puppet posed by take A (and B beside it)"));
    m_axis->setToolTip(tr("The motion axis (thesis 5.2.1): red front, green side, blue up, at the centre of mass"));
    m_orbits->setToolTip(tr("The paths of the head, shoulder, arm and hand sensors over the whole take, drawn over the "
                            "puppet, with a ball where each sensor is now"));
    m_grid->setToolTip(tr("The floor: a 20 cm grid under the lowest point of the figures"));
    m_partner->setToolTip(tr("Where the partner stands (the person greeted or served): a grey cone on a disc on the floor, "
                             "110 cm in front of the puppet"));
    // A tool bar, not a row of widgets: in a narrow dock what does not fit moves behind its
    // extension button instead of widening the dock.
    auto* toggles = new QToolBar(this);
    toggles->setObjectName("viewToolBar");
    toggles->setIconSize(QSize(16, 16));
    for (auto* box : {m_puppet, m_axis, m_orbits, m_grid, m_partner}) {
        toggles->addWidget(box);
        connect(box, &QCheckBox::toggled, this, &ViewportPanel::applyVisibility);
    }
    for (int slot = 0; slot < 2; ++slot) {
        auto* box = new QComboBox(this);
        box->setObjectName(slot == 0 ? "figureA" : "figureB");
        box->addItem(tr("Puppet"), int(render::FigureStyle::Puppet));
        box->addItem(tr("Skeleton"), int(render::FigureStyle::Skeleton));
        box->addItem(tr("Both"), int(render::FigureStyle::PuppetAndSkeleton));
        box->setToolTip(slot == 0 ? tr("Figure of take A: the puppet, the performer's skeleton (takes read from BVH), or both")
                                  : tr("Figure of take B: the puppet, the performer's skeleton (takes read from BVH), or both"));
        connect(box, &QComboBox::currentIndexChanged, this, &ViewportPanel::applyVisibility);
        toggles->addWidget(new QLabel(slot == 0 ? tr("A:") : tr("B:"), this));
        toggles->addWidget(box);
        m_figures[slot] = box;
    }
    toggles->addSeparator();
    createCameraActions(toggles);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(toggles);
    layout->addWidget(m_viewport, 1);

    // The axes of the shown takes, computed off the GUI thread, then added to the scene.
    m_axes = new Recomputer(
        document,
        [this]() -> Job {
            const auto takes = shownTakes(m_document);
            if (takes.empty()) return {};
            return [takes](const analysis::RunControl& control) -> JobOutput {
                static const analysis::AxisModel model = analysis::makeAxisModel(analysis::defaultBodyDescription());
                AxisResult result{takes, {}};
                for (const auto& take : takes) {
                    auto axis = analysis::computeMotionAxis(model, *take, {}, control);
                    result.axes.push_back(axis ? axis->world_T_axis : std::vector<analysis::RigidTransform>{});
                }
                return {result, {}};
            };
        },
        [this](const JobOutput& output) {
            if (!output.value.has_value()) return;
            const auto result = std::any_cast<AxisResult>(output.value);
            m_knownAxes.clear();
            for (std::size_t i = 0; i < result.takes.size(); ++i) m_knownAxes.emplace_back(result.takes[i], result.axes[i]);
            // The takes the axes were computed for (the serial check drops results of takes no
            // longer shown).
            const auto& takes = result.takes;
            const auto& axes = result.axes;
            m_viewport->setScene(sceneOf(takes, axes));
            m_viewport->setTime(m_document.currentTime());
        },
        this, 60, [this] { return m_sceneSerial; });
    m_axes->setObjectName(tr("Motion axis"));

    // Uploading a scene costs about one frame (it happens once, at the next paint, however many
    // scenes were set before it): a changed take shows at once.
    connect(&document, &Document::selectionChanged, this, &ViewportPanel::rebuildScene);
    connect(&document, &Document::corpusChanged, this, &ViewportPanel::rebuildScene);
    connect(&document, &Document::currentTimeChanged, m_viewport, &widgets::ViewportWidget::setTime);
    // A body part (face, torso, ...) selects the graphs of the take part that drives it.
    connect(m_viewport, &widgets::ViewportWidget::partPicked, this, [this](int, const QString& bodyPart) {
        for (const auto& part : analysis::defaultBodyDescription().parts)
            if (part.name == bodyPart.toStdString()) {
                emit partPicked(QString::fromStdString(part.drivenBy.empty() ? part.name : part.drivenBy));
                return;
            }
        emit partPicked(bodyPart);
    });
    // Frame Selected fits the body part clicked (the right hand, not both hands).
    connect(m_viewport, &widgets::ViewportWidget::partPicked, this, [this](int, const QString& bodyPart) { m_selectedPart = bodyPart; });
    connect(m_viewport, &widgets::ViewportWidget::backgroundPicked, this, [this] { m_selectedPart.clear(); });
    connect(m_viewport, &widgets::ViewportWidget::bonePicked, this, [this](int sceneSlot, const QString& joint, const QString& part) {
        const auto shown = shownSlots(m_document); // the scene's takes are the shown slots, in order
        emit bonePicked(sceneSlot < int(shown.size()) ? int(shown[std::size_t(sceneSlot)]) : sceneSlot, joint, part);
    });
    applyVisibility();
    rebuildScene();
}

void ViewportPanel::rebuildScene()
{
    ++m_sceneSerial; // also when nothing is shown: a pending axis result is stale either way
    const auto takes = shownTakes(m_document);
    if (takes.empty()) return;
    AxisPoses axes; // the known axes of takes that did not change; the others are recomputed
    for (const auto& take : takes) {
        const auto known = std::find_if(m_knownAxes.begin(), m_knownAxes.end(), [&](const auto& entry) { return entry.first == take; });
        axes.push_back(known != m_knownAxes.end() ? known->second : std::vector<analysis::RigidTransform>{});
    }
    m_viewport->setScene(sceneOf(takes, axes));
    m_viewport->setTime(m_document.currentTime());
    applyVisibility(); // take B may now be the scene's first take
    m_axes->schedule();
}

void ViewportPanel::applyVisibility()
{
    auto visibility = m_viewport->visibility();
    visibility.puppet = m_puppet->isChecked();
    visibility.axis = m_axis->isChecked();
    visibility.orbits = m_orbits->isChecked();
    visibility.grid = m_grid->isChecked();
    visibility.partner = m_partner->isChecked();
    visibility.orbitVisibility = render::OrbitVisibility::Always; // the box shows them, puppet or not
    const auto shown = shownSlots(m_document);
    for (std::size_t s = 0; s < shown.size() && s < visibility.figures.size(); ++s)
        visibility.figures[s] = render::FigureStyle(m_figures[int(shown[s])]->currentData().toInt());
    m_viewport->setVisibility(visibility);
}

} // namespace bunraku::app
