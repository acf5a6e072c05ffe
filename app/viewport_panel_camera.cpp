// The 3D view's camera actions and the camera as project view state (app/viewport_panel.h).
#include "app/viewport_panel.h"

#include "widgets/viewport_widget.h"

#include <QAction>
#include <QKeySequence>
#include <QLayout>
#include <QToolButton>
#include <QVariantList>

#include <cmath>

namespace bunraku::app {

void ViewportPanel::createCameraActions(QWidget* bar)
{
    m_frameAll = new QAction(tr("Frame All"), this);
    m_frameAll->setObjectName("frameAllAction");
    m_frameAll->setShortcut(QKeySequence(Qt::Key_F));
    m_frameAll->setToolTip(tr("Frame All (F): fit everything the 3D view draws over the whole take"));
    m_frameSelected = new QAction(tr("Frame Selected"), this);
    m_frameSelected->setObjectName("frameSelectedAction");
    m_frameSelected->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F));
    m_frameSelected->setToolTip(tr("Frame Selected (Shift+F): fit the part last clicked in the 3D view (else the "
                                   "figures) at the current frame"));
    // Home goes to the start everywhere but in the focused 3D view, where it resets the camera
    // (ViewportWidget): the menu shows it without a window-wide shortcut.
    m_resetCamera = new QAction(tr("Reset Camera") + QLatin1Char('\t') + tr("Home in 3D view"), this);
    m_resetCamera->setObjectName("resetCameraAction");
    m_resetCamera->setIconText(tr("Reset"));
    m_resetCamera->setToolTip(tr("Reset Camera (Home with the 3D view focused): the first view, framing the whole take"));
    for (QAction* action : {m_frameAll, m_frameSelected, m_resetCamera}) {
        action->setShortcutContext(Qt::WindowShortcut);
        bar->addAction(action);
        auto* button = new QToolButton(bar);
        button->setDefaultAction(action);
        button->setAutoRaise(true);
        bar->layout()->addWidget(button);
    }
    connect(m_frameAll, &QAction::triggered, m_viewport, &widgets::ViewportWidget::frameAll);
    connect(m_frameSelected, &QAction::triggered, this, [this] { m_viewport->frameSelected(m_selectedPart); });
    connect(m_resetCamera, &QAction::triggered, m_viewport, &widgets::ViewportWidget::resetCamera);
}

CameraState ViewportPanel::cameraState() const
{
    const render::Camera& camera = m_viewport->camera();
    CameraState state;
    state.angle = camera.angleDeg;
    state.elevation = camera.elevationDeg;
    state.distance = camera.distance;
    state.target = {camera.target.x, camera.target.y, camera.target.z};
    state.fov = camera.fieldOfViewDeg;
    return state;
}

void ViewportPanel::setCameraState(const CameraState& state)
{
    render::Camera camera;
    camera.angleDeg = float(state.angle);
    camera.elevationDeg = float(state.elevation);
    camera.distance = float(state.distance);
    camera.fieldOfViewDeg = float(state.fov);
    camera.target = {float(state.target[0]), float(state.target[1]), float(state.target[2])};
    for (float value : {camera.angleDeg, camera.elevationDeg, camera.distance, camera.fieldOfViewDeg, camera.target.x,
                        camera.target.y, camera.target.z})
        if (!std::isfinite(value)) return;
    m_viewport->setCamera(camera);
}

} // namespace bunraku::app
