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

QVariantMap ViewportPanel::cameraState() const
{
    const render::Camera& camera = m_viewport->camera();
    return {{"angle", double(camera.angleDeg)},
            {"elevation", double(camera.elevationDeg)},
            {"distance", double(camera.distance)},
            {"target", QVariantList{double(camera.target.x), double(camera.target.y), double(camera.target.z)}},
            {"fov", double(camera.fieldOfViewDeg)}};
}

void ViewportPanel::setCameraState(const QVariantMap& state)
{
    const QVariantList target = state.value("target").toList();
    if (target.size() != 3) return;
    render::Camera camera;
    camera.angleDeg = float(state.value("angle").toDouble());
    camera.elevationDeg = float(state.value("elevation").toDouble());
    camera.distance = float(state.value("distance").toDouble());
    camera.fieldOfViewDeg = float(state.value("fov", 35.0).toDouble());
    camera.target = {float(target[0].toDouble()), float(target[1].toDouble()), float(target[2].toDouble())};
    for (float value : {camera.angleDeg, camera.elevationDeg, camera.distance, camera.fieldOfViewDeg, camera.target.x,
                        camera.target.y, camera.target.z})
        if (!std::isfinite(value)) return;
    m_viewport->setCamera(camera);
}

} // namespace bunraku::app
