#include "app/viewport_panel.h"

#include "app/analysis_controller.h"

#include "widgets/flow_layout.h"
#include "widgets/viewport_widget.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/body/body_description.h"
#include "analysis/body/body_fit.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QStandardItem>
#include <QStandardItemModel>
#include <QStringList>
#include <QVBoxLayout>
#include <QToolButton>
#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QMessageBox>
#include <QPushButton>

#include <algorithm>
#include <map>
#include <string>
#include <tuple>

#include <utility>

namespace bunraku::app {
namespace {

/// The shown takes, with their slot: those that can pose the puppet (an axis take, for one,
/// cannot). The scene's take slots are these, in this order.
std::vector<std::pair<TakeSlot, TakePointer>> shownTakes(const Document& document)
{
    std::vector<std::pair<TakeSlot, TakePointer>> takes;
    for (TakeSlot slot : {TakeSlot::A, TakeSlot::B})
        if (TakePointer take = document.selectedTake(slot); take && render::drawableTake(*take)) takes.emplace_back(slot, take);
    return takes;
}

} // namespace

ViewportPanel::ViewportPanel(Document& document, AnalysisController& analysis, QWidget* parent)
    : QWidget(parent), m_document(document), m_analysis(analysis)
{
    m_viewport = new widgets::ViewportWidget(this);
    m_viewport->setObjectName("viewport");
    m_viewport->setMinimumSize(240, 200);
    m_puppet = new QCheckBox(tr("Puppet"), this);
    m_axis = new QCheckBox(tr("Axis"), this);
    m_orbits = new QCheckBox(tr("Orbits"), this);
    m_grid = new QCheckBox(tr("Grid"), this);
    m_shadows = new QCheckBox(tr("Shadows"), this);
    m_partner = new QCheckBox(tr("Partner"), this);
    m_follow = new QCheckBox(tr("Follow"), this);
    m_follow->setObjectName("followFigures");
    m_follow->setToolTip(tr("Carry the camera along the floor with the figures as the take plays (a walking take "
                            "stays in frame); orbit and zoom still work around them"));
    connect(m_follow, &QCheckBox::toggled, m_viewport, &widgets::ViewportWidget::setFollow);
    m_cloth = new QCheckBox(tr("Cloth"), this);
    m_cloth->setObjectName("showCloth");
    m_cloth->setToolTip(tr("Dress the puppet in its kimono simulated as cloth: the skirt and the long sleeves swing, lag and "
                           "settle with the motion (simulated in the background for each take shown; the kimono moving with "
                           "the body shows until then). Off: the kimono moves with the body. The orbits then include the "
                           "sleeve tips and the hem."));
    connect(m_cloth, &QCheckBox::toggled, this, [this](bool on) {
        m_analysis.setKimonoShown(on);
        refreshAxes();
        updateGapLabels();
    });
    m_clothSettings = new QAction(tr("Cloth Settings..."), this);
    m_clothSettings->setObjectName("clothSettings");
    m_clothSettings->setToolTip(tr("The cloth's mass per area, stiffness, damping, air drag, substeps and the margin it keeps off the body"));
    connect(m_clothSettings, &QAction::triggered, this, [this] { editClothSettings(); });
    const auto visibility = m_viewport->visibility();
    m_puppet->setChecked(visibility.puppet);
    m_axis->setChecked(visibility.axis);
    m_orbits->setChecked(false);
    m_grid->setChecked(visibility.grid);
    m_shadows->setChecked(visibility.shadows);
    m_partner->setChecked(visibility.partner);
    m_puppet->setObjectName("showPuppet");
    m_axis->setObjectName("showAxis");
    m_orbits->setObjectName("showOrbits");
    m_grid->setObjectName("showGrid");
    m_shadows->setObjectName("showShadows");
    m_partner->setObjectName("showPartner");
    m_puppet->setToolTip(tr("The puppet posed by take A (and B beside it)"));
    m_axis->setToolTip(tr("The motion axis (thesis 5.2.1): red front, green side, blue up, at the centre of mass"));
    m_orbits->setToolTip(tr("The paths of the head, shoulder, arm and hand sensors over the whole take, drawn over the "
                            "puppet, with a ball where each sensor is now"));
    m_grid->setToolTip(tr("The floor: a 20 cm grid under the lowest point of the figures, fading out at 2 m"));
    m_shadows->setToolTip(tr("The figures' soft shadows on the floor, cast by the key light above them, in front and "
                             "to their left"));
    m_partner->setToolTip(tr("The partner (the person greeted or served): a slate figure of the take's puppet as it "
                             "stands at the first frame, 110 cm in front of it and facing it"));
    // The controls flow onto more rows in a narrow dock: every one stays reachable, and the
    // dock does not widen (a tool bar's extension menu cannot show check and combo boxes).
    auto* toggles = new QWidget(this);
    toggles->setObjectName("viewToolBar");
    auto* flow = new widgets::FlowLayout(toggles);
    flow->setContentsMargins(4, 2, 4, 2);
    for (auto* box : {m_puppet, m_axis, m_orbits, m_grid, m_shadows, m_partner}) {
        flow->addWidget(box);
        connect(box, &QCheckBox::toggled, this, &ViewportPanel::applyVisibility);
    }
    flow->addWidget(m_follow);
    flow->addWidget(m_cloth);
    auto* clothButton = new QToolButton(toggles);
    clothButton->setDefaultAction(m_clothSettings);
    clothButton->setObjectName("clothSettingsButton");
    flow->addWidget(clothButton);
    for (int slot = 0; slot < 2; ++slot) {
        auto* box = new QComboBox(this);
        box->setObjectName(slot == 0 ? "figureA" : "figureB");
        box->addItem(tr("Puppet"), int(render::FigureStyle::Puppet));
        box->addItem(tr("Skeleton"), int(render::FigureStyle::Skeleton));
        box->addItem(tr("Both"), int(render::FigureStyle::PuppetAndSkeleton));
        box->addItem(tr("Body"), int(render::FigureStyle::Body));
        box->addItem(tr("File's mesh"), int(render::FigureStyle::FileMesh)); // enabled for a take whose file carries one
        box->setToolTip(slot == 0 ? tr("Figure of take A: the puppet, the performer's skeleton (takes read from BVH, FBX, glTF, Collada), "
                                       "both, the performer's body, or the file's own skinned mesh (FBX, glTF and Collada characters)")
                                  : tr("Figure of take B: the puppet, the performer's skeleton (takes read from BVH, FBX, glTF, Collada), "
                                       "both, the performer's body, or the file's own skinned mesh (FBX, glTF and Collada characters)"));
        connect(box, &QComboBox::currentIndexChanged, this, &ViewportPanel::applyVisibility);
        // The label and its box as one item: they never part at a row's end.
        auto* pair = new QWidget(toggles);
        auto* row = new QHBoxLayout(pair);
        row->setContentsMargins(0, 0, 0, 0);
        row->setSpacing(2);
        row->addWidget(new QLabel(slot == 0 ? tr("A:") : tr("B:"), pair));
        row->addWidget(box);
        flow->addWidget(pair);
        m_figures[slot] = box;
    }
    createCameraActions(toggles);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(toggles);
    m_gapLabel = new QLabel(this);
    m_gapLabel->setObjectName("skeletonGap");
    m_gapLabel->setWordWrap(true);
    m_gapLabel->setStyleSheet(QStringLiteral("color: #b35900;"));
    m_gapLabel->setToolTip(tr("A derived take's graphs are its 24 channels as the thesis computes them (each coordinate with its own "
                              "time warp, positions averaged); its skeleton moves as one body (one time per frame, joint rotations "
                              "averaged). The puppet follows the channels, the skeleton the body: this is how far apart they are. "
                              "BVH and glTF exports hold the skeleton, CSV the channels."));
    m_gapLabel->hide();
    layout->addWidget(m_gapLabel);
    layout->addWidget(m_viewport, 1);

    // Uploading a scene costs about one frame (it happens once, at the next paint, however many
    // scenes were set before it): a changed take shows at once, its axis when computed.
    connect(&document, &Document::selectionChanged, this, &ViewportPanel::rebuildScene);
    connect(&document, &Document::selectedTakeReplaced, this, &ViewportPanel::rebuildScene);
    connect(&document, &Document::corpusChanged, this, &ViewportPanel::rebuildScene);
    // An axis slot that finished, restarted for other inputs or was cleared.
    connect(&analysis.scheduler(), &StageScheduler::stateChanged, this, [this](int slot) {
        if (slot == AnalysisController::kTakeAxisSlot || slot == AnalysisController::kTakeAxisBSlot ||
            slot == AnalysisController::kKimonoSlot || slot == AnalysisController::kKimonoBSlot) {
            refreshAxes();
            updateGapLabels();
        }
    });
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
        const auto shown = shownTakes(m_document); // the scene's takes are the shown slots, in order
        emit bonePicked(sceneSlot < int(shown.size()) ? int(shown[std::size_t(sceneSlot)].first) : sceneSlot, joint, part);
    });
    applyVisibility();
    rebuildScene();
}

std::array<QCheckBox*, std::size(kShownObjectKeys)> ViewportPanel::shownObjectBoxes() const
{
    return {m_puppet, m_axis, m_orbits, m_grid, m_shadows, m_partner, m_follow};
}

ShownObjects ViewportPanel::shownObjects() const
{
    ShownObjects shown;
    const auto boxes = shownObjectBoxes();
    for (std::size_t i = 0; i < boxes.size(); ++i) shown.*(kShownObjectKeys[i].second) = boxes[i]->isChecked();
    return shown;
}

void ViewportPanel::setShownObjects(const ShownObjects& shown)
{
    const auto boxes = shownObjectBoxes();
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (const std::optional<bool>& value = shown.*(kShownObjectKeys[i].second)) boxes[i]->setChecked(*value);
}

void ViewportPanel::rebuildScene()
{
    const auto takes = shownTakes(m_document);
    m_drawnAxes.clear();
    m_drawnKimonos.clear();
    if (takes.empty()) {
        m_viewport->setScene(render::SceneContent{}); // nothing stays drawn of the takes shown before
        updateGapLabels();                            // and the view says why (a take with no figure)
        return;
    }
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    // The shipped body lives as long as the program: its address is its identity.
    scene.bodySource = std::shared_ptr<const void>(&analysis::defaultBodyDescription(), [](const void*) {});
    for (const auto& [slot, take] : takes) {
        render::TakeSlot shown;
        shown.take = *take;
        // A take with its performer's skeleton is drawn with the puppet fitted to it (fitted once per take).
        FittedBody& fitted = m_fittedBodies[int(slot)];
        if (take->skeleton && fitted.take.lock() != take) {
            fitted.take = take;
            fitted.body = std::make_shared<const analysis::BodyDescription>(analysis::bodyForTake(scene.body, *take));
        }
        if (take->skeleton) shown.body = fitted.body;
        // The axis of this very take (and the current axis parameters), or none until it is computed.
        const auto axis = m_analysis.takeAxis(slot, take);
        if (axis) shown.world_T_axis = axis->world_T_axis;
        m_drawnAxes.push_back(axis);
        // The kimono of this very take, body and cloth parameters, or the skinned one until then.
        const auto kimono = m_analysis.kimono(slot, take);
        shown.kimono = kimono;
        m_drawnKimonos.push_back(kimono);
        // What the slot is made from: a scene replaced for the other take keeps this one's (a drag of A).
        shown.sources = {take, axis, shown.body, kimono};
        scene.takes.push_back(std::move(shown));
    }
    m_viewport->setScene(std::move(scene));
    m_viewport->setTime(m_document.currentTime());
    applyVisibility(); // take B may now be the scene's first take
}

void ViewportPanel::refreshAxes()
{
    const auto takes = shownTakes(m_document);
    if (takes.size() != m_drawnAxes.size() || takes.size() != m_drawnKimonos.size()) return rebuildScene();
    for (std::size_t i = 0; i < takes.size(); ++i)
        if (m_analysis.takeAxis(takes[i].first, takes[i].second) != m_drawnAxes[i] ||
            m_analysis.kimono(takes[i].first, takes[i].second) != m_drawnKimonos[i])
            return rebuildScene();
}

void ViewportPanel::applyVisibility()
{
    auto visibility = m_viewport->visibility();
    visibility.puppet = m_puppet->isChecked();
    visibility.axis = m_axis->isChecked();
    visibility.orbits = m_orbits->isChecked();
    visibility.grid = m_grid->isChecked();
    visibility.shadows = m_shadows->isChecked();
    visibility.partner = m_partner->isChecked();
    visibility.orbitVisibility = render::OrbitVisibility::Always; // the box shows them, puppet or not
    const auto shown = shownTakes(m_document);
    for (std::size_t s = 0; s < shown.size() && s < visibility.figures.size(); ++s)
        visibility.figures[s] = render::FigureStyle(m_figures[int(shown[s].first)]->currentData().toInt());
    // "File's mesh" is offered for takes whose file carries a skinned mesh; a take without one
    // shows its skeleton (the label says so).
    for (int slot = 0; slot < 2; ++slot) {
        bool hasMesh = false;
        for (const auto& [s, t] : shown)
            if (int(s) == slot && t) hasMesh = render::takeHasFileMesh(*t);
        if (auto* model = qobject_cast<QStandardItemModel*>(m_figures[slot]->model()))
            if (QStandardItem* item = model->item(m_figures[slot]->findData(int(render::FigureStyle::FileMesh))))
                item->setEnabled(hasMesh);
    }
    for (std::size_t s = 0; s < shown.size() && s < visibility.figures.size(); ++s)
        if (visibility.figures[s] == render::FigureStyle::FileMesh && !(shown[s].second && render::takeHasFileMesh(*shown[s].second)))
            visibility.figures[s] = render::FigureStyle::Skeleton;
    m_viewport->setVisibility(visibility);
    updateGapLabels();
}

void ViewportPanel::updateGapLabels()
{
    const auto shown = shownTakes(m_document);
    QStringList lines;
    // A take shown with no figure to draw (the motion axis's or the kimono's channels) is said,
    // not left as an empty view.
    // (shownTakes keeps the drawable ones: a chosen take missing from it has none.)
    for (TakeSlot slot : {TakeSlot::A, TakeSlot::B})
        if (m_document.selectedTake(slot) &&
            std::none_of(shown.begin(), shown.end(), [slot](const auto& drawn) { return drawn.first == slot; }))
            lines << tr("%1: %2 has no figure to draw: its channels are in the graphs")
                         .arg(slot == TakeSlot::A ? QStringLiteral("A") : QStringLiteral("B"),
                              m_document.takeLabel(m_document.selectedId(slot)));
    for (int slot = 0; slot < 2; ++slot) {
        TakePointer take;
        for (const auto& [s, t] : shown)
            if (int(s) == slot) take = t;
        const bool skeletonDrawn =
            take && take->skeleton && render::FigureStyle(m_figures[slot]->currentData().toInt()) != render::FigureStyle::Puppet;
        std::optional<analysis::SkeletonChannelGap> gap;
        if (skeletonDrawn) {
            GapMemo& memo = m_gapMemo[slot];
            if (memo.take.lock() != take) memo = {take, analysis::noticeableSkeletonGap(*take)};
            gap = memo.gap;
        }
        if (gap)
            lines << tr("%1: skeleton off the channels by %2")
                         .arg(slot == 0 ? QStringLiteral("A") : QStringLiteral("B"),
                              QString::fromStdString(analysis::describeSkeletonChannelGap(*gap)));
    }
    for (int slot = 0; slot < 2; ++slot) {
        if (render::FigureStyle(m_figures[slot]->currentData().toInt()) != render::FigureStyle::FileMesh) continue;
        for (const auto& [s, t] : shown)
            if (int(s) == slot && t && !render::takeHasFileMesh(*t))
                lines << tr("%1: the take's file carries no skinned mesh: its skeleton is shown")
                             .arg(slot == 0 ? QStringLiteral("A") : QStringLiteral("B"));
    }
    // While a shown take's cloth is simulated, the view says what it shows meanwhile.
    if (m_cloth->isChecked())
        for (const auto& [slot, take] : shown) {
            if (render::FigureStyle(m_figures[int(slot)]->currentData().toInt()) == render::FigureStyle::Skeleton) continue;
            const int job = AnalysisController::kimonoSlot(slot);
            const QString name = slot == TakeSlot::A ? QStringLiteral("A") : QStringLiteral("B");
            if (m_analysis.kimono(slot, take)) continue;
            if (m_analysis.scheduler().state(job) == SlotState::Failed)
                lines << tr("%1: the kimono could not be simulated (%2): the kimono moving with the body is shown")
                             .arg(name, m_analysis.scheduler().error(job));
            else
                lines << tr("%1: simulating the kimono's cloth: the kimono moving with the body is shown until it is ready").arg(name);
        }
    m_gapLabel->setText(lines.join(QLatin1Char('\n')));
    m_gapLabel->setVisible(!lines.isEmpty());
}

bool ViewportPanel::editClothSettings()
{
    QDialog dialog(this);
    dialog.setObjectName("clothSettingsDialog");
    dialog.setWindowTitle(tr("Cloth Settings"));
    auto* form = new QFormLayout(&dialog);
    const analysis::ClothParameters current = m_analysis.clothParameters();
    // What each parameter means; its range is analysis's one table (clothParameterLimits).
    const std::map<std::string, std::tuple<QString, int, QString>> described{
        {"massPerArea", {tr("Mass per area (g/cm²)"), 5, tr("Silk crepe (chirimen) is about 0.015 g/cm² (150 g/m²)")}},
        {"stretchCompliance", {tr("Stretch compliance (cm/dyn)"), 6, tr("The inverse of the stiffness of the cloth's threads: 0 is inextensible")}},
        {"bendCompliance", {tr("Bend compliance (cm/dyn)"), 6, tr("How easily the cloth folds: larger is softer")}},
        {"damping", {tr("Damping (1/s)"), 3, tr("The velocity relative to the body lost per second (the cloth's internal friction)")}},
        {"drag", {tr("Air drag (1/s)"), 3, tr("The velocity lost to the air per second")}},
        {"substepRate", {tr("Substeps per second (Hz)"), 0, tr("Simulation steps per second of take (at least one per frame): more is stiffer and slower")}},
        {"collisionMargin", {tr("Margin off the body (cm)"), 2, tr("How far the cloth keeps off the puppet's torso and arms")}},
        {"settleSeconds", {tr("Settling before the take (s)"), 2,
                           tr("Seconds the first pose is held before frame 0, so that the kimono hangs at rest when the take starts")}},
    };
    const auto& fields = analysis::clothParameterLimits();
    std::vector<QDoubleSpinBox*> boxes;
    for (const analysis::ClothParameterLimit& field : fields) {
        const auto found = described.find(field.name);
        const auto [label, decimals, tip] = found != described.end() ? found->second : std::tuple<QString, int, QString>{QString::fromLatin1(field.name), 6, QString()};
        auto* box = new QDoubleSpinBox(&dialog);
        box->setObjectName(QString::fromLatin1(field.name));
        box->setDecimals(decimals);
        box->setRange(field.low, field.high);
        box->setValue(current.*(field.member));
        box->setToolTip(tip);
        form->addRow(label, box);
        boxes.push_back(box);
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel | QDialogButtonBox::RestoreDefaults, &dialog);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, &dialog, [&] {
        const analysis::ClothParameters defaults;
        for (std::size_t i = 0; i < fields.size(); ++i) boxes[i]->setValue(defaults.*(fields[i].member));
    });
    form->addRow(buttons);
    if (dialog.exec() != QDialog::Accepted) return false;
    analysis::ClothParameters chosen;
    for (std::size_t i = 0; i < fields.size(); ++i) chosen.*(fields[i].member) = boxes[i]->value();
    if (auto status = m_analysis.setClothParameters(chosen); !status) {
        QMessageBox::warning(this, tr("Cloth Settings"), QString::fromStdString(status.error().message));
        return false;
    }
    refreshAxes();
    updateGapLabels();
    return true;
}

} // namespace bunraku::app
