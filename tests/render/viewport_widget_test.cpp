// The thin viewport widget: it shows the scene it is given, a click picks the part under the
// pointer, a left drag orbits the camera and the wheel zooms; its window stays raster (the view
// draws offscreen), so screenshots, docking and floating work like any widget.
#include "render_test_support.h"
#include "widgets/viewport_widget.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QSignalSpy>
#include <QTest>
#include <QWindow>

using namespace bunraku;

namespace {

render::SceneContent oneTake()
{
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(3), {}});
    return scene;
}

render::Camera frontCamera()
{
    render::Camera camera;
    camera.angleDeg = 270.0f;
    camera.elevationDeg = 5.0f;
    camera.distance = 200.0f;
    camera.target = {0.0f, 0.0f, 75.0f};
    return camera;
}

} // namespace

TEST_CASE("the viewport shows the puppet and a click on its head picks the head", "[widgets][viewport]")
{
    widgets::ViewportWidget viewport;
    viewport.resize(400, 300);
    viewport.setScene(oneTake());
    viewport.setCamera(frontCamera());
    viewport.show();
    REQUIRE(QTest::qWaitForWindowExposed(&viewport));
    const QImage frame = viewport.grabFramebuffer();
    REQUIRE_FALSE(frame.isNull());
    REQUIRE(viewport.renderer() != nullptr);

    // The head's face, where the camera projects it (in widget pixels; the image is in device pixels).
    const auto world_T_head = viewport.renderer()->displayedPartTransforms(0, viewport.camera())[0];
    const glm::vec3 face = glm::vec3(world_T_head * glm::vec4(-2.0f, 0.0f, -0.5f, 1.0f));
    const QSize pixels(int(viewport.width() * viewport.devicePixelRatioF()),
                       int(viewport.height() * viewport.devicePixelRatioF()));
    const QPointF pixel = viewport.camera().project(face, pixels).pixel / viewport.devicePixelRatioF();
    CHECK_FALSE(test::isBackground(frame.pixel((pixel * viewport.devicePixelRatioF()).toPoint())));

    QSignalSpy picked(&viewport, &widgets::ViewportWidget::partPicked);
    QSignalSpy background(&viewport, &widgets::ViewportWidget::backgroundPicked);
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, pixel.toPoint());
    REQUIRE(picked.count() == 1);
    CHECK(picked.at(0).at(0).toInt() == 0);
    CHECK(picked.at(0).at(1).toString() == QStringLiteral("head"));
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(3, 3));
    CHECK(background.count() == 1);
}

TEST_CASE("dragging orbits the viewport's camera and the wheel zooms it", "[widgets][viewport]")
{
    widgets::ViewportWidget viewport;
    viewport.resize(320, 240);
    viewport.setScene(oneTake());
    viewport.setCamera(frontCamera());
    viewport.show();
    REQUIRE(QTest::qWaitForWindowExposed(&viewport));
    const float angle = viewport.camera().angleDeg;
    QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(100, 100));
    QMouseEvent move(QEvent::MouseMove, QPointF(150, 100), viewport.mapToGlobal(QPointF(150, 100)), Qt::NoButton,
                     Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&viewport, &move);
    QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(150, 100));
    // 50 pixels right turn the camera by -20 degrees (the scene follows the mouse).
    CHECK(viewport.camera().angleDeg == Approx(std::fmod(angle - 20.0f + 360.0f, 360.0f)).margin(1e-3));

    const float distance = viewport.camera().distance;
    QWheelEvent wheel(QPointF(160, 120), viewport.mapToGlobal(QPointF(160, 120)), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(&viewport, &wheel);
    CHECK(viewport.camera().distance < distance);
}

TEST_CASE("a viewport without a chosen camera frames each new scene", "[widgets][viewport]")
{
    widgets::ViewportWidget viewport(nullptr, 0);
    viewport.resize(320, 240);
    viewport.setScene(oneTake());
    viewport.show();
    REQUIRE(QTest::qWaitForWindowExposed(&viewport));
    (void)viewport.grabFramebuffer(); // paints: uploads the scene
    REQUIRE(viewport.renderer() != nullptr);
    // Reset Camera's view of the figures over the whole take (render/framing.h).
    render::BoundsQuery figures;
    figures.figuresOnly = true;
    const render::Camera framing = render::resetCamera(viewport.renderer()->displayedBounds(viewport.camera(), figures), QSize(320, 240));
    CHECK(viewport.camera().target.z == Approx(framing.target.z));
    CHECK(viewport.camera().distance == Approx(framing.distance));
    CHECK(viewport.camera().angleDeg == Approx(340.0f));
    // The framed puppet is on screen: its shoulder projects inside the image.
    const auto world_T_shoulder = viewport.renderer()->displayedPartTransforms(0, viewport.camera())[1];
    const auto shoulder = viewport.camera().project(glm::vec3(world_T_shoulder[3]), QSize(320, 240));
    CHECK(QRectF(0, 0, 320, 240).contains(shoulder.pixel));
}

namespace {

/// The pixel (in widget coordinates) where the viewport's camera shows the head's face.
QPoint facePixel(const widgets::ViewportWidget& viewport)
{
    const auto world_T_head = viewport.renderer()->displayedPartTransforms(0, viewport.camera())[0];
    const glm::vec3 face = glm::vec3(world_T_head * glm::vec4(-2.0f, 0.0f, -0.5f, 1.0f));
    const QSize pixels(int(viewport.width() * viewport.devicePixelRatioF()), int(viewport.height() * viewport.devicePixelRatioF()));
    return (viewport.camera().project(face, pixels).pixel / viewport.devicePixelRatioF()).toPoint();
}

} // namespace

TEST_CASE("a window holding the viewport stays raster and its screenshot shows the puppet", "[widgets][viewport]")
{
    // A QOpenGLWidget would turn its whole top-level window into an OpenGL-composed surface
    // (every repaint of any neighbour then costs a full-window composition).
    QMainWindow window;
    auto* dock = new QDockWidget(QStringLiteral("3D"), &window);
    auto* viewport = new widgets::ViewportWidget(nullptr, 0);
    dock->setWidget(viewport);
    window.addDockWidget(Qt::RightDockWidgetArea, dock);
    window.setCentralWidget(new QWidget(&window));
    viewport->setScene(oneTake());
    viewport->setCamera(frontCamera());
    window.resize(800, 400);
    window.show();
    REQUIRE(QTest::qWaitForWindowExposed(&window));
    REQUIRE(QTest::qWaitFor([&] { return viewport->renderedFrameCount() > 0; }, 5000));
    CHECK(window.windowHandle()->surfaceType() == QSurface::RasterSurface);
    REQUIRE(viewport->renderer() != nullptr);

    // QWidget::grab (the workbench's screenshots) shows the rendered puppet.
    const QImage screenshot = window.grab().toImage();
    const QPoint face = facePixel(*viewport);
    const QPoint inWindow = viewport->mapTo(&window, face) * window.devicePixelRatioF();
    CHECK_FALSE(test::isBackground(screenshot.pixel(inWindow)));
    CHECK(test::isBackground(screenshot.pixel(viewport->mapTo(&window, QPoint(3, 3)) * window.devicePixelRatioF())));

    // Floated out of the window, the view keeps drawing and picking.
    dock->setFloating(true);
    REQUIRE(QTest::qWaitForWindowExposed(dock));
    const int drawn = viewport->renderedFrameCount();
    viewport->setTime(0.2);
    viewport->repaint();
    CHECK(viewport->renderedFrameCount() > drawn);
    QSignalSpy picked(viewport, &widgets::ViewportWidget::partPicked);
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, facePixel(*viewport));
    REQUIRE(picked.count() == 1);
    CHECK(picked.at(0).at(1).toString() == QStringLiteral("head"));
    const QImage floating = viewport->grabFramebuffer();
    CHECK(floating.size() == viewport->size() * viewport->devicePixelRatioF());
    CHECK_FALSE(test::isBackground(floating.pixel(facePixel(*viewport) * viewport->devicePixelRatioF())));
}

TEST_CASE("quick successive frames skip multisampling and the still frame is redrawn with it", "[widgets][viewport]")
{
    widgets::ManualClock clock; // time moves only when the test says so
    widgets::ViewportWidget viewport(nullptr, 4);
    viewport.setClock(&clock);
    viewport.resize(320, 240);
    viewport.setScene(oneTake());
    viewport.setCamera(frontCamera());
    viewport.show();
    REQUIRE(QTest::qWaitForWindowExposed(&viewport));
    (void)QTest::qWaitFor([&] { return viewport.renderedFrameCount() > 0 && viewport.shownSamples() == 4; }, 5000);
    REQUIRE(viewport.shownSamples() == 4); // a first (or isolated) frame is drawn at full quality

    // A frame right after another one (playback, a drag): no multisampling, but a new frame.
    const int drawn = viewport.renderedFrameCount();
    viewport.setTime(0.4);
    viewport.repaint();
    REQUIRE(viewport.renderedFrameCount() == drawn + 1);
    CHECK(viewport.shownSamples() == 0);
    CHECK(viewport.renderer()->frame(0) == 2);
    // A paint without a change reuses the image.
    viewport.repaint();
    CHECK(viewport.renderedFrameCount() == drawn + 1);
    // Once the view is still, the same frame is redrawn with multisampling.
    clock.advance(widgets::ViewportWidget::kSettleMs - 1);
    CHECK(viewport.shownSamples() == 0);
    clock.advance(1);
    CHECK(viewport.shownSamples() == 4);
    CHECK(viewport.renderedFrameCount() == drawn + 2);
    CHECK(viewport.renderer()->frame(0) == 2);
    // A change after a still moment is drawn at full quality at once.
    clock.advance(widgets::ViewportWidget::kSettleMs);
    viewport.setTime(0.0);
    viewport.repaint();
    CHECK(viewport.shownSamples() == 4);
    CHECK(viewport.renderer()->frame(0) == 0);
    // Screenshots and frame export always use the view's multisampling.
    viewport.setTime(0.2);
    (void)viewport.grabFramebuffer();
    CHECK(viewport.shownSamples() == 4);
    CHECK(viewport.renderer()->frame(0) == 1);
}

TEST_CASE("Follow keeps a walking take in the middle of the view at every frame", "[widgets][viewport][travel]")
{
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{test::travellingTake(60, 400.0), {}});
    widgets::ViewportWidget viewport;
    viewport.resize(400, 300);
    viewport.setScene(scene);
    render::Camera camera = frontCamera();
    camera.angleDeg = 0.0f; // on +y, looking across the walk (along -y)
    camera.distance = 260.0f;
    viewport.setCamera(camera);
    viewport.show();
    REQUIRE(QTest::qWaitForWindowExposed(&viewport));
    const auto figureOffset = [&viewport](int frame) {
        viewport.setFrame(frame);
        const QImage image = viewport.grabFramebuffer();
        render::BoundsQuery now;
        now.span = render::FramingSpan::CurrentFrame;
        now.figuresOnly = true;
        const render::Bounds figure = viewport.renderer()->displayedBounds(viewport.camera(), now);
        const QSize pixels = image.size();
        const QPointF centre = viewport.camera().project(figure.centre(), pixels).pixel;
        // Also seen: the figure's middle is drawn there, not background.
        const bool drawn = QRect(QPoint(0, 0), pixels).contains(centre.toPoint()) &&
                           test::anyPixelNear(image, centre, 4, [](QRgb p) { return !test::isBackground(p); });
        return std::make_pair(std::abs(centre.x() - 0.5 * pixels.width()) / pixels.width(), drawn);
    };
    // Without Follow the walker leaves the view's middle (2 m either side of it).
    CHECK(figureOffset(0).first > 0.3);
    CHECK(figureOffset(59).first > 0.3);
    viewport.setFollow(true);
    for (const int frame : {0, 20, 40, 59}) {
        INFO("frame " << frame);
        const auto [offset, drawn] = figureOffset(frame);
        CHECK(offset < 0.02);
        CHECK(drawn);
    }
    // The camera kept its angle, elevation and distance.
    CHECK(viewport.camera().angleDeg == camera.angleDeg);
    CHECK(viewport.camera().distance == camera.distance);
}
