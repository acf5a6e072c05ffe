// The thin viewport widget: it shows the scene it is given, a click picks the part under the
// pointer, a left drag orbits the camera and the wheel zooms.
#include "render_test_support.h"
#include "widgets/viewport_widget.h"

#include <QSignalSpy>
#include <QTest>

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

    // The head's face, where the camera projects it (in widget pixels: device ratio 1 under Xvfb).
    const auto world_T_head = viewport.renderer()->displayedPartTransforms(0, viewport.camera())[0];
    const glm::vec3 face = glm::vec3(world_T_head * glm::vec4(-2.0f, 0.0f, -0.5f, 1.0f));
    const QSize pixels(int(viewport.width() * viewport.devicePixelRatioF()),
                       int(viewport.height() * viewport.devicePixelRatioF()));
    const QPointF pixel = viewport.camera().project(face, pixels).pixel / viewport.devicePixelRatioF();
    CHECK_FALSE(test::isBackground(frame.pixel(pixel.toPoint())));

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
    const render::Camera framing = viewport.renderer()->framingCamera();
    CHECK(viewport.camera().target.z == Approx(framing.target.z));
    CHECK(viewport.camera().target.z == Approx(viewport.renderer()->floorHeight() + 45.0f));
    // The framed puppet is on screen: its shoulder projects inside the image.
    const auto world_T_shoulder = viewport.renderer()->displayedPartTransforms(0, viewport.camera())[1];
    const auto shoulder = viewport.camera().project(glm::vec3(world_T_shoulder[3]), QSize(320, 240));
    CHECK(QRectF(0, 0, 320, 240).contains(shoulder.pixel));
}
